/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Pose conversions: true <-> grid north through the meridian
 *        convergence, {W} <-> {W-UTM}, {W-MGRS}, {l} <-> {W} through
 *        NED, and their Euler forms {We}, {We-UTM}, {We-MGRS}, {le}.
 */
#include <drdc/compiler.h>
#include <drdc/geo_pose.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>
#include <drdc/fixed_trig.h>

#include "geo_impl.h"

/** Nano-arcseconds in a turn. */
#define NAS_PER_TURN INT64_C(1296000000000000)

drdc_bam32_t drdc_pose_bam_from_convergence(drdc_nas_t convergence)
{
  int64_t b = drdc__geo_muldiv(convergence, INT64_C(4294967296), NAS_PER_TURN);

  /* modulo a turn: the conversion to uint64_t then uint32_t wraps */
  return (drdc_bam32_t)(uint64_t)b;
}

/* q_z(2 half) * q for half a turn's angle as a binary angle: r q with r
 * = (cos half, 0, 0, sin half). Out of line, sibling-called by
 * turn_about_down() once the half angle is known: r and the sine and
 * cosine are not in a frame under the division that finds it (issue 8's
 * stack). */
static DRDC_NOINLINE drdc_status_t turn_by_half(const drdc_quat_t *q,
                                                drdc_bam32_t half,
                                                drdc_quat_t *out)
{
  drdc_q1_30_t s = 0;
  drdc_q1_30_t c = 0;
  drdc_quat_t r;

  drdc_fx_sincos_bam32(half, &s, &c);
  r.s = c;
  r.x = 0;
  r.y = 0;
  r.z = s;
  return drdc_quat_mul(&r, q, out);
}

/* q_z(angle) * q for an angle in nas, |angle| <= 180 degrees */
static drdc_status_t turn_about_down(const drdc_quat_t *q, drdc_nas_t angle,
                                     drdc_quat_t *out)
{
  /* half the angle as a binary angle (|half| <= 90 degrees) */
  int64_t half = drdc__geo_muldiv(angle, INT64_C(2147483648), NAS_PER_TURN);

  return turn_by_half(q, (drdc_bam32_t)(uint64_t)half, out);
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

/* drdc_pose_wutm_from_w(), drdc_pose_w_from_wutm() and their Euler forms
 * are in utm_forward.c and utm_reverse.c, in the frame of the
 * projection's body (issue 8's stack) */

/* The last step of utm_reverse.c's w_from_grid(), after the projection:
 * q_true = q_z(gamma) q_grid straight into out->q, gamma (nas, |gamma| <
 * 180 degrees) in tm->gamma, then the height; written only on DRDC_OK. */
drdc_status_t drdc__geo_w_attitude(const drdc_WUTMPose_t *u,
                                   const drdc_WMGRSPose_t *m,
                                   const geo_tm_t *tm, drdc_WPose_t *out)
{
  drdc_status_t st;

  st = turn_about_down((u != NULL) ? &u->q : &m->q, tm->gamma, &out->q);
  if (st == DRDC_OK) {
    out->height = (u != NULL) ? u->height : m->height;
  }
  return st;
}

/* The attitude and height of utm_forward.c's drdc_pose_wmgrs_from_w(),
 * after the projection: q_grid = q_z(-gamma) q_true straight into
 * out->q, gamma (radians, |gamma| < 180 degrees) in tm->gamma; written
 * only on DRDC_OK. */
drdc_status_t drdc__geo_wmgrs_attitude(const drdc_WPose_t *w,
                                       const geo_tm_t *tm,
                                       drdc_WMGRSPose_t *out)
{
  drdc_status_t st;

  st = turn_about_down(&w->q, -drdc__geo_nas_from_rad(tm->gamma), &out->q);
  if (st == DRDC_OK) {
    out->height = w->height;
  }
  return st;
}

/* drdc_pose_weutm_from_we() is in utm_forward.c, in the frame of the
 * projection's body; it ends here */
void drdc__geo_weutm_attitude(const drdc_WePose_t *w, drdc_WeUTMPose_t *out)
{
  /* out->height holds the convergence until here */
  out->e.yaw = w->e.yaw - drdc_pose_bam_from_convergence(out->height);
  out->height = w->height;
  out->e.pitch = w->e.pitch;
  out->e.roll = w->e.roll;
}
