/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Geographic -> grid: the UTM zone rules, geographic -> UTM/UPS on
 *        the transverse Mercator of tm.c (validate in nas, convert in
 *        Q5.58), MGRS from geographic, and the grid poses {W}, {We} ->
 *        {W-UTM}, {We-UTM}, {W-MGRS}, {We-MGRS}, which run the
 *        projection's body in their own frames (issue 8's stack); the
 *        reverse is in utm_reverse.c.
 */
#include <drdc/compiler.h>
#include <drdc/geo.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>

#include "geo_projection.h"

/** Latitude limits of the UTM zones (UPS beyond): [-80, 84) degrees. */
#define UTM_LAT_MIN (INT64_C(-80) * GEO_NAS_DEG)
#define UTM_LAT_MAX (INT64_C(84) * GEO_NAS_DEG)

/* Q47.16 metres -> Q28.36 (exact for the false origins used here). */
#define Q36_FROM_Q16(v) ((v)*INT64_C(1048576))

/* Every zone code from here up asks forward_args() for Q28.36. */
#define ZONE_FINE_MIN (GEO_ZONE_Q36 + DRDC_GEO_ZONE_STANDARD)

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

/* standard zone of a validated point (0: UPS) */
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

/* an angle on the sphere of radius k0 A (Q5.58) -> metres (Q28.36,
 * rounded: 2^-36 m = 15 pm, far below the series' own error); a product
 * and a shift (drdc__geo_mul_shift()), no division */
static int64_t q36_from_angle(int64_t a)
{
  return drdc__geo_mul_shift(a, GEO_K0A_Q40, 62u);
}

/* The checks and the projection's arguments of utm_forward(), out of
 * line (out is only checked for NULL here, the first check): lat and lon
 * (nas) come in tm->xi and tm->eta and leave as phi and lam in radians
 * (UTM: lam from the zone's central meridian; UPS: the longitude in
 * [-180, 180) degrees). Returns the zone (0: UPS) plus GEO_ZONE_Q36 when
 * zone asked for Q28.36 plus GEO_CODE_SOUTH for lat < 0, or minus the
 * status of the first check that fails. The caller's frame then keeps
 * this one code and out across the projection, not lat, lon, zone and
 * the flags (issue 8's stack). */
static DRDC_NOINLINE int32_t forward_args(int32_t zone, const void *out,
                                          geo_tm_t *tm)
{
  drdc_nas_t lat = tm->xi;
  drdc_nas_t lon = tm->eta;
  int32_t fine = (zone >= ZONE_FINE_MIN) ? GEO_ZONE_Q36 : 0;
  int32_t z = zone - fine;
  drdc_status_t st = (out == NULL) ? DRDC_E_NULL : check_lat_lon(lat, lon);

  if (st != DRDC_OK) {
    return -(int32_t)st;
  }
  if (z == DRDC_GEO_ZONE_STANDARD) {
    z = standard_zone(lat, lon);
  }
  if ((z < DRDC_GEO_ZONE_UPS) || (z > DRDC_GEO_ZONE_MAX)) {
    return -(int32_t)DRDC_E_ZONE;
  }
  if (z == DRDC_GEO_ZONE_UPS) {
    lon = geo_lon_normalize(lon);
  } else {
    /* |dlon| <= 180 degrees; the series' domain ends at 90 */
    lon = geo_lon_normalize(lon - geo_central_meridian(z));
    if ((lon > (90 * GEO_NAS_DEG)) || (lon < (-90 * GEO_NAS_DEG))) {
      return -(int32_t)DRDC_E_RANGE;
    }
  }
  tm->xi = drdc__geo_rad_from_nas(lat);
  tm->eta = drdc__geo_rad_from_nas(lon);
  return z + fine + ((lat < 0) ? GEO_CODE_SOUTH : 0);
}

/* UPS forward of phi, lam in tm->xi, tm->eta (forward_args(), whose
 * code tells the hemisphere and the fine request), easting and northing
 * in Q47.16 or (fine) Q28.36; tm is the caller's scratch (x, y, gamma, k
 * in its xi, eta, gamma, k), so the UTM and UPS branches of
 * utm_forward() share one struct on the stack, and the caller writes
 * convergence and scale from it. Out of line with three arguments (no
 * stack argument): its values are not in utm_forward()'s frame. */
static DRDC_NOINLINE drdc_status_t ups_from_tm(int32_t code,
                                               drdc_geo_utm_t *out,
                                               geo_tm_t *tm);

/* After drdc__geo_ups_forward(): x and y in tm's xi and eta slots to easting
 * and northing, checked, into out. Out of line, one copy for
 * grid_to_utm() (a sibling call). */
static DRDC_NOINLINE drdc_status_t ups_from_tm(int32_t code,
                                               drdc_geo_utm_t *out,
                                               geo_tm_t *tm)
{
  bool north = (code < GEO_CODE_SOUTH);
  bool fine = ((code % GEO_CODE_SOUTH) >= GEO_ZONE_Q36);
  drdc_q47_16_t e;
  drdc_q47_16_t n;

  /* Q28.36 offsets in tm's slots; the Q47.16 metres for the checks */
  tm->xi = drdc__geo_ups_q36(tm->xi);
  tm->eta = drdc__geo_ups_q36(tm->eta);
  e = GEO_UPS_FALSE_ORIGIN + drdc_fx_rshift_round_s64(tm->xi, 20u);
  n = GEO_UPS_FALSE_ORIGIN + drdc_fx_rshift_round_s64(tm->eta, 20u);
  if (!geo_ups_in_range(north, e) || !geo_ups_in_range(north, n)) {
    return DRDC_E_RANGE;
  }
  out->zone = DRDC_GEO_ZONE_UPS;
  out->north = north;
  out->easting = fine ? (Q36_FROM_Q16(GEO_UPS_FALSE_ORIGIN) + tm->xi) : e;
  out->northing = fine ? (Q36_FROM_Q16(GEO_UPS_FALSE_ORIGIN) + tm->eta) : n;
  return DRDC_OK;
}

/* UTM easting and northing of the projection's xi, eta in tm (Q28.36
 * offsets left in tm's slots), checked, into out; the zone, the fine
 * request and the hemisphere from forward_args()'s code. Out of line,
 * after drdc__geo_tm_forward() has returned: its values (the offsets, the
 * rounded metres) are not in the frame under the projection. */
static DRDC_NOINLINE drdc_status_t utm_from_tm(int32_t code,
                                               drdc_geo_utm_t *out,
                                               geo_tm_t *tm)
{
  bool north = (code < GEO_CODE_SOUTH);
  bool fine = ((code % GEO_CODE_SOUTH) >= GEO_ZONE_Q36);
  drdc_q47_16_t e;
  drdc_q47_16_t n;

  /* the offsets in Q28.36 (in tm's own slots), each rounded to Q47.16
   * before the false origin is added (a tie of a negative offset rounds
   * away from zero, which the rounding of the sum would not) */
  tm->eta = q36_from_angle(tm->eta);
  tm->xi = q36_from_angle(tm->xi);
  e = GEO_UTM_FALSE_EASTING + drdc_fx_rshift_round_s64(tm->eta, 20u);
  n = drdc_fx_rshift_round_s64(tm->xi, 20u);
  if (!north) {
    n = n + GEO_UTM_FALSE_NORTHING_SOUTH;
    tm->xi = tm->xi + Q36_FROM_Q16(GEO_UTM_FALSE_NORTHING_SOUTH);
  }
  if ((e < GEO_UTM_E_MIN) || (e > GEO_UTM_E_MAX)) {
    return DRDC_E_RANGE;
  }
  if (north ? ((n < GEO_UTM_N_NORTH_MIN) || (n > GEO_UTM_N_NORTH_MAX))
            : ((n < GEO_UTM_N_SOUTH_MIN) || (n > GEO_UTM_N_SOUTH_MAX))) {
    return DRDC_E_RANGE;
  }
  out->zone = code % GEO_ZONE_Q36;
  out->north = north;
  out->easting = fine ? (Q36_FROM_Q16(GEO_UTM_FALSE_EASTING) + tm->eta) : e;
  out->northing = fine ? tm->xi : n;
  return DRDC_OK;
}

/* The forward projection (UPS or transverse Mercator, by the zone of a
 * code of forward_args() or of reverse_args()) of phi and lam in tm's xi
 * and eta slots: 0 beyond its domain, else 1 (never 0 after the reverse,
 * for the convergence and scale: UTM in the range reverse_args() checked
 * has |dlon| < 30 degrees, UPS within its ranges sin chi > 0.5). A
 * sibling call of either projection: no frame of its own on their
 * chains, its callers keep no hemisphere flag across them, and the grid
 * poses and the reverse (utm_reverse.c's grid_reverse(), hence external)
 * share one copy of the dispatch. Out of line (noinline): called, never
 * copied, from this file's entries too. */
DRDC_NOINLINE int drdc__geo_grid_forward_projection(int32_t code, geo_tm_t *tm)
{
  geo_projected_t p;
  int ok;

  if ((code % GEO_ZONE_Q36) == DRDC_GEO_ZONE_UPS) {
    ok = drdc__geo_ups_forward(code < GEO_CODE_SOUTH, tm->xi, tm->eta, &p);
    tm->xi = p.x;
    tm->eta = p.y;
  } else {
    ok = drdc__geo_tm_forward(tm->xi, tm->eta, &p);
    tm->xi = p.y;
    tm->eta = p.x;
  }
  tm->gamma = p.gamma;
  tm->k = p.k;
  return ok;
}

/* The easting and northing of the forward projection in tm, checked, into
 * out: ups_from_tm() or utm_from_tm() by the zone of forward_args()'s
 * code, each a sibling call; one copy of the dispatch for utm_forward()
 * and grid_metres(). */
static DRDC_NOINLINE drdc_status_t grid_to_utm(int32_t code,
                                               drdc_geo_utm_t *out,
                                               geo_tm_t *tm)
{
  if ((code % GEO_ZONE_Q36) == DRDC_GEO_ZONE_UPS) {
    return ups_from_tm(code, out, tm);
  }
  return utm_from_tm(code, out, tm);
}

/* drdc_geo_to_utm() and its Q28.36 form in one: zone is a zone code of
 * drdc_geo_to_utm(), plus GEO_ZONE_Q36 for the Q28.36 result. Inline
 * into its entries (drdc_geo_to_utm(), drdc_pose_weutm_from_we(); a few
 * dozen instructions: the stages are out of line), so that none stacks a
 * frame of its own on top of this one: a wrapper's frame, even a sibling
 * call's, counts on issue 8's chain (16 B on PowerPC). */
static inline DRDC_ALWAYS_INLINE drdc_status_t
utm_forward(drdc_nas_t lat, drdc_nas_t lon, int32_t zone, drdc_geo_utm_t *out,
            drdc_nas_t *convergence, drdc_q5_58_t *scale)
{
  /* forward_args()'s code: the zone, the fine request and the hemisphere
   * in one value, with out the only values of this frame live across the
   * projection; the stages before and after run out of line, each from
   * this frame (issue 8's stack) */
  int32_t code;
  geo_tm_t tm = {lat, lon, 0, 0};

  code = forward_args(zone, out, &tm);
  if (code < 0) {
    return (drdc_status_t)-code;
  }
  if ((drdc__geo_grid_forward_projection(code, &tm) == 0) ||
      (grid_to_utm(code, out, &tm) != DRDC_OK)) {
    return DRDC_E_RANGE;
  }
  if (convergence != NULL) {
    *convergence = drdc__geo_nas_from_rad(tm.gamma);
  }
  if (scale != NULL) {
    *scale = tm.k;
  }
  return DRDC_OK;
}

drdc_status_t drdc_geo_to_utm(drdc_nas_t lat, drdc_nas_t lon, int32_t zone,
                              drdc_geo_utm_t *out, drdc_nas_t *convergence,
                              drdc_q5_58_t *scale)
{
  /* a zone code above the zones is DRDC_E_ZONE, never a request for
   * Q28.36 */
  return utm_forward(
      lat, lon, (zone > DRDC_GEO_ZONE_MAX) ? (DRDC_GEO_ZONE_MAX + 1) : zone,
      out, convergence, scale);
}

/* A pose conversion of pose.c, here because it runs the body of
 * drdc_geo_to_utm() in its own frame: the chain under the projection is
 * that of drdc_geo_to_utm(), with no frame of a pose function on top of
 * it (issue 8's stack; on PowerPC even a frameless tail call counts 16
 * B). */
drdc_status_t drdc_pose_weutm_from_we(const drdc_WePose_t *w, int32_t zone,
                                      drdc_WeUTMPose_t *out)
{
  drdc_status_t st;

  if ((w == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  /* as drdc_geo_to_utm(); no buffer for the convergence in this frame:
   * out->height receives it, as out->utm the position, only on DRDC_OK,
   * and drdc__geo_weutm_attitude() then overwrites it */
  st = utm_forward(w->latitude, w->longitude,
                   (zone > DRDC_GEO_ZONE_MAX) ? (DRDC_GEO_ZONE_MAX + 1) : zone,
                   &out->utm, &out->height, NULL);
  if (st != DRDC_OK) {
    return st;
  }
  drdc__geo_weutm_attitude(w, out);
  return DRDC_OK;
}

/* The easting and northing (Q47.16) of drdc_pose_wutm_from_w()'s
 * projection, checked as utm_from_tm() and ups_from_tm() check them
 * (same statuses), left in tm->eta and tm->xi rather than in out: the
 * attitude, which can still fail, comes first. Out of line, after the
 * projection has returned: its drdc_geo_utm_t is not under it. */
static DRDC_NOINLINE drdc_status_t grid_metres(int32_t code, geo_tm_t *tm)
{
  drdc_geo_utm_t u;
  drdc_status_t st;

  st = grid_to_utm(code, &u, tm);
  if (st == DRDC_OK) {
    tm->eta = u.easting;
    tm->xi = u.northing;
  }
  return st;
}

/* forward_args() of (lat, lon) for zone (its statuses; out only tested
 * for NULL), then the projection of its code (UPS or transverse
 * Mercator) on tm, then its metres checked by grid_metres(): the steps
 * and statuses that drdc_pose_wutm_from_w(), drdc_geo_mgrs_encode() and
 * the MGRS poses share; the code into *code. Inlined (always_inline) so
 * the projection stays called from their own frames (by
 * drdc__geo_grid_forward_projection(), a sibling call). */
static inline DRDC_ALWAYS_INLINE drdc_status_t
project_to_grid(drdc_nas_t lat, drdc_nas_t lon, int32_t zone, const void *out,
                geo_tm_t *tm, int32_t *code)
{
  tm->xi = lat;
  tm->eta = lon;
  tm->gamma = 0;
  tm->k = 0;
  *code = forward_args(zone, out, tm);
  if (*code < 0) {
    return (drdc_status_t) - *code;
  }
  if (drdc__geo_grid_forward_projection(*code, tm) == 0) {
    return DRDC_E_RANGE;
  }
  /* xi, eta (and gamma) in tm */
  return grid_metres(*code, tm);
}

/* A pose conversion of pose.c, here for the reason of
 * drdc_pose_weutm_from_we(): the body of drdc_geo_to_utm() in its own
 * frame. The position cannot wait in out (the attitude after it may
 * fail, and out stays unchanged on error): it waits in tm, with the
 * convergence, and out is written only once the attitude is in. */
drdc_status_t drdc_pose_wutm_from_w(const drdc_WPose_t *w, int32_t zone,
                                    drdc_WUTMPose_t *out)
{
  int32_t code;
  geo_tm_t tm;
  drdc_status_t st;

  if ((w == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  /* utm_forward()'s steps and statuses, as drdc_geo_to_utm() (a zone
   * code above the zones is DRDC_E_ZONE) */
  st = project_to_grid(w->latitude, w->longitude,
                       (zone > DRDC_GEO_ZONE_MAX) ? (DRDC_GEO_ZONE_MAX + 1)
                                                  : zone,
                       &out->utm, &tm, &code);
  if (st != DRDC_OK) {
    return st;
  }
  /* q_grid = q_z(-gamma) q_true, the last step that can fail, straight
   * into out->q (written only on DRDC_OK); |gamma| < 180 degrees */
  st = drdc_pose_grid_from_true(&w->q, drdc__geo_nas_from_rad(tm.gamma),
                                &out->q);
  if (st != DRDC_OK) {
    return st;
  }
  out->utm.zone = code % GEO_ZONE_Q36;
  out->utm.north = (code < GEO_CODE_SOUTH);
  out->utm.easting = tm.eta;
  out->utm.northing = tm.xi;
  out->height = w->height;
  return DRDC_OK;
}

/* The text of drdc_geo_mgrs_encode() after its projection, out of line:
 * its drdc_geo_utm_t is not under the projection. tm holds
 * grid_metres()'s easting and northing (Q28.36) in its eta and xi slots,
 * and in its gamma and k slots the latitude (nas) and the precision. */
static DRDC_NOINLINE drdc_status_t mgrs_from_tm(int32_t code, geo_tm_t *tm,
                                                char *text, size_t size)
{
  drdc_geo_utm_t u;
  drdc_nas_t lat = tm->gamma;
  int32_t prec = (int32_t)tm->k;

  u.zone = code % GEO_ZONE_Q36;
  u.north = (code < GEO_CODE_SOUTH);
  u.easting = tm->eta;
  u.northing = tm->xi;
  /* the standard zone is always inside the MGRS limits */
  return drdc__geo_mgrs_format_bits(&u, 36u, lat, prec, text, size);
}

/* MGRS text of a geographic position (mgrs.c's encoder), here for the
 * reason of drdc_pose_weutm_from_we(): the body of utm_forward(), in
 * the standard zone, with the easting and northing before their rounding
 * to Q47.16 (2^-36 m), so the truncation falls on the side of a digit
 * boundary that GeographicLib's value falls on, but within nanometres of
 * it. */
drdc_status_t drdc_geo_mgrs_encode(drdc_nas_t lat, drdc_nas_t lon, int32_t prec,
                                   char *text, size_t size)
{
  int32_t code;
  geo_tm_t tm;
  drdc_status_t st;

  if (text == NULL) {
    return DRDC_E_NULL;
  }
  /* forward_args() only tests its out for NULL (text is not) */
  st = project_to_grid(lat, lon, DRDC_GEO_ZONE_STANDARD + GEO_ZONE_Q36, text,
                       &tm, &code);
  if (st != DRDC_OK) {
    return st;
  }
  /* the slots the encoder does not read carry the latitude and the
   * precision on: four arguments in registers, no outgoing stack
   * arguments in this frame (Cortex-M3) */
  tm.gamma = lat;
  tm.k = prec;
  return mgrs_from_tm(code, &tm, text, size);
}

/* The MGRS text of drdc_geo_mgrs_encode()'s projection in tm (its
 * code), at prec (checked) and for the latitude lat (nas), into text
 * (DRDC_GEO_MGRS_SIZE bytes): mgrs_from_tm(), which never fails here (a
 * standard zone's position is always inside the MGRS limits, the size
 * holds the longest text), so the MGRS poses write it last, after the
 * attitude and height; tm is left holding lat and prec. */
static inline DRDC_ALWAYS_INLINE void
mgrs_text(int32_t code, drdc_nas_t lat, int32_t prec, geo_tm_t *tm, char *text)
{
  tm->gamma = lat;
  tm->k = prec;
  (void)mgrs_from_tm(code, tm, text, DRDC_GEO_MGRS_SIZE);
}

/* The steps and statuses the MGRS poses share before their attitude:
 * prec checked first (DRDC_E_RANGE must not depend on the position),
 * then project_to_grid() of (lat, lon) in its standard zone, in Q28.36
 * for the text (out only tested for NULL). Inlined, as
 * project_to_grid(). */
static inline DRDC_ALWAYS_INLINE drdc_status_t
project_to_mgrs(drdc_nas_t lat, drdc_nas_t lon, int32_t prec, const void *out,
                geo_tm_t *tm, int32_t *code)
{
  if ((prec < DRDC_GEO_MGRS_PREC_MIN) || (prec > DRDC_GEO_MGRS_PREC_MAX)) {
    return DRDC_E_RANGE;
  }
  return project_to_grid(lat, lon, DRDC_GEO_ZONE_STANDARD + GEO_ZONE_Q36, out,
                         tm, code);
}

/* A pose conversion of pose.c, here for the reason of
 * drdc_pose_weutm_from_we(): the body of drdc_geo_mgrs_encode() in its
 * own frame, the position and the convergence waiting in its geo_tm_t
 * (as drdc_pose_wutm_from_w()) while pose.c's drdc__geo_wmgrs_attitude() turns
 * the attitude, the last step that can fail, straight into out->q and
 * writes the height (only on DRDC_OK); then the text. Statuses and their
 * order as before. */
drdc_status_t drdc_pose_wmgrs_from_w(const drdc_WPose_t *w, int32_t prec,
                                     drdc_WMGRSPose_t *out)
{
  int32_t code;
  geo_tm_t tm;
  drdc_status_t st;

  if ((w == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = project_to_mgrs(w->latitude, w->longitude, prec, out, &tm, &code);
  if (st != DRDC_OK) {
    return st;
  }
  st = drdc__geo_wmgrs_attitude(w, &tm, out);
  if (st != DRDC_OK) {
    return st;
  }
  mgrs_text(code, w->latitude, prec, &tm, out->mgrs);
  return DRDC_OK;
}

/* As drdc_pose_wmgrs_from_w(), the yaw turned instead (which cannot
 * fail) */
drdc_status_t drdc_pose_wemgrs_from_we(const drdc_WePose_t *w, int32_t prec,
                                       drdc_WeMGRSPose_t *out)
{
  int32_t code;
  geo_tm_t tm;
  drdc_status_t st;

  if ((w == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = project_to_mgrs(w->latitude, w->longitude, prec, out, &tm, &code);
  if (st != DRDC_OK) {
    return st;
  }
  out->e.yaw = w->e.yaw -
               drdc_pose_bam_from_convergence(drdc__geo_nas_from_rad(tm.gamma));
  out->e.pitch = w->e.pitch;
  out->e.roll = w->e.roll;
  out->height = w->height;
  mgrs_text(code, w->latitude, prec, &tm, out->mgrs);
  return DRDC_OK;
}
