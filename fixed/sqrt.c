/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_sqrt
 * @brief Correctly rounded square roots of integers, Q15.16 and Q1.30.
 *
 * Digit-by-digit (base 4) square root: one result bit per step, using only
 * shifts, compares and subtractions, giving floor(sqrt(n)) = s and the
 * remainder n - s^2. Rounding to nearest: sqrt(n) >= s + 1/2 exactly when
 * n >= s^2 + s + 1/4, i.e. (integers) remainder > s.
 */
#include <drdc/fixed_sqrt.h>

#include <stddef.h>

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

/* The same digit-by-digit root for n < 2^58 with 32-bit registers only
 * (the targets are 32-bit): two input bits enter the remainder per step,
 * high word first. The remainder stays below 2 root + 1 < 2^30, so after
 * taking two more bits it is below 2^32; the root stays below 2^29. */
static uint64_t sqrt_u58(uint64_t n)
{
  uint32_t high = (uint32_t)(n >> 32);
  uint32_t low = (uint32_t)n;
  uint32_t rem = 0;
  uint32_t root = 0;
  unsigned w;

  for (w = 0u; w < 2u; w++) {
    uint32_t word = (w == 0u) ? high : low;
    unsigned pairs = 16u;

    if ((w == 0u) || (root == 0u)) {
      /* leading zero pairs of the number add nothing */
      while ((pairs != 0u) && ((word >> 30) == 0u)) {
        word <<= 2;
        pairs--;
      }
    }
    for (; pairs != 0u; pairs--) {
      uint32_t trial;

      rem = (rem << 2) | (word >> 30);
      word <<= 2;
      trial = (root << 2) | 1u;
      if (rem >= trial) {
        rem -= trial;
        root = (root << 1) | 1u;
      } else {
        root <<= 1;
      }
    }
  }
  return (rem > root) ? ((uint64_t)root + 1u) : (uint64_t)root;
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

drdc_status_t drdc_fx_sqrt_q15_16(drdc_q15_16_t x, drdc_q15_16_t *out)
{
  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if (x < 0) {
    return DRDC_E_DOMAIN;
  }
  /* x 2^16 < 2^47, root < 2^23.5 */
  *out = (drdc_q15_16_t)sqrt_u58((uint64_t)x << 16);
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
