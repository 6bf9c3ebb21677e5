/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Grid -> geographic: UTM/UPS -> geographic on the transverse
 *        Mercator of tm.c (validate in nas, convert in Q5.58), the grid
 *        poses {W-UTM}, {We-UTM}, {W-MGRS}, {We-MGRS} -> {W}, {We}, and
 *        MGRS from UTM, which run the reverse projection's body in their
 *        own frames (issue 8's stack); the forward is in utm_forward.c.
 */
#include <drdc/compiler.h>
#include <drdc/geo.h>

#include <stddef.h>

#include "geo_projection.h"

/* metres (Q47.16, |v| < 2^43) -> angle on the sphere of radius k0 A */
static DRDC_NOINLINE int64_t angle_from_metres(drdc_q47_16_t v)
{
  return drdc__geo_muldiv(v * INT64_C(1048576), GEO_TWO_POW_62, GEO_K0A_Q40);
}

/* The checks of drdc_geo_from_utm() after the zone's, and the reverse
 * projection's arguments: the metres (Q47.16) of a zone with its
 * hemisphere (code: the zone, 0..60, plus GEO_CODE_SOUTH south), northing in
 * tm->xi and easting in tm->eta, to the angles that drdc__geo_tm_reverse()
 * (xi, eta on the sphere of radius k0 A) or drdc__geo_ups_reverse() (x, y from
 * the pole) takes in the same slots. Out of line, before the projection:
 * its constants and values are not in the frame under it. */
static DRDC_NOINLINE drdc_status_t reverse_args(int32_t code, geo_tm_t *tm)
{
  bool north = (code < GEO_CODE_SOUTH);
  drdc_q47_16_t n = tm->xi;

  if ((code % GEO_CODE_SOUTH) == DRDC_GEO_ZONE_UPS) {
    if (!geo_ups_in_range(north, tm->eta)) {
      return DRDC_E_EASTING;
    }
    if (!geo_ups_in_range(north, n)) {
      return DRDC_E_NORTHING;
    }
    tm->xi = tm->eta - GEO_UPS_FALSE_ORIGIN;
    tm->eta = n - GEO_UPS_FALSE_ORIGIN;
    return DRDC_OK;
  }
  if ((tm->eta < GEO_UTM_E_MIN) || (tm->eta > GEO_UTM_E_MAX)) {
    return DRDC_E_EASTING;
  }
  if (north ? ((n < GEO_UTM_N_NORTH_MIN) || (n > GEO_UTM_N_NORTH_MAX))
            : ((n < GEO_UTM_N_SOUTH_MIN) || (n > GEO_UTM_N_SOUTH_MAX))) {
    return DRDC_E_NORTHING;
  }
  tm->xi = angle_from_metres(north ? n : (n - GEO_UTM_FALSE_NORTHING_SOUTH));
  tm->eta = angle_from_metres(tm->eta - GEO_UTM_FALSE_EASTING);
  return DRDC_OK;
}

/* The reverse projection (UPS or transverse Mercator, by the code of
 * reverse_args()) on tm's slots. A sibling call of either: no frame of
 * its own on their chains, and its callers keep no hemisphere flag
 * across them. */
static DRDC_NOINLINE void grid_reverse_projection(int32_t code, geo_tm_t *tm)
{
  geo_phi_lam_t g;

  if ((code % GEO_CODE_SOUTH) == DRDC_GEO_ZONE_UPS) {
    drdc__geo_ups_reverse(code < GEO_CODE_SOUTH, tm->xi, tm->eta, &g);
  } else {
    drdc__geo_tm_reverse(tm->xi, tm->eta, &g);
  }
  tm->xi = g.phi;
  tm->eta = g.lam;
}

/* The latitude and longitude (nas) of the reverse projection's phi and
 * lam in tm->xi and tm->eta (UTM: lam from the zone's central meridian),
 * into *lat and *lon, either NULL when not wanted, each written after its
 * slot is last read (they may point into tm's xi and eta). Out of line,
 * after the projection; DRDC_OK, for its callers' sibling call. */
static DRDC_NOINLINE drdc_status_t reverse_angles(int32_t code, geo_tm_t *tm,
                                                  drdc_nas_t *lat,
                                                  drdc_nas_t *lon)
{
  int32_t zone = code % GEO_CODE_SOUTH;
  drdc_nas_t a;

  if (lat != NULL) {
    *lat = drdc__geo_nas_from_rad(tm->xi);
  }
  if (lon != NULL) {
    a = drdc__geo_nas_from_rad(tm->eta);
    *lon = (zone == DRDC_GEO_ZONE_UPS)
               ? a
               : geo_lon_normalize(geo_central_meridian(zone) + a);
  }
  return DRDC_OK;
}

/* The convergence (nas) and scale of the forward projection in tm into
 * *convergence and *scale, either NULL; DRDC_OK, as reverse_angles(). */
static DRDC_NOINLINE drdc_status_t forward_outputs(const geo_tm_t *tm,
                                                   drdc_nas_t *convergence,
                                                   drdc_q5_58_t *scale)
{
  if (convergence != NULL) {
    *convergence = drdc__geo_nas_from_rad(tm->gamma);
  }
  if (scale != NULL) {
    *scale = tm->k;
  }
  return DRDC_OK;
}

/* The reverse projection of a zone (0..60) with its hemisphere (code: the
 * zone, plus GEO_CODE_SOUTH south) and the metres (Q47.16) in tm,
 * northing in tm->xi and easting in tm->eta: drdc_geo_from_utm() after
 * its NULL and zone checks, inline into each entry that runs it in its
 * own frame (as utm_forward.c's utm_forward() into its entries): no
 * wrapper frame on the projection's chain. Only the calls are inline (the
 * checks and conversions are stages, out of line, before and after the
 * projections, the last one a sibling call), so each copy is small and
 * the frame keeps only code and the outputs' pointers across the
 * projections. Writes only on DRDC_OK; lat and lon may be NULL (not
 * wanted). tm is the entry's scratch; with convergence and scale NULL (no
 * forward after the reverse), lat and lon may point into its xi and eta,
 * so an entry that needs only the angles keeps no buffer for them. */
static inline DRDC_ALWAYS_INLINE drdc_status_t
grid_reverse(int32_t code, drdc_nas_t *lat, drdc_nas_t *lon,
             drdc_nas_t *convergence, drdc_q5_58_t *scale, geo_tm_t *tm)
{
  drdc_status_t st = reverse_args(code, tm);

  if (st != DRDC_OK) {
    return st;
  }
  /* phi and lam of the reverse wait in tm's own slots (xi, eta) until
   * the forward overwrites them: one struct is the whole frame's data
   * on the deepest path */
  grid_reverse_projection(code, tm);
  if ((convergence == NULL) && (scale == NULL)) {
    return reverse_angles(code, tm, lat, lon);
  }
  (void)reverse_angles(code, tm, lat, lon);
  (void)drdc__geo_grid_forward_projection(code, tm);
  return forward_outputs(tm, convergence, scale);
}

/* grid_reverse() of a drdc_geo_utm_t, its zone checked first */
static inline DRDC_ALWAYS_INLINE drdc_status_t
utm_reverse(const drdc_geo_utm_t *in, drdc_nas_t *lat, drdc_nas_t *lon,
            drdc_nas_t *convergence, drdc_q5_58_t *scale, geo_tm_t *tm)
{
  if ((in->zone < DRDC_GEO_ZONE_UPS) || (in->zone > DRDC_GEO_ZONE_MAX)) {
    return DRDC_E_ZONE;
  }
  tm->xi = in->northing;
  tm->eta = in->easting;
  return grid_reverse(in->zone + (in->north ? 0 : GEO_CODE_SOUTH), lat, lon,
                      convergence, scale, tm);
}

drdc_status_t drdc_geo_from_utm(const drdc_geo_utm_t *in, drdc_nas_t *lat,
                                drdc_nas_t *lon, drdc_nas_t *convergence,
                                drdc_q5_58_t *scale)
{
  geo_tm_t tm;

  if ((in == NULL) || (lat == NULL) || (lon == NULL)) {
    return DRDC_E_NULL;
  }
  return utm_reverse(in, lat, lon, convergence, scale, &tm);
}

/* The position of a grid pose in tm, as grid_reverse() takes it: from
 * in's zone, hemisphere and metres (DRDC_E_ZONE for a zone outside
 * 0..60), or else the centre of the cell of the MGRS text (DRDC_E_MGRS
 * when no NUL is within DRDC_GEO_MGRS_SIZE bytes, then the decoder's
 * statuses). Returns grid_reverse()'s code or minus the status. Out of
 * line, one copy for the four reverse poses, called before their
 * projection; the decoder a sibling call, its drdc_geo_utm_t nowhere. */
static DRDC_NOINLINE int32_t grid_of(const drdc_geo_utm_t *in, const char *text,
                                     geo_tm_t *tm)
{
  size_t n = 0u;

  if (in != NULL) {
    if ((in->zone < DRDC_GEO_ZONE_UPS) || (in->zone > DRDC_GEO_ZONE_MAX)) {
      return -(int32_t)DRDC_E_ZONE;
    }
    tm->xi = in->northing;
    tm->eta = in->easting;
    return in->zone + (in->north ? 0 : GEO_CODE_SOUTH);
  }
  /* the decoder must not read beyond the array */
  while ((n < DRDC_GEO_MGRS_SIZE) && (text[n] != '\0')) {
    n++;
  }
  if (n == DRDC_GEO_MGRS_SIZE) {
    return -(int32_t)DRDC_E_MGRS;
  }
  return drdc__geo_mgrs_decode_tm(text, tm, NULL);
}

/* The position of utm (or of the MGRS text mgrs, utm NULL) reversed:
 * grid_of() then grid_reverse(), their statuses; the latitude and
 * longitude into lat and lon (neither written when NULL) and the
 * convergence (nas) into tm->gamma, where the forward leaves it.
 * Inlined: each pass of the grid poses is its own copy, a few calls
 * (see w_from_grid()). */
static inline DRDC_ALWAYS_INLINE drdc_status_t
grid_position(const drdc_geo_utm_t *utm, const char *mgrs, drdc_nas_t *lat,
              drdc_nas_t *lon, geo_tm_t *tm)
{
  int32_t code = grid_of(utm, mgrs, tm);

  if (code < 0) {
    return (drdc_status_t)-code;
  }
  return grid_reverse(code, lat, lon, &tm->gamma, NULL, tm);
}

/* Every part of q within [-1, 1] (|raw| <= 2^30): then a turn about the
 * down axis, r q with r = (c, 0, 0, s) from drdc_fx_sincos_bam32(),
 * cannot fail. Each part of the product is c a -/+ s b for two parts a,
 * b of q, at most sqrt(c^2 + s^2) sqrt(a^2 + b^2) in size; with c and s
 * within 1 LSB of the cosine and sine, sqrt(c^2 + s^2) < 1 + 2^-29, so
 * the part stays below 1.415, inside Q1.30's [-2, 2), and
 * drdc_quat_mul()'s only error (DRDC_E_OVERFLOW) cannot occur. */
static bool turn_cannot_fail(const drdc_quat_t *q)
{
  const int32_t one = INT32_C(1073741824); /* 1.0 in Q1.30 */

  return (q->s >= -one) && (q->s <= one) && (q->x >= -one) && (q->x <= one) &&
         (q->y >= -one) && (q->y <= one) && (q->z >= -one) && (q->z <= one);
}

/* drdc_pose_w_from_wutm() (u) and drdc_pose_w_from_wmgrs() (m; u NULL),
 * with the body of drdc_geo_from_utm() in this frame, the sibling call of
 * both (so no frame of theirs on the projection's chain: issue 8's
 * stack). The attitude's turn, after the projection, is the last step
 * that can fail, and out stays unchanged on error; the position cannot
 * wait in this frame (a buffer of it on top of the projection's chain
 * would pass 256 B), so it goes straight into out when the turn cannot
 * fail (turn_cannot_fail(), the common case: one pass). Otherwise a
 * first pass keeps nothing but the convergence (the angles are not
 * written) and turns the attitude into out->q and writes the height,
 * only on DRDC_OK; then the second pass writes the position, the same
 * projection of the same input (which cannot fail now), and the same
 * turn (twice the cycles for such an attitude). Statuses and their order
 * as before: the position's, then the turn's. Each pass a copy of
 * grid_reverse(), a few calls: no loop whose state would stay in this
 * frame across the projections. */
static DRDC_NOINLINE drdc_status_t w_from_grid(const drdc_WUTMPose_t *u,
                                               const drdc_WMGRSPose_t *m,
                                               drdc_WPose_t *out)
{
  geo_tm_t tm;
  drdc_status_t st;

  if (!turn_cannot_fail((u != NULL) ? &u->q : &m->q)) {
    /* the convergence alone, in tm.gamma */
    st = grid_position((u != NULL) ? &u->utm : NULL,
                       (m != NULL) ? m->mgrs : NULL, NULL, NULL, &tm);
    if (st == DRDC_OK) {
      st = drdc__geo_w_attitude(u, m, &tm, out);
    }
    if (st != DRDC_OK) {
      return st;
    }
  }
  /* the position straight into out: nothing after it can fail now (the
   * same turn returns DRDC_OK) */
  st = grid_position((u != NULL) ? &u->utm : NULL, (m != NULL) ? m->mgrs : NULL,
                     &out->latitude, &out->longitude, &tm);
  if (st != DRDC_OK) {
    return st;
  }
  return drdc__geo_w_attitude(u, m, &tm, out);
}

/* A pose conversion of pose.c, here for the reason of
 * drdc_pose_weutm_from_we() (utm_forward.c): w_from_grid() runs the body of
 * drdc_geo_from_utm() in its own frame, in place of this one (a sibling
 * call). */
drdc_status_t drdc_pose_w_from_wutm(const drdc_WUTMPose_t *u, drdc_WPose_t *out)
{
  if ((u == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  return w_from_grid(u, NULL, out);
}

/* As drdc_pose_w_from_wutm(), from the centre of the MGRS cell */
drdc_status_t drdc_pose_w_from_wmgrs(const drdc_WMGRSPose_t *m,
                                     drdc_WPose_t *out)
{
  if ((m == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  return w_from_grid(NULL, m, out);
}

/* drdc_pose_we_from_weutm() (u) and drdc_pose_we_from_wemgrs() (m; u
 * NULL), as w_from_grid(); nothing can fail after the projection, so the
 * position goes straight into out, the convergence waits in tm, and then
 * the yaw is turned. */
static DRDC_NOINLINE drdc_status_t we_from_grid(const drdc_WeUTMPose_t *u,
                                                const drdc_WeMGRSPose_t *m,
                                                drdc_WePose_t *out)
{
  const drdc_euler_t *e;
  geo_tm_t tm;
  drdc_status_t st;

  st = grid_position((u != NULL) ? &u->utm : NULL, (m != NULL) ? m->mgrs : NULL,
                     &out->latitude, &out->longitude, &tm);
  if (st != DRDC_OK) {
    return st;
  }
  e = (u != NULL) ? &u->e : &m->e;
  out->e.yaw = e->yaw + drdc_pose_bam_from_convergence(tm.gamma);
  out->e.pitch = e->pitch;
  out->e.roll = e->roll;
  out->height = (u != NULL) ? u->height : m->height;
  return DRDC_OK;
}

/* A pose conversion of pose.c, here for the reason of
 * drdc_pose_w_from_wutm() */
drdc_status_t drdc_pose_we_from_weutm(const drdc_WeUTMPose_t *u,
                                      drdc_WePose_t *out)
{
  if ((u == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  return we_from_grid(u, NULL, out);
}

/* As drdc_pose_we_from_weutm(), from the centre of the MGRS cell */
drdc_status_t drdc_pose_we_from_wemgrs(const drdc_WeMGRSPose_t *m,
                                       drdc_WePose_t *out)
{
  if ((m == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  return we_from_grid(NULL, m, out);
}

/* MGRS text of a UTM/UPS position (mgrs.c's encoder), here for the
 * reason of drdc_pose_weutm_from_we() (utm_forward.c): the body of
 * drdc_geo_from_utm(), which validates the position and gives the
 * latitude of the band letter, in this frame, the angles in its
 * scratch. */
drdc_status_t drdc_geo_mgrs_from_utm(const drdc_geo_utm_t *u, int32_t prec,
                                     char *text, size_t size)
{
  geo_tm_t tm;
  drdc_status_t st;

  if ((u == NULL) || (text == NULL)) {
    return DRDC_E_NULL;
  }
  st = utm_reverse(u, &tm.xi, &tm.eta, NULL, NULL, &tm);
  if (st != DRDC_OK) {
    return st;
  }
  return drdc__geo_mgrs_format(u, tm.xi, prec, text, size);
}
