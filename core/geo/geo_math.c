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

int64_t geo_mul(int64_t a, int64_t b)
{
  return drdc_fx_mul_q5_58_unchecked(a, b);
}

int64_t geo_muldiv(int64_t a, int64_t b, int64_t c)
{
  int64_t r = 0;

  /* callers keep the quotient in range and c != 0: never fails */
  (void)drdc_fx_muldiv_s64(a, b, c, &r);
  return r;
}

int64_t geo_mul_shift(int64_t a, int64_t b, unsigned n)
{
  uint64_t m = (a < 0) ? (UINT64_C(0) - (uint64_t)a) : (uint64_t)a;
  uint64_t half = UINT64_C(1) << (n - 1u);
  unsigned up = 64u - n;
  uint64_t hi;
  uint64_t lo;
  uint64_t q;

  /* the exact 128-bit |a| b plus half the divisor, shifted: the quotient
   * rounded half up, which with the sign put back is round to nearest,
   * ties away from zero, of a b / 2^n: geo_muldiv(a, b, 2^n) (b > 0),
   * both being that one rounding of the same rational */
  drdc_fx_mul_u64_u128(m, (uint64_t)b, &hi, &lo);
  lo = lo + half;
  hi = hi + ((lo < half) ? 1u : 0u);
  q = (lo >> n) | (hi << up);
  return (a < 0) ? (int64_t)(UINT64_C(0) - q) : (int64_t)q;
}

drdc_q47_16_t geo_metres_from_angle(int64_t a)
{
  /* the projection's angles keep the Q36 metres within int64_t */
  return drdc_fx_rshift_round_s64_inline(
      geo_mul_shift(a, GEO_K0A_Q40, 62u), 20u);
}

int64_t geo_floor_div(int64_t a, int64_t b)
{
  int64_t q = a / b;

  /* C division truncates: step down when a negative quotient was cut */
  if (((a % b) != 0) && (a < 0)) {
    q = q - 1;
  }
  return q;
}

int64_t geo_rad_from_nas(drdc_nas_t a)
{
  /* a pi 2^58 / 648e12 = 1397 a + a 0.38029... (the fraction in Q5.58):
   * no division; |a| <= 2^51 keeps 1397 a in range */
  return (a * 1397) + geo_mul(a, GEO_NAS_RAD_FRACTION);
}

drdc_nas_t geo_nas_from_rad(int64_t r)
{
  return geo_muldiv(r, GEO_NAS_180, GEO_PI);
}
