/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_arith
 * @brief a * b / c for int32 with an exact 64-bit intermediate, one
 *        correctly rounded division: apart from muldiv.c, whose int64 form
 *        is on the timed geodesy, so that it can be compiled for flash.
 */
#include <drdc/fixed_arith.h>

#include <stddef.h>

#include "fixed_impl.h"

static drdc_status_t muldiv_s32(int32_t a, int32_t b, int32_t c, int sat,
                                int32_t *out)
{
  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if (c == 0) {
    return DRDC_E_DIVIDE_BY_ZERO;
  }
  /* |a b| <= 2^62: exact in uint64_t */
  return fx_finish_s32(
      fx_quotient_negative((a < 0) ? 1 : 0, (b < 0) ? 1 : 0, (c < 0) ? 1 : 0),
      fx_div_round_u64((uint64_t)fx_abs32(a) * fx_abs32(b), fx_abs32(c)), sat,
      out);
}

drdc_status_t drdc_fx_muldiv_s32(int32_t a, int32_t b, int32_t c, int32_t *out)
{
  return muldiv_s32(a, b, c, 0, out);
}

drdc_status_t drdc_fx_muldiv_s32_sat(int32_t a, int32_t b, int32_t c,
                                     int32_t *out)
{
  return muldiv_s32(a, b, c, 1, out);
}
