/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief Integer-only parsers of NMEA fields: unsigned integers, decimal
 *        numbers to fixed point (one rounding), time of day and
 *        latitude/longitude to nano-arcseconds (exact).
 */
#include <drdc/fixed_arith.h>

#include "nmea_impl.h"

/* Decimals of minutes kept exactly: 1e-10 minute = 6 nas. */
#define MINUTE_DECIMALS_MAX 10u
#define NAS_PER_MINUTE      INT64_C(60000000000)

static int is_digit(char c)
{
  return ((c >= '0') && (c <= '9')) ? 1 : 0;
}

static int64_t digit(char c)
{
  return (int64_t)c - (int64_t)'0';
}

static int64_t pow10_s64(size_t n)
{
  int64_t p = 1;
  size_t i;

  for (i = 0u; i < n; i++) {
    p *= 10;
  }
  return p;
}

drdc_status_t drdc__nmea_digits(const char *p, size_t n, size_t min_digits,
                                size_t max_digits, int32_t *out)
{
  int32_t v = 0;
  size_t i;

  if (n == 0u) {
    return DRDC_E_MISSING_FIELD;
  }
  if ((n < min_digits) || (n > max_digits)) {
    return DRDC_E_SYNTAX;
  }
  for (i = 0u; i < n; i++) {
    if (is_digit(p[i]) == 0) {
      return DRDC_E_SYNTAX;
    }
    v = (v * 10) + (int32_t)digit(p[i]);
  }
  if (out != NULL) {
    *out = v;
  }
  return DRDC_OK;
}

drdc_status_t drdc__nmea_uint(const nmea_frame_t *fr, size_t i,
                              size_t min_digits, size_t max_digits,
                              int32_t *out)
{
  nmea_field_t f = nmea_field(fr, i);

  return drdc__nmea_digits(f.p, f.n, min_digits, max_digits, out);
}

drdc_status_t drdc__nmea_fixed(const nmea_frame_t *fr, size_t i,
                               nmea_scale_t scale, int64_t *out)
{
  /* num x 2^frac and den of each scale: metres x 2^16, knots x 1852 m /
   * 3600 s x 2^16, km/h x 1000 m / 3600 s x 2^16, degrees x 2^32 / 360 */
  static const int64_t scales[5][2] = {{INT64_C(65536), 1},
                                       {INT64_C(65536), 1},
                                       {INT64_C(121372672), 3600},
                                       {INT64_C(65536000), 3600},
                                       {INT64_C(4294967296), 360}};
  const int64_t *sc = scales[scale];
  int narrow = 0;
  nmea_field_t f = nmea_field(fr, i);
  int64_t m = 0;
  int64_t p10 = 1;
  int negative = 0;
  drdc_status_t st = drdc__nmea_decimal(f.p, f.n, &m, &p10);

  if ((scale == NMEA_METRES_Q15_16) || (scale == NMEA_KNOTS_Q15_16) ||
      (scale == NMEA_KMH_Q15_16)) {
    narrow = 1;
  }
  if (st != DRDC_OK) {
    return st;
  }
  if (m < 0) {
    negative = 1;
  }
  /* den x 10^15 < 2^63 for every scale (at most 15 decimals); the
   * product itself overflows int64_t only for a Q15.16 or degrees value
   * of 18 digits, far beyond int32_t */
  st = drdc_fx_muldiv_s64(m, sc[0], sc[1] * p10, &m);
  if ((narrow != 0) &&
      ((st != DRDC_OK) || (m > INT32_MAX) || (m < INT32_MIN))) {
    m = (negative != 0) ? INT32_MIN : INT32_MAX;
    st = DRDC_W_SATURATED;
  } else if (st != DRDC_OK) {
    return DRDC_E_RANGE;
  } else {
    /* in range */
  }
  if (out != NULL) {
    *out = m;
  }
  return st;
}

drdc_status_t drdc__nmea_q15_16(const nmea_frame_t *fr, size_t i,
                                nmea_scale_t scale, drdc_nmea_t *n,
                                drdc_q15_16_t *field, uint32_t has_bit,
                                uint32_t beyond_bit)
{
  int64_t v = 0;
  drdc_status_t st = drdc__nmea_fixed(fr, i, scale, &v);

  if ((st != DRDC_OK) && (st != DRDC_W_SATURATED)) {
    return st;
  }
  if (n != NULL) {
    *field = (drdc_q15_16_t)v; /* within int32_t: saturated above */
    n->has |= has_bit;
    if (st == DRDC_W_SATURATED) {
      n->beyond |= beyond_bit;
    }
  }
  return DRDC_OK;
}

drdc_status_t drdc__nmea_letter(const nmea_frame_t *fr, size_t i, char letter)
{
  nmea_field_t f = nmea_field(fr, i);
  drdc_status_t st = DRDC_OK;
  char c = '\0';

  if (f.n != 0u) {
    c = f.p[0];
  }
  if (f.n == 0u) {
    st = (fr->strict != 0u) ? DRDC_E_MISSING_FIELD : DRDC_OK;
  } else if ((f.n != 1u) || (c != letter)) {
    st = DRDC_E_SYNTAX;
  } else {
    st = DRDC_OK;
  }
  return st;
}

drdc_status_t drdc__nmea_tod(const nmea_frame_t *fr, size_t i_field,
                             drdc_nmea_tod_t *out)
{
  nmea_field_t f = nmea_field(fr, i_field);
  int32_t v[3] = {0, 0, 0};
  int32_t nsec = 0;
  size_t i;
  size_t k;
  const char *p = f.p;

  if (f.n == 0u) {
    return DRDC_E_MISSING_FIELD;
  }
  if ((f.n < 6u) ||
      ((f.n > 6u) && ((p[6] != '.') || (f.n == 7u) || (f.n > 16u)))) {
    return DRDC_E_SYNTAX;
  }
  for (i = 0u; i < 6u; i++) {
    if (is_digit(p[i]) == 0) {
      return DRDC_E_SYNTAX;
    }
    v[i / 2u] = (v[i / 2u] * 10) + (int32_t)digit(p[i]);
  }
  for (k = 7u; k < f.n; k++) {
    if (is_digit(p[k]) == 0) {
      return DRDC_E_SYNTAX;
    }
    nsec = (nsec * 10) + (int32_t)digit(p[k]);
  }
  for (k = f.n; k < 16u; k++) {
    if (k >= 7u) {
      nsec *= 10; /* fewer than 9 decimals: scale to nanoseconds */
    }
  }
  if (v[0] > 23) {
    return DRDC_E_HOUR;
  }
  if (v[1] > 59) {
    return DRDC_E_MINUTE;
  }
  if (v[2] > 60) {
    return DRDC_E_SECOND;
  }
  if (out != NULL) {
    out->hour = v[0];
    out->minute = v[1];
    out->second = v[2];
    out->nsec = nsec;
  }
  return DRDC_OK;
}

drdc_status_t drdc__nmea_angle(const nmea_frame_t *fr, size_t i_field,
                               int latitude, drdc_nas_t *out)
{
  nmea_field_t value = nmea_field(fr, i_field);
  nmea_field_t hemisphere = nmea_field(fr, i_field + 1u);
  size_t point = value.n;
  size_t i;
  int64_t degrees = 0;
  int64_t minutes = 0;
  int64_t fraction = 0;
  int64_t limit = 180;
  size_t max_int = 5u;
  char positive = 'E';
  char negative = 'W';
  char h;
  const char *vp = value.p;
  drdc_nas_t nas;

  if ((value.n == 0u) || (hemisphere.n == 0u)) {
    return DRDC_E_MISSING_FIELD;
  }
  if (latitude != 0) {
    limit = 90;
    max_int = 4u;
    positive = 'N';
    negative = 'S';
  }
  h = hemisphere.p[0];
  for (i = 0u; i < value.n; i++) {
    if ((vp[i] == '.') && (point == value.n)) {
      point = i;
    } else if (is_digit(vp[i]) == 0) {
      return DRDC_E_SYNTAX;
    } else {
      /* a digit */
    }
  }
  /* (d)ddmm: 3..max_int integer digits, the last two are minutes */
  if ((point < 3u) || (point > max_int) || (point == (value.n - 1u)) ||
      ((value.n - point) > (MINUTE_DECIMALS_MAX + 1u))) {
    return DRDC_E_SYNTAX;
  }
  if ((hemisphere.n != 1u) || ((h != positive) && (h != negative))) {
    return DRDC_E_SYNTAX;
  }
  for (i = 0u; i < (point - 2u); i++) {
    degrees = (degrees * 10) + digit(vp[i]);
  }
  minutes = (digit(vp[point - 2u]) * 10) + digit(vp[point - 1u]);
  for (i = point + 1u; i < value.n; i++) {
    fraction = (fraction * 10) + digit(vp[i]);
  }
  if (minutes >= 60) {
    return DRDC_E_MINUTE;
  }
  /* fraction of a minute in units of 1e-10 minute = 6 nas */
  if (value.n > point) {
    fraction *= pow10_s64((MINUTE_DECIMALS_MAX + point + 1u) - value.n);
  }
  nas = (degrees * DRDC_NAS_PER_DEGREE) + (minutes * NAS_PER_MINUTE) +
        (fraction * 6);
  if (nas > (limit * DRDC_NAS_PER_DEGREE)) {
    return DRDC_E_RANGE;
  }
  if (out != NULL) {
    *out = (h == negative) ? -nas : nas;
  }
  return DRDC_OK;
}

drdc_status_t drdc__nmea_fix(const nmea_frame_t *fr, size_t time,
                             size_t latitude, drdc_nmea_t *n)
{
  drdc_status_t st = drdc__nmea_tod(fr, time, (n != NULL) ? &n->time : NULL);

  if (st == DRDC_OK) {
    st = drdc__nmea_angle(fr, latitude, 1, (n != NULL) ? &n->latitude : NULL);
  }
  if (st == DRDC_OK) {
    st = drdc__nmea_angle(fr, latitude + 2u, 0,
                          (n != NULL) ? &n->longitude : NULL);
  }
  if ((st == DRDC_OK) && (n != NULL)) {
    n->has |= DRDC_NMEA_HAS_TIME | DRDC_NMEA_HAS_POSITION;
  }
  return st;
}
