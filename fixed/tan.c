/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_trig
 * @brief tan of a binary angle in Q15.16: the quotient of the unrounded
 *        first-quadrant sine kernels (Q62), one rounded 128/64 division.
 *
 * tan is S(r) / S(2^30 - r) in quadrants 0 and 2 and -S(2^30 - r) / S(r)
 * in quadrants 1 and 3 (exact reduction, so tan(a + pi) = tan(a) and
 * tan(-a) = -tan(a) bit for bit). The denominator is zero only at the
 * poles, where the kernel is exactly 0.
 *
 * Near a pole the kernel's absolute precision (2^-38.9) is not enough
 * relative to a tiny denominator, so within d < 2^21 units of a pole
 * (|tan| > 326) the series cot(e) = 1/e - e/3 - e^3/45 of the distance
 * e = d 2 pi / 2^32 is used instead; e^3/45 < 6.4e-10 is dropped (4e-5
 * LSB). 1/e and e/3 are computed in Q24 from constants with 2^-61
 * relative error, so that branch is correctly rounded but for 2^-8 LSB.
 */
#include <drdc/fixed_trig.h>

#include <stddef.h>

#include "fixed_impl.h"
#include "trig_impl.h"

/* 2^61 / (2 pi): 1/e in Q24 is this over d 2^5 (d 2^5 < 2^26). */
#define COT_NUM UINT64_C(366986312910250153)
/* 2 pi 2^40 / 3: e/3 in Q24 is d times this over 2^48 (< 2^62.1). */
#define COT_E3 UINT64_C(2302811768238)
/* Distance from a pole, in units, below which the cot series is used. */
#define COT_LIMIT (UINT32_C(1) << 21)

/* |tan| at distance 0 < d < 2^21 units from a pole, in Q16, rounded;
 * the result is at most 2^48 / (2 pi) < 2^46. */
static uint64_t cot_near_pole(uint32_t d)
{
  uint64_t inv = COT_NUM / ((uint64_t)d << 5);   /* 1/e, Q24 */
  uint64_t third = ((uint64_t)d * COT_E3) >> 48; /* e/3, Q24 */

  return ((inv - third) + 128u) >> 8;
}

static drdc_status_t tan_bam32(drdc_bam32_t a, int sat, drdc_q15_16_t *out)
{
  uint32_t q = a >> 30;
  uint32_t r = a & (FX_BAM_QUARTER - 1u);
  uint64_t s = (uint64_t)fx_sin_quadrant_q62(r);
  uint64_t c = (uint64_t)fx_sin_quadrant_q62(FX_BAM_QUARTER - r);
  uint64_t num = ((q & 1u) != 0u) ? c : s;
  uint64_t den = ((q & 1u) != 0u) ? s : c;
  fx_u128_t n;
  uint64_t t = 0;
  uint32_t pole;
  int too_big;

  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if (den == 0u) {
    return DRDC_E_DOMAIN;
  }
  /* the distance from the pole: the denominator's kernel argument */
  pole = ((q & 1u) != 0u) ? r : (FX_BAM_QUARTER - r);
  if (pole < COT_LIMIT) {
    t = cot_near_pole(pole);
    return fx_finish_s32((q & 1u) != 0u, t, sat, out);
  }
  /* num 2^16 / den, num < 2^63: the dividend has 79 bits */
  n.hi = num >> 48;
  n.lo = num << 16;
  too_big = fx_div_round_u128(n, den, &t);
  return fx_finish_s32((q & 1u) != 0u, too_big ? UINT64_MAX : t, sat, out);
}

drdc_status_t drdc_fx_tan_bam32(drdc_bam32_t a, drdc_q15_16_t *out)
{
  return tan_bam32(a, 0, out);
}

drdc_status_t drdc_fx_tan_bam32_sat(drdc_bam32_t a, drdc_q15_16_t *out)
{
  return tan_bam32(a, 1, out);
}
