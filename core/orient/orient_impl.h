/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_orient
 * @brief Internal helpers of core/orient/: exact 64-bit sums of Q60
 *        products, power-of-two prescaling of quaternions, half-angle
 *        sines and atan2 of 64-bit coordinates; powers of two, squares
 *        and limits spelled for MISRA C:2012 (no shift of a signed
 *        value, no cast of a composite expression, no unsigned INT64_MIN).
 *
 * Products of two Q1.30 values are Q60 (2^60 per unit) and are kept exact
 * in int64_t as long as possible; each public result is rounded once, at
 * the end, by drdc_fx_rshift_round_s64() or drdc_fx_muldiv_s64().
 */
#ifndef DRDC_ORIENT_IMPL_H
#define DRDC_ORIENT_IMPL_H

#include <stdint.h>

#include <drdc/fixed_arith.h>
#include <drdc/orient.h>

/** The least int64_t, spelled without the unsigned constant of the
 *  <stdint.h> macro (MISRA C:2012 rule 7.2), as fixed/fixed_impl.h does
 *  for FX_INT64_MIN. Same value and type as INT64_MIN. */
#define ORIENT_INT64_MIN (-INT64_MAX - 1)

/** 1.0 in Q1.30, the value and type of DRDC_Q1_30_ONE, written as a
 *  constant instead of a left shift of a signed value (rule 10.1). */
#define ORIENT_Q1_30_ONE ((drdc_q1_30_t)0x40000000)

/** 2^n as int64_t for n <= 62, from an unsigned shift (rule 10.1: no shift
 *  of a signed value), as fx_scale_pow2_64() in fixed/trig_impl.h; equal
 *  to ((int64_t)1 << n). A constant n folds to a constant. */
static inline int64_t orient_pow2_s64(unsigned n)
{
  uint64_t p = UINT64_C(1) << n;

  return (int64_t)p;
}

/** v^2 as uint64_t, exact (<= 2^62), the product computed in int64_t and
 *  then converted (rule 10.8: no cast of a composite expression). */
static inline uint64_t orient_square_u64(int32_t v)
{
  int64_t sq = (int64_t)v * v;

  return (uint64_t)sq;
}

/** Components of a quaternion scaled by 2^k so that the largest magnitude
 *  is in [2^29, 2^30]; the sum of squares n2 (raw units squared) is then
 *  exact and in [2^58, 2^62]. */
typedef struct orient_scaled_quat {
  int32_t c[4]; /**< s, x, y, z times 2^k (rounded when k == -1) */
  int64_t n2;   /**< c[0]^2 + c[1]^2 + c[2]^2 + c[3]^2 */
  int32_t k;    /**< the scale exponent, -1..30 */
} orient_scaled_quat_t;

/**
 * Scale q by a power of two: up (exact) when its largest part is below
 * 0.5, down by 2 (rounded) when it is above 1.0.
 * @return DRDC_OK, or DRDC_E_DOMAIN for the zero quaternion.
 */
drdc_status_t drdc_orient_impl_scale(const drdc_quat_t *q,
                                     orient_scaled_quat_t *out);

/** a + b + c + d without overflow; DRDC_E_OVERFLOW when the exact sum
 *  does not fit int64_t. */
drdc_status_t drdc_orient_impl_sum4(int64_t a, int64_t b, int64_t c,
                                    int64_t d, int64_t *out);

/** Round a Q60 value to Q1.30 (ties away from zero); DRDC_E_OVERFLOW
 *  when the result does not fit int32_t. */
static inline drdc_status_t drdc_orient_impl_q60_to_q30(int64_t v,
                                                        drdc_q1_30_t *out)
{
  /* inline: a quaternion product calls it four times */
  int64_t r = drdc_fx_rshift_round_s64_inline(v, 30u);
  drdc_status_t st = DRDC_E_OVERFLOW;

  if ((r <= INT32_MAX) && (r >= INT32_MIN)) {
    *out = (drdc_q1_30_t)r;
    st = DRDC_OK;
  }
  return st;
}

/**
 * sin and cos of half the signed angle a ([-pi, pi) -> [-pi/2, pi/2)),
 * both doubled: Q1.31 scale (2^31 = 1.0) in int64_t. For an odd a the
 * half angle falls between two binary angles; the mean of the two table
 * values is used (its error is that of drdc_fx_sin_bam32(), the
 * curvature term is below 2^-60).
 */
void drdc_orient_impl_half_sincos(drdc_bam32_t a, int64_t *s2, int64_t *c2);

/** atan2 of two int64_t coordinates: both are scaled by the same power
 *  of two (rounded) so that the larger fits in 31 bits with the most
 *  precision left, then drdc_fx_atan2_bam32(). DRDC_E_DOMAIN for (0, 0). */
drdc_status_t drdc_orient_impl_atan2_s64(int64_t y, int64_t x,
                                         drdc_bam32_t *out);

/** Exact Q60 numerators p of the rotation matrix of q (prescaled) and
 *  their common denominator n2: R = p / n2, |p| <= n2 <= 2^62.
 *  DRDC_E_DOMAIN for the zero quaternion. */
drdc_status_t drdc_orient_impl_numerators(const drdc_quat_t *q,
                                          int64_t p[3][3], int64_t *n2);

/** Largest shift s <= max such that |v| * 2^s < 2^limit (v any uint64). */
unsigned drdc_orient_impl_headroom(uint64_t v, unsigned limit);

#endif /* DRDC_ORIENT_IMPL_H */
