/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_trig
 * @brief atan2, asin and acos as binary angles, by exact octant reduction
 *        to the kernel atan(num / den), 0 <= num <= den.
 *
 * asin(x) = atan2(x, sqrt(1 - x^2)): 1 - x^2 is exact in Q60 (x Q30) and
 * its root is taken correctly rounded in Q31 (error 2^-32, at most 0.16
 * binary-angle units after the atan), with x in Q31 (exact) beside it.
 */
#include <drdc/fixed_trig.h>

#include <stdbool.h>
#include <stddef.h>

#include <drdc/fixed_sqrt.h>

#include "fixed_impl.h"
#include "trig_impl.h"

drdc_status_t drdc_fx_atan2_bam32(int32_t y, int32_t x, drdc_bam32_t *out)
{
  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if ((x == 0) && (y == 0)) {
    return DRDC_E_DOMAIN;
  }
  *out = fx_atan2_bam(y, x);
  return DRDC_OK;
}

/* Q1.30 one, the domain limit of asin and acos. */
#define Q30_ONE (INT32_C(1) << 30)

drdc_status_t drdc_fx_asin_q1_30(drdc_q1_30_t x, drdc_bam32_t *out)
{
  uint32_t ax;
  uint32_t c;
  uint32_t a;

  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if ((x > Q30_ONE) || (x < -Q30_ONE)) {
    return DRDC_E_DOMAIN;
  }
  ax = fx_abs32(x);
  /* sqrt(1 - x^2) in Q31: sqrt(4 (2^60 - x^2)) with x^2 <= 2^60 exact */
  c = (uint32_t)drdc_fx_sqrt_u64(((UINT64_C(1) << 60) - ((uint64_t)ax * ax))
                                 << 2);
  a = fx_atan_first_quadrant(ax << 1, c);
  *out = (x < 0) ? (0u - a) : a;
  return DRDC_OK;
}

drdc_status_t drdc_fx_acos_q1_30(drdc_q1_30_t x, drdc_bam32_t *out)
{
  drdc_bam32_t a = 0;
  drdc_status_t st;

  if (out == NULL) {
    return DRDC_E_NULL;
  }
  st = drdc_fx_asin_q1_30(x, &a);
  if (st != DRDC_OK) {
    return st;
  }
  *out = FX_BAM_QUARTER - a; /* pi/2 - asin(x), in [0, pi] */
  return DRDC_OK;
}
