/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_units
 * @brief int64_t rationals for unit factors: exact, or (only in
 *        drdc__units_rat_mul(), for unit expressions) rounded to 63 bits
 *        with the rounding reported.
 */
#include <drdc/fixed_wide.h>

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

/* A 128-bit unsigned integer. */
typedef struct rat_u128 {
  uint64_t hi;
  uint64_t lo;
} rat_u128_t;

/* Number of significant bits of x (0 for 0). */
static unsigned bits_u128(const rat_u128_t *x)
{
  uint64_t top = x->lo;
  unsigned n = 0u;

  if (x->hi != 0u) {
    top = x->hi;
    n = 64u;
  }

  while (top != 0u) {
    top >>= 1u;
    n++;
  }
  return n;
}

/* a >= b */
static int ge_u128(const rat_u128_t *a, const rat_u128_t *b)
{
  return (a->hi > b->hi) || ((a->hi == b->hi) && (a->lo >= b->lo));
}

/* a - b for a >= b, into a */
static void sub_u128(rat_u128_t *a, const rat_u128_t *b)
{
  uint64_t borrow = 0u;

  if (a->lo < b->lo) {
    borrow = 1u;
  }

  a->lo -= b->lo;
  a->hi = a->hi - b->hi - borrow;
}

/* x x 2^s, s = 0..127, for a result below 2^128 */
static rat_u128_t shl_u128(const rat_u128_t *x, unsigned s)
{
  rat_u128_t r;

  if (s == 0u) {
    r = *x;
  } else if (s >= 64u) {
    r.hi = x->lo << (s - 64u);
    r.lo = 0u;
  } else {
    r.hi = (x->hi << s) | (x->lo >> (64u - s));
    r.lo = x->lo << s;
  }
  return r;
}

/* x / 2^s, s = 0..127, truncated */
static rat_u128_t shr_u128(const rat_u128_t *x, unsigned s)
{
  rat_u128_t r;

  if (s == 0u) {
    r = *x;
  } else if (s >= 64u) {
    r.hi = 0u;
    r.lo = x->hi >> (s - 64u);
  } else {
    r.hi = x->hi >> s;
    r.lo = (x->lo >> s) | (x->hi << (64u - s));
  }
  return r;
}

/*
 * round(l x 2^e / s) for l >= s > 0, both below 2^126, and a quotient
 * below 2^62: binary long division, the integer bits first (62 steps,
 * comparing r / 2^b with s so nothing overflows), then e fraction bits
 * (the remainder stays below s, so doubling it stays below 2^127), then
 * nearest, ties up.
 */
static uint64_t div_round_u128(const rat_u128_t *l, const rat_u128_t *s,
                               unsigned e)
{
  rat_u128_t r = *l;
  uint64_t q = 0u;
  unsigned i;

  for (i = 0u; i <= 62u; i++) {
    unsigned b = 62u - i;
    rat_u128_t top = shr_u128(&r, b);

    q <<= 1u;
    if (ge_u128(&top, s) != 0) {
      rat_u128_t part = shl_u128(s, b);

      sub_u128(&r, &part);
      q |= 1u;
    }
  }
  for (i = 0u; i < e; i++) {
    r = shl_u128(&r, 1u);
    q <<= 1u;
    if (ge_u128(&r, s) != 0) {
      sub_u128(&r, s);
      q |= 1u;
    }
  }
  r = shl_u128(&r, 1u);
  if (ge_u128(&r, s) != 0) {
    q++;
  }
  return q;
}

drdc_status_t drdc__units_rat_mul(const units_rat_t *a, int64_t num,
                                  int64_t den, units_rat_t *out, int8_t *scale,
                                  uint8_t *rounded)
{
  rat_u128_t n;
  rat_u128_t d;
  rat_u128_t *large;
  rat_u128_t *small;
  unsigned k;
  unsigned e;
  unsigned fraction_bits;
  uint64_t q;
  int64_t g1;
  int64_t g2;
  int64_t g;
  int64_t p2;
  int negative = 0;
  int64_t den_a;
  int64_t den_b;
  uint64_t bit;

  if ((a->num < -INT64_MAX) || (num < -INT64_MAX) || (a->den <= 0) ||
      (den <= 0)) {
    return DRDC_E_OVERFLOW;
  }
  if ((a->num < 0) != (num < 0)) {
    negative = 1;
  }
  if ((a->num == 0) || (num == 0)) {
    out->num = 0;
    out->den = 1;
    return DRDC_OK;
  }
  /* the exact product, cross-cancelled (lowest terms when a and
   * num / den are), as 128-bit magnitudes, each below 2^126; computed
   * here rather than by drdc__units_rat_scale() to keep the stack of
   * drdc_units_parse() within its budget */
  g1 = gcd_s64(a->num, den);
  g2 = gcd_s64(num, a->den);
  drdc_fx_mul_u64_u128(abs_u64(a->num / g1), abs_u64(num / g2), &n.hi, &n.lo);
  den_a = a->den / g2;
  den_b = den / g1;
  drdc_fx_mul_u64_u128((uint64_t)den_a, (uint64_t)den_b, &d.hi, &d.lo);
  if ((n.hi == 0u) && (n.lo <= INT64_MAX_U) && (d.hi == 0u) &&
      (d.lo <= INT64_MAX_U)) {
    out->num = (negative != 0) ? -(int64_t)n.lo : (int64_t)n.lo;
    out->den = (int64_t)d.lo;
    return DRDC_OK;
  }
  /* v = n / d as Q / 2^e (v >= 1) or 2^e / Q (v < 1), Q = round(large x
   * 2^e / small) in [2^60, 2^62], e = 61 - k >= 0: relative error below
   * 2^-61. From about 2^61 up (or 2^-61 down), k > 61: Q = round(large /
   * (small 2^(k - 61))), the divisor below 2^126 as large is, and v =
   * Q 2^(k - 61) = (Q / 2^e) 2^(32 steps) (or its inverse) with
   * e = 32 steps - (k - 61) in 0..31. */
  if (ge_u128(&n, &d) != 0) {
    large = &n;
    small = &d;
  } else {
    large = &d;
    small = &n;
  }
  k = bits_u128(large) - bits_u128(small);
  if (k > 61u) {
    unsigned steps = ((k - 61u) + (UNITS_SCALE_BITS - 1u)) / UNITS_SCALE_BITS;
    int add = (large == &n) ? (int)steps : -(int)steps;

    if ((scale == NULL) || (((int)*scale + add) > UNITS_SCALE_MAX) ||
        (((int)*scale + add) < -UNITS_SCALE_MAX)) {
      return DRDC_E_OVERFLOW;
    }
    *scale = (int8_t)((int)*scale + add);
    *small = shl_u128(small, k - 61u); /* the divisor, in place */
    e = (steps * UNITS_SCALE_BITS) - (k - 61u);
    fraction_bits = 0u;
  } else {
    e = 61u - k;
    fraction_bits = e;
  }
  q = div_round_u128(large, small, fraction_bits);
  bit = (uint64_t)1u << e;
  p2 = (int64_t)bit;
  g = gcd_s64((int64_t)q, p2);
  if (large == &n) {
    out->num = (int64_t)q / g;
    out->den = p2 / g;
  } else {
    out->num = p2 / g;
    out->den = (int64_t)q / g;
  }
  if (negative != 0) {
    out->num = -out->num;
  }
  *rounded = 1u;
  return DRDC_OK;
}
