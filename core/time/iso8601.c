/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time_iso8601
 * @brief ISO 8601 UTC text in and out, without libc.
 */
#include <drdc/time_iso8601.h>

#include "time_impl.h"

#define MAX_DIGITS 9
/* "YYYY-MM-DDTHH:MM:SS" + "Z" + NUL */
#define BASE_SIZE 21

/* Write `n` decimal digits of v (0 <= v < 10^n), most significant first;
 * return the position after them. */
static char *put_digits(char *p, int32_t v, int32_t n)
{
  int32_t rest = v;
  int32_t i;

  for (i = n - 1; i >= 0; i--) {
    p[i] = (char)('0' + (rest % 10));
    rest /= 10;
  }
  return &p[n];
}

/* Write the character ch; return the position after it. */
static char *put_char(char *p, char ch)
{
  p[0] = ch;
  return &p[1];
}

drdc_status_t drdc_time_iso8601_format(const drdc_time_leap_t *leap,
                                       const drdc_time_t *utc, int32_t digits,
                                       char *buf, size_t size)
{
  static const int32_t pow10[MAX_DIGITS + 1] = {
      1,      10,      100,      1000,      10000,
      100000, 1000000, 10000000, 100000000, 1000000000};
  drdc_time_civil_t c;
  drdc_status_t st;
  size_t need;
  char *p;

  if (buf == NULL) {
    return DRDC_E_NULL;
  }
  if ((digits < 0) || (digits > MAX_DIGITS)) {
    return DRDC_E_RANGE;
  }
  need = (size_t)BASE_SIZE + ((digits > 0) ? ((size_t)digits + 1u) : 0u);
  st = drdc_time_to_civil(leap, utc, &c);
  if (st != DRDC_OK) {
    return st;
  }
  if (size < need) {
    return DRDC_E_BUFFER;
  }
  p = put_digits(buf, c.year, 4); /* DRDC_YEAR_MAX has four digits */
  p = put_char(p, '-');
  p = put_digits(p, c.month, 2);
  p = put_char(p, '-');
  p = put_digits(p, c.day, 2);
  p = put_char(p, 'T');
  p = put_digits(p, c.hour, 2);
  p = put_char(p, ':');
  p = put_digits(p, c.minute, 2);
  p = put_char(p, ':');
  p = put_digits(p, c.second, 2);
  if (digits > 0) {
    p = put_char(p, '.');
    p = put_digits(p, c.nsec / pow10[MAX_DIGITS - digits], digits);
  }
  p = put_char(p, 'Z');
  *p = '\0';
  return DRDC_OK;
}

/* Read exactly n digits; -1 if one is not a digit (NUL included). */
static int32_t get_digits(const char *p, int32_t n)
{
  int32_t v = 0;
  int32_t i;

  for (i = 0; i < n; i++) {
    if ((p[i] < '0') || (p[i] > '9')) {
      return -1;
    }
    v = (v * 10) + (p[i] - '0');
  }
  return v;
}

drdc_status_t drdc_time_iso8601_parse(const drdc_time_leap_t *leap,
                                      const char *text, drdc_time_t *utc)
{
  /* Field positions in "YYYY-MM-DDTHH:MM:SS": start, width, and the
   * separator that follows it. */
  static const struct {
    uint8_t at;
    uint8_t width;
    char after;
  } fields[6] = {{0, 4, '-'},  {5, 2, '-'},  {8, 2, 'T'},
                 {11, 2, ':'}, {14, 2, ':'}, {17, 2, '\0'}};
  int32_t v[6];
  drdc_time_civil_t c;
  const char *p;
  int32_t i;

  if ((text == NULL) || (utc == NULL)) {
    return DRDC_E_NULL;
  }
  /* The scan stops at the first mismatch, so it never reads past the
   * string's NUL. */
  for (i = 0; i < 6; i++) {
    char after;

    v[i] = get_digits(&text[fields[i].at], fields[i].width);
    if (v[i] < 0) {
      return DRDC_E_SYNTAX;
    }
    after = fields[i].after;
    if ((after != '\0') && (text[fields[i].at + fields[i].width] != after)) {
      return DRDC_E_SYNTAX;
    }
  }
  p = &text[19];
  c.nsec = 0;
  if (*p == '.') {
    int32_t n = 0;

    p++;
    while ((*p >= '0') && (*p <= '9')) {
      if (n == MAX_DIGITS) {
        return DRDC_E_SYNTAX; /* finer than a nanosecond */
      }
      c.nsec = (c.nsec * 10) + (*p - '0');
      n++;
      p++;
    }
    if (n == 0) {
      return DRDC_E_SYNTAX;
    }
    for (; n < MAX_DIGITS; n++) {
      c.nsec *= 10;
    }
  }
  if (*p != 'Z') {
    return DRDC_E_SYNTAX;
  }
  if (p[1] != '\0') {
    return DRDC_E_TRAILING;
  }
  c.year = v[0];
  c.month = v[1];
  c.day = v[2];
  c.hour = v[3];
  c.minute = v[4];
  c.second = v[5];
  return drdc_time_from_civil(leap, &c, utc);
}
