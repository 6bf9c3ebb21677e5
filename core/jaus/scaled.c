/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_jaus_scaled
 * @brief JAUS scaled integers (RA 3.x and AS6009) with one symmetric
 *        rounding.
 */
#include <stddef.h>

#include <drdc/jaus_scaled.h>

drdc_status_t drdc_jaus_scaled_range(drdc_jaus_type_t type,
                                     drdc_jaus_form_t form, int64_t *ilo,
                                     int64_t *ihi)
{
  /* bits of each drdc_jaus_type_t, and whether it is signed */
  static const uint8_t type_bits[] = {8u, 8u, 16u, 16u, 32u, 32u};
  static const uint8_t type_signed[] = {1u, 0u, 1u, 0u, 1u, 0u};
  unsigned t = (unsigned)type;
  int64_t half;

  if ((ilo == NULL) || (ihi == NULL)) {
    return DRDC_E_NULL;
  }
  if ((t >= (unsigned)(sizeof(type_bits) / sizeof(type_bits[0]))) ||
      ((form != DRDC_JAUS_FORM_RA3) && (form != DRDC_JAUS_FORM_AS6009))) {
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
 * The mapping is exact rational arithmetic on one factor below 2^32: the
 * integer span ihi - ilo of a JAUS type is at most 2^32 - 1. Encoding
 * takes (value - min) (ihi - ilo) / (max - min), decoding
 * (integer - ilo) (max - min) / (ihi - ilo); in both the other factor is
 * brought to at most the divisor first, so a 64-bit remainder and the
 * 32 steps of Horner's rule give the quotient and remainder exactly,
 * without a 128-bit product, a 128-bit division or any call: the scaling
 * is a leaf, which keeps the pose functions' stack small.
 */

/*
 * floor(a b / r) and its remainder (*rem) for a < 2^32, 0 <= b <= r and
 * 0 < r < 2^63, by Horner's rule over the bits of a: the partial product
 * is Q r + R with 0 <= R < r; doubling gives 2 R < 2 r < 2^64 and adding
 * b gives R + b < 2 r, so each step needs one conditional subtraction.
 * The quotient is at most a.
 */
static uint64_t mul_div_small(uint32_t a, uint64_t b, uint64_t r, uint64_t *rem)
{
  uint64_t q = 0u;
  uint64_t x = 0u;
  unsigned k;

  for (k = 32u; k > 0u; k--) {
    q <<= 1;
    x <<= 1;
    if (x >= r) {
      x -= r;
      q++;
    }
    if (((a >> (k - 1u)) & 1u) != 0u) {
      x += b;
      if (x >= r) {
        x -= r;
        q++;
      }
    }
  }
  *rem = x;
  return q;
}

/*
 * c + q + rem / r (0 <= rem < r) rounded to nearest, ties away from zero
 * on the whole sum: up when 2 rem > r, and for a tie (2 rem = r) when
 * c + q >= 0. The result lies between c and c + q + 1, which the callers'
 * bounds keep inside the target range.
 */
static int64_t round_sum(int64_t c, uint64_t q, uint64_t rem, uint64_t r)
{
  int64_t sum = c + (int64_t)q;
  uint64_t rest = r - rem; /* > 0 */

  if ((rem > rest) || ((rem == rest) && (sum >= 0))) {
    sum += 1;
  }
  return sum;
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

/* One body for each direction: the saturating form, which validates, then
 * clamps an outside input (statuses in the plain form's order, with
 * DRDC_W_SATURATED last). The plain forms refuse an outside input first
 * and are otherwise a sibling call of it, which then cannot saturate.
 * Refusing first does not change a status: every failure of the
 * validation but a NULL output is DRDC_E_RANGE, as an outside input is,
 * and a NULL output is left to the body's first test. */
drdc_status_t drdc_jaus_scaled_encode_sat(int64_t value, int64_t min,
                                          int64_t max, drdc_jaus_type_t type,
                                          drdc_jaus_form_t form,
                                          int64_t *integer)
{
  int64_t span = 0;
  int64_t ilo = 0;
  int64_t ihi = 0;
  int64_t offset;
  int64_t width;
  uint64_t q;
  uint64_t rem = 0u;
  drdc_status_t st;

  if (integer == NULL) {
    return DRDC_E_NULL;
  }
  st = check(min, max, type, form, &span, &ilo, &ihi);
  if (st != DRDC_OK) {
    return st;
  }
  if ((value < min) || (value > max)) {
    *integer = (value < min) ? ilo : ihi;
    return DRDC_W_SATURATED;
  }
  /* value - min <= span, ihi - ilo < 2^32 */
  offset = value - min;
  width = ihi - ilo;
  q = mul_div_small((uint32_t)width, (uint64_t)offset, (uint64_t)span, &rem);
  *integer = round_sum(ilo, q, rem, (uint64_t)span);
  return DRDC_OK;
}

drdc_status_t drdc_jaus_scaled_encode(int64_t value, int64_t min, int64_t max,
                                      drdc_jaus_type_t type,
                                      drdc_jaus_form_t form, int64_t *integer)
{
  if ((integer != NULL) && ((value < min) || (value > max))) {
    return DRDC_E_RANGE;
  }
  return drdc_jaus_scaled_encode_sat(value, min, max, type, form, integer);
}

drdc_status_t drdc_jaus_scaled_decode_sat(int64_t integer, int64_t min,
                                          int64_t max, drdc_jaus_type_t type,
                                          drdc_jaus_form_t form, int64_t *value)
{
  int64_t span = 0;
  int64_t ilo = 0;
  int64_t ihi = 0;
  int64_t offset;
  int64_t width;
  uint64_t r;
  uint64_t whole;
  uint64_t part;
  uint64_t q;
  uint64_t rem = 0u;
  drdc_status_t st;

  if (value == NULL) {
    return DRDC_E_NULL;
  }
  st = check(min, max, type, form, &span, &ilo, &ihi);
  if (st != DRDC_OK) {
    return st;
  }
  if ((integer < ilo) || (integer > ihi)) {
    *value = (integer < ilo) ? min : max;
    return DRDC_W_SATURATED;
  }
  /* span = whole r + part, part < r = ihi - ilo < 2^32; then
   * (integer - ilo) span / r = (integer - ilo) whole + (integer - ilo)
   * part / r, the first exact and at most span */
  offset = integer - ilo;
  width = ihi - ilo;
  r = (uint64_t)width;
  whole = (uint64_t)span / r;
  part = (uint64_t)span % r;
  q = mul_div_small((uint32_t)offset, part, r, &rem);
  q += (uint64_t)offset * whole;
  *value = round_sum(min, q, rem, r);
  return DRDC_OK;
}

drdc_status_t drdc_jaus_scaled_decode(int64_t integer, int64_t min, int64_t max,
                                      drdc_jaus_type_t type,
                                      drdc_jaus_form_t form, int64_t *value)
{
  int64_t ilo = 0;
  int64_t ihi = 0;

  if (value != NULL) {
    /* no [ilo, ihi] (a bad type or form): the body's DRDC_E_RANGE */
    if ((drdc_jaus_scaled_range(type, form, &ilo, &ihi) == DRDC_OK) &&
        ((integer < ilo) || (integer > ihi))) {
      return DRDC_E_RANGE;
    }
  }
  return drdc_jaus_scaled_decode_sat(integer, min, max, type, form, value);
}
