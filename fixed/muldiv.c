/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_arith
 * @brief a * b / c for int64 with an exact 128-bit intermediate, one
 *        correctly rounded division (int32 in muldiv_s32.c).
 */
#include <drdc/fixed_arith.h>

#include <stddef.h>

#include "fixed_impl.h"

/* The saturating form calls the plain one: the plain form fails with
 * DRDC_E_OVERFLOW exactly when the saturating one clamps, and leaves `*out`
 * unchanged then. */
drdc_status_t drdc_fx_muldiv_s64(int64_t a, int64_t b, int64_t c, int64_t *out)
{
  uint64_t q = 0;
  int too_big;

  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if (c == 0) {
    return DRDC_E_DIVIDE_BY_ZERO;
  }
  too_big =
      fx_div_round_u128(fx_mul_u64(fx_abs64(a), fx_abs64(b)), fx_abs64(c), &q);
  /* a zero product is never negative */
  return fx_finish_s64(
      fx_quotient_negative((a < 0) ? 1 : 0, (b < 0) ? 1 : 0, (c < 0) ? 1 : 0),
      too_big, q, 0, out);
}

drdc_status_t drdc_fx_muldiv_s64_sat(int64_t a, int64_t b, int64_t c,
                                     int64_t *out)
{
  int neg =
      fx_quotient_negative((a < 0) ? 1 : 0, (b < 0) ? 1 : 0, (c < 0) ? 1 : 0);
  drdc_status_t st = drdc_fx_muldiv_s64(a, b, c, out);

  if (st == DRDC_E_OVERFLOW) {
    *out = (neg != 0) ? FX_INT64_MIN : INT64_MAX;
    st = DRDC_W_SATURATED;
  }
  return st;
}
