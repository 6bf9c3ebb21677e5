/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Console helpers shared by every board: strings and numbers without
 *        printf, so bare-metal images need no C library.
 */
#include "console.h"

#include "drdc_board.h"

void bsp_puts(const char *s)
{
  while (*s != '\0') {
    bsp_putc(*s);
    s++;
  }
}

void console_put_u64(uint64_t value)
{
  char digits[20];
  unsigned n = 0;

  do {
    digits[n] = (char)('0' + (int)(value % 10u));
    value /= 10u;
    n++;
  } while (value != 0u);
  while (n > 0u) {
    n--;
    bsp_putc(digits[n]);
  }
}

void console_put_i64(int64_t value)
{
  if (value < 0) {
    bsp_putc('-');
    /* Negate in unsigned arithmetic: INT64_MIN has no positive twin. */
    console_put_u64(0u - (uint64_t)value);
  } else {
    console_put_u64((uint64_t)value);
  }
}

void console_put_decimal(int64_t value, unsigned decimals)
{
  uint64_t magnitude;
  uint64_t scale = 1u;
  uint64_t fraction;
  unsigned i;

  if (value < 0) {
    bsp_putc('-');
    magnitude = 0u - (uint64_t)value;
  } else {
    magnitude = (uint64_t)value;
  }
  for (i = 0u; (i < decimals) && (i < 18u); i++) {
    scale *= 10u;
  }
  console_put_u64(magnitude / scale);
  if (scale == 1u) {
    return;
  }
  bsp_putc('.');
  fraction = magnitude % scale;
  /* leading zeros of the fraction */
  for (scale /= 10u; scale > fraction; scale /= 10u) {
    if (scale == 1u) {
      break;
    }
    bsp_putc('0');
  }
  console_put_u64(fraction);
}

void console_put_hex32(uint32_t value)
{
  static const char hex[] = "0123456789abcdef";
  int shift;

  bsp_puts("0x");
  for (shift = 28; shift >= 0; shift -= 4) {
    bsp_putc(hex[(value >> shift) & 0xFu]);
  }
}
