/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_orient
 * @brief Z-Y-X Euler angles <-> quaternions, and from rotation matrices
 *        (to them in euler_dcm.c), with the gimbal-lock rule (roll 0,
 *        all rotation in yaw).
 */
#include <drdc/orient.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>
#include <drdc/fixed_sqrt.h>
#include <drdc/fixed_trig.h>

#include "orient_impl.h"

/* Every product below is of two uint32 magnitudes (<= 2^31) with the
 * signs carried beside them: one 32x32->64 multiply each (UMULL,
 * mullw/mulhwu) instead of a 64x64 product. */

/* round(a b / 2^31) of two magnitudes <= 2^31 (ties up, which is ties
 * away from zero once the sign is put back): <= 2^31. */
static inline uint32_t mul_round_q31(uint32_t a, uint32_t b)
{
  uint64_t p = ((uint64_t)a * b) + (UINT64_C(1) << 30u);

  return (uint32_t)(p >> 31u);
}

/* (-1)^na (a b + (-1)^nc c d) for magnitudes <= 2^31 (each product
 * <= 2^62), rounded from Q62 to Q1.30 to nearest, ties away from zero.
 * The sum is formed modulo 2^64; by Cauchy-Schwarz its magnitude is at
 * most 2^62 (+ the slop of the Q1.31 roundings), so the modular value is
 * the exact one. Rounding without a branch, as orient_q60_round_bits():
 * floor((v + 2^31 - [v < 0]) / 2^32) is the high word of the biased
 * value, |result| <= 2^30 sqrt(2) < 2^31; the rounding is symmetric, so
 * the common sign (-1)^na is applied to the rounded word. */
static inline drdc_q1_30_t part_q30(uint32_t a, uint32_t b, uint32_t na,
                                    uint32_t c, uint32_t d, uint32_t nc)
{
  uint64_t ab = (uint64_t)a * b;
  uint64_t cd = (uint64_t)c * d;
  uint64_t v = (nc != 0u) ? (ab - cd) : (ab + cd);
  uint32_t hi;

  v += (UINT64_C(1) << 31u) - (v >> 63u);
  hi = (uint32_t)(v >> 32u);
  if (na != 0u) {
    hi = 0u - hi;
  }
  return (drdc_q1_30_t)hi;
}

drdc_status_t drdc_quat_from_euler(const drdc_euler_t *e, drdc_quat_t *out)
{
  orient_half_t y;
  orient_half_t p;
  orient_half_t r;
  uint32_t cc;
  uint32_t ss;
  uint32_t cs;
  uint32_t sc;
  uint32_t nss;

  if ((e == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  /* Doubled half-angle sines and cosines: Q1.31 scale, |.| <= 2^31;
   * the half angle is in [-pi/2, pi/2], so every cosine is >= 0. */
  orient_half_sincos_mag(e->yaw, &y);
  orient_half_sincos_mag(e->pitch, &p);
  orient_half_sincos_mag(e->roll, &r);
  /* Pair products Q62 (<= 2^62), rounded once to Q1.31 (<= 2^31):
   * magnitudes here, the signs carried beside them (cc >= 0, ss has
   * y.neg ^ p.neg, cs has p.neg, sc has y.neg). */
  cc = mul_round_q31(y.c, p.c);
  ss = mul_round_q31(y.s, p.s);
  cs = mul_round_q31(y.c, p.s);
  sc = mul_round_q31(y.s, p.c);
  nss = y.neg ^ p.neg;
  /* Each part: a sum of two Q62 products, rounded once. */
  out->s = part_q30(cc, r.c, 0u, ss, r.s, nss ^ r.neg);
  out->x = part_q30(cc, r.s, r.neg, ss, r.c, nss ^ r.neg ^ 1u);
  out->y = part_q30(cs, r.c, p.neg, sc, r.s, y.neg ^ r.neg ^ p.neg);
  out->z = part_q30(sc, r.c, y.neg, cs, r.s, p.neg ^ r.neg ^ 1u ^ y.neg);
  return DRDC_OK;
}

/** Euler angles from the matrix elements p (any common positive scale
 *  `one`, as exact int64 values |p| <= 2^62). */
static drdc_status_t euler_from_elements(const int64_t p[3][3], int64_t one,
                                         drdc_euler_t *out)
{
  uint64_t h = drdc_fx_hypot62(p[0][0], p[1][0]); /* cos(pitch) */
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

/* Element (i, j) of the exact Q60 numerators of R(c) for the scaled
 * quaternion c, the value drdc_orient_impl_numerator_row() gives (exact
 * integers: the same bits whatever the order of the sums). One element
 * at a time, where it is used: drdc_euler_from_quat() keeps no 3x3
 * matrix of int64_t live across its atan2 calls. */
static int64_t numerator(const int32_t c[4], unsigned i, unsigned j)
{
  int64_t a;
  int64_t b;

  if (i == j) {
    /* (ss + dd) - (the other two squares), d the part of axis i */
    a = (int64_t)c[1u + i] * c[1u + i];
    b = (((int64_t)c[1] * c[1]) + ((int64_t)c[2] * c[2]) +
         ((int64_t)c[3] * c[3])) -
        ((int64_t)c[0] * c[0]);
    return (2 * a) - b;
  }
  /* 2 (c_i c_j +- s c_k), k the third axis; plus below the diagonal in
   * the cyclic order (1 0), (2 1), (0 2) */
  a = (int64_t)c[1u + i] * c[1u + j];
  b = (int64_t)c[0] * c[4u - i - j];
  return 2 * ((((j + 3u - i) % 3u) == 2u) ? (a + b) : (a - b));
}

/* As euler_from_elements() on the numerators of the scaled quaternion,
 * each element computed where it is used, so that only the scaled
 * quaternion, cos(pitch) and the angles are live across the calls. */
drdc_status_t drdc_euler_from_quat(const drdc_quat_t *q, drdc_euler_t *out)
{
  orient_scaled_quat_t sq;
  drdc_euler_t e;
  uint64_t h;
  drdc_status_t st;

  if ((q == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc_orient_impl_scale(q, &sq);
  if (st != DRDC_OK) {
    return st;
  }
  h = drdc_fx_hypot62(numerator(sq.c, 0u, 0u), numerator(sq.c, 1u, 0u));
  st = drdc_orient_impl_atan2_s64(-numerator(sq.c, 2u, 0u), (int64_t)h,
                                  &e.pitch);
  if (st != DRDC_OK) {
    return st;
  }
  if (h < ((uint64_t)sq.n2 >> DRDC_ORIENT_GIMBAL_COS_LOG2)) {
    /* gimbal lock, as in euler_from_elements() */
    e.roll = 0u;
    st = drdc_orient_impl_atan2_s64(-numerator(sq.c, 0u, 1u),
                                    numerator(sq.c, 1u, 1u), &e.yaw);
  } else {
    st = drdc_orient_impl_atan2_s64(numerator(sq.c, 1u, 0u),
                                    numerator(sq.c, 0u, 0u), &e.yaw);
    if (st == DRDC_OK) {
      st = drdc_orient_impl_atan2_s64(numerator(sq.c, 2u, 1u),
                                      numerator(sq.c, 2u, 2u), &e.roll);
    }
  }
  if (st == DRDC_OK) {
    *out = e;
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
