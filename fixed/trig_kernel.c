/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_trig
 * @brief First-quadrant kernels: sin by table and Taylor correction, atan
 *        of a ratio by table and a cubic Taylor correction.
 *
 * sin: with x0 the nearest of the 257 table angles and delta = x - x0,
 * |delta| <= pi / 1024 = 3.07e-3 rad,
 *   sin(x0 + delta) = s0 (1 - delta^2 / 2) + c0 (delta - delta^3 / 6)
 * with a truncation error s0 delta^4 / 24 <= 3.7e-12 (0.004 LSB of Q1.30).
 * Intermediate formats (all int64, no overflow):
 *   delta Q39 (|.| <= 2^30.65), delta^2 Q46 (<= 2^29.3),
 *   delta^3 / 6 Q58 (<= 2^30.4), s0 and c0 Q0.31 (<= 2^31),
 *   products Q70, Q77 and Q89 (<= 2^61.7), summed in Q62 (<= 2^62).
 * The table entries carry the error (<= 2^-32, 0.25 LSB of Q1.30); the
 * other terms add less than 2^-40.
 *
 * atan: t = num / den in Q32 (rounded, <= 2^-33 error), t0 = i / 256 the
 * nearest table point, h = t - t0, |h| <= 2^-9:
 *   B atan(t0 + h) = A + D1 h - C2 h^2 + C3 h^3
 * (B = 2^32 / (2 pi) binary-angle units per radian), truncation error
 * <= 0.2 B h^4 = 0.002 units. Intermediates: h Q32 (|.| <= 2^23),
 * h^2 Q42 (<= 2^24), h^3 Q42 (<= 2^15), table values in units times 4,
 * products in units times 2^34 and 2^44 (<= 2^54.4), summed in units
 * times 2^33 (<= 2^62).
 */
#include "trig_impl.h"

#include "fixed_impl.h"

/* 2 pi 2^31: one binary-angle unit is 2 pi / 2^32 rad, so d units times
 * this constant is the angle in radians in Q63; |d| <= 2^21 keeps the
 * product below 2^54.7. Rounding the constant costs 2^-63 relative. */
#define TWO_PI_Q31 INT64_C(13493037705)

/* Table index step in binary-angle units: 2^30 / 256. */
#define SIN_STEP_SHIFT 22u

int64_t fx_sin_quadrant_q62(uint32_t r)
{
  uint32_t i = (r + (UINT32_C(1) << (SIN_STEP_SHIFT - 1u))) >> SIN_STEP_SHIFT;
  uint32_t node = i << SIN_STEP_SHIFT;
  int32_t d = (int32_t)r - (int32_t)node;                         /* |d| <= 2^21 */
  int64_t s0 = (int64_t)fx_sin_q31[i];
  int64_t c0 = (int64_t)fx_sin_q31[(uint32_t)FX_TRIG_STEPS - i];
  int64_t dl = fx_floor_shift64((int64_t)d * TWO_PI_Q31, 24u);   /* Q39 */
  int64_t d2 = fx_floor_shift64(dl * dl, 32u);                    /* Q46 */
  int64_t d3 = fx_floor_shift64(d2 * dl, 27u);                    /* Q58 */
  int64_t acc = fx_scale_pow2_64(s0, 31u);                        /* Q62 */

  acc += fx_floor_shift64(c0 * dl, 8u);    /* c0 delta:         Q70 */
  acc -= fx_floor_shift64(s0 * d2, 16u);   /* s0 delta^2 / 2:   Q77 */
  /* delta^3 / 6 by the magnitude (truncated, 2^-58) */
  d3 = (d3 < 0) ? -(int64_t)fx_div_u64_small(fx_abs64(d3), 6u)
                : (int64_t)fx_div_u64_small((uint64_t)d3, 6u);
  acc -= fx_floor_shift64(c0 * d3, 27u);   /* c0 delta^3 / 6:   Q89 */
  return (acc < 0) ? 0 : acc;
}

/* Table step in Q32 t: 2^32 / 256. */
#define ATAN_STEP_SHIFT 24u

uint32_t fx_atan_ratio_bam(uint32_t num, uint32_t den)
{
  uint64_t t = fx_div_round_u64((uint64_t)num << 32, den); /* Q32, <= 2^32 */
  uint32_t i = (uint32_t)((t + (UINT64_C(1) << (ATAN_STEP_SHIFT - 1u)))
                          >> ATAN_STEP_SHIFT);
  int64_t h = (int64_t)t - fx_scale_pow2_64((int64_t)i, ATAN_STEP_SHIFT); /* |h| <= 2^23 */
  int64_t h2 = fx_floor_shift64(h * h, 22u);             /* Q42 */
  int64_t h3 = fx_floor_shift64(h2 * h, 32u);            /* Q42 */
  int64_t acc = fx_scale_pow2_64((int64_t)fx_atan_a[i], 31u); /* units 2^33 */

  acc += fx_floor_shift64((int64_t)fx_atan_d1[i] * h, 1u);
  acc -= fx_floor_shift64((int64_t)fx_atan_c2[i] * h2, 11u);
  acc += fx_floor_shift64((int64_t)fx_atan_c3[i] * h3, 11u);
  if (acc < 0) {
    return 0;
  }
  return (uint32_t)(((uint64_t)acc + (UINT64_C(1) << 32)) >> 33);
}
