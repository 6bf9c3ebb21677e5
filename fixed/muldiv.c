/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_arith
 * @brief a * b / c with an exact intermediate: 64 bits for int32, 128 bits
 *        for int64, one correctly rounded division.
 */
#include <drdc/fixed_arith.h>

#include <stddef.h>

#include "fixed_impl.h"

/* 1 when the quotient a * b / c is negative: an odd count of negative
 * operands. */
static int quotient_negative(int a_negative, int b_negative, int c_negative)
{
  return (a_negative + b_negative + c_negative) & 1;
}

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
  return fx_finish_s32(quotient_negative((a < 0) ? 1 : 0, (b < 0) ? 1 : 0,
                                             (c < 0) ? 1 : 0),
                       fx_div_round_u64((uint64_t)fx_abs32(a) * fx_abs32(b),
                                        fx_abs32(c)),
                       sat, out);
}

drdc_status_t drdc_fx_muldiv_s32(int32_t a, int32_t b, int32_t c,
                                 int32_t *out)
{
  return muldiv_s32(a, b, c, 0, out);
}

drdc_status_t drdc_fx_muldiv_s32_sat(int32_t a, int32_t b, int32_t c,
                                     int32_t *out)
{
  return muldiv_s32(a, b, c, 1, out);
}

/* The work is done in drdc_fx_muldiv_s64()'s own frame (no forwarding
 * wrapper above the 128-bit division), and the saturating form calls it:
 * the plain form fails with DRDC_E_OVERFLOW exactly when the saturating
 * one clamps, and leaves `*out` unchanged then. */
drdc_status_t drdc_fx_muldiv_s64(int64_t a, int64_t b, int64_t c,
                                 int64_t *out)
{
  uint64_t q = 0;
  int too_big;

  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if (c == 0) {
    return DRDC_E_DIVIDE_BY_ZERO;
  }
  too_big = fx_div_round_u128(fx_mul_u64(fx_abs64(a), fx_abs64(b)),
                              fx_abs64(c), &q);
  /* a zero product is never negative */
  return fx_finish_s64(quotient_negative((a < 0) ? 1 : 0, (b < 0) ? 1 : 0,
                                         (c < 0) ? 1 : 0),
                       too_big, q, 0, out);
}

drdc_status_t drdc_fx_muldiv_s64_sat(int64_t a, int64_t b, int64_t c,
                                     int64_t *out)
{
  int neg = quotient_negative((a < 0) ? 1 : 0, (b < 0) ? 1 : 0,
                              (c < 0) ? 1 : 0);
  drdc_status_t st = drdc_fx_muldiv_s64(a, b, c, out);

  if (st == DRDC_E_OVERFLOW) {
    *out = (neg != 0) ? FX_INT64_MIN : INT64_MAX;
    st = DRDC_W_SATURATED;
  }
  return st;
}
