/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_arith
 * @brief Conversions between integers, Q1.30, Q15.16 and Q47.16.
 *
 * Widening conversions are exact; narrowing ones either drop fraction bits
 * (rounded to nearest, ties away from zero) or integer bits (range check,
 * then an exact shift of the magnitude).
 */
#include <drdc/fixed_arith.h>

#include <stddef.h>

#include "fixed_impl.h"

/* Range of a Q47.16 integer part: +-2^47. */
#define Q47_16_INT_MAX ((INT64_C(1) << 47) - 1)
#define Q47_16_INT_MIN (-(INT64_C(1) << 47))

static drdc_status_t q15_16_from_int(int32_t i, int sat, drdc_q15_16_t *out)
{
  if (out == NULL) {
    return DRDC_E_NULL;
  }
  /* |i| << 16 as a magnitude: |i| <= 2^31, so the shift fits 64 bits */
  return fx_finish_s32(i < 0, (uint64_t)fx_abs32(i) << 16, sat, out);
}

drdc_status_t drdc_fx_q15_16_from_int(int32_t i, drdc_q15_16_t *out)
{
  return q15_16_from_int(i, 0, out);
}

drdc_status_t drdc_fx_q15_16_from_int_sat(int32_t i, drdc_q15_16_t *out)
{
  return q15_16_from_int(i, 1, out);
}

int32_t drdc_fx_int_from_q15_16(drdc_q15_16_t x)
{
  return drdc_fx_rshift_round_s32(x, 16u);
}

static drdc_status_t q47_16_from_int(int64_t i, int sat, drdc_q47_16_t *out)
{
  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if ((i > Q47_16_INT_MAX) || (i < Q47_16_INT_MIN)) {
    if (!sat) {
      return DRDC_E_OVERFLOW;
    }
    *out = (i < 0) ? FX_INT64_MIN : INT64_MAX;
    return DRDC_W_SATURATED;
  }
  /* |i| <= 2^47: the magnitude shift is exact; i * 65536 has no overflow */
  *out = i * 65536;
  return DRDC_OK;
}

drdc_status_t drdc_fx_q47_16_from_int(int64_t i, drdc_q47_16_t *out)
{
  return q47_16_from_int(i, 0, out);
}

drdc_status_t drdc_fx_q47_16_from_int_sat(int64_t i, drdc_q47_16_t *out)
{
  return q47_16_from_int(i, 1, out);
}

int64_t drdc_fx_int_from_q47_16(drdc_q47_16_t x)
{
  return drdc_fx_rshift_round_s64(x, 16u);
}

drdc_q47_16_t drdc_fx_q47_16_from_q15_16(drdc_q15_16_t x)
{
  return (drdc_q47_16_t)x;
}

static drdc_status_t q15_16_from_q47_16(drdc_q47_16_t x, int sat,
                                        drdc_q15_16_t *out)
{
  if (out == NULL) {
    return DRDC_E_NULL;
  }
  return fx_finish_s32(x < 0, fx_abs64(x), sat, out);
}

drdc_status_t drdc_fx_q15_16_from_q47_16(drdc_q47_16_t x, drdc_q15_16_t *out)
{
  return q15_16_from_q47_16(x, 0, out);
}

drdc_status_t drdc_fx_q15_16_from_q47_16_sat(drdc_q47_16_t x,
                                             drdc_q15_16_t *out)
{
  return q15_16_from_q47_16(x, 1, out);
}

static drdc_status_t q1_30_from_q15_16(drdc_q15_16_t x, int sat,
                                       drdc_q1_30_t *out)
{
  if (out == NULL) {
    return DRDC_E_NULL;
  }
  return fx_finish_s32(x < 0, (uint64_t)fx_abs32(x) << 14, sat, out);
}

drdc_status_t drdc_fx_q1_30_from_q15_16(drdc_q15_16_t x, drdc_q1_30_t *out)
{
  return q1_30_from_q15_16(x, 0, out);
}

drdc_status_t drdc_fx_q1_30_from_q15_16_sat(drdc_q15_16_t x, drdc_q1_30_t *out)
{
  return q1_30_from_q15_16(x, 1, out);
}

drdc_q15_16_t drdc_fx_q15_16_from_q1_30(drdc_q1_30_t x)
{
  return drdc_fx_rshift_round_s32(x, 14u);
}
