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

/* Angle of (ax, ay) in the first quadrant, magnitudes <= 2^31, not both
 * zero: the octant below the diagonal directly, the other by
 * atan(y/x) = pi/2 - atan(x/y). */
static uint32_t first_quadrant(uint32_t ay, uint32_t ax)
{
  bool steep = ay > ax;
  uint32_t a = fx_atan_ratio_bam(steep ? ax : ay, steep ? ay : ax);

  return steep ? (FX_BAM_QUARTER - a) : a;
}

drdc_status_t drdc_fx_atan2_bam32(int32_t y, int32_t x, drdc_bam32_t *out)
{
  uint32_t a;

  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if ((x == 0) && (y == 0)) {
    return DRDC_E_DOMAIN;
  }
  a = first_quadrant(fx_abs32(y), fx_abs32(x));
  if (x < 0) {
    a = (FX_BAM_QUARTER << 1) - a; /* pi - a */
  }
  *out = (y < 0) ? (0u - a) : a;  /* -a modulo one turn */
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
  a = first_quadrant(ax << 1, c);
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
