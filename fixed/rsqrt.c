/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_sqrt
 * @brief Correctly rounded reciprocal square roots in Q15.16 and Q1.30.
 *
 * The result is r = round(sqrt(2^e / x)) (e = 48 for Q15.16, 90 for
 * Q1.30). An estimate from the integer root of the truncated quotient is
 * within one of r; it is then corrected by the exact criterion
 *   x (2r - 1)^2 < 2^(e+2) < x (2r + 1)^2,
 * evaluated in 128 bits as 4x (r^2 -+ r) + x. Equality is impossible: an
 * odd square times x < 2^31 is never 2^(e+2).
 */
#include <drdc/fixed_sqrt.h>

#include <stddef.h>

#include "fixed_impl.h"

/* x (2r + 1)^2 when `plus`, x (2r - 1)^2 otherwise (r >= 1), r < 2^32. */
static fx_u128_t odd_square_times(uint32_t x, uint64_t r, int plus)
{
  uint64_t rr = r * r; /* r < 2^32 */
  uint64_t k = plus ? (rr + r) : (rr - r);

  return fx_add_u128(fx_mul_u64((uint64_t)x << 2, k), x);
}

/* round(sqrt(2^e / x)) for 0 < x < 2^31, given 2^e / x < 2^64. */
static uint64_t rsqrt_core(uint32_t x, unsigned e)
{
  fx_u128_t limit; /* 2^(e+2) */
  fx_u128_t num;   /* 2^e */
  uint64_t q = 0;
  uint64_t r;

  num.hi = (e >= 64u) ? (UINT64_C(1) << (e - 64u)) : 0u;
  num.lo = (e >= 64u) ? 0u : (UINT64_C(1) << e);
  limit.hi = ((e + 2u) >= 64u) ? (UINT64_C(1) << (e + 2u - 64u)) : 0u;
  limit.lo = ((e + 2u) >= 64u) ? 0u : (UINT64_C(1) << (e + 2u));
  (void)fx_div_round_u128(num, x, &q);
  r = drdc_fx_sqrt_u64(q);
  while (!fx_le_u128(limit, odd_square_times(x, r, 1))) {
    r++;
  }
  while ((r > 0u) && fx_le_u128(limit, odd_square_times(x, r, 0))) {
    r--;
  }
  return r;
}

drdc_status_t drdc_fx_rsqrt_q15_16(drdc_q15_16_t x, drdc_q15_16_t *out)
{
  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if (x <= 0) {
    return DRDC_E_DOMAIN;
  }
  /* x >= 1 gives r <= 2^24 */
  *out = (drdc_q15_16_t)rsqrt_core((uint32_t)x, 48u);
  return DRDC_OK;
}

/* Largest Q1.30 input whose reciprocal root overflows: 0.25 (root 2). */
#define RSQRT_Q1_30_OVERFLOW_MAX (INT32_C(1) << 28)

drdc_status_t drdc_fx_rsqrt_q1_30(drdc_q1_30_t x, drdc_q1_30_t *out)
{
  uint64_t r;

  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if (x <= 0) {
    return DRDC_E_DOMAIN;
  }
  if (x <= RSQRT_Q1_30_OVERFLOW_MAX) {
    return DRDC_E_OVERFLOW;
  }
  /* x > 2^28: 2^90 / x < 2^62, r <= 2^31 */
  r = rsqrt_core((uint32_t)x, 90u);
  if (r > (uint64_t)INT32_MAX) {
    return DRDC_E_OVERFLOW;
  }
  *out = (drdc_q1_30_t)r;
  return DRDC_OK;
}
