/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Decimal text of the library's integers, one array at a time:
 *        Q formats through drdc_fx_format() (exactly, or rounded to a
 *        number of decimals), nano-arcseconds and binary angles as
 *        degrees, correctly rounded, ties away from zero (the library's
 *        rule and `drdc nmea`'s).
 *
 * Only python/build_backend.py compiles this file; drdc/_lib.py declares
 * the prototypes. Each text is a row of `width` bytes, NUL-padded
 * (numpy's "S" arrays); rows of an element whose status is an error are
 * all NUL.
 */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <drdc/fixed_format.h>

/** Bytes of a row of degrees: a sign, 20 digits, a point, up to 18
 *  decimals and the NUL fit. */
#define DEGREES_WIDTH 48u
#define DECIMALS_MAX  18u

/* value / 2^frac_bits with `decimals` decimals; with decimals < 0 the
 * exact value (frac_bits decimals, which 2^-frac_bits needs) without its
 * trailing zeros, nor a point when nothing follows it. */
void drdc_batch_format_fixed(size_t n, const int64_t *value, uint32_t frac_bits,
                             int32_t decimals, char *text, size_t width,
                             int32_t *status)
{
  int exact = (decimals < 0);
  uint32_t d = exact ? frac_bits : (uint32_t)decimals;
  size_t i;

  for (i = 0; i < n; i++) {
    char *row = &text[i * width];
    size_t length = 0u;
    drdc_status_t st;

    memset(row, 0, width);
    st = drdc_fx_format(value[i], frac_bits, d, row, width, &length);
    status[i] = (int32_t)st;
    if (st != DRDC_OK) {
      memset(row, 0, width);
      continue;
    }
    if (exact && (d > 0u)) {
      while (row[length - 1u] == '0') {
        length--;
        row[length] = '\0';
      }
      if (row[length - 1u] == '.') {
        length--;
        row[length] = '\0';
      }
    }
  }
}

/* magnitude / den (den > 0) with `decimals` decimals, rounded to nearest,
 * ties away from zero, and a '-' when `negative` and the rounded text is
 * not zero: long division, one decimal at a time (every remainder below
 * den, times 10 below 10 den, which fits for the denominators here). */
static void put_ratio(char *row, uint64_t magnitude, uint64_t den,
                      unsigned decimals, int negative)
{
  char digits[DECIMALS_MAX];
  char whole[24];
  uint64_t integer = magnitude / den;
  uint64_t rem = magnitude % den;
  size_t w = 0u;
  size_t k;
  size_t at = 0u;
  int nonzero;

  for (k = 0u; k < decimals; k++) {
    rem *= 10u;
    digits[k] = (char)('0' + (int)(rem / den));
    rem %= den;
  }
  /* round half away from zero on the magnitude */
  if (rem >= (den - rem)) {
    k = decimals;
    while (k > 0u) {
      k--;
      if (digits[k] != '9') {
        digits[k]++;
        break;
      }
      digits[k] = '0';
      if (k == 0u) {
        integer++;
      }
    }
    if (decimals == 0u) {
      integer++;
    }
  }
  nonzero = (integer != 0u);
  for (k = 0u; k < decimals; k++) {
    nonzero = nonzero || (digits[k] != '0');
  }
  do {
    whole[w] = (char)('0' + (int)(integer % 10u));
    integer /= 10u;
    w++;
  } while (integer != 0u);
  if (negative && nonzero) {
    row[at] = '-';
    at++;
  }
  while (w > 0u) {
    w--;
    row[at] = whole[w];
    at++;
  }
  if (decimals > 0u) {
    row[at] = '.';
    at++;
    memcpy(&row[at], digits, decimals);
    at += decimals;
  }
  row[at] = '\0';
}

/* nas / 3.6e12 = degrees, `decimals` 0..18 */
void drdc_batch_format_nas_degrees(size_t n, const int64_t *nas,
                                   int32_t decimals, char *text,
                                   int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    char *row = &text[i * DEGREES_WIDTH];
    int64_t v = nas[i];
    /* |INT64_MIN| as uint64_t without overflow */
    uint64_t magnitude = (v < 0) ? ((uint64_t)(-(v + 1)) + 1u) : (uint64_t)v;

    memset(row, 0, DEGREES_WIDTH);
    if ((decimals < 0) || ((uint32_t)decimals > DECIMALS_MAX)) {
      status[i] = (int32_t)DRDC_E_RANGE;
      continue;
    }
    status[i] = (int32_t)DRDC_OK;
    put_ratio(row, magnitude, UINT64_C(3600000000000), (unsigned)decimals,
              v < 0);
  }
}

/* bam x 360 / 2^32 = degrees in [0, 360), `decimals` 0..18 */
void drdc_batch_format_bam32_degrees(size_t n, const uint32_t *bam,
                                     int32_t decimals, char *text,
                                     int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    char *row = &text[i * DEGREES_WIDTH];

    memset(row, 0, DEGREES_WIDTH);
    if ((decimals < 0) || ((uint32_t)decimals > DECIMALS_MAX)) {
      status[i] = (int32_t)DRDC_E_RANGE;
      continue;
    }
    status[i] = (int32_t)DRDC_OK;
    put_ratio(row, (uint64_t)bam[i] * 360u, UINT64_C(4294967296),
              (unsigned)decimals, 0);
  }
}
