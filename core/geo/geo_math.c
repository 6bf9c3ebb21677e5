/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Shorthands of core/geo for the Q5.58 products and quotients of
 *        fixed/, floor division and the nas <-> radian conversions.
 */
#include "geo_impl.h"

#include <drdc/fixed_arith.h>
#include <drdc/fixed_wide.h>

int64_t drdc__geo_mul(int64_t a, int64_t b)
{
  return drdc_fx_mul_q5_58_unchecked(a, b);
}

int64_t drdc__geo_mul_short(int64_t a, int64_t b)
{
  return drdc_fx_mul_q5_58_short(a, b);
}

int64_t drdc__geo_muldiv(int64_t a, int64_t b, int64_t c)
{
  int64_t r = 0;

  /* callers keep the quotient in range and c != 0: never fails */
  (void)drdc_fx_muldiv_s64(a, b, c, &r);
  return r;
}

int64_t drdc__geo_mul_shift(int64_t a, int64_t b, unsigned n)
{
  uint64_t m = (a < 0) ? (UINT64_C(0) - (uint64_t)a) : (uint64_t)a;
  uint64_t half = UINT64_C(1) << (n - 1u);
  unsigned up = 64u - n;
  uint64_t hi;
  uint64_t lo;
  uint64_t q;

  /* the exact 128-bit |a| b plus half the divisor, shifted: the quotient
   * rounded half up, which with the sign put back is round to nearest,
   * ties away from zero, of a b / 2^n: drdc__geo_muldiv(a, b, 2^n) (b > 0),
   * both being that one rounding of the same rational */
  drdc_fx_mul_u64_u128(m, (uint64_t)b, &hi, &lo);
  lo = lo + half;
  hi = hi + ((lo < half) ? 1u : 0u);
  q = (lo >> n) | (hi << up);
  return (a < 0) ? (int64_t)(UINT64_C(0) - q) : (int64_t)q;
}

int64_t drdc__geo_floor_div(int64_t a, int64_t b)
{
  int64_t q = a / b;

  /* C division truncates: step down when a negative quotient was cut */
  if (((a % b) != 0) && (a < 0)) {
    q = q - 1;
  }
  return q;
}

int64_t drdc__geo_rad_from_nas(drdc_nas_t a)
{
  /* a pi 2^58 / 648e12 = 1397 a + a 0.38029... (the fraction in Q5.58):
   * no division; |a| <= 2^51 keeps 1397 a in range */
  return (a * 1397) + drdc__geo_mul(a, GEO_NAS_RAD_FRACTION);
}

/** floor(2^63 GEO_NAS_180 / GEO_PI), GEO_PI being pi 2^58 rounded to an
 *  integer: the nas in a radian in Q63, 53 bits. */
#define NAS_PER_RAD_Q63 INT64_C(6600473799907083)

drdc_nas_t drdc__geo_nas_from_rad(int64_t r)
{
  const uint64_t c = (uint64_t)GEO_NAS_180;
  const uint64_t d = (uint64_t)GEO_PI;
  uint64_t x = (r < 0) ? (UINT64_C(0) - (uint64_t)r) : (uint64_t)r;
  uint64_t hi;
  uint64_t lo;
  uint64_t q;
  uint64_t rem;

  /* drdc__geo_muldiv(r, GEO_NAS_180, GEO_PI) bit for bit, without the
   * 128-bit division: with x = |r| <= 2^63, c = GEO_NAS_180, d = GEO_PI and
   * f = floor(x c / d), the magnitude is f + [2 rem >= d], rem = x c -
   * f d (rounded half up, the sign then put back: to nearest, ties away
   * from zero, as drdc_fx_muldiv_s64()). Here m = NAS_PER_RAD_Q63 =
   * c 2^63 / d - e, 0 <= e < 1, so x m / 2^63 is within (x c / d - 1,
   * x c / d]: its floor q is f or f - 1, and x c - q d lies in [0, 2 d),
   * below 2^61: exact as the 64-bit difference of the two products
   * taken modulo 2^64. One step corrects q to f. d is odd and shares
   * with c only the factor 15, so x c / d is never a half: no ties. */
  drdc_fx_mul_u64_u128(x, (uint64_t)NAS_PER_RAD_Q63, &hi, &lo);
  q = (hi << 1u) | (lo >> 63u);
  rem = (x * c) - (q * d);
  if (rem >= d) {
    q++;
    rem -= d;
  }
  if (rem >= (d - rem)) {
    q++;
  }
  /* q <= 2^63 c / d < 2^53 */
  return (r < 0) ? -(int64_t)q : (int64_t)q;
}
