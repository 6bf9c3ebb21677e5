/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_fix16
 * @brief Interop with libfixmath's fix16_t, without its header.
 */
#ifndef DRDC_FIXED_FIX16_H
#define DRDC_FIXED_FIX16_H

#include <stdint.h>

#include <drdc/fixed_types.h>
#include <drdc/status.h>

/**
 * @defgroup drdc_fixed_fix16 libfixmath interop
 *
 * libfixmath's fix16_t is an int32_t in Q15.16, the same bits as
 * drdc_q15_16_t; its fix16_one (0x00010000) is DRDC_Q15_16_ONE. The one
 * difference is the value 0x80000000: libfixmath returns it as
 * fix16_overflow from a failed operation (and also names it fix16_minimum,
 * -32768.0), so a fix16_t holding it cannot be trusted. These conversions
 * make that explicit: a fix16_t of 0x80000000 is reported as an overflow
 * coming in, and a Q15.16 value of -32768.0 is refused going out because
 * libfixmath code would read it as an overflow marker.
 *
 * Which libfixmath functions could replace ours (host measurements,
 * libfixmath 0~20220222 default configuration; docs/accuracy.md):
 * - fix16_mul (rounding build) gives exactly drdc_fx_mul_q15_16() wherever
 *   the product is in range (20 million random pairs). We still keep our
 *   own: its overflow result is the valid value 0x80000000, and fixed/
 *   must build without libfixmath.
 * - fix16_sqrt is within 0.501 LSB, not correctly rounded (it differs from
 *   drdc_fx_sqrt_q15_16() on 145 of 2.15 million inputs).
 * - fix16_sin/cos (max error 7.8e-3) and fix16_atan2 (wrong by up to pi/2
 *   for full-range int32 inputs) are far from the 1e-9 this library needs.
 * Firmware that already links libfixmath may keep using fix16_mul for
 *   in-range products; for everything else use the drdc_fx_ functions.
 * @{
 */

/**
 * libfixmath fix16_t -> Q15.16 (same bits).
 *
 * @param f a fix16_t value (pass the int32_t itself; no libfixmath header
 *          needed)
 * @param[out] out Q15.16 value, bit-identical to f; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_OVERFLOW f is 0x80000000, libfixmath's fix16_overflow
 */
drdc_status_t drdc_fx_q15_16_from_fix16(int32_t f, drdc_q15_16_t *out);

/**
 * Q15.16 -> libfixmath fix16_t (same bits).
 *
 * @param x Q15.16 value, (-32768, 32768) m
 * @param[out] out fix16_t value (int32_t), bit-identical to x; unchanged
 *             on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_RANGE x is INT32_MIN (-32768.0), which libfixmath
 *         cannot tell from fix16_overflow
 */
drdc_status_t drdc_fx_fix16_from_q15_16(drdc_q15_16_t x, int32_t *out);

/** @} */

#endif /* DRDC_FIXED_FIX16_H */
