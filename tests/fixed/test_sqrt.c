/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Tests of fixed/ square roots: the exact rounding criterion over
 *        exhaustive small domains and structured points, exact-integer
 *        reference tables for rsqrt and hypot, named bad inputs.
 */
#include <drdc/fixed_sqrt.h>

#include <stddef.h>

#include "suites.h"
#include "unity.h"
#include "vectors_sqrt.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

/* r == round(sqrt(n)) iff r^2 - r < n <= r^2 + r (from (r -+ 1/2)^2 and
 * integer n); r == 2^32 is right only for n > 2^64 - 2^32. */
static int is_rounded_root(uint64_t n, uint64_t r)
{
  if (r > (UINT64_C(1) << 32)) {
    return 0;
  }
  if (r == (UINT64_C(1) << 32)) {
    return n > (UINT64_MAX - UINT32_MAX);
  }
  return ((r * r) - r < n || ((r == 0u) && (n == 0u))) && (n <= (r * r) + r);
}

/* Every n < 2^20: the whole small domain. */
static void test_sqrt_u32_exhaustive_below_2_20(void)
{
  uint32_t n;
  uint32_t first_bad = UINT32_MAX;

  for (n = 0; n < (UINT32_C(1) << 20); n++) {
    if (!is_rounded_root(n, drdc_fx_sqrt_u32(n))) {
      first_bad = n;
      break;
    }
  }
  TEST_ASSERT_EQUAL_UINT32(UINT32_MAX, first_bad);
}

/* Around every square k^2 and every rounding boundary k^2 + k (the root
 * rounds down) / k^2 + k + 1 (up), for every k < 2^16, plus the top. */
static void test_sqrt_u32_at_every_boundary(void)
{
  uint32_t k;
  uint32_t first_bad = UINT32_MAX;

  for (k = 1; k < 65536u; k++) {
    uint32_t sq = k * k;
    uint32_t n[5];
    int j;

    n[0] = sq - 1u;
    n[1] = sq;
    n[2] = sq + 1u;
    n[3] = sq + k;
    n[4] = sq + k + 1u;
    for (j = 0; j < 5; j++) {
      if (!is_rounded_root(n[j], drdc_fx_sqrt_u32(n[j]))) {
        first_bad = k;
      }
    }
    if ((drdc_fx_sqrt_u32(sq + k) != k) ||
        (drdc_fx_sqrt_u32(sq + k + 1u) != k + 1u)) {
      first_bad = k;
    }
  }
  TEST_ASSERT_EQUAL_UINT32(UINT32_MAX, first_bad);
  TEST_ASSERT_EQUAL_UINT32(65536u, drdc_fx_sqrt_u32(UINT32_MAX));
  TEST_ASSERT_EQUAL_UINT32(65535u, drdc_fx_sqrt_u32(4294901760u));
  TEST_ASSERT_EQUAL_UINT32(65536u, drdc_fx_sqrt_u32(4294901761u));
  TEST_ASSERT_EQUAL_UINT32(0u, drdc_fx_sqrt_u32(0u));
  TEST_ASSERT_EQUAL_UINT32(1u, drdc_fx_sqrt_u32(1u));
  TEST_ASSERT_EQUAL_UINT32(1u, drdc_fx_sqrt_u32(2u));
  TEST_ASSERT_EQUAL_UINT32(2u, drdc_fx_sqrt_u32(3u));
}

/* 64-bit: the same boundaries for k spread over 0..2^32 (every 2^32/2^17
 * plus an odd offset), and a pseudo-random walk of 2^18 points. */
static void test_sqrt_u64_structured_and_random(void)
{
  uint64_t k;
  uint64_t first_bad = 0;
  uint64_t lcg = 12345u;
  uint32_t i;

  for (k = 3; k < (UINT64_C(1) << 32); k += 32771u) {
    uint64_t sq = k * k;
    uint64_t n[5];
    int j;

    n[0] = sq - 1u;
    n[1] = sq;
    n[2] = sq + 1u;
    n[3] = sq + k;
    n[4] = sq + k + 1u;
    for (j = 0; j < 5; j++) {
      if (!is_rounded_root(n[j], drdc_fx_sqrt_u64(n[j]))) {
        first_bad = n[j];
      }
    }
  }
  for (i = 0; i < (UINT32_C(1) << 18); i++) {
    uint64_t n;

    lcg = (lcg * UINT64_C(6364136223846793005)) + UINT64_C(1442695040888963407);
    n = lcg >> (lcg & 63u); /* every magnitude */
    if (!is_rounded_root(n, drdc_fx_sqrt_u64(n))) {
      first_bad = n;
    }
  }
  TEST_ASSERT_EQUAL_UINT64(0, first_bad);
  TEST_ASSERT_EQUAL_UINT64(UINT64_C(1) << 32, drdc_fx_sqrt_u64(UINT64_MAX));
  TEST_ASSERT_EQUAL_UINT64(UINT32_MAX,
                           drdc_fx_sqrt_u64(UINT64_MAX - UINT32_MAX));
  TEST_ASSERT_EQUAL_UINT64(UINT64_C(1) << 32,
                           drdc_fx_sqrt_u64(UINT64_MAX - UINT32_MAX + 1u));
  TEST_ASSERT_EQUAL_UINT64(65536u, drdc_fx_sqrt_u64(UINT32_MAX));
  TEST_ASSERT_EQUAL_UINT64(65536u, drdc_fx_sqrt_u64((uint64_t)UINT32_MAX + 1u));
}

/* Q forms are the integer root of x shifted up: same criterion. */
static void test_sqrt_q_formats(void)
{
  int32_t x;
  int32_t bad = -1;
  drdc_q15_16_t r = 0;

  for (x = 0; x < INT32_MAX - 65537; x += 65537) {
    drdc_q15_16_t a = -1;
    drdc_q1_30_t b = -1;

    if ((drdc_fx_sqrt_q15_16(x, &a) != DRDC_OK) ||
        !is_rounded_root((uint64_t)x << 16, (uint64_t)a) ||
        (drdc_fx_sqrt_q1_30(x, &b) != DRDC_OK) ||
        !is_rounded_root((uint64_t)x << 30, (uint64_t)b)) {
      bad = x;
    }
  }
  TEST_ASSERT_EQUAL_INT32(-1, bad);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_sqrt_q15_16(4 << 16, &r));
  TEST_ASSERT_EQUAL_INT32(2 << 16, r);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_sqrt_q15_16(INT32_MAX, &r));
  TEST_ASSERT_EQUAL_INT32(11863283, r); /* 181.019... m^(1/2) */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_sqrt_q1_30(1 << 30, &r));
  TEST_ASSERT_EQUAL_INT32(1 << 30, r);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_sqrt_q1_30(INT32_MAX, &r));
  TEST_ASSERT_EQUAL_INT32(1518500250, r); /* sqrt(2) 2^30 */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_sqrt_q1_30(0, &r));
  TEST_ASSERT_EQUAL_INT32(0, r);
}

/* drdc_fx_sqrt_q15_16 takes one Zimmermann step after a table-seeded
 * Newton step (fixed/sqrt.c); its risky inputs are small x, the edges of
 * the 192 seed bins at every normalising shift, and x on either side of
 * each rounding boundary (x 2^16 around r^2 + r). Each is judged by the
 * exact criterion. (On the host every x in [0, 2^31) was compared with
 * the digit-by-digit root it replaced: identical.) */
static int q15_16_root_ok(int32_t x)
{
  drdc_q15_16_t r = -1;

  return (drdc_fx_sqrt_q15_16(x, &r) == DRDC_OK) &&
         is_rounded_root((uint64_t)x << 16, (uint64_t)r);
}

static void test_sqrt_q15_16_dense(void)
{
  int32_t bad = -1;
  uint32_t x;
  uint32_t j;
  uint32_t z;
  uint32_t r;

  for (x = 0; x < 65536u; x++) { /* every small x */
    if (!q15_16_root_ok((int32_t)x)) {
      bad = (int32_t)x;
    }
  }
  for (z = 0; z <= 30u; z += 2u) { /* every shift, every bin */
    for (j = 64u; j < 256u; j++) {
      uint32_t first = (j << 24) >> z; /* m = x 2^z in bin j */
      uint32_t last = (((j + 1u) << 24) - 1u) >> z;

      if (((first >> 31) == 0u) && !q15_16_root_ok((int32_t)first)) {
        bad = (int32_t)first;
      }
      if (((last >> 31) == 0u) && !q15_16_root_ok((int32_t)last)) {
        bad = (int32_t)last;
      }
    }
  }
  /* rounding boundaries: x = floor((r^2 + r) / 2^16) rounds down to r,
   * x + 1 up to r + 1; r < 2^23.5 */
  for (r = 1u; r < 11863283u; r += 97u) {
    uint64_t b = (((uint64_t)r * r) + r) >> 16;

    if (!q15_16_root_ok((int32_t)b) || !q15_16_root_ok((int32_t)(b + 1u))) {
      bad = (int32_t)b;
    }
  }
  TEST_ASSERT_EQUAL_INT32(-1, bad);
}

static void test_rsqrt_q15_16(void)
{
  size_t i;
  int32_t x;
  int32_t bad = 0;

  for (i = 0; i < COUNT(rsqrt_q15_16_vectors); i++) {
    drdc_q15_16_t r = 0;

    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_fx_rsqrt_q15_16(rsqrt_q15_16_vectors[i].x, &r));
    TEST_ASSERT_EQUAL_INT32(rsqrt_q15_16_vectors[i].r, r);
  }
  /* every x < 2^16 by the criterion x (2r-1)^2 < 2^50 < x (2r+1)^2 */
  for (x = 1; x < 65536; x++) {
    drdc_q15_16_t r = 0;
    uint64_t lo;
    uint64_t hi;

    (void)drdc_fx_rsqrt_q15_16(x, &r);
    lo = (uint64_t)x * (uint64_t)((2 * (int64_t)r) - 1) *
         (uint64_t)((2 * (int64_t)r) - 1);
    hi = (uint64_t)x * (uint64_t)((2 * (int64_t)r) + 1) *
         (uint64_t)((2 * (int64_t)r) + 1);
    if (!((lo < (UINT64_C(1) << 50)) && ((UINT64_C(1) << 50) < hi))) {
      bad = x;
    }
  }
  TEST_ASSERT_EQUAL_INT32(0, bad);
}

static void test_rsqrt_q1_30(void)
{
  size_t i;
  drdc_q1_30_t r = 77;

  for (i = 0; i < COUNT(rsqrt_q1_30_vectors); i++) {
    r = 0;
    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_fx_rsqrt_q1_30(rsqrt_q1_30_vectors[i].x, &r));
    TEST_ASSERT_EQUAL_INT32(rsqrt_q1_30_vectors[i].r, r);
  }
  r = 77;
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_fx_rsqrt_q1_30(1 << 28, &r));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_fx_rsqrt_q1_30(1, &r));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_fx_rsqrt_q1_30(0, &r));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_fx_rsqrt_q1_30(INT32_MIN, &r));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_rsqrt_q1_30(1 << 30, NULL));
  TEST_ASSERT_EQUAL_INT32(77, r);
}

static void test_hypot(void)
{
  size_t i;
  int32_t x;
  int32_t bad = 0;
  drdc_q15_16_t q = 5;

  for (i = 0; i < COUNT(hypot64_vectors); i++) {
    TEST_ASSERT_EQUAL_UINT64(
        hypot64_vectors[i].r,
        drdc_fx_hypot_s64(hypot64_vectors[i].x, hypot64_vectors[i].y));
  }
  /* int32 hypot is the rounded root of the exact 64-bit sum of squares */
  for (x = INT32_MIN; x < INT32_MAX - 8388609; x += 8388609) {
    int32_t y = (int32_t)(((int64_t)x * 7) / 11);
    uint64_t n = ((uint64_t)((int64_t)x * x)) + (uint64_t)((int64_t)y * y);

    if (!is_rounded_root(n, drdc_fx_hypot_s32(x, y)) ||
        (drdc_fx_hypot_s32(x, y) != (uint32_t)drdc_fx_hypot_s64(x, y))) {
      bad = x;
    }
  }
  TEST_ASSERT_EQUAL_INT32(0, bad);
  TEST_ASSERT_EQUAL_UINT32(5u, drdc_fx_hypot_s32(3, -4));
  TEST_ASSERT_EQUAL_UINT32(3037000500u,
                           drdc_fx_hypot_s32(INT32_MIN, INT32_MIN));
  TEST_ASSERT_EQUAL_UINT32(UINT32_C(1) << 31, drdc_fx_hypot_s32(INT32_MIN, 0));
  TEST_ASSERT_EQUAL_UINT32(0u, drdc_fx_hypot_s32(0, 0));
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_hypot_q15_16(3 << 16, 4 << 16, &q));
  TEST_ASSERT_EQUAL_INT32(5 << 16, q);
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_fx_hypot_q15_16(INT32_MIN, 0, &q));
  TEST_ASSERT_EQUAL_INT32(5 << 16, q);
  TEST_ASSERT_EQUAL_INT(DRDC_W_SATURATED,
                        drdc_fx_hypot_q15_16_sat(INT32_MIN, 0, &q));
  TEST_ASSERT_EQUAL_INT32(INT32_MAX, q);
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_hypot_q15_16(0, 0, NULL));
}

static void test_bad_inputs_leave_outputs(void)
{
  int32_t r = 42;

  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_fx_sqrt_q15_16(-1, &r));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_fx_sqrt_q15_16(INT32_MIN, &r));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_fx_sqrt_q1_30(-1, &r));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_fx_rsqrt_q15_16(0, &r));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_fx_rsqrt_q15_16(-5, &r));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_sqrt_q15_16(1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_sqrt_q1_30(1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_rsqrt_q15_16(1, NULL));
  TEST_ASSERT_EQUAL_INT32(42, r);
}

void suite_fixed_sqrt(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_sqrt_u32_exhaustive_below_2_20);
  RUN_TEST(test_sqrt_u32_at_every_boundary);
  RUN_TEST(test_sqrt_u64_structured_and_random);
  RUN_TEST(test_sqrt_q_formats);
  RUN_TEST(test_sqrt_q15_16_dense);
  RUN_TEST(test_rsqrt_q15_16);
  RUN_TEST(test_rsqrt_q1_30);
  RUN_TEST(test_hypot);
  RUN_TEST(test_bad_inputs_leave_outputs);
}
