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
static inline int32_t quadrant_sin(uint32_t r)
{
  uint64_t v = (uint64_t)fx_sin_quadrant_q62(r);

  return (int32_t)((v + (UINT64_C(1) << 31)) >> 32);
}

/* sin(a) = +-S(r) or +-S(2^30 - r) by the quadrant q: odd quadrants mirror
 * the kernel's argument, the lower half plane negates. */
static inline int32_t sin_of(uint32_t q, uint32_t r)
{
  int32_t v = quadrant_sin(((q & 1u) != 0u) ? (FX_BAM_QUARTER - r) : r);

  return (q >= 2u) ? -v : v;
}

/* cos(a) = sin(a + 2^30): the same with the next quadrant. */
static inline int32_t cos_of(uint32_t q, uint32_t r)
{
  int32_t v = quadrant_sin(((q & 1u) != 0u) ? r : (FX_BAM_QUARTER - r));

  return ((q == 1u) || (q == 2u)) ? -v : v;
}

void drdc_fx_sincos_bam32(drdc_bam32_t a, drdc_q1_30_t *s, drdc_q1_30_t *c)
{
  uint32_t q = a >> 30;
  uint32_t r = a & (FX_BAM_QUARTER - 1u);

  if (s != NULL) {
    *s = sin_of(q, r);
  }
  if (c != NULL) {
    *c = cos_of(q, r);
  }
}

drdc_q1_30_t drdc_fx_sin_bam32(drdc_bam32_t a)
{
  return sin_of(a >> 30, a & (FX_BAM_QUARTER - 1u));
}

/* cos(a) = sin(a + 2^30), bit for bit: the next quadrant q + 1 mirrors
 * where q does not and is negative for q = 1, 2, as cos_of. */
drdc_q1_30_t drdc_fx_cos_bam32(drdc_bam32_t a)
{
  return drdc_fx_sin_bam32(a + FX_BAM_QUARTER);
}
