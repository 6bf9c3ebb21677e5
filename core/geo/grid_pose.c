/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Grid poses: the attitude turned between true and grid north by
 *        the meridian convergence, and {W}, {We} <-> {W-UTM}, {We-UTM},
 *        {W-MGRS}, {We-MGRS} on the grid of utm.c and the MGRS of mgrs.c.
 *
 * Grid north lies the convergence gamma east of true north, so a yaw
 * from true north is the yaw from grid north plus gamma: q_true = q_z(gamma)
 * q_grid about the down axis of NED. Every output is written only on
 * DRDC_OK.
 */
#include <drdc/geo_mgrs.h>
#include <drdc/geo_pose.h>

#include <stddef.h>

#include <drdc/fixed_trig.h>

#include "geo_grid.h"

/** Nano-arcseconds in a turn. */
#define NAS_PER_TURN INT64_C(1296000000000000)

drdc_bam32_t drdc_pose_bam_from_convergence(drdc_nas_t convergence)
{
  int64_t b = drdc__geo_muldiv(convergence, INT64_C(4294967296), NAS_PER_TURN);

  /* modulo a turn: the conversion to uint64_t then uint32_t wraps */
  return (drdc_bam32_t)(uint64_t)b;
}

/* q_z(angle) q for an angle in nas, |angle| <= 180 degrees: r q with r =
 * (cos(angle/2), 0, 0, sin(angle/2)), the half angle as a binary angle
 * (|half| <= 90 degrees). drdc_quat_mul()'s DRDC_E_OVERFLOW when a part
 * leaves Q1.30 (only for a q that is far from a unit quaternion). */
static drdc_status_t turn_about_down(const drdc_quat_t *q, drdc_nas_t angle,
                                     drdc_quat_t *out)
{
  int64_t half = drdc__geo_muldiv(angle, INT64_C(2147483648), NAS_PER_TURN);
  drdc_q1_30_t s = 0;
  drdc_q1_30_t c = 0;
  drdc_quat_t r;

  drdc_fx_sincos_bam32((drdc_bam32_t)(uint64_t)half, &s, &c);
  r.s = c;
  r.x = 0;
  r.y = 0;
  r.z = s;
  return drdc_quat_mul(&r, q, out);
}

static bool convergence_ok(drdc_nas_t convergence)
{
  return (convergence <= (180 * GEO_NAS_DEG)) &&
         (convergence >= (-180 * GEO_NAS_DEG));
}

drdc_status_t drdc_pose_grid_from_true(const drdc_quat_t *q_true,
                                       drdc_nas_t convergence,
                                       drdc_quat_t *q_grid)
{
  if ((q_true == NULL) || (q_grid == NULL)) {
    return DRDC_E_NULL;
  }
  if (!convergence_ok(convergence)) {
    return DRDC_E_RANGE;
  }
  return turn_about_down(q_true, -convergence, q_grid);
}

drdc_status_t drdc_pose_true_from_grid(const drdc_quat_t *q_grid,
                                       drdc_nas_t convergence,
                                       drdc_quat_t *q_true)
{
  if ((q_grid == NULL) || (q_true == NULL)) {
    return DRDC_E_NULL;
  }
  if (!convergence_ok(convergence)) {
    return DRDC_E_RANGE;
  }
  return turn_about_down(q_grid, convergence, q_true);
}

/* The projection's convergence is below 180 degrees in magnitude (UPS:
 * the longitude; UTM: under 90), inside turn_about_down()'s domain. */

drdc_status_t drdc_pose_wutm_from_w(const drdc_WPose_t *w, int32_t zone,
                                    drdc_WUTMPose_t *out)
{
  geo_grid_fwd_t g;
  drdc_status_t st;

  if ((w == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc__geo_grid_forward(w->latitude, w->longitude, zone, &g);
  if (st != DRDC_OK) {
    return st;
  }
  st = turn_about_down(&w->q, -drdc__geo_nas_from_rad(g.proj.gamma), &out->q);
  if (st != DRDC_OK) {
    return st;
  }
  out->utm = g.utm;
  out->height = w->height;
  return DRDC_OK;
}

drdc_status_t drdc_pose_weutm_from_we(const drdc_WePose_t *w, int32_t zone,
                                      drdc_WeUTMPose_t *out)
{
  geo_grid_fwd_t g;
  drdc_status_t st;

  if ((w == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc__geo_grid_forward(w->latitude, w->longitude, zone, &g);
  if (st != DRDC_OK) {
    return st;
  }
  out->utm = g.utm;
  out->height = w->height;
  out->e.yaw = w->e.yaw - drdc_pose_bam_from_convergence(
                              drdc__geo_nas_from_rad(g.proj.gamma));
  out->e.pitch = w->e.pitch;
  out->e.roll = w->e.roll;
  return DRDC_OK;
}

/* The grid position utm, or else the centre of the MGRS text's cell
 * (utm NULL), back on the ellipsoid with the convergence there. */
static drdc_status_t grid_reverse(const drdc_geo_utm_t *utm, const char *text,
                                  geo_grid_rev_t *g)
{
  drdc_geo_utm_t centre;
  const drdc_geo_utm_t *pos = utm;
  drdc_status_t st;

  if (pos == NULL) {
    st = drdc__geo_mgrs_centre(text, &centre);
    if (st != DRDC_OK) {
      return st;
    }
    pos = &centre;
  }
  return drdc__geo_grid_reverse(pos, true, g);
}

/* The attitude q_grid turned to true north, then the position and the
 * height: out->q is the last output that can fail. */
static drdc_status_t w_from_grid(const drdc_geo_utm_t *utm, const char *text,
                                 const drdc_quat_t *q_grid,
                                 drdc_q47_16_t height, drdc_WPose_t *out)
{
  geo_grid_rev_t g;
  drdc_status_t st;

  st = grid_reverse(utm, text, &g);
  if (st != DRDC_OK) {
    return st;
  }
  st = turn_about_down(q_grid, drdc__geo_nas_from_rad(g.cs.gamma), &out->q);
  if (st != DRDC_OK) {
    return st;
  }
  out->latitude = g.lat;
  out->longitude = g.lon;
  out->height = height;
  return DRDC_OK;
}

drdc_status_t drdc_pose_w_from_wutm(const drdc_WUTMPose_t *u, drdc_WPose_t *out)
{
  if ((u == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  return w_from_grid(&u->utm, NULL, &u->q, u->height, out);
}

drdc_status_t drdc_pose_w_from_wmgrs(const drdc_WMGRSPose_t *m,
                                     drdc_WPose_t *out)
{
  if ((m == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  return w_from_grid(NULL, m->mgrs, &m->q, m->height, out);
}

/* The yaw from grid north turned to true north (which cannot fail),
 * the position and the height. */
static drdc_status_t we_from_grid(const drdc_geo_utm_t *utm, const char *text,
                                  const drdc_euler_t *e, drdc_q47_16_t height,
                                  drdc_WePose_t *out)
{
  geo_grid_rev_t g;
  drdc_status_t st;

  st = grid_reverse(utm, text, &g);
  if (st != DRDC_OK) {
    return st;
  }
  out->latitude = g.lat;
  out->longitude = g.lon;
  out->e.yaw = e->yaw + drdc_pose_bam_from_convergence(
                            drdc__geo_nas_from_rad(g.cs.gamma));
  out->e.pitch = e->pitch;
  out->e.roll = e->roll;
  out->height = height;
  return DRDC_OK;
}

drdc_status_t drdc_pose_we_from_weutm(const drdc_WeUTMPose_t *u,
                                      drdc_WePose_t *out)
{
  if ((u == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  return we_from_grid(&u->utm, NULL, &u->e, u->height, out);
}

drdc_status_t drdc_pose_we_from_wemgrs(const drdc_WeMGRSPose_t *m,
                                       drdc_WePose_t *out)
{
  if ((m == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  return we_from_grid(NULL, m->mgrs, &m->e, m->height, out);
}

/* The grid position of an MGRS pose: the standard zone after the
 * precision's check (DRDC_E_RANGE must not depend on the position). */
static drdc_status_t mgrs_position(drdc_nas_t lat, drdc_nas_t lon, int32_t prec,
                                   geo_grid_fwd_t *g)
{
  if ((prec < DRDC_GEO_MGRS_PREC_MIN) || (prec > DRDC_GEO_MGRS_PREC_MAX)) {
    return DRDC_E_RANGE;
  }
  return drdc__geo_grid_forward(lat, lon, DRDC_GEO_ZONE_STANDARD, g);
}

/* The MGRS text of a checked position at a checked precision, into a
 * DRDC_GEO_MGRS_SIZE array: it cannot fail (a standard zone's position
 * lies inside the MGRS limits, the array holds the longest text). */
static void mgrs_text(geo_grid_fwd_t *g, drdc_nas_t lat, int32_t prec,
                      char *text)
{
  g->utm.easting = g->easting_q36;
  g->utm.northing = g->northing_q36;
  (void)drdc__geo_mgrs_format(&g->utm, 36u, lat, prec, text,
                              DRDC_GEO_MGRS_SIZE);
}

drdc_status_t drdc_pose_wmgrs_from_w(const drdc_WPose_t *w, int32_t prec,
                                     drdc_WMGRSPose_t *out)
{
  geo_grid_fwd_t g;
  drdc_status_t st;

  if ((w == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = mgrs_position(w->latitude, w->longitude, prec, &g);
  if (st != DRDC_OK) {
    return st;
  }
  st = turn_about_down(&w->q, -drdc__geo_nas_from_rad(g.proj.gamma), &out->q);
  if (st != DRDC_OK) {
    return st;
  }
  out->height = w->height;
  mgrs_text(&g, w->latitude, prec, out->mgrs);
  return DRDC_OK;
}

drdc_status_t drdc_pose_wemgrs_from_we(const drdc_WePose_t *w, int32_t prec,
                                       drdc_WeMGRSPose_t *out)
{
  geo_grid_fwd_t g;
  drdc_status_t st;

  if ((w == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = mgrs_position(w->latitude, w->longitude, prec, &g);
  if (st != DRDC_OK) {
    return st;
  }
  out->e.yaw = w->e.yaw - drdc_pose_bam_from_convergence(
                              drdc__geo_nas_from_rad(g.proj.gamma));
  out->e.pitch = w->e.pitch;
  out->e.roll = w->e.roll;
  out->height = w->height;
  mgrs_text(&g, w->latitude, prec, out->mgrs);
  return DRDC_OK;
}
