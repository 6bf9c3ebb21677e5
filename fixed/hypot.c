/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_sqrt
 * @brief hypot without overflow: exact sums of squares (64 bits for int32
 *        inputs, 128 bits for int64) and a correctly rounded integer root.
 */
#include <drdc/fixed_sqrt.h>

#include <stddef.h>

#include "fixed_impl.h"

uint32_t drdc_fx_hypot_s32(int32_t x, int32_t y)
{
  uint64_t ax = fx_abs32(x);
  uint64_t ay = fx_abs32(y);

  /* each square <= 2^62, the sum <= 2^63; root <= 2^31.5 < 2^32 */
  return (uint32_t)drdc_fx_sqrt_u64((ax * ax) + (ay * ay));
}

uint64_t drdc_fx_hypot_s64(int64_t x, int64_t y)
{
  uint64_t ax = fx_abs64(x);
  uint64_t ay = fx_abs64(y);
  fx_u128_t sx = fx_mul_u64(ax, ax);
  fx_u128_t sy = fx_mul_u64(ay, ay);
  fx_u128_t n;
  fx_u128_t rem;
  uint64_t root = 0;
  uint64_t bit;

  /* n = x^2 + y^2 <= 2^127: no carry out of 128 bits */
  n = fx_add_u128(sx, sy.lo);
  n.hi += sy.hi;
  /* floor(sqrt(n)) < 2^64, bit by bit from the top: keep a bit when the
   * square of the candidate stays <= n */
  for (bit = UINT64_C(1) << 63; bit != 0u; bit >>= 1) {
    uint64_t cand = root | bit;

    if (fx_le_u128(fx_mul_u64(cand, cand), n) != 0) {
      root = cand;
    }
  }
  /* remainder n - root^2 (>= 0, < 2^65); round up when it exceeds root */
  sx = fx_mul_u64(root, root);
  rem.hi = n.hi - sx.hi - ((n.lo < sx.lo) ? 1u : 0u);
  rem.lo = n.lo - sx.lo;
  return ((rem.hi != 0u) || (rem.lo > root)) ? (root + 1u) : root;
}

static drdc_status_t hypot_q15_16(drdc_q15_16_t x, drdc_q15_16_t y, int sat,
                                  drdc_q15_16_t *out)
{
  if (out == NULL) {
    return DRDC_E_NULL;
  }
  return fx_finish_s32(0, drdc_fx_hypot_s32(x, y), sat, out);
}

drdc_status_t drdc_fx_hypot_q15_16(drdc_q15_16_t x, drdc_q15_16_t y,
                                   drdc_q15_16_t *out)
{
  return hypot_q15_16(x, y, 0, out);
}

drdc_status_t drdc_fx_hypot_q15_16_sat(drdc_q15_16_t x, drdc_q15_16_t y,
                                       drdc_q15_16_t *out)
{
  return hypot_q15_16(x, y, 1, out);
}
