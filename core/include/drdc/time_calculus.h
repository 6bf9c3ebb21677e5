/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time_calculus
 * @brief Time-scale calculus: delta derivative and delta integral of
 *        integer samples on a non-uniform time scale.
 */
#ifndef DRDC_TIME_CALCULUS_H
#define DRDC_TIME_CALCULUS_H

#include <stddef.h>
#include <stdint.h>

#include <drdc/types.h>

/**
 * @defgroup drdc_time_calculus Time-scale calculus
 *
 * The time scale is the set of sample times t_0 < t_1 < ... < t_{n-1},
 * given in nanoseconds of a uniform scale as int64_t (TAI or GPS
 * nanoseconds, a monotonic counter: not UTC, whose seconds are not
 * uniform across a leap second; convert with drdc_time_utc_to_tai()
 * first). The graininess is mu(t_i) = t_{i+1} - t_i (ns). Samples f_i are
 * int32_t in any unit and any Q format; results keep that unit and Q
 * format, per second or times seconds.
 *
 * Scaling and overflow: every intermediate is exact. A difference of two
 * samples needs 33 bits, times 1e9 (30 bits) 63 bits: an int64_t holds
 * it. The integral accumulates f_i * mu_i (up to 95 bits each) in a
 * 128-bit integer made of two uint64_t, then divides by 1e9 once. Each
 * result is rounded to the nearest integer, halves away from zero: the
 * error is at most 0.5 LSB of the output, and that is the only error.
 * @{
 */

/**
 * Delta derivative: f^delta(t_i) = (f_{i+1} - f_i) / mu(t_i) for
 * i = 0..n-2, in sample units per second.
 *
 * @param t_ns  n strictly increasing time stamps, nanoseconds
 * @param f     n samples
 * @param n     number of samples, at least 2
 * @param[out] deriv n - 1 derivatives: round((f_{i+1} - f_i) * 1e9 /
 *             mu_i), sample units (same Q format) per second; unchanged
 *             on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_RANGE n < 2, or a time stamp before its predecessor
 * @retval DRDC_E_DIVIDE_BY_ZERO two equal time stamps (mu = 0)
 *
 * Accuracy: exactly rounded (<= 0.5 LSB), checked against Python's
 * fractions.Fraction. Every result fits: |f_{i+1} - f_i| * 1e9 < 2^62.
 *
 * @code
 * int64_t t[3] = { 0, 500000000, 2000000000 };  // 0 s, 0.5 s, 2 s
 * int32_t f[3] = { 0, 10, 13 };
 * int64_t d[2];
 * drdc_time_delta_derivative(t, f, 3, d);       // d = { 20, 2 }
 * @endcode
 */
drdc_status_t drdc_time_delta_derivative(const int64_t *t_ns, const int32_t *f,
                                         size_t n, int64_t *deriv);

/**
 * Delta integral from t_0 to t_{n-1}: sum of f_i * mu(t_i) for
 * i = 0..n-2 (the left Riemann sum, which is the exact delta integral on
 * the time scale), in sample units times seconds.
 *
 * @param t_ns  n strictly increasing time stamps, nanoseconds
 * @param f     n samples (the last one does not contribute)
 * @param n     number of samples, at least 1 (one sample: integral 0)
 * @param[out] integral round(sum f_i * mu_i / 1e9); unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_RANGE n = 0, or a time stamp before its predecessor
 * @retval DRDC_E_DIVIDE_BY_ZERO two equal time stamps
 * @retval DRDC_E_OVERFLOW the rounded integral does not fit an int64_t
 *
 * Accuracy: exactly rounded (<= 0.5 LSB), checked against Python's
 * fractions.Fraction; no intermediate can overflow for n < 2^32.
 */
drdc_status_t drdc_time_delta_integral(const int64_t *t_ns, const int32_t *f,
                                       size_t n, int64_t *integral);

/** @} */

#endif /* DRDC_TIME_CALCULUS_H */
