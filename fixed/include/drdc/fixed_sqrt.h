/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_sqrt
 * @brief Correctly rounded integer and Q-format square roots, reciprocal
 *        square roots and hypot without overflow.
 */
#ifndef DRDC_FIXED_SQRT_H
#define DRDC_FIXED_SQRT_H

#include <stdint.h>

#include <drdc/fixed_types.h>
#include <drdc/status.h>

/**
 * @defgroup drdc_fixed_sqrt Square roots
 *
 * Every function here is correctly rounded: the result r is the integer
 * nearest to the exact real root (error < 0.5 LSB, 0 LSB against the
 * rounded reference). A square root is never exactly half-way between two
 * integers (4n would equal an odd square), so no tie rule is needed.
 * Checked in tests/fixed/test_sqrt.c by the exact integer criterion
 * (2r - 1)^2 < 4n < (2r + 1)^2 (as r^2 - r < n <= r^2 + r): every uint32
 * n below 2^20; k^2 - 1, k^2, k^2 + 1, k^2 + k (rounds down) and
 * k^2 + k + 1 (rounds up) for every k < 2^16 and for 131 068 k spread up
 * to 2^32; 262 144 pseudo-random uint64; the Q forms and rsqrt by the
 * same criterion scaled to their formats (Q15.16 also on every x < 2^16,
 * the edges of its seed table's bins and 244 000 inputs beside rounding
 * boundaries); rsqrt and hypot also against
 * exact roots from Python's math.isqrt (tests/ref/gen_fixed_sqrt.py).
 * @{
 */

/**
 * round(sqrt(n)) for a 32-bit n.
 *
 * @param n any uint32_t
 * @return round(sqrt(n)), 0..65536 (65536 for n >= 4294901761)
 */
uint32_t drdc_fx_sqrt_u32(uint32_t n);

/**
 * round(sqrt(n)) for a 64-bit n.
 *
 * @param n any uint64_t
 * @return round(sqrt(n)), 0..2^32
 */
uint64_t drdc_fx_sqrt_u64(uint64_t n);

/**
 * Square root in Q15.16: round(sqrt(x / 2^16) * 2^16) = round(sqrt(x
 * 2^16)), correctly rounded; 64-bit intermediate, cannot overflow (the
 * largest result is 181.02 m^(1/2) in Q15.16).
 *
 * @param x Q15.16 value, >= 0
 * @param[out] out root in Q15.16; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_DOMAIN x < 0
 */
drdc_status_t drdc_fx_sqrt_q15_16(drdc_q15_16_t x, drdc_q15_16_t *out);

/**
 * Square root in Q1.30: round(sqrt(x 2^30)), correctly rounded; cannot
 * overflow (sqrt(2) < 2).
 *
 * @param x Q1.30 value, >= 0
 * @param[out] out root in Q1.30; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_DOMAIN x < 0
 */
drdc_status_t drdc_fx_sqrt_q1_30(drdc_q1_30_t x, drdc_q1_30_t *out);

/**
 * Reciprocal square root in Q15.16: round(2^16 / sqrt(x / 2^16)) =
 * round(sqrt(2^48 / x)), correctly rounded (decided by the exact
 * criterion x (2r - 1)^2 < 2^50 < x (2r + 1)^2). Results 1.4e-2 (x = max)
 * .. 256.0 (x = 2^-16); cannot overflow.
 *
 * @param x Q15.16 value, > 0
 * @param[out] out 1/sqrt(x) in Q15.16; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_DOMAIN x <= 0
 */
drdc_status_t drdc_fx_rsqrt_q15_16(drdc_q15_16_t x, drdc_q15_16_t *out);

/**
 * Reciprocal square root in Q1.30: round(sqrt(2^90 / x)), correctly
 * rounded (from the integer root of the exact 64-bit quotient
 * floor(2^92 / x)). For normalising unit quaternions and vectors, whose
 * squared norm is near 1.
 *
 * @param x Q1.30 value, > 0.25 (x > 2^28) for a result below 2
 * @param[out] out 1/sqrt(x) in Q1.30; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_DOMAIN x <= 0
 * @retval DRDC_E_OVERFLOW 0 < x <= 0.25: the result is >= 2
 */
drdc_status_t drdc_fx_rsqrt_q1_30(drdc_q1_30_t x, drdc_q1_30_t *out);

/**
 * sqrt(x^2 + y^2), correctly rounded, exact 64-bit sum of squares: never
 * overflows, for any inputs including INT32_MIN. x and y share any
 * format (integers, Q15.16 metres, Q1.30), the result has that format.
 *
 * @return round(hypot(x, y)), 0..3037000500 (as uint32_t)
 *
 * @code
 * drdc_fx_hypot_s32(3, 4);   // 5
 * @endcode
 */
uint32_t drdc_fx_hypot_s32(int32_t x, int32_t y);

/**
 * hypot for int64 inputs (e.g. Q47.16 global lengths): exact 128-bit sum
 * of squares and 128-bit integer root, correctly rounded; never overflows.
 *
 * @return round(hypot(x, y)), 0..13043817825332782212 (as uint64_t)
 */
uint64_t drdc_fx_hypot_s64(int64_t x, int64_t y);

/**
 * hypot of two Q15.16 values as a Q15.16 value, correctly rounded.
 *
 * @param x first leg, Q15.16 (any value)
 * @param y second leg, Q15.16 (any value)
 * @param[out] out hypot in Q15.16; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_OVERFLOW the result is >= 32768
 */
drdc_status_t drdc_fx_hypot_q15_16(drdc_q15_16_t x, drdc_q15_16_t y,
                                   drdc_q15_16_t *out);

/**
 * Saturating form of drdc_fx_hypot_q15_16(): the same correctly rounded
 * result when it fits; otherwise `*out` = INT32_MAX, the limit on the side
 * of the true result, and DRDC_W_SATURATED.
 *
 * @retval DRDC_OK written
 * @retval DRDC_W_SATURATED written, clamped to the limit
 * @retval DRDC_E_NULL `out` is NULL; nothing written
 */
drdc_status_t drdc_fx_hypot_q15_16_sat(drdc_q15_16_t x, drdc_q15_16_t y,
                                       drdc_q15_16_t *out);

/** @} */

#endif /* DRDC_FIXED_SQRT_H */
