/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_jaus_scaled
 * @brief JAUS scaled integers (RA 3.x and AS6009) with one symmetric
 *        rounding.
 */
#include <stddef.h>

#include <drdc/fixed_arith.h>
#include <drdc/jaus_scaled.h>

/* Greatest common divisor of two positive values (Euclid). */
static int64_t gcd_pos(int64_t a, int64_t b)
{
  int64_t x = a;
  int64_t y = b;

  while (y != 0) {
    int64_t r = x % y;

    x = y;
    y = r;
  }
  return x;
}

drdc_status_t drdc_jaus_scaled_range(drdc_jaus_type_t type,
                                     drdc_jaus_form_t form, int64_t *ilo,
                                     int64_t *ihi)
{
  /* bits of each drdc_jaus_type_t, and whether it is signed */
  static const uint8_t type_bits[] = { 8u, 8u, 16u, 16u, 32u, 32u };
  static const uint8_t type_signed[] = { 1u, 0u, 1u, 0u, 1u, 0u };
  unsigned t = (unsigned)type;
  int64_t half;

  if ((ilo == NULL) || (ihi == NULL)) {
    return DRDC_E_NULL;
  }
  if ((t >= (unsigned)(sizeof(type_bits) / sizeof(type_bits[0])))
      || ((form != DRDC_JAUS_FORM_RA3) && (form != DRDC_JAUS_FORM_AS6009))) {
    return DRDC_E_RANGE;
  }
  if (type_signed[t] == 0u) {
    *ilo = 0;
    *ihi = (INT64_C(1) << type_bits[t]) - 1;
  } else {
    half = INT64_C(1) << (type_bits[t] - 1u);
    /* RA 3.x leaves the most negative integer out: symmetric range */
    *ilo = (form == DRDC_JAUS_FORM_RA3) ? (1 - half) : -half;
    *ihi = half - 1;
  }
  return DRDC_OK;
}

/*
 * c + p x q / r rounded to nearest, ties away from zero on the whole sum,
 * for c any integer, p >= 0, q > 0, r > 0. drdc_fx_muldiv_s64 rounds
 * p q / r (>= 0) with ties upwards; that is wrong only when the sum is a
 * tie below zero, which then rounds down instead. p q / r is a tie iff
 * 2 p q' / r' is odd (q' = q / g, r' = r / g, g = gcd(q, r)): r' even,
 * k = p / (r' / 2) a whole odd number, and q' odd. The result lies
 * between c and c + p q / r, so it fits whenever those do.
 */
static drdc_status_t round_affine(int64_t c, int64_t p, int64_t q, int64_t r,
                                  int64_t *out)
{
  int64_t m = 0;
  int64_t g = gcd_pos(q, r);
  int64_t q1 = q / g;
  int64_t r1 = r / g;
  int64_t sum;
  drdc_status_t st = drdc_fx_muldiv_s64(p, q, r, &m);

  if (st != DRDC_OK) {
    return st;
  }
  sum = c + m;
  if (((r1 % 2) == 0) && ((q1 % 2) != 0) && ((p % (r1 / 2)) == 0)
      && (((p / (r1 / 2)) % 2) != 0) && (sum <= 0)) {
    sum -= 1;
  }
  *out = sum;
  return DRDC_OK;
}

/* Validate the bounds and the type; the span max - min and [ilo, ihi]. */
static drdc_status_t check(int64_t min, int64_t max, drdc_jaus_type_t type,
                          drdc_jaus_form_t form, int64_t *span, int64_t *ilo,
                          int64_t *ihi)
{
  drdc_status_t st = drdc_jaus_scaled_range(type, form, ilo, ihi);

  if (st != DRDC_OK) {
    return st;
  }
  /* max - min must be positive and fit: no overflow when min >= 0 or
   * max < min + INT64_MAX */
  if ((min >= max) || ((min < 0) && (max > (INT64_MAX + min)))) {
    return DRDC_E_RANGE;
  }
  *span = max - min;
  return DRDC_OK;
}

static drdc_status_t encode(int64_t value, int64_t min, int64_t max,
                            drdc_jaus_type_t type, drdc_jaus_form_t form,
                            int sat, int64_t *integer)
{
  int64_t span = 0;
  int64_t ilo = 0;
  int64_t ihi = 0;
  drdc_status_t st;

  if (integer == NULL) {
    return DRDC_E_NULL;
  }
  st = check(min, max, type, form, &span, &ilo, &ihi);
  if (st != DRDC_OK) {
    return st;
  }
  if ((value < min) || (value > max)) {
    if (sat == 0) {
      return DRDC_E_RANGE;
    }
    *integer = (value < min) ? ilo : ihi;
    return DRDC_W_SATURATED;
  }
  return round_affine(ilo, value - min, ihi - ilo, span, integer);
}

static drdc_status_t decode(int64_t integer, int64_t min, int64_t max,
                            drdc_jaus_type_t type, drdc_jaus_form_t form,
                            int sat, int64_t *value)
{
  int64_t span = 0;
  int64_t ilo = 0;
  int64_t ihi = 0;
  drdc_status_t st;

  if (value == NULL) {
    return DRDC_E_NULL;
  }
  st = check(min, max, type, form, &span, &ilo, &ihi);
  if (st != DRDC_OK) {
    return st;
  }
  if ((integer < ilo) || (integer > ihi)) {
    if (sat == 0) {
      return DRDC_E_RANGE;
    }
    *value = (integer < ilo) ? min : max;
    return DRDC_W_SATURATED;
  }
  return round_affine(min, integer - ilo, span, ihi - ilo, value);
}

drdc_status_t drdc_jaus_scaled_encode(int64_t value, int64_t min, int64_t max,
                                      drdc_jaus_type_t type,
                                      drdc_jaus_form_t form, int64_t *integer)
{
  return encode(value, min, max, type, form, 0, integer);
}

drdc_status_t drdc_jaus_scaled_encode_sat(int64_t value, int64_t min,
                                          int64_t max, drdc_jaus_type_t type,
                                          drdc_jaus_form_t form,
                                          int64_t *integer)
{
  return encode(value, min, max, type, form, 1, integer);
}

drdc_status_t drdc_jaus_scaled_decode(int64_t integer, int64_t min,
                                      int64_t max, drdc_jaus_type_t type,
                                      drdc_jaus_form_t form, int64_t *value)
{
  return decode(integer, min, max, type, form, 0, value);
}

drdc_status_t drdc_jaus_scaled_decode_sat(int64_t integer, int64_t min,
                                          int64_t max, drdc_jaus_type_t type,
                                          drdc_jaus_form_t form,
                                          int64_t *value)
{
  return decode(integer, min, max, type, form, 1, value);
}
