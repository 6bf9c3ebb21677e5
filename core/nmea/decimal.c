/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief [-]digits[.digits] -> an exact int64_t mantissa and 10^decimals.
 */
#include "nmea_impl.h"

/* Digits of a decimal mantissa that int64_t always holds. */
#define DECIMAL_DIGITS_MAX 18u
/* Decimals of a number converted with a scale: 3600 x 10^15 < 2^63. */
#define DECIMALS_MAX 15u

drdc_status_t drdc__nmea_decimal(const char *p, size_t n, int64_t *mantissa,
                                 int64_t *scale)
{
  size_t i = 0u;
  size_t digits = 0u;
  size_t after = 0u;
  int point = 0;
  int negative = 0;
  int64_t m = 0;
  int64_t p10 = 1;

  if (n == 0u) {
    return DRDC_E_MISSING_FIELD;
  }
  if (p[0] == '-') {
    negative = 1;
    i = 1u;
  }
  for (; i < n; i++) {
    char c = p[i];

    if ((c == '.') && (point == 0)) {
      point = 1;
    } else if ((c >= '0') && (c <= '9')) {
      if (digits == DECIMAL_DIGITS_MAX) {
        return DRDC_E_RANGE;
      }
      m = (m * 10) + ((int64_t)c - (int64_t)'0');
      digits++;
      if (point != 0) {
        after++;
        p10 *= 10; /* at most 10^18: digits <= 18 */
      }
    } else {
      return DRDC_E_SYNTAX;
    }
  }
  if (digits == 0u) {
    return DRDC_E_SYNTAX;
  }
  if (after > DECIMALS_MAX) {
    return DRDC_E_RANGE;
  }
  *mantissa = (negative != 0) ? -m : m;
  *scale = p10;
  return DRDC_OK;
}
