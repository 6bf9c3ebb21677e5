/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Number output on the board console, for images without printf.
 */
#ifndef DRDC_CONSOLE_H
#define DRDC_CONSOLE_H

#include <stdint.h>

/** Write `value` in decimal. */
void console_put_u64(uint64_t value);
/** Write `value` in decimal with a leading '-' when negative. */
void console_put_i64(int64_t value);
/** Write value / 10^decimals in decimal with exactly `decimals` digits
 *  after the point (0..18), e.g. (-12345, 3) -> "-12.345". */
void console_put_decimal(int64_t value, unsigned decimals);

/** Write `value` as 0x followed by 8 lower-case hex digits. */
void console_put_hex32(uint32_t value);

#endif /* DRDC_CONSOLE_H */
