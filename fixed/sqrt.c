/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_sqrt
 * @brief Correctly rounded square roots of integers, Q15.16 and Q1.30.
 *
 * Integers and Q1.30: digit-by-digit (base 4) square root, one result bit
 * per step, using only shifts, compares and subtractions, giving
 * floor(sqrt(n)) = s and the remainder n - s^2. Rounding to nearest:
 * sqrt(n) >= s + 1/2 exactly when n >= s^2 + s + 1/4, i.e. (integers)
 * remainder > s.
 *
 * Q15.16, the hot one: a seed table, one Newton step and one step of
 * Zimmermann's Karatsuba square root (P. Zimmermann, "Karatsuba Square
 * Root", INRIA RR-3805, 1999) in 32-bit words with two hardware divides:
 * about 50 instructions instead of 24 two-bit steps.
 */
#include <drdc/fixed_sqrt.h>

#include <stddef.h>

#include <drdc/compiler.h>

#include "sqrt_impl.h"

uint32_t drdc_fx_sqrt_u32(uint32_t n)
{
  uint32_t rem = n;
  uint32_t root = 0;
  uint32_t bit = UINT32_C(1) << 30;

  while (bit > rem) {
    bit >>= 2;
  }
  while (bit != 0u) {
    if (rem >= (root + bit)) {
      rem -= root + bit;
      root = (root >> 1) + bit;
    } else {
      root >>= 1;
    }
    bit >>= 2;
  }
  return (rem > root) ? (root + 1u) : root;
}

uint64_t drdc_fx_sqrt_u64(uint64_t n)
{
  uint64_t rem = n;
  uint64_t root = 0;
  uint64_t bit = UINT64_C(1) << 62;

  if (n <= UINT32_MAX) {
    return drdc_fx_sqrt_u32((uint32_t)n); /* 32-bit steps are cheaper */
  }
  while (bit > rem) {
    bit >>= 2;
  }
  while (bit != 0u) {
    if (rem >= (root + bit)) {
      rem -= root + bit;
      root = (root >> 1) + bit;
    } else {
      root >>= 1;
    }
    bit >>= 2;
  }
  return (rem > root) ? (root + 1u) : root;
}

/* Base of the two-digit step of sqrt_q15_16: 2^13. */
#define SQRT_DIGIT_BITS 13u

drdc_status_t drdc_fx_sqrt_q15_16(drdc_q15_16_t x, drdc_q15_16_t *out)
{
  uint32_t z;
  uint32_t m;
  uint32_t k;
  uint32_t h;
  uint32_t s1;
  uint32_t num;
  uint32_t q;
  uint32_t u;
  uint32_t s;

  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if (x <= 0) {
    if (x < 0) {
      return DRDC_E_DOMAIN;
    }
    *out = 0;
    return DRDC_OK;
  }
  /* n = x 2^16 < 2^47, scaled by 4^k into N = n 4^k = m 2^20 in
   * [2^50, 2^52) with m = x 2^(2 floor(clz / 2)) in [2^30, 2^32), so
   * k = floor(clz / 2) + 2 >= 2. */
  z = (uint32_t)drdc__clz32((uint32_t)x) & ~1u;
  m = (uint32_t)x << z;
  k = (z >> 1) + 2u;
  /* floor(sqrt(N)) by one step of Zimmermann's Karatsuba square root
   * in base b = 2^13 (N = H b^2 + a1 b + a0, H = N / 2^26 in [2^24, 2^26),
   * a1 = the low 6 bits of m times 2^7, a0 = 0):
   *   (s1, r1) = sqrt and remainder of H; (q, u) = (r1 b + a1) / (2 s1)
   *   with remainder; s = s1 b + q, less one when u b + a0 < q^2.
   * H >= b^2 / 4 makes the one correction sufficient. */
  h = m >> 6;
  /* floor(sqrt(H)): one Newton step from the table's upper bound of the
   * root over H's bin lands on it or one above (checked for every H) */
  s1 = drdc__flash_u16(&drdc__fx_sqrt_seed[(m >> 24) - FX_SQRT_SEED_FIRST]);
  s1 = (s1 + (h / s1)) >> 1;
  if ((s1 * s1) > h) {
    s1--;
  }
  /* r1 = h - s1^2 <= 2 s1 < 2^14: num < 2^27 + 2^13 */
  num = ((h - (s1 * s1)) << SQRT_DIGIT_BITS) | ((m & 0x3Fu) << 7);
  q = num / (s1 << 1);       /* <= b */
  u = num - (q * (s1 << 1)); /* < 2 s1 < 2^14 */
  s = (s1 << SQRT_DIGIT_BITS) + q;
  if ((u << SQRT_DIGIT_BITS) < (q * q)) {
    s--;
  }
  /* round(sqrt(n)) = floor(sqrt(N) / 2^k + 1/2) = (s + 2^(k-1)) >> k:
   * adding the integer 2^(k-1) commutes with the floor of sqrt(N) */
  *out = (drdc_q15_16_t)((s + (UINT32_C(1) << (k - 1u))) >> k);
  return DRDC_OK;
}

drdc_status_t drdc_fx_sqrt_q1_30(drdc_q1_30_t x, drdc_q1_30_t *out)
{
  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if (x < 0) {
    return DRDC_E_DOMAIN;
  }
  /* x 2^30 < 2^61, root < 2^30.5 < 2^31 */
  *out = (drdc_q1_30_t)drdc_fx_sqrt_u64((uint64_t)x << 30);
  return DRDC_OK;
}
