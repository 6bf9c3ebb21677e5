/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_units
 * @brief Exact int64_t rationals for unit factors (no rounding here: an
 *        operation whose exact result does not fit says so).
 */
#include "units_impl.h"

/* INT64_MAX as an unsigned constant */
#define INT64_MAX_U UINT64_C(0x7FFFFFFFFFFFFFFF)

/* Greatest common divisor by Euclid's algorithm; gcd(0, b) = b. */
static uint64_t gcd_u64(uint64_t a, uint64_t b)
{
  uint64_t x = a;
  uint64_t y = b;

  while (y != 0u) {
    uint64_t r = x % y;

    x = y;
    y = r;
  }
  return x;
}

/* |x| as uint64_t, defined for INT64_MIN too. */
static uint64_t abs_u64(int64_t x)
{
  uint64_t u = (uint64_t)x;

  if (x < 0) {
    u = 0u - u;
  }
  return u;
}

/* gcd of |a| and |b| as int64_t; 1 when both are 0. The result is at
 * most |b| for b != 0, so it fits whenever b != INT64_MIN. */
static int64_t gcd_s64(int64_t a, int64_t b)
{
  uint64_t g = gcd_u64(abs_u64(a), abs_u64(b));

  if ((g == 0u) || (g > (uint64_t)INT64_MAX)) {
    g = 1u;
  }
  return (int64_t)g;
}

drdc_status_t drdc__units_mul_s64(int64_t x, int64_t y, int64_t *out)
{
  uint64_t ux = abs_u64(x);
  uint64_t uy = abs_u64(y);
  int negative = 0;
  uint64_t product;

  /* The product must stay within +-INT64_MAX (INT64_MIN is never needed
   * by the callers and keeps the negation below defined). */
  if ((ux != 0u) && (uy > (INT64_MAX_U / ux))) {
    return DRDC_E_RANGE;
  }
  if ((x < 0) != (y < 0)) {
    negative = 1;
  }
  product = ux * uy;
  if (negative != 0) {
    *out = -(int64_t)product;
  } else {
    *out = (int64_t)product;
  }
  return DRDC_OK;
}

drdc_status_t drdc__units_rat_scale(const units_rat_t *a, int64_t num,
                                    int64_t den, units_rat_t *out)
{
  int64_t g1 = gcd_s64(a->num, den);
  int64_t g2 = gcd_s64(num, a->den);
  int64_t n;
  int64_t d;

  if ((a->num < -INT64_MAX) || (num < -INT64_MAX) || (a->den <= 0) ||
      (den <= 0)) {
    return DRDC_E_RANGE;
  }
  if (drdc__units_mul_s64(a->num / g1, num / g2, &n) != DRDC_OK) {
    return DRDC_E_RANGE;
  }
  if (drdc__units_mul_s64(a->den / g2, den / g1, &d) != DRDC_OK) {
    return DRDC_E_RANGE;
  }
  out->num = n;
  out->den = d;
  return DRDC_OK;
}

drdc_status_t drdc__units_rat_inv(const units_rat_t *a, units_rat_t *out)
{
  int64_t num = a->num;
  int64_t den = a->den;

  if ((num == 0) || (num < -INT64_MAX) || (den <= 0)) {
    return DRDC_E_RANGE;
  }
  if (num < 0) {
    out->num = -den;
    out->den = -num;
  } else {
    out->num = den;
    out->den = num;
  }
  return DRDC_OK;
}

drdc_status_t drdc__units_rat_sub(int64_t a_num, int64_t a_den,
                                  const units_rat_t *b, units_rat_t *out)
{
  /* a/b - c/d = (a (d/g) - c (b/g)) / (b/g d), g = gcd(b, d). The
   * products are read only after all three succeeded, which GCC 13 does
   * not see through the || chain (-Wmaybe-uninitialized): they start at
   * 0. */
  int64_t g;
  int64_t left = 0;
  int64_t right = 0;
  int64_t den = 0;
  int64_t num;
  int64_t r;

  if ((a_den <= 0) || (b->den <= 0)) {
    return DRDC_E_RANGE;
  }
  g = gcd_s64(a_den, b->den);
  if ((drdc__units_mul_s64(a_num, b->den / g, &left) != DRDC_OK) ||
      (drdc__units_mul_s64(b->num, a_den / g, &right) != DRDC_OK) ||
      (drdc__units_mul_s64(a_den / g, b->den, &den) != DRDC_OK)) {
    return DRDC_E_RANGE;
  }
  /* both terms are within +-INT64_MAX: check the difference */
  if (((right < 0) && (left > (INT64_MAX + right))) ||
      ((right > 0) && (left < (-INT64_MAX + right)))) {
    return DRDC_E_RANGE;
  }
  num = left - right;
  r = gcd_s64(num, den);
  out->num = num / r;
  out->den = den / r;
  return DRDC_OK;
}
