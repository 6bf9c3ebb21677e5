/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Tests of the wide-integer primitives of fixed_wide.h against
 *        exact Python integers (tests/ref/gen_fixed_wide.py), and dense
 *        exact identities for the reciprocals and 16-bit digits.
 */
#include <drdc/fixed_wide.h>

#include "suites.h"
#include "unity.h"
#include "vectors_wide.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

static unsigned clz64(uint64_t v)
{
  return (unsigned)__builtin_clzll(v);
}

static void test_div_digit16(void)
{
  size_t i;

  for (i = 0; i < COUNT(digit16_vectors); i++) {
    const struct digit16_vector *t = &digit16_vectors[i];
    uint32_t r = t->r;
    uint32_t q = drdc_fx_div_digit16(&r, t->u, t->d);

    TEST_ASSERT_EQUAL_UINT32_MESSAGE(t->q, q, "quotient digit");
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(t->rem, r, "remainder");
  }
}

/* Dense: 65 536 normalised divisors spread over [2^31, 2^32) (and their
 * neighbours), the 2/1 reciprocal checked by the exact identity
 * 0 <= (2^64 - 1) - (2^32 + v) d < d, computed modulo 2^64 (a v off by
 * k moves the value by k d, out of [0, d)). */
static void test_reciprocal_2by1_dense(void)
{
  uint32_t k;
  uint32_t first_bad = 0u;
  int bad = 0;

  for (k = 0u; k < 65536u; k++) {
    uint32_t d = (UINT32_C(1) << 31) | (k << 15) | ((k * 40503u) & 0x7FFFu);
    uint32_t v = drdc_fx_reciprocal_2by1(d);
    uint64_t rem = UINT64_MAX - ((uint64_t)d << 32u) - ((uint64_t)v * d);

    if ((rem >= d) && (bad == 0)) {
      bad = 1;
      first_bad = d;
    }
  }
  TEST_ASSERT_EQUAL_UINT32(0u, first_bad);
  TEST_ASSERT_EQUAL_INT(0, bad);
  for (k = 0; k < COUNT(recip2_vectors); k++) {
    TEST_ASSERT_EQUAL_UINT32(recip2_vectors[k].v,
                             drdc_fx_reciprocal_2by1(recip2_vectors[k].d));
  }
}

static void test_reciprocal_3by2(void)
{
  size_t i;

  for (i = 0; i < COUNT(recip3_vectors); i++) {
    const struct recip3_vector *t = &recip3_vectors[i];

    TEST_ASSERT_EQUAL_UINT32(t->v, drdc_fx_reciprocal_3by2(t->d1, t->d0));
  }
}

static void test_div_3by2(void)
{
  size_t i;

  for (i = 0; i < COUNT(div3by2_vectors); i++) {
    const struct div3by2_vector *t = &div3by2_vectors[i];
    uint32_t v =
        drdc_fx_reciprocal_3by2((uint32_t)(t->d >> 32u), (uint32_t)t->d);
    uint64_t r = 0u;
    uint32_t q = drdc_fx_div_3by2(t->u2, t->u1, t->u0, t->d, v, &r);

    TEST_ASSERT_EQUAL_UINT32_MESSAGE(t->q, q, "quotient word");
    TEST_ASSERT_EQUAL_UINT64_MESSAGE(t->r, r, "remainder");
  }
}

static void test_mul_u64_u128(void)
{
  size_t i;

  for (i = 0; i < COUNT(mul128_vectors); i++) {
    const struct mul128_vector *t = &mul128_vectors[i];
    uint64_t hi = 0u;
    uint64_t lo = 0u;

    drdc_fx_mul_u64_u128(t->x, t->y, &hi, &lo);
    TEST_ASSERT_EQUAL_UINT64(t->hi, hi);
    TEST_ASSERT_EQUAL_UINT64(t->lo, lo);
  }
}

static void test_round_div_shifted(void)
{
  size_t i;

  for (i = 0; i < COUNT(rdshift_vectors); i++) {
    const struct rdshift_vector *t = &rdshift_vectors[i];
    unsigned z = clz64(t->d);
    uint64_t dn = t->d << z;
    uint32_t rcp = drdc_fx_reciprocal_3by2((uint32_t)(dn >> 32u), (uint32_t)dn);

    TEST_ASSERT_EQUAL_UINT32(
        t->q, drdc_fx_round_div_shifted(t->p, t->t + z, dn, rcp));
  }
}

static void test_round_div_128(void)
{
  size_t i;

  for (i = 0; i < COUNT(rd128_vectors); i++) {
    const struct rd128_vector *t = &rd128_vectors[i];
    unsigned z = clz64(t->d);
    uint64_t dn = t->d << z;
    uint32_t rcp = drdc_fx_reciprocal_3by2((uint32_t)(dn >> 32u), (uint32_t)dn);

    TEST_ASSERT_EQUAL_INT64(t->q,
                            drdc_fx_round_div_128(t->p, t->w, dn, z, rcp));
  }
}

static void test_muldiv_round64(void)
{
  size_t i;

  for (i = 0; i < COUNT(muldiv64_vectors); i++) {
    const struct muldiv64_vector *t = &muldiv64_vectors[i];

    TEST_ASSERT_EQUAL_INT64(t->q, drdc_fx_muldiv_round64(t->a, t->b, t->c));
  }
}

static void test_mul_rshift_round(void)
{
  size_t i;

  for (i = 0; i < COUNT(mulrs_vectors); i++) {
    const struct mulrs_vector *t = &mulrs_vectors[i];

    TEST_ASSERT_EQUAL_INT64(t->q, drdc_fx_mul_rshift_round(t->a, t->b, t->n));
  }
}

static void test_div_128_64(void)
{
  size_t i;

  for (i = 0; i < COUNT(div128_vectors); i++) {
    const struct div128_vector *t = &div128_vectors[i];

    TEST_ASSERT_EQUAL_UINT64(t->q, drdc_fx_div_128_64(t->nh, t->nl, t->x));
  }
}

static void test_hypot62(void)
{
  size_t i;

  for (i = 0; i < COUNT(hypot62_vectors); i++) {
    const struct hypot62_vector *t = &hypot62_vectors[i];

    TEST_ASSERT_EQUAL_UINT64(t->r, drdc_fx_hypot62(t->x, t->y));
  }
}

static void test_headroom_and_high_word(void)
{
  size_t i;

  for (i = 0; i < COUNT(headroom_vectors); i++) {
    const struct headroom_vector *t = &headroom_vectors[i];

    TEST_ASSERT_EQUAL_UINT32(t->s, drdc_fx_headroom(t->v, t->limit));
  }
  TEST_ASSERT_EQUAL_INT32(-1, drdc_fx_high_word(-1));
  TEST_ASSERT_EQUAL_INT32(INT32_MIN, drdc_fx_high_word(INT64_MIN));
  TEST_ASSERT_EQUAL_INT32(INT32_MAX, drdc_fx_high_word(INT64_MAX));
  TEST_ASSERT_EQUAL_INT32(-2, drdc_fx_high_word(-INT64_C(4294967297)));
  TEST_ASSERT_EQUAL_INT32(0, drdc_fx_high_word(INT64_C(4294967295)));
}

void suite_fixed_wide(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_div_digit16);
  RUN_TEST(test_reciprocal_2by1_dense);
  RUN_TEST(test_reciprocal_3by2);
  RUN_TEST(test_div_3by2);
  RUN_TEST(test_mul_u64_u128);
  RUN_TEST(test_round_div_shifted);
  RUN_TEST(test_round_div_128);
  RUN_TEST(test_muldiv_round64);
  RUN_TEST(test_mul_rshift_round);
  RUN_TEST(test_div_128_64);
  RUN_TEST(test_hypot62);
  RUN_TEST(test_headroom_and_high_word);
}
