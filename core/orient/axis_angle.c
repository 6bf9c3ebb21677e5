/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_orient
 * @brief Axis-angle <-> quaternion.
 */
#include <drdc/orient.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>
#include <drdc/fixed_sqrt.h>
#include <drdc/fixed_trig.h>

#include "orient_impl.h"

drdc_status_t drdc_quat_from_axis_angle(const drdc_vec3_q1_30_t *axis,
                                        drdc_bam32_t angle, drdc_quat_t *out)
{
  drdc_quat_t a;
  drdc_quat_t n;
  int64_t s2;
  int64_t c2;
  drdc_status_t st;

  if ((axis == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  a.s = 0;
  a.x = axis->x;
  a.y = axis->y;
  a.z = axis->z;
  st = drdc_quat_normalize(&a, &n); /* the unit axis, 0.75 LSB per part */
  if (st != DRDC_OK) {
    return st;
  }
  /* Doubled half-angle sine and cosine (Q1.31 scale, |.| <= 2^31): the
   * products with the Q1.30 axis are <= 2^61; one rounding each. */
  drdc_orient_impl_half_sincos(angle, &s2, &c2);
  out->s = (drdc_q1_30_t)drdc_fx_rshift_round_s64(c2, 1u);
  out->x = (drdc_q1_30_t)drdc_fx_rshift_round_s64(s2 * n.x, 31u);
  out->y = (drdc_q1_30_t)drdc_fx_rshift_round_s64(s2 * n.y, 31u);
  out->z = (drdc_q1_30_t)drdc_fx_rshift_round_s64(s2 * n.z, 31u);
  return DRDC_OK;
}

drdc_status_t drdc_axis_angle_from_quat(const drdc_quat_t *q,
                                        drdc_vec3_q1_30_t *axis,
                                        drdc_bam32_t *angle)
{
  drdc_quat_t n;
  drdc_quat_t v;
  uint64_t vn;
  drdc_bam32_t half;
  drdc_status_t st;

  if ((q == NULL) || ((axis == NULL) && (angle == NULL))) {
    return DRDC_E_NULL;
  }
  st = drdc_quat_normalize(q, &n);
  if (st != DRDC_OK) {
    return st;
  }
  if (n.s < 0) { /* unit parts: |part| <= 2^30, negation is safe */
    n.s = -n.s;
    n.x = -n.x;
    n.y = -n.y;
    n.z = -n.z;
  }
  /* exact sum of squares <= 2^60, correctly rounded root <= 2^30 */
  vn = drdc_fx_sqrt_u64(orient_square_u64(n.x) + orient_square_u64(n.y) +
                        orient_square_u64(n.z));
  half = 0u;
  if (vn != 0u) {
    (void)drdc_fx_atan2_bam32((int32_t)vn, n.s, &half); /* [0, 2^30] */
  }
  /* The axis is the input's own vector part made unit, not that of the
   * rounded n: near the identity n's vector part is a few LSB and its
   * rounding would turn the axis by degrees. Its sign follows the
   * input's scalar part, so that the angle is at most 180 degrees. */
  v.s = 0;
  v.x = q->x;
  v.y = q->y;
  v.z = q->z;
  if (drdc_quat_normalize(&v, &v) != DRDC_OK) {
    v.x = ORIENT_Q1_30_ONE; /* identity rotation: any axis; x by convention */
    v.y = 0;
    v.z = 0;
  } else if (q->s < 0) {
    v.x = -v.x; /* unit parts: negation is safe */
    v.y = -v.y;
    v.z = -v.z;
  } else {
    /* axis as it is */
  }
  if (axis != NULL) {
    axis->x = v.x;
    axis->y = v.y;
    axis->z = v.z;
  }
  if (angle != NULL) {
    *angle = half * 2u;
  }
  return DRDC_OK;
}
