/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief UTM/UPS: the zone rules, geographic -> grid and grid ->
 *        geographic on the transverse Mercator of tm.c and the polar
 *        stereographic of ups.c, with the zones, false origins and
 *        coordinate limits of GeographicLib's UTMUPS (and GeoConvert).
 *
 * Positions are validated in nas and metres, converted in Q5.58 radians
 * and angles on the projection's sphere, and come back as metres in
 * Q28.36, rounded to Q47.16 after the false origin's offset is known.
 */
#include <drdc/geo.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>

#include "geo_grid.h"
#include "geo_projection.h"

/** Latitude limits of the UTM zones (UPS beyond): [-80, 84) degrees. */
#define UTM_LAT_MIN (INT64_C(-80) * GEO_NAS_DEG)
#define UTM_LAT_MAX (INT64_C(84) * GEO_NAS_DEG)

/* 2^62: k0 A (Q40) times an angle (Q58) over 2^62 is metres in Q36. */
#define TWO_POW_62 INT64_C(4611686018427387904)

/* Q47.16 metres -> Q28.36 (exact for the false origins used here). */
#define Q36_FROM_Q16(v) ((v)*INT64_C(1048576))

static drdc_status_t check_lat_lon(drdc_nas_t lat, drdc_nas_t lon)
{
  if ((lat > (90 * GEO_NAS_DEG)) || (lat < (-90 * GEO_NAS_DEG))) {
    return DRDC_E_LATITUDE;
  }
  if ((lon >= (540 * GEO_NAS_DEG)) || (lon < (-540 * GEO_NAS_DEG))) {
    return DRDC_E_LONGITUDE;
  }
  return DRDC_OK;
}

/* The standard zone of a checked point (0: UPS), with the exceptions of
 * Norway and Svalbard. */
static int32_t standard_zone(drdc_nas_t lat, drdc_nas_t lon)
{
  int64_t ilon;
  int64_t band;
  int64_t zone;

  if ((lat >= UTM_LAT_MAX) || (lat < UTM_LAT_MIN)) {
    return 0;
  }
  ilon = drdc__geo_floor_div(geo_lon_normalize(lon), GEO_NAS_DEG);
  zone = (ilon + 186) / 6;
  band = drdc__geo_floor_div(lat, 8 * GEO_NAS_DEG);
  if (band > 9) {
    band = 9;
  }
  if ((band == 7) && (zone == 31) && (ilon >= 3)) {
    zone = 32; /* Norway: 32V reaches 3 degrees east */
  } else if ((band == 9) && (ilon >= 0) && (ilon < 42)) {
    zone = (2 * ((ilon + 183) / 12)) + 1; /* Svalbard: 31X 33X 35X 37X */
  } else {
    /* the regular 6-degree zone */
  }
  return (int32_t)zone;
}

drdc_status_t drdc_geo_utm_zone(drdc_nas_t lat, drdc_nas_t lon, int32_t *zone)
{
  drdc_status_t st;

  if (zone == NULL) {
    return DRDC_E_NULL;
  }
  st = check_lat_lon(lat, lon);
  if (st != DRDC_OK) {
    return st;
  }
  *zone = standard_zone(lat, lon);
  return DRDC_OK;
}

/* A TM angle (radius k0 A) -> metres in Q28.36, rounded (2^-36 m = 15 pm,
 * far below the series' own error). */
static int64_t q36_from_angle(int64_t a)
{
  return drdc__geo_mul_shift(a, GEO_K0A_Q40, 62u);
}

/* The forward projection of the zone (UTM: lam from its central
 * meridian; UPS: from Greenwich) with the hemisphere of north. */
static int project(int32_t zone, bool north, int64_t phi, int64_t lam,
                   geo_projected_t *p)
{
  if (zone == DRDC_GEO_ZONE_UPS) {
    return drdc__geo_ups_forward(north, phi, lam, p);
  }
  return drdc__geo_tm_forward(phi, lam, p);
}

/* x, y of the UPS projection to metres from the false origin, checked
 * (DRDC_E_RANGE) */
static drdc_status_t ups_metres(const geo_projected_t *p, geo_grid_fwd_t *out)
{
  bool north = out->utm.north;
  int64_t x = drdc__geo_ups_q36(p->x);
  int64_t y = drdc__geo_ups_q36(p->y);

  out->utm.easting = GEO_UPS_FALSE_ORIGIN + drdc_fx_rshift_round_s64(x, 20u);
  out->utm.northing = GEO_UPS_FALSE_ORIGIN + drdc_fx_rshift_round_s64(y, 20u);
  if (!geo_ups_in_range(north, out->utm.easting) ||
      !geo_ups_in_range(north, out->utm.northing)) {
    return DRDC_E_RANGE;
  }
  out->easting_q36 = Q36_FROM_Q16(GEO_UPS_FALSE_ORIGIN) + x;
  out->northing_q36 = Q36_FROM_Q16(GEO_UPS_FALSE_ORIGIN) + y;
  return DRDC_OK;
}

/* eta, xi of the TM projection to metres from the false origin, checked
 * (DRDC_E_RANGE). Each offset is rounded to Q47.16 before the false
 * origin is added (a tie of a negative offset rounds away from zero,
 * which the rounding of the sum would not). */
static drdc_status_t utm_metres(const geo_projected_t *p, geo_grid_fwd_t *out)
{
  bool north = out->utm.north;
  int64_t x = q36_from_angle(p->x);
  int64_t y = q36_from_angle(p->y);
  drdc_q47_16_t e = GEO_UTM_FALSE_EASTING + drdc_fx_rshift_round_s64(x, 20u);
  drdc_q47_16_t n = drdc_fx_rshift_round_s64(y, 20u);

  if (!north) {
    n = n + GEO_UTM_FALSE_NORTHING_SOUTH;
    y = y + Q36_FROM_Q16(GEO_UTM_FALSE_NORTHING_SOUTH);
  }
  if ((e < GEO_UTM_E_MIN) || (e > GEO_UTM_E_MAX)) {
    return DRDC_E_RANGE;
  }
  if (north ? ((n < GEO_UTM_N_NORTH_MIN) || (n > GEO_UTM_N_NORTH_MAX))
            : ((n < GEO_UTM_N_SOUTH_MIN) || (n > GEO_UTM_N_SOUTH_MAX))) {
    return DRDC_E_RANGE;
  }
  out->utm.easting = e;
  out->utm.northing = n;
  out->easting_q36 = Q36_FROM_Q16(GEO_UTM_FALSE_EASTING) + x;
  out->northing_q36 = y;
  return DRDC_OK;
}

drdc_status_t drdc__geo_grid_forward(drdc_nas_t lat, drdc_nas_t lon,
                                     int32_t zone, geo_grid_fwd_t *out)
{
  drdc_status_t st = check_lat_lon(lat, lon);
  int32_t z = zone;
  drdc_nas_t dlon;

  if (st != DRDC_OK) {
    return st;
  }
  if (z == DRDC_GEO_ZONE_STANDARD) {
    z = standard_zone(lat, lon);
  }
  if ((z < DRDC_GEO_ZONE_UPS) || (z > DRDC_GEO_ZONE_MAX)) {
    return DRDC_E_ZONE;
  }
  if (z == DRDC_GEO_ZONE_UPS) {
    dlon = geo_lon_normalize(lon);
  } else {
    /* |dlon| <= 180 degrees; the series' domain ends at 90 */
    dlon = geo_lon_normalize(lon - geo_central_meridian(z));
    if ((dlon > (90 * GEO_NAS_DEG)) || (dlon < (-90 * GEO_NAS_DEG))) {
      return DRDC_E_RANGE;
    }
  }
  out->utm.zone = z;
  out->utm.north = (lat >= 0);
  if (project(z, out->utm.north, drdc__geo_rad_from_nas(lat),
              drdc__geo_rad_from_nas(dlon), &out->proj) == 0) {
    return DRDC_E_RANGE;
  }
  return (z == DRDC_GEO_ZONE_UPS) ? ups_metres(&out->proj, out)
                                  : utm_metres(&out->proj, out);
}

drdc_status_t drdc_geo_to_utm(drdc_nas_t lat, drdc_nas_t lon, int32_t zone,
                              drdc_geo_utm_t *out, drdc_nas_t *convergence,
                              drdc_q5_58_t *scale)
{
  geo_grid_fwd_t g;
  drdc_status_t st;

  if (out == NULL) {
    return DRDC_E_NULL;
  }
  st = drdc__geo_grid_forward(lat, lon, zone, &g);
  if (st != DRDC_OK) {
    return st;
  }
  *out = g.utm;
  if (convergence != NULL) {
    *convergence = drdc__geo_nas_from_rad(g.proj.gamma);
  }
  if (scale != NULL) {
    *scale = g.proj.k;
  }
  return DRDC_OK;
}

/* TM metres (Q47.16, |v| < 2^43) -> an angle on the sphere of radius
 * k0 A */
static int64_t angle_from_metres(drdc_q47_16_t v)
{
  return drdc__geo_muldiv(v * INT64_C(1048576), TWO_POW_62, GEO_K0A_Q40);
}

drdc_status_t drdc__geo_grid_reverse(const drdc_geo_utm_t *in, bool with_scale,
                                     geo_grid_rev_t *out)
{
  bool north = in->north;
  drdc_q47_16_t e = in->easting;
  drdc_q47_16_t n = in->northing;
  geo_phi_lam_t g;
  drdc_nas_t lon;

  if ((in->zone < DRDC_GEO_ZONE_UPS) || (in->zone > DRDC_GEO_ZONE_MAX)) {
    return DRDC_E_ZONE;
  }
  if (in->zone == DRDC_GEO_ZONE_UPS) {
    if (!geo_ups_in_range(north, e)) {
      return DRDC_E_EASTING;
    }
    if (!geo_ups_in_range(north, n)) {
      return DRDC_E_NORTHING;
    }
    drdc__geo_ups_reverse(north, e - GEO_UPS_FALSE_ORIGIN,
                          n - GEO_UPS_FALSE_ORIGIN, &g);
    lon = drdc__geo_nas_from_rad(g.lam);
    if (with_scale) {
      drdc__geo_ups_conv_scale(north, g.phi, g.lam, &out->cs);
    }
  } else {
    if ((e < GEO_UTM_E_MIN) || (e > GEO_UTM_E_MAX)) {
      return DRDC_E_EASTING;
    }
    if (north ? ((n < GEO_UTM_N_NORTH_MIN) || (n > GEO_UTM_N_NORTH_MAX))
              : ((n < GEO_UTM_N_SOUTH_MIN) || (n > GEO_UTM_N_SOUTH_MAX))) {
      return DRDC_E_NORTHING;
    }
    drdc__geo_tm_reverse(
        angle_from_metres(north ? n : (n - GEO_UTM_FALSE_NORTHING_SOUTH)),
        angle_from_metres(e - GEO_UTM_FALSE_EASTING), &g,
        with_scale ? &out->cs : NULL);
    lon = geo_lon_normalize(geo_central_meridian(in->zone) +
                            drdc__geo_nas_from_rad(g.lam));
  }
  out->lat = drdc__geo_nas_from_rad(g.phi);
  out->lon = lon;
  return DRDC_OK;
}

drdc_status_t drdc_geo_from_utm(const drdc_geo_utm_t *in, drdc_nas_t *lat,
                                drdc_nas_t *lon, drdc_nas_t *convergence,
                                drdc_q5_58_t *scale)
{
  geo_grid_rev_t g;
  drdc_status_t st;

  if ((in == NULL) || (lat == NULL) || (lon == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc__geo_grid_reverse(in, (convergence != NULL) || (scale != NULL), &g);
  if (st != DRDC_OK) {
    return st;
  }
  *lat = g.lat;
  *lon = g.lon;
  if (convergence != NULL) {
    *convergence = drdc__geo_nas_from_rad(g.cs.gamma);
  }
  if (scale != NULL) {
    *scale = g.cs.k;
  }
  return DRDC_OK;
}
