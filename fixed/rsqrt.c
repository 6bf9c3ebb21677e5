/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_sqrt
 * @brief Correctly rounded reciprocal square roots in Q15.16 and Q1.30.
 *
 * The result is r = round(sqrt(2^e / x)) (e = 48 for Q15.16, 90 for
 * Q1.30). round(sqrt(v)) = floor((floor(2 sqrt(v)) + 1) / 2), and
 * floor(2 sqrt(v)) = isqrt(floor(2^(e+2) / x)): the floor of the root of a
 * real equals the integer root of its floor. So one 64-bit quotient and
 * one integer square root give r exactly, without 128-bit arithmetic.
 */
#include <drdc/fixed_sqrt.h>

#include <stddef.h>

#include "fixed_impl.h"

/* floor(sqrt(n)) from the correctly rounded root (which may be 2^32). */
static uint64_t isqrt_floor(uint64_t n)
{
  uint64_t s = drdc_fx_sqrt_u64(n);

  if (s > UINT32_MAX) {
    s = UINT32_MAX; /* the root of any uint64 is below 2^32 */
  }
  if ((s * s) > n) {
    s--;
  }
  return s;
}

/* round(sqrt(2^e / x)) from q = floor(2^(e+2) / x). */
static uint64_t rsqrt_from_quotient(uint64_t q)
{
  return (isqrt_floor(q) + 1u) >> 1;
}

drdc_status_t drdc_fx_rsqrt_q15_16(drdc_q15_16_t x, drdc_q15_16_t *out)
{
  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if (x <= 0) {
    return DRDC_E_DOMAIN;
  }
  /* x >= 1: 2^50 / x < 2^51, r <= 2^24 */
  *out = (drdc_q15_16_t)rsqrt_from_quotient((UINT64_C(1) << 50) / (uint32_t)x);
  return DRDC_OK;
}

/* Largest Q1.30 input whose reciprocal root overflows: 0.25 (root 2). */
#define RSQRT_Q1_30_OVERFLOW_MAX (INT32_C(1) << 28)

drdc_status_t drdc_fx_rsqrt_q1_30(drdc_q1_30_t x, drdc_q1_30_t *out)
{
  uint64_t q_hi;
  uint64_t rem;
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
  /* x > 2^28: floor(2^92 / x) < 2^64 in two long-division steps of 32
   * bits (the remainder < x < 2^31 leaves room for the shift); r <= 2^31 */
  q_hi = (UINT64_C(1) << 60) / (uint32_t)x;
  rem = (UINT64_C(1) << 60) % (uint32_t)x;
  r = rsqrt_from_quotient((q_hi << 32) + ((rem << 32) / (uint32_t)x));
  if (r > (uint64_t)INT32_MAX) {
    return DRDC_E_OVERFLOW;
  }
  *out = (drdc_q1_30_t)r;
  return DRDC_OK;
}
