/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_q5_58
 * @brief Q5.58 functions of the geodesy: sin and cos in radians, atan2,
 *        square root and quotient, to a few units of 2^-58.
 */
#ifndef DRDC_FIXED_Q5_58_H
#define DRDC_FIXED_Q5_58_H

#include <stdint.h>

#include <drdc/fixed_types.h>
#include <drdc/status.h>

/**
 * @defgroup drdc_fixed_q5_58 Q5.58 elementary functions
 *
 * Arguments and results are drdc_q5_58_t: int64_t, real value raw / 2^58,
 * range [-32, 32), resolution 3.5e-18; angles in radians. The binary
 * angles of fixed_trig.h (1.5e-9 rad = 9 mm on the Earth) are too coarse
 * for the 15 um of the geodesy (core/geo), so these refine them: sin/cos
 * by Taylor series on [-pi/4, pi/4] after a quadrant reduction, atan2 by
 * one exact correction step from the binary-angle seed, sqrt by Newton
 * steps from the integer root. Every product is a rounded 64 x 64 ->
 * 128-bit product (drdc_fx_mul_q5_58(), drdc_fx_muldiv_s64()); no
 * division but in the atan2 step and the sqrt iteration.
 *
 * Errors are absolute, in LSB of Q5.58 (2^-58 = 3.5e-18), against mpmath
 * at 60 digits rounded to nearest (tests/ref/gen_fixed_q5_58.py), over
 * dense grids and random arguments of each domain, stored as vectors and
 * run on every target (tests/fixed/test_q5_58.c).
 * @{
 */

/** pi in Q5.58, rounded to nearest. */
#define DRDC_Q5_58_PI INT64_C(905502432259640355)
/** pi / 2 in Q5.58, rounded to nearest. */
#define DRDC_Q5_58_HALF_PI INT64_C(452751216129820178)
/** 2 pi in Q5.58, rounded to nearest. */
#define DRDC_Q5_58_TWO_PI INT64_C(1811004864519280711)

/**
 * sin(x) and cos(x) of x radians in Q5.58.
 *
 * @param x radians, Q5.58, any value (|x| < 32).
 * @param[out] s sin(x); unchanged on error.
 * @param[out] c cos(x); unchanged on error.
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL s or c is NULL
 *
 * Method: k = round(x 2/pi) by a product, r = x - k pi/2 (|r| <= pi/4
 * plus a few LSB), Taylor series of sin r and cos r to r^19 and r^18
 * (first omitted terms below 1e-19), Horner in Q5.58; the quadrant k mod
 * 4 picks and negates. The 0.4 LSB error of pi/2 grows with k.
 *
 * Accuracy: measured max error 2 LSB (7e-18) for
 * |x| <= 8, 7 LSB for all x; 1 714 stored points.
 */
drdc_status_t drdc_fx_sincos_q5_58(drdc_q5_58_t x, drdc_q5_58_t *s,
                                   drdc_q5_58_t *c);

/**
 * atan2(y, x) in radians, Q5.58, in (-pi, pi].
 *
 * @param y any int64_t (only the ratio y : x matters, so both may carry
 *        any one scale).
 * @param x any int64_t; not both zero.
 * @param[out] out the angle; unchanged on error. An angle that rounds
 *        to -pi (y < 0 within 2^-59 of the negative x axis) is returned as
 *        +pi, the same direction.
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL out is NULL
 * @retval DRDC_E_DOMAIN y and x are both zero
 *
 * Method: both scaled so the larger magnitude lies in [2^57, 2^58]
 * (right shifts round), a binary-angle seed by drdc_fx_atan2_bam32()
 * (1 LSB, 1.5e-9 rad), then the remainder d with tan d =
 * (y cos t - x sin t) / (x cos t + y sin t), |d| < 3e-9 (the seed's
 * 1.5e-9 plus 1.3e-9 from rounding y and x to 31 bits), taken as the
 * quotient (d^3 / 3 < 1e-26 is below the resolution).
 *
 * Accuracy: measured max error 3 LSB (1.1e-17 rad) over
 * 1 200 stored points (random angles at magnitudes from 1 to
 * 2^63, the axes, the diagonals, INT64_MIN and INT64_MAX).
 */
drdc_status_t drdc_fx_atan2_q5_58(int64_t y, int64_t x, drdc_q5_58_t *out);

/**
 * sqrt(x) in Q5.58.
 *
 * @param x Q5.58, x >= 0.
 * @param[out] out sqrt(x), 0 .. 5.66; unchanged on error.
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL out is NULL
 * @retval DRDC_E_DOMAIN x < 0
 *
 * Method: x below 2^-30 is first scaled up by an even power of two 4^k;
 * the rounded integer root of the raw value (the root in Q29, within
 * 2^-15 relative) times 2^29 seeds two Newton steps y = (y + x / y) / 2
 * (each squares the relative error, so 2^-60 is reached); the result is
 * shifted back by 2^k, rounded.
 *
 * Accuracy: measured max error 1 LSB over 1 046 stored
 * points (every magnitude from 2^-58 to 32, squares, their neighbours).
 */
drdc_status_t drdc_fx_sqrt_q5_58(drdc_q5_58_t x, drdc_q5_58_t *out);

/**
 * Q5.58 quotient a / b (a 2^58 / b), correctly rounded (ties away from
 * zero), 128-bit intermediate (drdc_fx_muldiv_s64()).
 *
 * @param a dividend, Q5.58.
 * @param b divisor, Q5.58, non-zero.
 * @param[out] out the quotient, Q5.58; unchanged on error.
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL out is NULL
 * @retval DRDC_E_DIVIDE_BY_ZERO b == 0
 * @retval DRDC_E_OVERFLOW the quotient does not fit Q5.58 (|a / b| >= 32)
 *
 * Accuracy: correctly rounded, error <= 0.5 LSB; checked exactly on
 * 789 stored pairs.
 */
drdc_status_t drdc_fx_div_q5_58(drdc_q5_58_t a, drdc_q5_58_t b,
                                drdc_q5_58_t *out);

/**
 * Q5.58 quotient a / b without a status, for callers whose bounds are
 * proven: the same bits as drdc_fx_div_q5_58() whenever that returns
 * DRDC_OK, and 0 where it fails (b == 0, or |a / b| >= 32).
 *
 * @param a dividend, Q5.58.
 * @param b divisor, Q5.58; the caller guarantees b != 0 and |a / b| < 32.
 * @return the correctly rounded quotient (ties away from zero), Q5.58.
 *
 * Why: for bounded inner loops the quotient is a plain value, with no
 * status to test and no output pointer. Accuracy: as
 * drdc_fx_div_q5_58(); checked bit for bit against it on the stored
 * quotient vectors (tests/fixed/test_q5_58.c).
 */
drdc_q5_58_t drdc_fx_div_q5_58_unchecked(drdc_q5_58_t a, drdc_q5_58_t b);

/**
 * Q5.58 product a b / 2^58 rounded to nearest (ties away from zero),
 * inline and without a status, for inner loops whose bounds are proven:
 * the same bits as drdc_fx_mul_q5_58() whenever that returns DRDC_OK.
 *
 * @param a Q5.58 factor.
 * @param b Q5.58 factor; the caller guarantees |a b| < 32 (the product
 *        fits Q5.58). Beyond that the result is the low 64 bits of the
 *        rounded magnitude with the sign applied: wrong, but defined
 *        (no undefined behaviour, no trap).
 * @return the rounded product, Q5.58.
 *
 * Method: the magnitudes' 128-bit product from four 32 x 32 -> 64
 * products, plus 2^57, bits 58..121; then the sign; no call, no check
 * and no output pointer. Accuracy: correctly rounded, error
 * <= 0.5 LSB; checked bit for bit against drdc_fx_mul_q5_58() on the
 * stored product vectors (tests/fixed/test_q5_58.c).
 */
static inline drdc_q5_58_t drdc_fx_mul_q5_58_unchecked(drdc_q5_58_t a,
                                                       drdc_q5_58_t b)
{
  uint64_t ma = (a < 0) ? (UINT64_C(0) - (uint64_t)a) : (uint64_t)a;
  uint64_t mb = (b < 0) ? (UINT64_C(0) - (uint64_t)b) : (uint64_t)b;
  uint32_t a0 = (uint32_t)ma;
  uint32_t a1 = (uint32_t)(ma >> 32);
  uint32_t b0 = (uint32_t)mb;
  uint32_t b1 = (uint32_t)(mb >> 32);
  /* bits 32..95 of the magnitudes' product column by column, each sum
   * below 2^64: (2^32 - 1) + (2^32 - 1)^2 + 2^25 < 2^64. Bits 0..31 of
   * a0 b0 cannot carry into bit 57, where the rounding half 2^25 (of the
   * second word) is added. */
  uint64_t t = (((uint64_t)a0 * b0) >> 32) + ((uint64_t)a0 * b1);
  uint64_t u =
      (uint64_t)(uint32_t)t + ((uint64_t)a1 * b0) + (UINT64_C(1) << 25);
  uint64_t hi = ((uint64_t)a1 * b1) + (t >> 32) + (u >> 32);
  uint64_t m = (hi << 6) | ((uint64_t)(uint32_t)u >> 26);

  return ((a < 0) != (b < 0)) ? (drdc_q5_58_t)(UINT64_C(0) - m)
                              : (drdc_q5_58_t)m;
}

/**
 * drdc_fx_mul_q5_58_unchecked(a, b) when the raw |b| is below 2^32 (a
 * Q5.58 value under 1.5e-8, such as the high-order terms of a series):
 * the same bits, from two 32 x 32 -> 64 products instead of four.
 *
 * @param a Q5.58 factor, any value.
 * @param b Q5.58 factor; the caller guarantees |b| < 2^32 raw (its
 *        bound proven where it is called). Beyond that the result is
 *        wrong but defined.
 * @return the rounded product, Q5.58.
 *
 * Method: with |b| one word, |a b| = (|a|_hi |b|) 2^32 + |a|_lo |b|, and
 * t = floor(|a b| / 2^32) = |a|_hi |b| + floor(|a|_lo |b| / 2^32) <
 * 2^64. Adding the half 2^57 = 2^25 2^32 carries nothing out of the low
 * word, so floor((|a b| + 2^57) / 2^58) = floor((t + 2^25) / 2^26): the
 * magnitude drdc_fx_mul_q5_58_unchecked() rounds, bit for bit; then the
 * sign as there. Accuracy: correctly rounded, error <= 0.5 LSB; checked
 * bit for bit against drdc_fx_mul_q5_58_unchecked() (tests/fixed/
 * test_q5_58.c).
 */
static inline drdc_q5_58_t drdc_fx_mul_q5_58_short(drdc_q5_58_t a,
                                                   drdc_q5_58_t b)
{
  uint64_t ma = (a < 0) ? (UINT64_C(0) - (uint64_t)a) : (uint64_t)a;
  uint32_t mb = (uint32_t)((b < 0) ? (UINT64_C(0) - (uint64_t)b) : (uint64_t)b);
  uint64_t lo = (uint64_t)(uint32_t)ma * mb;
  uint64_t t = ((ma >> 32) * mb) + (lo >> 32);
  uint64_t m = (t + (UINT64_C(1) << 25)) >> 26;

  return ((a < 0) != (b < 0)) ? (drdc_q5_58_t)(UINT64_C(0) - m)
                              : (drdc_q5_58_t)m;
}

/** @} */

#endif /* DRDC_FIXED_Q5_58_H */
