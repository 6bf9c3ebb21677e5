/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_orient
 * @brief Internal helpers of core/orient/: exact 64-bit sums of Q60
 *        products and their rounding to Q1.30, power-of-two prescaling of
 *        quaternions, numerator rows of the rotation matrix, half-angle
 *        sines and atan2 of 64-bit coordinates; powers of two, squares
 *        and limits spelled for MISRA C:2012 (no shift of a signed
 *        value, no cast of a composite expression, no unsigned INT64_MIN).
 *        General wide-integer arithmetic (128-bit products, division by
 *        invariant integers, rounded 128-bit quotients, the exact 62-bit
 *        hypot) comes from fixed/: <drdc/fixed_wide.h>.
 *
 * Products of two Q1.30 values are Q60 (2^60 per unit) and are kept exact
 * in int64_t as long as possible; each public result is rounded once, at
 * the end, by drdc_fx_rshift_round_s64() or drdc_fx_muldiv_s64().
 */
#ifndef DRDC_ORIENT_IMPL_H
#define DRDC_ORIENT_IMPL_H

#include <stdint.h>

#include <drdc/fixed_trig.h>
#include <drdc/fixed_wide.h>
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
drdc_status_t drdc_orient_impl_sum4(int64_t a, int64_t b, int64_t c, int64_t d,
                                    int64_t *out);

/**
 * Round a Q60 value to Q1.30 bits (ties away from zero) without a branch,
 * for hot paths whose callers know v cannot reach 2^63: the sign bias
 * 2^29 - [v < 0] turns the floor of the shift into the rounding of
 * drdc_fx_rshift_round_s64() (ceil((v - 2^29) / 2^30) equals
 * floor((v + 2^29 - 1) / 2^30)). The high word of the biased value plus
 * 2^29 is ORed into *ovf: the result fits int32_t exactly when that word
 * is below 2^30, so bits 30..31 of *ovf flag an overflow of any of the
 * parts rounded with the same *ovf.
 * @return the low 32 bits of the rounded value (the Q1.30 part when
 *         *ovf stays below 2^30)
 */
static inline uint32_t orient_q60_round_bits(int64_t v, uint32_t *ovf)
{
  uint64_t u = (uint64_t)v;
  uint32_t neg = (uint32_t)(u >> 63u);
  uint32_t hi;

  u += UINT64_C(0x20000000) - neg;
  hi = (uint32_t)(u >> 32u);
  *ovf |= hi + UINT32_C(0x20000000);
  return (uint32_t)(u >> 30u);
}

/** The divisor n2 of the numerator rows (in [2^58, 2^62]) normalised
 *  for drdc_fx_div_3by2(): *dn = n2 2^z with bit 63 set (z = 1..5 into
 *  *z), and its reciprocal returned; one for the nine divisions of a
 *  matrix. */
static inline uint32_t orient_row_divisor(int64_t n2, uint64_t *dn, unsigned *z)
{
  *z = (unsigned)__builtin_clzll((uint64_t)n2);
  *dn = (uint64_t)n2 << *z;
  return drdc_fx_reciprocal_3by2((uint32_t)(*dn >> 32u), (uint32_t)*dn);
}

/** Row i of the exact Q60 numerators p of R(c) for the scaled quaternion
 * c (R(c / |c|) = p / n2, |p| <= n2 <= 2^62), one row at a time so that
 * the whole matrix never sits on the stack. */
void drdc_orient_impl_numerator_row(const int32_t c[4], unsigned i,
                                    int64_t row[3]);

/** Q60 -> Q1.30 bits of p = w + x + y + z for any four products of two
 * int32 values (the parts of a quaternion product, the elements of a
 * matrix product), each term (|.| <= 2^62, so also its negation), summed
 * modulo 2^64.
 * With each term = h 2^32 + l (h its signed high word, 0 <= l < 2^32),
 * |p - (sum of h) 2^32| < 2^34: when that sum of high words is within
 * 2^30, |p| < 2^63 and the modular sum is p itself; beyond, |p| > 2^62
 * and the part cannot fit [-2, 2) (bit 31 of *ovf is set). */
static inline uint32_t orient_sum4_round_bits(int64_t w, int64_t x, int64_t y,
                                              int64_t z, uint32_t *ovf)
{
  int64_t hs = (int64_t)drdc_fx_high_word(w) + drdc_fx_high_word(x) +
               drdc_fx_high_word(y) + drdc_fx_high_word(z);
  uint64_t sum = (uint64_t)w + (uint64_t)x + (uint64_t)y + (uint64_t)z;

  if ((hs > (INT64_C(1) << 30)) || (hs < -(INT64_C(1) << 30))) {
    *ovf |= (UINT32_C(1) << 31);
    sum = 0u;
  }
  return orient_q60_round_bits((int64_t)sum, ovf);
}

/**
 * sin and cos of half the signed angle a ([-pi, pi) -> [-pi/2, pi/2)),
 * both doubled: Q1.31 scale (2^31 = 1.0) in int64_t. For an odd a the
 * half angle falls between two binary angles; the mean of the two table
 * values is used (its error is that of drdc_fx_sin_bam32(), the
 * curvature term is below 2^-60).
 */
void drdc_orient_impl_half_sincos(drdc_bam32_t a, int64_t *s2, int64_t *c2);

/** |v| of an int32_t as uint32_t; exact for INT32_MIN. */
static inline uint32_t orient_abs32(int32_t v)
{
  return (v < 0) ? (0u - (uint32_t)v) : (uint32_t)v;
}

/** Doubled half-angle sine and cosine as magnitudes (Q1.31 scale,
 *  <= 2^31) and the sign of the sine; the cosine is never negative. */
typedef struct orient_half {
  uint32_t s;   /**< |2 sin(a / 2)|, Q1.31 scale */
  uint32_t c;   /**< 2 cos(a / 2) >= 0, Q1.31 scale */
  uint32_t neg; /**< 1 when the sine is negative, else 0 */
} orient_half_t;

/** The values of drdc_orient_impl_half_sincos() as magnitudes and a sign
 *  bit (the same bits: s2 = (-1)^neg s, c2 = c), for callers that
 *  multiply them with 32x32->64 products; inline, so that the three
 *  angles of drdc_quat_from_euler() pay no call of their own. */
static inline void orient_half_sincos_mag(drdc_bam32_t a, orient_half_t *out)
{
  drdc_bam32_t h = (a >> 1u) | (a & 0x80000000u); /* floor(a / 2), signed */
  drdc_q1_30_t s0;
  drdc_q1_30_t c0;
  drdc_q1_30_t s1;
  drdc_q1_30_t c1;

  drdc_fx_sincos_bam32(h, &s0, &c0);
  if ((a & 1u) == 0u) {
    s1 = s0;
    c1 = c0;
  } else {
    drdc_fx_sincos_bam32(h + 1u, &s1, &c1);
  }
  /* c0, c1 >= 0 (the half angle is in [-pi/2, pi/2]): the sum <= 2^31
   * fits uint32. s0 and s1 never have opposite signs (h < 0 < h + 1 has
   * no integer h), so the sign is that of either nonzero one and the
   * magnitude the sum of theirs (|s0|, |s1| <= 2^30). */
  out->c = (uint32_t)c0 + (uint32_t)c1;
  out->neg = ((uint32_t)s0 | (uint32_t)s1) >> 31u;
  out->s = orient_abs32(s0) + orient_abs32(s1);
}

/** atan2 of two int64_t coordinates: both are scaled by the same power
 *  of two (rounded) so that the larger fits in 31 bits with the most
 *  precision left, then drdc_fx_atan2_bam32(). DRDC_E_DOMAIN for (0, 0). */
drdc_status_t drdc_orient_impl_atan2_s64(int64_t y, int64_t x,
                                         drdc_bam32_t *out);

#endif /* DRDC_ORIENT_IMPL_H */
