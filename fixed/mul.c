/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_arith
 * @brief Rounded Q1.30, Q15.16 and Q47.16 products.
 *
 * Scaling: Q1.30 x Q1.30 = Q2.60 in 64 bits (|a b| <= 2^62, one guard bit
 * left), rounded back by 30 bits; Q15.16 x Q15.16 = Q30.32 likewise by 16
 * bits. Q47.16 x Q47.16 = Q94.32 needs 127 bits: an exact 128-bit product
 * of the magnitudes, rounded back by 16 bits.
 */
#include <drdc/fixed_arith.h>

#include <stddef.h>

#include "fixed_impl.h"

/* Product of two int32 values scaled down by 2^shift, rounded.
 *
 * The exact product p = a b (one SMULL / mullw + mulhw) is rounded as
 * floor((p + 2^(shift-1) - [p < 0]) / 2^shift): adding half rounds ties
 * up, and one less for a negative p turns that into ties away from zero
 * (the same as rounding the magnitude). The sum fits: |p| <= 2^62. The
 * result fits int32_t exactly when the sum lies in [-2^(31+shift),
 * 2^(31+shift)), which the high word of its two's complement tells with
 * one add and compare; the floor itself is then the low 32 bits of the
 * logical shift (the bits a logical shift gets wrong lie above them). */
static inline drdc_status_t mul_s32(int32_t a, int32_t b, unsigned shift,
                                    int sat, int32_t *out)
{
  int64_t p;
  uint64_t v;
  uint32_t high;

  if (out == NULL) {
    return DRDC_E_NULL;
  }
  p = (int64_t)a * b;
  v = (uint64_t)p +
      ((UINT32_C(1) << (shift - 1u)) - (uint32_t)((uint64_t)p >> 63));
  high = (uint32_t)(v >> 32);
  if (((high + (UINT32_C(1) << (shift - 1u))) >> shift) == 0u) {
    *out = fx_s32_from_bits((uint32_t)(v >> shift));
    return DRDC_OK;
  }
  if (sat == 0) {
    return DRDC_E_OVERFLOW;
  }
  *out = (p < 0) ? INT32_MIN : INT32_MAX;
  return DRDC_W_SATURATED;
}

drdc_status_t drdc_fx_mul_q1_30(drdc_q1_30_t a, drdc_q1_30_t b,
                                drdc_q1_30_t *out)
{
  return mul_s32(a, b, 30u, 0, out);
}

drdc_status_t drdc_fx_mul_q1_30_sat(drdc_q1_30_t a, drdc_q1_30_t b,
                                    drdc_q1_30_t *out)
{
  return mul_s32(a, b, 30u, 1, out);
}

drdc_status_t drdc_fx_mul_q15_16(drdc_q15_16_t a, drdc_q15_16_t b,
                                 drdc_q15_16_t *out)
{
  return mul_s32(a, b, 16u, 0, out);
}

drdc_status_t drdc_fx_mul_q15_16_sat(drdc_q15_16_t a, drdc_q15_16_t b,
                                     drdc_q15_16_t *out)
{
  return mul_s32(a, b, 16u, 1, out);
}

static drdc_status_t mul_q47_16(int64_t a, int64_t b, int sat, int64_t *out)
{
  fx_u128_t p;

  if (out == NULL) {
    return DRDC_E_NULL;
  }
  /* |a b| <= 2^126: adding 2^15 cannot carry out of 128 bits */
  p = fx_add_u128(fx_mul_u64(fx_abs64(a), fx_abs64(b)), UINT64_C(1) << 15);
  p = fx_shr_u128(p, 16u);
  return fx_finish_s64((a < 0) != (b < 0), p.hi != 0u, p.lo, sat, out);
}

drdc_status_t drdc_fx_mul_q47_16(drdc_q47_16_t a, drdc_q47_16_t b,
                                 drdc_q47_16_t *out)
{
  return mul_q47_16(a, b, 0, out);
}

drdc_status_t drdc_fx_mul_q47_16_sat(drdc_q47_16_t a, drdc_q47_16_t b,
                                     drdc_q47_16_t *out)
{
  return mul_q47_16(a, b, 1, out);
}

drdc_status_t drdc_fx_mul_q5_58(drdc_q5_58_t a, drdc_q5_58_t b,
                                drdc_q5_58_t *out)
{
  fx_u128_t p;

  if (out == NULL) {
    return DRDC_E_NULL;
  }
  /* |a b| <= 2^126: adding 2^57 cannot carry out of 128 bits */
  p = fx_add_u128(fx_mul_u64(fx_abs64(a), fx_abs64(b)), UINT64_C(1) << 57);
  p = fx_shr_u128(p, 58u);
  return fx_finish_s64((a < 0) != (b < 0), p.hi != 0u, p.lo, 0, out);
}
