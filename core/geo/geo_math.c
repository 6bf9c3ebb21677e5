/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Shorthands of core/geo for the Q5.58 products and quotients of
 *        fixed/, floor division and the nas <-> radian conversions.
 */
#include "geo_impl.h"

#include <drdc/fixed_arith.h>

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

drdc_q47_16_t geo_metres_from_angle(int64_t a)
{
  int64_t r = 0;

  /* the projection's angles keep the Q36 metres within int64_t (as for
   * geo_muldiv()): never fails */
  (void)drdc_fx_muldiv_s64(a, GEO_K0A_Q40, GEO_TWO_POW_62, &r);
  return drdc_fx_rshift_round_s64_inline(r, 20u);
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
