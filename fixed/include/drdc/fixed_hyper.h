/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_hyper
 * @brief Hyperbolic and inverse hyperbolic functions in Q5.58 (int64),
 *        for the transverse Mercator (UTM) series of the geodesy.
 */
#ifndef DRDC_FIXED_HYPER_H
#define DRDC_FIXED_HYPER_H

#include <stdint.h>

#include <drdc/fixed_types.h>
#include <drdc/status.h>

/**
 * @defgroup drdc_fixed_hyper Hyperbolic functions
 *
 * Arguments and results are drdc_q5_58_t: int64_t, real value raw / 2^58,
 * range [-32, 32), resolution 3.5e-18. The Krueger series of the UTM
 * projection needs atanh(e sin(phi)) (|arg| < 0.082), sinh of that,
 * asinh of a ratio and sinh/cosh of 2j eta' (j <= 6, |eta'| < 0.2), all
 * well inside these domains; geodesy asks for 1e-11 relative, these give
 * about 1e-17 absolute.
 *
 * Method: exp by range reduction x = k ln 2 + r, |r| <= ln 2 / 2, and a
 * Taylor series in Q62; logarithms as e ln 2 + 2 atanh(s) with the
 * mantissa in [1/sqrt 2, sqrt 2), |s| <= 3 - 2 sqrt 2, by the atanh
 * series in Q62. Every product is a rounded 64 x 64 -> 128-bit product.
 * Errors are absolute, in LSB of Q5.58 (2^-58), against mpmath at 60
 * digits rounded to nearest (tests/ref/gen_fixed_hyper.py), measured on a
 * grid over each domain and random arguments.
 * @{
 */

/**
 * sinh(x) in Q5.58.
 *
 * @param x Q5.58, |x| <= asinh(32 - 2^-58) = 4.15912713...
 * @param[out] out sinh(x); unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_OVERFLOW |sinh(x)| does not fit Q5.58
 *
 * Accuracy: max error 3 LSB (1.0e-17; relative 2e-19 where it occurs,
 * at |sinh| ~ 28) for |x| <= 4.159. Measured on 634 stored points and
 * 25 000 random host trials.
 */
drdc_status_t drdc_fx_sinh_q5_58(drdc_q5_58_t x, drdc_q5_58_t *out);

/**
 * cosh(x) in Q5.58.
 *
 * @param x Q5.58, |x| <= acosh(32 - 2^-58) = 4.15863885...
 * @param[out] out cosh(x), >= 1; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_OVERFLOW cosh(x) does not fit Q5.58
 *
 * Accuracy: max error 3 LSB (1.0e-17) for |x| <= 4.158. Measured as
 * for sinh.
 */
drdc_status_t drdc_fx_cosh_q5_58(drdc_q5_58_t x, drdc_q5_58_t *out);

/**
 * atanh(x) in Q5.58.
 *
 * @param x Q5.58, -1 < x < 1 (|raw| < 2^58)
 * @param[out] out atanh(x), |.| <= 20.5; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_DOMAIN |x| >= 1
 *
 * Accuracy: max error 1 LSB (3.5e-18) over the whole domain; 612
 * stored points up to 1 - 2^-58 and 25 000 random host trials.
 */
drdc_status_t drdc_fx_atanh_q5_58(drdc_q5_58_t x, drdc_q5_58_t *out);

/**
 * asinh(x) in Q5.58 for every Q5.58 x (|asinh| <= 4.16); never fails but
 * for a NULL output.
 *
 * @param x any Q5.58 value
 * @param[out] out asinh(x)
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 *
 * Accuracy: max error 1 LSB (3.5e-18) over the whole domain; 612
 * stored points including INT64_MIN and INT64_MAX, 25 000 random host
 * trials.
 */
drdc_status_t drdc_fx_asinh_q5_58(drdc_q5_58_t x, drdc_q5_58_t *out);

/** @} */

#endif /* DRDC_FIXED_HYPER_H */
