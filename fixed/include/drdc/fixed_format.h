/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_format
 * @brief Decimal text of fixed-point and 64-bit values, for firmware
 *        whose printf has no %lld and no floating point.
 */
#ifndef DRDC_FIXED_FORMAT_H
#define DRDC_FIXED_FORMAT_H

#include <stddef.h>
#include <stdint.h>

#include <drdc/status.h>

/**
 * @defgroup drdc_fixed_format Decimal text
 *
 * newlib-nano's printf, the one small firmware links, has neither %lld
 * nor floating point. drdc_fx_format() writes any of the library's
 * integer and Q-format values as decimal text: drdc_q47_16_t metres with
 * frac_bits 16, drdc_q1_30_t with 30, drdc_nas_t or any 64-bit count with
 * 0. The scale is a power of two only: decimals of an integer are zeros,
 * so a value in nas, nanoseconds or millimetres prints in those units.
 * @{
 */

/** Characters of the longest text drdc_fx_format() writes, with its NUL:
 *  a sign, 19 integer digits, a point, 18 decimals and the NUL. */
#define DRDC_FX_FORMAT_MAX 40

/**
 * Decimal text of value / 2^frac_bits, rounded to `decimals` digits after
 * the point, ties away from zero; no point when decimals is 0. A minus
 * sign precedes a negative value whose rounded text is not zero ("-0.50",
 * but "0.00" for -0.001 at two decimals). No leading zeros but the one
 * before the point.
 *
 * Exact: the text is the correctly rounded value for every input
 * (integer arithmetic on the magnitude; tests/fixed/test_format.c against
 * Python's exact fractions, tests/ref/gen_fixed_format.py).
 *
 * @param value     the raw integer, any int64_t
 * @param frac_bits its fraction bits, 0..60 (0: an integer)
 * @param decimals  digits after the point, 0..18
 * @param[out] buf  the NUL-terminated text; unchanged on error
 * @param size      bytes at buf; DRDC_FX_FORMAT_MAX is always enough
 * @param[out] length characters written, without the NUL; may be NULL;
 *                  unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL buf is NULL
 * @retval DRDC_E_RANGE frac_bits above 60 or decimals above 18
 * @retval DRDC_E_BUFFER size is less than the text's length plus one;
 *         nothing was written
 *
 * Example: drdc_fx_format(-98304, 16, 3, buf, sizeof buf, NULL) writes
 * "-1.500" (-98304 / 65536 = -1.5).
 */
drdc_status_t drdc_fx_format(int64_t value, uint32_t frac_bits,
                             uint32_t decimals, char *buf, size_t size,
                             size_t *length);

/** @} */

#endif /* DRDC_FIXED_FORMAT_H */
