/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_arith
 * @brief Q-format conversions, rounding shifts, multiply, divide and
 *        multiply-divide with overflow reported through a status.
 */
#ifndef DRDC_FIXED_ARITH_H
#define DRDC_FIXED_ARITH_H

#include <stdint.h>

#include <drdc/fixed_types.h>
#include <drdc/status.h>

/**
 * @defgroup drdc_fixed_arith Fixed-point arithmetic
 *
 * Rounding: to nearest, ties away from zero (see fixed_types.h), for every
 * function here. Every function in this group is correctly rounded: its
 * result is the exact real result rounded by that rule (error <= 0.5 LSB,
 * 0 LSB against the correctly rounded reference). Checked against exact
 * rational results from Python's fractions module (tests/fixed/
 * test_arith.c, tests/ref/gen_fixed_arith.py) and by exact integer
 * identities in the tests.
 *
 * Overflow: a function whose result may not fit comes in two forms.
 * - drdc_fx_<op>_<format>() returns DRDC_E_OVERFLOW and leaves `*out`
 *   unchanged;
 * - drdc_fx_<op>_<format>_sat() writes the nearest representable value
 *   (INT32_MIN/INT32_MAX or INT64_MIN/INT64_MAX) and returns
 *   DRDC_W_SATURATED.
 * Overflow is decided on the rounded result. No function wraps silently.
 * Every function that returns a status returns DRDC_E_NULL for a NULL
 * `out`, and leaves `*out` unchanged on every error.
 *
 * Intermediate formats: Q1.30 and Q15.16 products and quotients use a
 * 64-bit intermediate (|a * b| <= 2^62, |a| << 30 <= 2^61); Q47.16 and
 * int64 multiply-divide use an exact 128-bit intermediate built from
 * 32 x 32 -> 64 products, so there is no intermediate overflow anywhere.
 * @{
 */

/**
 * x / 2^n rounded to nearest, ties away from zero (a rounding right shift).
 *
 * @param x any int32_t value
 * @param n shift count; any value (n >= 32 gives 0, or -1 for INT32_MIN
 *          at n == 32 since -0.5 rounds away from zero)
 * @return the rounded quotient; cannot overflow for n >= 1 (for n == 0 it
 *         is x).
 *
 * @code
 * drdc_fx_rshift_round_s32(5, 1);   // 3 (2.5 -> 3)
 * drdc_fx_rshift_round_s32(-5, 1);  // -3
 * @endcode
 */
int32_t drdc_fx_rshift_round_s32(int32_t x, unsigned n);

/** int64_t form of drdc_fx_rshift_round_s32(): n >= 64 gives 0 (or -1 for
 *  INT64_MIN at n == 64). */
int64_t drdc_fx_rshift_round_s64(int64_t x, unsigned n);

/**
 * Inline form of drdc_fx_rshift_round_s64() for hot paths, shift counts
 * 1..63 only: x / 2^n rounded to nearest, ties away from zero; the same
 * result as the function (which calls it).
 *
 * @param x any int64_t value
 * @param n shift count, 1..63 (not checked)
 * @return the rounded quotient
 */
static inline int64_t drdc_fx_rshift_round_s64_inline(int64_t x, unsigned n)
{
  /* round the magnitude: no shift of a negative value */
  uint64_t mag = (x < 0) ? (0u - (uint64_t)x) : (uint64_t)x;
  uint64_t rounded = (mag + (UINT64_C(1) << (n - 1u))) >> n; /* < 2^63 */
  int64_t result = (int64_t)rounded;

  if (x < 0) {
    result = -result;
  }
  return result;
}

/**
 * Integer -> Q15.16: `*out` = i * 2^16, exact.
 *
 * @param i integer, -32768..32767
 * @param[out] out Q15.16 value; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_OVERFLOW i outside -32768..32767
 */
drdc_status_t drdc_fx_q15_16_from_int(int32_t i, drdc_q15_16_t *out);

/**
 * Saturating form of drdc_fx_q15_16_from_int(): the same correctly rounded
 * result when it fits; otherwise `*out` = INT32_MIN or INT32_MAX, the limit
 * on the side of the true result, and DRDC_W_SATURATED.
 *
 * @retval DRDC_OK written
 * @retval DRDC_W_SATURATED written, clamped to the limit
 * @retval DRDC_E_NULL `out` is NULL; nothing written
 */
drdc_status_t drdc_fx_q15_16_from_int_sat(int32_t i, drdc_q15_16_t *out);

/** Q15.16 -> nearest integer (ties away from zero); never fails: the
 *  result is in -32768..32768. */
int32_t drdc_fx_int_from_q15_16(drdc_q15_16_t x);

/**
 * Integer -> Q47.16: `*out` = i * 2^16, exact.
 *
 * @param i integer, -2^47..2^47 - 1
 * @param[out] out Q47.16 value; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_OVERFLOW i outside -2^47..2^47 - 1
 */
drdc_status_t drdc_fx_q47_16_from_int(int64_t i, drdc_q47_16_t *out);

/**
 * Saturating form of drdc_fx_q47_16_from_int(): the same correctly rounded
 * result when it fits; otherwise `*out` = INT64_MIN or INT64_MAX, the limit
 * on the side of the true result, and DRDC_W_SATURATED.
 *
 * @retval DRDC_OK written
 * @retval DRDC_W_SATURATED written, clamped to the limit
 * @retval DRDC_E_NULL `out` is NULL; nothing written
 */
drdc_status_t drdc_fx_q47_16_from_int_sat(int64_t i, drdc_q47_16_t *out);

/** Q47.16 -> nearest integer (ties away from zero); never fails. */
int64_t drdc_fx_int_from_q47_16(drdc_q47_16_t x);

/** Q15.16 -> Q47.16 (local to global length): exact, never fails (same
 *  binary point, sign extension only). */
drdc_q47_16_t drdc_fx_q47_16_from_q15_16(drdc_q15_16_t x);

/**
 * Q47.16 -> Q15.16 (global to local length), exact when in range.
 *
 * @param x Q47.16 value; in range when -32768 <= x / 2^16 < 32768
 * @param[out] out Q15.16 value; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_OVERFLOW x outside the Q15.16 range
 */
drdc_status_t drdc_fx_q15_16_from_q47_16(drdc_q47_16_t x, drdc_q15_16_t *out);

/**
 * Saturating form of drdc_fx_q15_16_from_q47_16(): the same correctly
 * rounded result when it fits; otherwise `*out` = INT32_MIN or INT32_MAX,
 * the limit on the side of the true result, and DRDC_W_SATURATED.
 *
 * @retval DRDC_OK written
 * @retval DRDC_W_SATURATED written, clamped to the limit
 * @retval DRDC_E_NULL `out` is NULL; nothing written
 */
drdc_status_t drdc_fx_q15_16_from_q47_16_sat(drdc_q47_16_t x,
                                             drdc_q15_16_t *out);

/**
 * Q15.16 -> Q1.30 (x * 2^14), exact when in range.
 *
 * @param x Q15.16 value; in range when -2 <= x / 2^16 < 2
 * @param[out] out Q1.30 value; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_OVERFLOW x outside [-2, 2)
 */
drdc_status_t drdc_fx_q1_30_from_q15_16(drdc_q15_16_t x, drdc_q1_30_t *out);

/**
 * Saturating form of drdc_fx_q1_30_from_q15_16(): the same correctly rounded
 * result when it fits; otherwise `*out` = INT32_MIN or INT32_MAX, the limit
 * on the side of the true result, and DRDC_W_SATURATED.
 *
 * @retval DRDC_OK written
 * @retval DRDC_W_SATURATED written, clamped to the limit
 * @retval DRDC_E_NULL `out` is NULL; nothing written
 */
drdc_status_t drdc_fx_q1_30_from_q15_16_sat(drdc_q15_16_t x, drdc_q1_30_t *out);

/** Q1.30 -> Q15.16: x / 2^14 rounded to nearest, ties away from zero;
 *  never fails. Error <= 0.5 LSB of Q15.16 (correctly rounded). */
drdc_q15_16_t drdc_fx_q15_16_from_q1_30(drdc_q1_30_t x);

/**
 * Q1.30 product: a * b / 2^30, correctly rounded.
 *
 * @param a, b Q1.30 factors, any values
 * @param[out] out Q1.30 product; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_OVERFLOW the product is outside [-2, 2) (only when
 *         |a * b| >= 2 - 2^-31, e.g. -2 * -1)
 *
 * @code
 * drdc_q1_30_t half = DRDC_Q1_30_ONE / 2, p;
 * drdc_fx_mul_q1_30(half, half, &p);   // p == DRDC_Q1_30_ONE / 4
 * @endcode
 */
drdc_status_t drdc_fx_mul_q1_30(drdc_q1_30_t a, drdc_q1_30_t b,
                                drdc_q1_30_t *out);

/**
 * Saturating form of drdc_fx_mul_q1_30(): the same correctly rounded result
 * when it fits; otherwise `*out` = INT32_MIN or INT32_MAX, the limit on the
 * side of the true result, and DRDC_W_SATURATED.
 *
 * @retval DRDC_OK written
 * @retval DRDC_W_SATURATED written, clamped to the limit
 * @retval DRDC_E_NULL `out` is NULL; nothing written
 */
drdc_status_t drdc_fx_mul_q1_30_sat(drdc_q1_30_t a, drdc_q1_30_t b,
                                    drdc_q1_30_t *out);

/**
 * Q15.16 product: a * b / 2^16, correctly rounded. Same result as
 * libfixmath's fix16_mul (rounding build) for every in-range product
 * (checked on the host on 20 million random pairs); overflow is reported
 * instead of returning fix16_overflow, which equals a valid value.
 *
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_OVERFLOW the product is outside [-32768, 32768)
 */
drdc_status_t drdc_fx_mul_q15_16(drdc_q15_16_t a, drdc_q15_16_t b,
                                 drdc_q15_16_t *out);

/**
 * Saturating form of drdc_fx_mul_q15_16(): the same correctly rounded result
 * when it fits; otherwise `*out` = INT32_MIN or INT32_MAX, the limit on the
 * side of the true result, and DRDC_W_SATURATED.
 *
 * @retval DRDC_OK written
 * @retval DRDC_W_SATURATED written, clamped to the limit
 * @retval DRDC_E_NULL `out` is NULL; nothing written
 */
drdc_status_t drdc_fx_mul_q15_16_sat(drdc_q15_16_t a, drdc_q15_16_t b,
                                     drdc_q15_16_t *out);

/**
 * Q47.16 product: a * b / 2^16, correctly rounded, 128-bit intermediate.
 *
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_OVERFLOW the product does not fit Q47.16
 */
drdc_status_t drdc_fx_mul_q47_16(drdc_q47_16_t a, drdc_q47_16_t b,
                                 drdc_q47_16_t *out);

/**
 * Saturating form of drdc_fx_mul_q47_16(): the same correctly rounded result
 * when it fits; otherwise `*out` = INT64_MIN or INT64_MAX, the limit on the
 * side of the true result, and DRDC_W_SATURATED.
 *
 * @retval DRDC_OK written
 * @retval DRDC_W_SATURATED written, clamped to the limit
 * @retval DRDC_E_NULL `out` is NULL; nothing written
 */
drdc_status_t drdc_fx_mul_q47_16_sat(drdc_q47_16_t a, drdc_q47_16_t b,
                                     drdc_q47_16_t *out);

/**
 * Q5.58 product: a * b / 2^58, correctly rounded (ties away from zero),
 * 128-bit intermediate; no division (four 32 x 32 products and a shift),
 * the workhorse of the geodesy series.
 *
 * @param a first factor, Q5.58.
 * @param b second factor, Q5.58.
 * @param[out] out the product, Q5.58; unchanged on error.
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_OVERFLOW the product does not fit Q5.58 (|a b| >= 32)
 */
drdc_status_t drdc_fx_mul_q5_58(drdc_q5_58_t a, drdc_q5_58_t b,
                                drdc_q5_58_t *out);

/**
 * Q1.30 quotient: a / b in Q1.30 (a * 2^30 / b), correctly rounded.
 *
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_DIVIDE_BY_ZERO b == 0 (also from the _sat form)
 * @retval DRDC_E_OVERFLOW the quotient is outside [-2, 2)
 */
drdc_status_t drdc_fx_div_q1_30(drdc_q1_30_t a, drdc_q1_30_t b,
                                drdc_q1_30_t *out);

/**
 * Saturating form of drdc_fx_div_q1_30(): the same correctly rounded result
 * when it fits; otherwise `*out` = INT32_MIN or INT32_MAX, the limit on the
 * side of the true result, and DRDC_W_SATURATED.
 *
 * @retval DRDC_OK written
 * @retval DRDC_W_SATURATED written, clamped to the limit
 * @retval DRDC_E_NULL `out` is NULL; nothing written
 * @retval DRDC_E_DIVIDE_BY_ZERO the divisor is 0; `*out` unchanged
 */
drdc_status_t drdc_fx_div_q1_30_sat(drdc_q1_30_t a, drdc_q1_30_t b,
                                    drdc_q1_30_t *out);

/**
 * Q15.16 quotient: a * 2^16 / b, correctly rounded.
 *
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_DIVIDE_BY_ZERO b == 0 (also from the _sat form)
 * @retval DRDC_E_OVERFLOW the quotient is outside [-32768, 32768)
 */
drdc_status_t drdc_fx_div_q15_16(drdc_q15_16_t a, drdc_q15_16_t b,
                                 drdc_q15_16_t *out);

/**
 * Saturating form of drdc_fx_div_q15_16(): the same correctly rounded result
 * when it fits; otherwise `*out` = INT32_MIN or INT32_MAX, the limit on the
 * side of the true result, and DRDC_W_SATURATED.
 *
 * @retval DRDC_OK written
 * @retval DRDC_W_SATURATED written, clamped to the limit
 * @retval DRDC_E_NULL `out` is NULL; nothing written
 * @retval DRDC_E_DIVIDE_BY_ZERO the divisor is 0; `*out` unchanged
 */
drdc_status_t drdc_fx_div_q15_16_sat(drdc_q15_16_t a, drdc_q15_16_t b,
                                     drdc_q15_16_t *out);

/**
 * Q47.16 quotient: a * 2^16 / b, correctly rounded, 128-bit intermediate.
 *
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_DIVIDE_BY_ZERO b == 0 (also from the _sat form)
 * @retval DRDC_E_OVERFLOW the quotient does not fit Q47.16
 */
drdc_status_t drdc_fx_div_q47_16(drdc_q47_16_t a, drdc_q47_16_t b,
                                 drdc_q47_16_t *out);

/**
 * Saturating form of drdc_fx_div_q47_16(): the same correctly rounded result
 * when it fits; otherwise `*out` = INT64_MIN or INT64_MAX, the limit on the
 * side of the true result, and DRDC_W_SATURATED.
 *
 * @retval DRDC_OK written
 * @retval DRDC_W_SATURATED written, clamped to the limit
 * @retval DRDC_E_NULL `out` is NULL; nothing written
 * @retval DRDC_E_DIVIDE_BY_ZERO the divisor is 0; `*out` unchanged
 */
drdc_status_t drdc_fx_div_q47_16_sat(drdc_q47_16_t a, drdc_q47_16_t b,
                                     drdc_q47_16_t *out);

/**
 * a * b / c for int32_t, correctly rounded, exact 64-bit intermediate.
 * Works for any Q format: the result has the format of a * b / c (e.g.
 * scaling a Q15.16 length by the ratio b / c of two integers).
 *
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_DIVIDE_BY_ZERO c == 0 (also from the _sat form)
 * @retval DRDC_E_OVERFLOW the result does not fit int32_t
 */
drdc_status_t drdc_fx_muldiv_s32(int32_t a, int32_t b, int32_t c, int32_t *out);

/**
 * Saturating form of drdc_fx_muldiv_s32(): the same correctly rounded result
 * when it fits; otherwise `*out` = INT32_MIN or INT32_MAX, the limit on the
 * side of the true result, and DRDC_W_SATURATED.
 *
 * @retval DRDC_OK written
 * @retval DRDC_W_SATURATED written, clamped to the limit
 * @retval DRDC_E_NULL `out` is NULL; nothing written
 * @retval DRDC_E_DIVIDE_BY_ZERO the divisor is 0; `*out` unchanged
 */
drdc_status_t drdc_fx_muldiv_s32_sat(int32_t a, int32_t b, int32_t c,
                                     int32_t *out);

/**
 * a * b / c for int64_t, correctly rounded, exact 128-bit intermediate.
 *
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_DIVIDE_BY_ZERO c == 0 (also from the _sat form)
 * @retval DRDC_E_OVERFLOW the result does not fit int64_t
 */
drdc_status_t drdc_fx_muldiv_s64(int64_t a, int64_t b, int64_t c, int64_t *out);

/**
 * Saturating form of drdc_fx_muldiv_s64(): the same correctly rounded result
 * when it fits; otherwise `*out` = INT64_MIN or INT64_MAX, the limit on the
 * side of the true result, and DRDC_W_SATURATED.
 *
 * @retval DRDC_OK written
 * @retval DRDC_W_SATURATED written, clamped to the limit
 * @retval DRDC_E_NULL `out` is NULL; nothing written
 * @retval DRDC_E_DIVIDE_BY_ZERO the divisor is 0; `*out` unchanged
 */
drdc_status_t drdc_fx_muldiv_s64_sat(int64_t a, int64_t b, int64_t c,
                                     int64_t *out);

/** @} */

#endif /* DRDC_FIXED_ARITH_H */
