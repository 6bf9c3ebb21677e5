/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Internal interface of the UTM/UPS grid (utm.c) for MGRS (mgrs.c)
 *        and the grid poses (grid_pose.c): the zone rules and limits of
 *        GeographicLib's UTMUPS, and the projection of a geographic
 *        position to the grid and back with the statuses of
 *        drdc_geo_to_utm() and drdc_geo_from_utm().
 */
#ifndef DRDC_GEO_GRID_H
#define DRDC_GEO_GRID_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include <drdc/geo.h>
#include <drdc/types.h>

#include "geo_impl.h"
#include "geo_projection.h"

/** Metres in Q47.16. */
#define GEO_METRES(v) ((int64_t)(v)*INT64_C(65536))

/** GeoConvert's UTM coordinate limits (UTMUPS::CheckCoords, including its
 *  100 km slop), metres; the forward projection checks its result and the
 *  reverse its input against the same ones. */
#define GEO_UTM_E_MIN                GEO_METRES(0)
#define GEO_UTM_E_MAX                GEO_METRES(1000000)
#define GEO_UTM_N_NORTH_MIN          GEO_METRES(-9100000)
#define GEO_UTM_N_NORTH_MAX          GEO_METRES(9600000)
#define GEO_UTM_N_SOUTH_MIN          GEO_METRES(900000)
#define GEO_UTM_N_SOUTH_MAX          GEO_METRES(19600000)
#define GEO_UTM_FALSE_EASTING        GEO_METRES(500000)
#define GEO_UTM_FALSE_NORTHING_SOUTH GEO_METRES(10000000)

/** GeoConvert's UPS limits (100 km slop included), metres; the same for
 *  easting and northing. */
#define GEO_UPS_NORTH_MIN    GEO_METRES(1200000)
#define GEO_UPS_NORTH_MAX    GEO_METRES(2800000)
#define GEO_UPS_SOUTH_MIN    GEO_METRES(700000)
#define GEO_UPS_SOUTH_MAX    GEO_METRES(3300000)
#define GEO_UPS_FALSE_ORIGIN GEO_METRES(2000000)

/** A UPS easting or northing (Q47.16) within the limits of its
 *  hemisphere. */
static inline bool geo_ups_in_range(bool north, drdc_q47_16_t v)
{
  return north ? ((v >= GEO_UPS_NORTH_MIN) && (v <= GEO_UPS_NORTH_MAX))
               : ((v >= GEO_UPS_SOUTH_MIN) && (v <= GEO_UPS_SOUTH_MAX));
}

/** lon (nas) reduced to [-180, 180) degrees. */
static inline drdc_nas_t geo_lon_normalize(drdc_nas_t lon)
{
  drdc_nas_t turn = 360 * GEO_NAS_DEG;
  drdc_nas_t r = (lon + (180 * GEO_NAS_DEG)) % turn;

  if (r < 0) {
    r = r + turn;
  }
  return r - (180 * GEO_NAS_DEG);
}

/** Central meridian of a UTM zone (1..60), nas. */
static inline drdc_nas_t geo_central_meridian(int32_t zone)
{
  return ((6 * (int64_t)zone) - 183) * GEO_NAS_DEG;
}

/** A geographic position on the grid: the checked position of
 *  drdc_geo_to_utm() (metres in Q47.16), the same easting and northing
 *  before their rounding (Q28.36, for MGRS, whose digits truncate them),
 *  and the projection there (its convergence and scale). */
typedef struct geo_grid_fwd {
  drdc_geo_utm_t utm;   /**< zone, hemisphere, metres (Q47.16) */
  int64_t easting_q36;  /**< easting, metres, Q28.36 */
  int64_t northing_q36; /**< northing, metres, Q28.36 */
  geo_projected_t proj; /**< the projection of the point */
} geo_grid_fwd_t;

/**
 * drdc_geo_to_utm() after its NULL checks: the zone rules, the checks and
 * the projection of (lat, lon) in zone (a zone, DRDC_GEO_ZONE_UPS or
 * DRDC_GEO_ZONE_STANDARD) into *out. The same statuses in the same order;
 * *out undefined on error.
 */
drdc_status_t drdc__geo_grid_forward(drdc_nas_t lat, drdc_nas_t lon,
                                     int32_t zone, geo_grid_fwd_t *out);

/** A grid position back on the ellipsoid. */
typedef struct geo_grid_rev {
  drdc_nas_t lat;      /**< latitude, nas */
  drdc_nas_t lon;      /**< longitude, nas, [-180, 180] degrees */
  geo_conv_scale_t cs; /**< convergence and scale at the point */
} geo_grid_rev_t;

/**
 * drdc_geo_from_utm() after its NULL checks: the zone (DRDC_E_ZONE),
 * easting and northing (DRDC_E_EASTING, DRDC_E_NORTHING) of *in checked,
 * then the reverse projection into out->lat and out->lon and, when
 * with_scale, the convergence and scale there into out->cs (UTM: from
 * the reverse series' derivative; UPS: by the forward projection of the
 * point; else undefined). *out undefined on error.
 */
drdc_status_t drdc__geo_grid_reverse(const drdc_geo_utm_t *in, bool with_scale,
                                     geo_grid_rev_t *out);

/**
 * MGRS text of a position on the grid (mgrs.c): the easting and northing
 * carry frac_bits fraction bits (16: Q47.16; 36: the Q28.36 of
 * geo_grid_fwd_t) and the digits truncate that value; lat (nas) picks the
 * UTM latitude band. Returns DRDC_E_RANGE (prec outside -1..11),
 * DRDC_E_EASTING or DRDC_E_NORTHING (outside the MGRS limits),
 * DRDC_E_BUFFER (size too small); the text is written only on DRDC_OK.
 */
drdc_status_t drdc__geo_mgrs_format(const drdc_geo_utm_t *u, unsigned frac_bits,
                                    drdc_nas_t lat, int32_t prec, char *text,
                                    size_t size);

/**
 * The cell of an MGRS text (NUL-terminated within DRDC_GEO_MGRS_SIZE
 * bytes, else DRDC_E_MGRS): drdc_geo_mgrs_decode()'s statuses in its
 * order; on DRDC_OK its centre into *centre.
 */
drdc_status_t drdc__geo_mgrs_centre(const char *text, drdc_geo_utm_t *centre);

#endif /* DRDC_GEO_GRID_H */
