/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_arith
 * @brief Rounding right shifts (to nearest, ties away from zero).
 *
 * The magnitude is shifted, never the signed value: adding half of the
 * last kept bit to the magnitude and truncating rounds ties away from zero,
 * and |x| + half fits the unsigned type (|x| <= 2^31, half <= 2^30).
 */
#include <drdc/fixed_arith.h>

#include "fixed_impl.h"

int32_t drdc_fx_rshift_round_s32(int32_t x, unsigned n)
{
  uint32_t mag = fx_abs32(x);

  if (n == 0u) {
    return x;
  }
  if (n >= 32u) {
    /* |x| / 2^n <= 0.5, and == 0.5 only for INT32_MIN at n == 32 */
    return ((n == 32u) && (x == INT32_MIN)) ? -1 : 0;
  }
  mag = (mag + (UINT32_C(1) << (n - 1u))) >> n; /* <= 2^30, fits int32 */
  return (x < 0) ? -(int32_t)mag : (int32_t)mag;
}

int64_t drdc_fx_rshift_round_s64(int64_t x, unsigned n)
{
  if (n == 0u) {
    return x;
  }
  if (n >= 64u) {
    return ((n == 64u) && (x == FX_INT64_MIN)) ? -1 : 0;
  }
  return drdc_fx_rshift_round_s64_inline(x, n);
}
