/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_trig
 * @brief sin, cos and sincos of binary angles.
 *
 * Quadrant reduction is exact: with q = a / 2^30 and r = a mod 2^30,
 * sin and cos are +-S(r) or +-S(2^30 - r), S the first-quadrant kernel,
 * so every symmetry of sin and cos holds bit for bit.
 */
#include <drdc/fixed_trig.h>

#include <stddef.h>

#include "trig_impl.h"

/* S(r) rounded to Q1.30 (kernel value >= 0, <= 2^62). */
static int32_t quadrant_sin(uint32_t r)
{
  uint64_t v = (uint64_t)fx_sin_quadrant_q62(r);

  return (int32_t)((v + (UINT64_C(1) << 31)) >> 32);
}

void drdc_fx_sincos_bam32(drdc_bam32_t a, drdc_q1_30_t *s, drdc_q1_30_t *c)
{
  uint32_t q = a >> 30;
  uint32_t r = a & (FX_BAM_QUARTER - 1u);
  int32_t sr;
  int32_t cr;

  if (s != NULL) {
    sr = quadrant_sin(((q & 1u) != 0u) ? (FX_BAM_QUARTER - r) : r);
    *s = (q >= 2u) ? -sr : sr;
  }
  if (c != NULL) {
    cr = quadrant_sin(((q & 1u) != 0u) ? r : (FX_BAM_QUARTER - r));
    *c = ((q == 1u) || (q == 2u)) ? -cr : cr;
  }
}

drdc_q1_30_t drdc_fx_sin_bam32(drdc_bam32_t a)
{
  drdc_q1_30_t s = 0;

  drdc_fx_sincos_bam32(a, &s, NULL);
  return s;
}

drdc_q1_30_t drdc_fx_cos_bam32(drdc_bam32_t a)
{
  drdc_q1_30_t c = 0;

  drdc_fx_sincos_bam32(a, NULL, &c);
  return c;
}
