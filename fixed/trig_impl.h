/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_trig
 * @brief Internal part of the trig functions: the tables and the
 *        first-quadrant kernels shared by sin, cos, tan, atan2, asin, acos.
 */
#ifndef DRDC_TRIG_IMPL_H
#define DRDC_TRIG_IMPL_H

#include <stdint.h>

/** Intervals per table: 256 per quarter wave, 256 over atan's [0, 1]. */
#define FX_TRIG_STEPS 256

/** Binary-angle units in a quarter turn (pi/2) and an eighth (pi/4). */
#define FX_BAM_QUARTER (UINT32_C(1) << 30)
#define FX_BAM_EIGHTH (UINT32_C(1) << 29)

extern const uint32_t fx_sin_q31[FX_TRIG_STEPS + 1];
extern const uint32_t fx_atan_a[FX_TRIG_STEPS + 1];
extern const uint32_t fx_atan_d1[FX_TRIG_STEPS + 1];
extern const int32_t fx_atan_c2[FX_TRIG_STEPS + 1];
extern const int32_t fx_atan_c3[FX_TRIG_STEPS + 1];

/**
 * sin(r 2 pi / 2^32) for 0 <= r <= 2^30 (first quadrant) in Q2.62-ish:
 * the value times 2^62, >= 0, before the final rounding. Error below
 * 2^-32 (from the table) plus 2^-40.
 */
int64_t fx_sin_quadrant_q62(uint32_t r);

/**
 * atan(num / den) in binary-angle units, rounded, for 0 <= num <= den,
 * 0 < den <= 2^31. Result 0..2^29.
 */
uint32_t fx_atan_ratio_bam(uint32_t num, uint32_t den);

/** floor(x / 2^n) for 0 < n < 64, shifting only unsigned values. */
static inline int64_t fx_floor_shift64(int64_t x, unsigned n)
{
  int64_t result;

  if (x < 0) {
    /* -x - 1 (= ~x) is >= 0 and in range; floor(x / 2^n) = -(m + 1)
     * where m = (-x - 1) / 2^n truncated */
    uint64_t m = (uint64_t)(-(x + 1)) >> n;

    result = -(int64_t)m - 1;
  } else {
    uint64_t m = (uint64_t)x >> n;

    result = (int64_t)m;
  }
  return result;
}

/** x * 2^n for 0 <= n < 63 by multiplication (no shift of a signed
 *  value); the caller keeps the product within int64_t. */
static inline int64_t fx_scale_pow2_64(int64_t x, unsigned n)
{
  uint64_t p = UINT64_C(1) << n;
  int64_t factor = (int64_t)p;

  return x * factor;
}

#endif /* DRDC_TRIG_IMPL_H */
