/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_format
 * @brief drdc_fx_format(): decimal text of a fixed-point value.
 */
#include <drdc/fixed_format.h>

#include <stdbool.h>

/* Fraction bits and decimals the arithmetic below allows: the fraction
 * f < 2^60 times 10 stays below 2^64, and 18 decimals of it fit the text. */
#define FORMAT_FRAC_BITS_MAX 60u
#define FORMAT_DECIMALS_MAX  18u
/* Decimal digits of the largest integer part, 2^63 (after rounding up). */
#define FORMAT_INTEGER_DIGITS_MAX 19u

/* The magnitude's text in `text` (room for DRDC_FX_FORMAT_MAX - 1
 * characters), without its sign or NUL; returns its length. */
static size_t magnitude_text(uint64_t integer_part, uint64_t fraction_part,
                             uint32_t frac_bits, uint32_t decimals, char *text)
{
  /* decimal digits by value, without arithmetic on characters */
  static const char digits[] = "0123456789";
  uint8_t digit[FORMAT_DECIMALS_MAX];
  char reversed[FORMAT_INTEGER_DIGITS_MAX + 1u];
  uint64_t mask = (frac_bits == 0u) ? 0u : ((UINT64_C(1) << frac_bits) - 1u);
  uint64_t integer = integer_part;
  uint64_t fraction = fraction_part;
  bool carry = false;
  size_t n = 0u;
  size_t k = 0u;
  uint32_t i;

  /* One decimal a step: the fraction f / 2^frac_bits times 10. */
  for (i = 0u; i < decimals; i++) {
    fraction *= 10u;
    digit[i] = (uint8_t)(fraction >> frac_bits);
    fraction &= mask;
  }
  /* The rest decides the rounding, ties away from zero (on the
   * magnitude): up when rest / 2^frac_bits >= 1/2. */
  if ((frac_bits != 0u) && ((fraction << 1) >= (UINT64_C(1) << frac_bits))) {
    carry = true;
    for (i = decimals; carry && (i > 0u); i--) {
      digit[i - 1u]++;
      carry = (digit[i - 1u] == 10u);
      if (carry) {
        digit[i - 1u] = 0u;
      }
    }
  }
  if (carry) {
    integer++;
  }
  do {
    reversed[k] = digits[integer % 10u];
    k++;
    integer /= 10u;
  } while (integer != 0u);
  while (k > 0u) {
    k--;
    text[n] = reversed[k];
    n++;
  }
  if (decimals > 0u) {
    text[n] = '.';
    n++;
    for (i = 0u; i < decimals; i++) {
      text[n] = digits[digit[i]];
      n++;
    }
  }
  return n;
}

static bool all_zero(const char *text, size_t n)
{
  size_t i;

  for (i = 0u; i < n; i++) {
    if ((text[i] != '0') && (text[i] != '.')) {
      return false;
    }
  }
  return true;
}

drdc_status_t drdc_fx_format(int64_t value, uint32_t frac_bits,
                             uint32_t decimals, char *buf, size_t size,
                             size_t *length)
{
  char text[DRDC_FX_FORMAT_MAX];
  /* the magnitude, INT64_MIN included, without a signed negation */
  uint64_t magnitude = (value < 0) ? (0u - (uint64_t)value) : (uint64_t)value;
  uint64_t integer;
  uint64_t fraction;
  size_t n;
  size_t i;
  bool negative;

  if (buf == NULL) {
    return DRDC_E_NULL;
  }
  if ((frac_bits > FORMAT_FRAC_BITS_MAX) || (decimals > FORMAT_DECIMALS_MAX)) {
    return DRDC_E_RANGE;
  }
  integer = magnitude >> frac_bits;
  fraction =
      (frac_bits == 0u) ? 0u : (magnitude & ((UINT64_C(1) << frac_bits) - 1u));
  n = magnitude_text(integer, fraction, frac_bits, decimals, &text[1]);
  negative = (value < 0) && !all_zero(&text[1], n);
  if (negative) {
    text[0] = '-';
    n++;
  }
  if (size < (n + 1u)) {
    return DRDC_E_BUFFER;
  }
  for (i = 0u; i < n; i++) {
    buf[i] = negative ? text[i] : text[i + 1u];
  }
  buf[n] = '\0';
  if (length != NULL) {
    *length = n;
  }
  return DRDC_OK;
}
