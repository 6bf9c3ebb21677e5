/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_arith
 * @brief Rounded Q1.30, Q15.16 and Q47.16 quotients.
 *
 * The dividend's magnitude is shifted up by the fraction bits first:
 * |a| << 30 <= 2^61 and |a| << 16 <= 2^47 fit 64 bits; for Q47.16,
 * |a| << 16 <= 2^79 is a 128-bit dividend. One rounded unsigned division
 * then gives the correctly rounded quotient.
 */
#include <drdc/fixed_arith.h>

#include <stddef.h>

#include "fixed_impl.h"

static drdc_status_t div_s32(int32_t a, int32_t b, unsigned shift, int sat,
                             int32_t *out)
{
  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if (b == 0) {
    return DRDC_E_DIVIDE_BY_ZERO;
  }
  return fx_finish_s32(
      (a < 0) != (b < 0),
      fx_div_round_u64((uint64_t)fx_abs32(a) << shift, fx_abs32(b)), sat, out);
}

drdc_status_t drdc_fx_div_q1_30(drdc_q1_30_t a, drdc_q1_30_t b,
                                drdc_q1_30_t *out)
{
  return div_s32(a, b, 30u, 0, out);
}

drdc_status_t drdc_fx_div_q1_30_sat(drdc_q1_30_t a, drdc_q1_30_t b,
                                    drdc_q1_30_t *out)
{
  return div_s32(a, b, 30u, 1, out);
}

drdc_status_t drdc_fx_div_q15_16(drdc_q15_16_t a, drdc_q15_16_t b,
                                 drdc_q15_16_t *out)
{
  return div_s32(a, b, 16u, 0, out);
}

drdc_status_t drdc_fx_div_q15_16_sat(drdc_q15_16_t a, drdc_q15_16_t b,
                                     drdc_q15_16_t *out)
{
  return div_s32(a, b, 16u, 1, out);
}

static drdc_status_t div_q47_16(int64_t a, int64_t b, int sat, int64_t *out)
{
  uint64_t mag = fx_abs64(a);
  fx_u128_t n;
  uint64_t q = 0;
  int too_big;

  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if (b == 0) {
    return DRDC_E_DIVIDE_BY_ZERO;
  }
  n.hi = mag >> 48;
  n.lo = mag << 16;
  too_big = fx_div_round_u128(n, fx_abs64(b), &q);
  return fx_finish_s64((a < 0) != (b < 0), too_big, q, sat, out);
}

drdc_status_t drdc_fx_div_q47_16(drdc_q47_16_t a, drdc_q47_16_t b,
                                 drdc_q47_16_t *out)
{
  return div_q47_16(a, b, 0, out);
}

drdc_status_t drdc_fx_div_q47_16_sat(drdc_q47_16_t a, drdc_q47_16_t b,
                                     drdc_q47_16_t *out)
{
  return div_q47_16(a, b, 1, out);
}
