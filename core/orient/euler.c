/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_orient
 * @brief Z-Y-X Euler angles <-> quaternions and rotation matrices, with
 *        the gimbal-lock rule (roll 0, all rotation in yaw).
 */
#include <drdc/orient.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>
#include <drdc/fixed_sqrt.h>
#include <drdc/fixed_trig.h>

#include "orient_impl.h"

/* Round a Q62 value to Q1.30. The callers' values are sums of two
 * products of half-angle factors, at most sqrt(2) 2^62 in magnitude (so
 * the result is at most 2^30 sqrt(2) < 2^31: no overflow). */
static drdc_q1_30_t q62_to_q30(int64_t v)
{
  return (drdc_q1_30_t)drdc_fx_rshift_round_s64(v, 32u);
}

drdc_status_t drdc_quat_from_euler(const drdc_euler_t *e, drdc_quat_t *out)
{
  int64_t cy;
  int64_t sy;
  int64_t cp;
  int64_t sp;
  int64_t cr;
  int64_t sr;
  int64_t cc;
  int64_t ss;
  int64_t cs;
  int64_t sc;

  if ((e == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  /* Doubled half-angle sines and cosines: Q1.31 scale, |.| <= 2^31. */
  drdc_orient_impl_half_sincos(e->yaw, &sy, &cy);
  drdc_orient_impl_half_sincos(e->pitch, &sp, &cp);
  drdc_orient_impl_half_sincos(e->roll, &sr, &cr);
  /* Pair products Q62 (<= 2^62), rounded once to Q1.31 (<= 2^31). */
  cc = drdc_fx_rshift_round_s64(cy * cp, 31u);
  ss = drdc_fx_rshift_round_s64(sy * sp, 31u);
  cs = drdc_fx_rshift_round_s64(cy * sp, 31u);
  sc = drdc_fx_rshift_round_s64(sy * cp, 31u);
  /* Each part: a sum of two Q62 products; by Cauchy-Schwarz its
   * magnitude is <= 2^62 (+ rounding slop), far from 2^63. */
  out->s = q62_to_q30((cc * cr) + (ss * sr));
  out->x = q62_to_q30((cc * sr) - (ss * cr));
  out->y = q62_to_q30((cs * cr) + (sc * sr));
  out->z = q62_to_q30((sc * cr) - (cs * sr));
  return DRDC_OK;
}

/** Euler angles from the matrix elements p (any common positive scale
 *  `one`, as exact int64 values |p| <= 2^62). */
static drdc_status_t euler_from_elements(const int64_t p[3][3], int64_t one,
                                         drdc_euler_t *out)
{
  uint64_t h = drdc_orient_impl_hypot62(p[0][0], p[1][0]); /* cos(pitch) */
  drdc_euler_t e;
  drdc_status_t st;

  st = drdc_orient_impl_atan2_s64(-p[2][0], (int64_t)h, &e.pitch);
  if (st != DRDC_OK) {
    return st;
  }
  if (h < ((uint64_t)one >> DRDC_ORIENT_GIMBAL_COS_LOG2)) {
    /* Gimbal lock: with roll = 0, R12 = -sin(yaw) and R22 = cos(yaw)
     * for pitch = +90 and -90 degrees alike. */
    e.roll = 0u;
    st = drdc_orient_impl_atan2_s64(-p[0][1], p[1][1], &e.yaw);
  } else {
    st = drdc_orient_impl_atan2_s64(p[1][0], p[0][0], &e.yaw);
    if (st == DRDC_OK) {
      st = drdc_orient_impl_atan2_s64(p[2][1], p[2][2], &e.roll);
    }
  }
  if (st == DRDC_OK) {
    *out = e;
  }
  return st;
}

drdc_status_t drdc_euler_from_quat(const drdc_quat_t *q, drdc_euler_t *out)
{
  int64_t p[3][3];
  int64_t n2;
  drdc_status_t st;

  if ((q == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc_orient_impl_numerators(q, p, &n2);
  if (st == DRDC_OK) {
    st = euler_from_elements(p, n2, out);
  }
  return st;
}

drdc_status_t drdc_euler_from_dcm(const drdc_dcm_t *r, drdc_euler_t *out)
{
  int64_t p[3][3];
  unsigned i;
  unsigned j;

  if ((r == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  for (i = 0u; i < 3u; i++) {
    for (j = 0u; j < 3u; j++) {
      p[i][j] = r->m[i][j];
    }
  }
  return euler_from_elements(p, orient_pow2_s64(30u), out);
}

/* Q1.30 product of three Q1.30 factors a b c plus or minus d e, rounded
 * once: a b is kept to Q1.31 (one rounding of 0.25 LSB), then the sum of
 * the two Q61 products is rounded to Q1.30. */
static drdc_q1_30_t triple(int32_t a, int32_t b, int32_t c, int32_t d,
                           int32_t e, int sign)
{
  int64_t ab = drdc_fx_rshift_round_s64((int64_t)a * b, 29u); /* Q1.31 */
  int64_t de = (int64_t)d * e * 2;                            /* Q61 */
  int64_t sum = (sign > 0) ? ((ab * c) + de) : ((ab * c) - de);

  return (drdc_q1_30_t)drdc_fx_rshift_round_s64(sum, 31u);
}

drdc_status_t drdc_dcm_from_euler(const drdc_euler_t *e, drdc_dcm_t *out)
{
  drdc_q1_30_t cy;
  drdc_q1_30_t sy;
  drdc_q1_30_t cp;
  drdc_q1_30_t sp;
  drdc_q1_30_t cr;
  drdc_q1_30_t sr;

  if ((e == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  drdc_fx_sincos_bam32(e->yaw, &sy, &cy);
  drdc_fx_sincos_bam32(e->pitch, &sp, &cp);
  drdc_fx_sincos_bam32(e->roll, &sr, &cr);
  out->m[0][0] = (drdc_q1_30_t)drdc_fx_rshift_round_s64((int64_t)cy * cp, 30u);
  out->m[0][1] = triple(cy, sp, sr, sy, cr, -1);
  out->m[0][2] = triple(cy, sp, cr, sy, sr, 1);
  out->m[1][0] = (drdc_q1_30_t)drdc_fx_rshift_round_s64((int64_t)sy * cp, 30u);
  out->m[1][1] = triple(sy, sp, sr, cy, cr, 1);
  out->m[1][2] = triple(sy, sp, cr, cy, sr, -1);
  out->m[2][0] = -sp;
  out->m[2][1] = (drdc_q1_30_t)drdc_fx_rshift_round_s64((int64_t)cp * sr, 30u);
  out->m[2][2] = (drdc_q1_30_t)drdc_fx_rshift_round_s64((int64_t)cp * cr, 30u);
  return DRDC_OK;
}

drdc_status_t drdc_euler_canonical(const drdc_euler_t *e, drdc_euler_t *out)
{
  const drdc_bam32_t quarter = UINT32_C(1) << 30;
  const drdc_bam32_t half = UINT32_C(1) << 31;
  drdc_euler_t r;

  if ((e == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  r = *e;
  /* |pitch| > 90 degrees: Rz(y) Ry(p) Rx(r) = Rz(y + 180) Ry(180 - p)
   * Rx(r + 180). The pitch is outside [-90, 90] exactly when the
   * unsigned value is in (2^30, 3 2^30). */
  if ((r.pitch > quarter) && (r.pitch < (3u * quarter))) {
    r.pitch = half - r.pitch;
    r.yaw += half;
    r.roll += half;
  }
  /* Gimbal lock: only yaw - roll (pitch +90) or yaw + roll (pitch -90)
   * is defined; the rule puts it all in yaw. */
  if (r.pitch == quarter) {
    r.yaw -= r.roll;
    r.roll = 0u;
  } else if (r.pitch == (3u * quarter)) {
    r.yaw += r.roll;
    r.roll = 0u;
  } else {
    /* no gimbal lock: yaw and roll are both defined, kept as they are */
  }
  *out = r;
  return DRDC_OK;
}
