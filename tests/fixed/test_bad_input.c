/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Bad-input rows of the fixed-point arithmetic that the other
 *        suites do not name (docs/bad-input.md): a NULL `out`, and
 *        results beyond the output format of each product,
 *        quotient and multiply-divide, in the plain form (DRDC_E_OVERFLOW,
 *        `*out` unchanged) and the _sat form (DRDC_W_SATURATED, `*out`
 *        the limit on the side of the true result).
 *
 * Every case states its exact real result; overflow is decided on the
 * rounded result (fixed_arith.h), so the cases include results that
 * round onto the limit from inside (ties away from zero) and the
 * in-range neighbours that must still succeed.
 */
#include <drdc/fixed_arith.h>

#include <stddef.h>

#include "suites.h"
#include "unity.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

/* Pre-filled into every output; an error must leave it there. */
#define SENTINEL32 INT32_C(0x5A5A5A5A)
#define SENTINEL64 INT64_C(0x5A5A5A5A5A5A5A5A)

/* One out-of-range case of a 32-bit operation: the operands, the limit
 * the _sat form must write, and why the true result is out of range. */
struct case32 {
  int32_t a;
  int32_t b;
  int32_t c; /* divisor of muldiv; unused elsewhere */
  int32_t limit;
  const char *why;
};

/* The same for 64-bit operations. */
struct case64 {
  int64_t a;
  int64_t b;
  int64_t c;
  int64_t limit;
  const char *why;
};

/* A product or quotient of one format: the plain and the _sat form have
 * the same type (the formats are typedefs of int32_t or int64_t). */
typedef drdc_status_t (*op32_fn)(int32_t a, int32_t b, int32_t *out);
typedef drdc_status_t (*op64_fn)(int64_t a, int64_t b, int64_t *out);

/* Each case through the plain form, which must return `plain_status`
 * and leave the sentinel, then the _sat form, which must return
 * `sat_status` and write the case's limit; every assertion names the
 * case. The caller passes the statuses so that each test function names
 * the function and the status it tests: that is how tools/gates/badinput.py
 * finds the test of a row of docs/bad-input.md. */
static void expect_beyond32(op32_fn plain, drdc_status_t plain_status,
                            op32_fn sat, drdc_status_t sat_status,
                            const struct case32 *cases, size_t n)
{
  size_t i;

  for (i = 0; i < n; i++) {
    const struct case32 *k = &cases[i];
    int32_t out = SENTINEL32;

    TEST_ASSERT_EQUAL_INT_MESSAGE(plain_status, plain(k->a, k->b, &out),
                                  k->why);
    TEST_ASSERT_EQUAL_INT32_MESSAGE(SENTINEL32, out, k->why);
    TEST_ASSERT_EQUAL_INT_MESSAGE(sat_status, sat(k->a, k->b, &out), k->why);
    TEST_ASSERT_EQUAL_INT32_MESSAGE(k->limit, out, k->why);
  }
}

/* The same for 64-bit formats. */
static void expect_beyond64(op64_fn plain, drdc_status_t plain_status,
                            op64_fn sat, drdc_status_t sat_status,
                            const struct case64 *cases, size_t n)
{
  size_t i;

  for (i = 0; i < n; i++) {
    const struct case64 *k = &cases[i];
    int64_t out = SENTINEL64;

    TEST_ASSERT_EQUAL_INT_MESSAGE(plain_status, plain(k->a, k->b, &out),
                                  k->why);
    TEST_ASSERT_EQUAL_INT64_MESSAGE(SENTINEL64, out, k->why);
    TEST_ASSERT_EQUAL_INT_MESSAGE(sat_status, sat(k->a, k->b, &out), k->why);
    TEST_ASSERT_EQUAL_INT64_MESSAGE(k->limit, out, k->why);
  }
}

/* ------------------------------------------------------------ NULL */

static void test_null_out_gives_null(void)
{
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_q47_16_from_int_sat(1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_q15_16_from_q47_16_sat(1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_q1_30_from_q15_16_sat(1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_mul_q1_30(1, 1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_mul_q1_30_sat(1, 1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_mul_q15_16(1, 1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_mul_q15_16_sat(1, 1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_mul_q47_16(1, 1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_mul_q47_16_sat(1, 1, NULL));
  /* the NULL check comes first: also with operands that would overflow
   * or divide by zero */
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_fx_q47_16_from_int_sat(INT64_MAX, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_fx_q15_16_from_q47_16_sat(INT64_MIN, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_fx_q1_30_from_q15_16_sat(INT32_MAX, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_fx_mul_q1_30_sat(INT32_MIN, INT32_MIN, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_fx_mul_q15_16(INT32_MIN, INT32_MIN, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_fx_mul_q47_16_sat(INT64_MIN, INT64_MIN, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_div_q1_30_sat(1, 0, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_muldiv_s64_sat(1, 1, 0, NULL));
}

/* ------------------------------------------------------- products */

/* Q1.30 covers [-2, 2): the product overflows when it rounds to 2 or
 * more, or below -2. */
static void test_mul_q1_30_beyond_2_overflows_or_saturates(void)
{
  static const struct case32 cases[] = {
      {INT32_MIN, -(INT32_C(1) << 30), 0, INT32_MAX, "-2 * -1 = 2"},
      {INT32_MIN, INT32_MIN, 0, INT32_MAX, "-2 * -2 = 4"},
      {INT32_MAX, INT32_MAX, 0, INT32_MAX, "(2 - 2^-30)^2 = 4 - 2^-28 + .."},
      /* 65535 2^15 * 65537 2^14 = (2^32 - 1) 2^29 raw, / 2^30 =
       * 2^31 - 0.5: the tie rounds away from zero, onto 2^31 = 2.0 */
      {INT32_C(2147450880), INT32_C(1073758208), 0, INT32_MAX,
       "2 - 2^-31 rounds to 2"},
      {INT32_MIN, INT32_MAX, 0, INT32_MIN, "-2 * (2 - 2^-30) = -4 + 2^-29"},
      {INT32_MIN, (INT32_C(1) << 30) + 1, 0, INT32_MIN,
       "-2 * (1 + 2^-30) = -2 - 2^-29"},
  };
  drdc_q1_30_t out = SENTINEL32;

  expect_beyond32(drdc_fx_mul_q1_30, DRDC_E_OVERFLOW, drdc_fx_mul_q1_30_sat,
                  DRDC_W_SATURATED, cases, COUNT(cases));
  /* the neighbours inside: -2 * 1 = -2 is INT32_MIN exactly */
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_fx_mul_q1_30(INT32_MIN, INT32_C(1) << 30, &out));
  TEST_ASSERT_EQUAL_INT32(INT32_MIN, out);
  TEST_ASSERT_EQUAL_INT(
      DRDC_OK, drdc_fx_mul_q1_30_sat(INT32_MIN, INT32_C(1) << 30, &out));
  TEST_ASSERT_EQUAL_INT32(INT32_MIN, out);
}

/* Q15.16 covers [-32768, 32768) m. */
static void test_mul_q15_16_beyond_32768_overflows_or_saturates(void)
{
  static const struct case32 cases[] = {
      {INT32_C(256) << 16, INT32_C(128) << 16, 0, INT32_MAX,
       "256 * 128 = 32768"},
      {INT32_MIN, INT32_MIN, 0, INT32_MAX, "-32768 * -32768 = 2^30"},
      {-(INT32_C(256) << 16), INT32_C(129) << 16, 0, INT32_MIN,
       "-256 * 129 = -33024"},
      /* raw (2^31 - 1) (2^16 + 1) / 2^16 = 2^31 + 2^15 - 1 - 2^-16, about
       * 32768.5 m: beyond INT32_MAX */
      {INT32_MAX, (INT32_C(1) << 16) + 1, 0, INT32_MAX,
       "(32768 - 2^-16) * (1 + 2^-16)"},
  };
  drdc_q15_16_t out = SENTINEL32;

  expect_beyond32(drdc_fx_mul_q15_16, DRDC_E_OVERFLOW, drdc_fx_mul_q15_16_sat,
                  DRDC_W_SATURATED, cases, COUNT(cases));
  /* -256 * 128 = -32768 is INT32_MIN exactly */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_mul_q15_16(-(INT32_C(256) << 16),
                                                    INT32_C(128) << 16, &out));
  TEST_ASSERT_EQUAL_INT32(INT32_MIN, out);
}

/* Q47.16 covers [-2^47, 2^47) m: raw [-2^63, 2^63). */
static void test_mul_q47_16_beyond_2_47_overflows_or_saturates(void)
{
  static const struct case64 cases[] = {
      /* 2^24 m * 2^23 m = 2^47 m: raw 2^40 2^39 / 2^16 = 2^63 */
      {INT64_C(1) << 40, INT64_C(1) << 39, 0, INT64_MAX, "2^24 * 2^23"},
      /* (2^32 - 1) 2^15 * (2^32 + 1) = (2^64 - 1) 2^15 raw, / 2^16 =
       * 2^63 - 0.5: the tie rounds away from zero, onto 2^63 */
      {(INT64_C(4294967295) << 15), INT64_C(4294967297), 0, INT64_MAX,
       "raw 2^63 - 0.5 rounds to 2^63"},
      /* raw 2^126 / 2^16 = 2^110: beyond 64 bits altogether */
      {INT64_MIN, INT64_MIN, 0, INT64_MAX, "-2^47 * -2^47 = 2^94"},
      {-(INT64_C(1) << 40), INT64_C(1) << 40, 0, INT64_MIN,
       "-2^24 * 2^24 = -2^48"},
      {INT64_MIN, INT64_MAX, 0, INT64_MIN, "-2^47 * (2^47 - 2^-16)"},
  };
  drdc_q47_16_t out = SENTINEL64;

  expect_beyond64(drdc_fx_mul_q47_16, DRDC_E_OVERFLOW, drdc_fx_mul_q47_16_sat,
                  DRDC_W_SATURATED, cases, COUNT(cases));
  /* -2^24 * 2^23 = -2^47 m is INT64_MIN exactly */
  TEST_ASSERT_EQUAL_INT(
      DRDC_OK, drdc_fx_mul_q47_16(-(INT64_C(1) << 40), INT64_C(1) << 39, &out));
  TEST_ASSERT_EQUAL_INT64(INT64_MIN, out);
}

/* ------------------------------------------------------ quotients */

static void test_div_q1_30_beyond_2_overflows_or_saturates(void)
{
  static const struct case32 cases[] = {
      {INT32_C(1) << 30, INT32_C(1) << 29, 0, INT32_MAX, "1 / 0.5 = 2"},
      {INT32_MIN, -(INT32_C(1) << 30), 0, INT32_MAX, "-2 / -1 = 2"},
      /* (2 - 2^-30) / 2^-30 = 2^31 - 1 */
      {INT32_MAX, 1, 0, INT32_MAX, "(2 - 2^-30) / 2^-30"},
      {-(INT32_C(3) << 29), INT32_C(1) << 29, 0, INT32_MIN, "-1.5 / 0.5 = -3"},
      {INT32_MIN, INT32_C(1) << 29, 0, INT32_MIN, "-2 / 0.5 = -4"},
  };
  drdc_q1_30_t out = SENTINEL32;

  expect_beyond32(drdc_fx_div_q1_30, DRDC_E_OVERFLOW, drdc_fx_div_q1_30_sat,
                  DRDC_W_SATURATED, cases, COUNT(cases));
  /* -1 / 0.5 = -2 is INT32_MIN exactly */
  TEST_ASSERT_EQUAL_INT(
      DRDC_OK, drdc_fx_div_q1_30(-(INT32_C(1) << 30), INT32_C(1) << 29, &out));
  TEST_ASSERT_EQUAL_INT32(INT32_MIN, out);
}

static void test_div_q15_16_beyond_32768_overflows_or_saturates(void)
{
  static const struct case32 cases[] = {
      {INT32_C(16384) << 16, INT32_C(1) << 15, 0, INT32_MAX,
       "16384 / 0.5 = 32768"},
      {INT32_MIN, -(INT32_C(1) << 16), 0, INT32_MAX, "-32768 / -1 = 32768"},
      {INT32_C(1) << 16, 1, 0, INT32_MAX, "1 / 2^-16 = 65536"},
      {-(INT32_C(16384) << 16), INT32_C(1) << 14, 0, INT32_MIN,
       "-16384 / 0.25 = -65536"},
      {INT32_MAX, -1, 0, INT32_MIN, "(32768 - 2^-16) / -2^-16"},
  };
  drdc_q15_16_t out = SENTINEL32;

  expect_beyond32(drdc_fx_div_q15_16, DRDC_E_OVERFLOW, drdc_fx_div_q15_16_sat,
                  DRDC_W_SATURATED, cases, COUNT(cases));
  /* -32768 / 1 = -32768 is INT32_MIN exactly */
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_fx_div_q15_16(INT32_MIN, INT32_C(1) << 16, &out));
  TEST_ASSERT_EQUAL_INT32(INT32_MIN, out);
}

static void test_div_q47_16_beyond_2_47_overflows_or_saturates(void)
{
  static const struct case64 cases[] = {
      {INT64_MIN, -(INT64_C(1) << 16), 0, INT64_MAX, "-2^47 / -1 = 2^47"},
      {INT64_C(1) << 62, INT64_C(1) << 15, 0, INT64_MAX, "2^46 / 0.5 = 2^47"},
      /* raw 2^63 2^16 / 1 = 2^79: a quotient of more than 64 bits */
      {INT64_MAX, 1, 0, INT64_MAX, "(2^47 - 2^-16) / 2^-16"},
      {INT64_MIN, INT64_C(1) << 15, 0, INT64_MIN, "-2^47 / 0.5 = -2^48"},
      {INT64_C(1) << 62, -(INT64_C(1) << 14), 0, INT64_MIN,
       "2^46 / -0.25 = -2^48"},
  };
  drdc_q47_16_t out = SENTINEL64;

  expect_beyond64(drdc_fx_div_q47_16, DRDC_E_OVERFLOW, drdc_fx_div_q47_16_sat,
                  DRDC_W_SATURATED, cases, COUNT(cases));
  /* -2^47 / 1 = -2^47 is INT64_MIN exactly */
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_fx_div_q47_16(INT64_MIN, INT64_C(1) << 16, &out));
  TEST_ASSERT_EQUAL_INT64(INT64_MIN, out);
}

/* ------------------------------------------------ multiply-divide */

static void test_muldiv_s32_beyond_int32_overflows_or_saturates(void)
{
  static const struct case32 cases[] = {
      {INT32_MAX, 2, 1, INT32_MAX, "(2^31 - 1) 2 / 1"},
      {INT32_MIN, 1, -1, INT32_MAX, "-2^31 / -1 = 2^31"},
      {INT32_MIN, INT32_MIN, 1, INT32_MAX, "2^62"},
      /* 65535 * 65537 = 2^32 - 1; / 2 = 2^31 - 0.5, the tie rounds away
       * from zero onto 2^31 */
      {65535, 65537, 2, INT32_MAX, "2^31 - 0.5 rounds to 2^31"},
      /* 641 * 6700417 = 2^32 + 1; -(2^32 + 1) / 2 = -2^31 - 0.5 rounds to
       * -2^31 - 1 */
      {-641, 6700417, 2, INT32_MIN, "-2^31 - 0.5 rounds to -2^31 - 1"},
      {INT32_MIN, 2, 1, INT32_MIN, "-2^32"},
  };
  size_t i;

  for (i = 0; i < COUNT(cases); i++) {
    const struct case32 *k = &cases[i];
    int32_t out = SENTINEL32;

    TEST_ASSERT_EQUAL_INT_MESSAGE(
        DRDC_E_OVERFLOW, drdc_fx_muldiv_s32(k->a, k->b, k->c, &out), k->why);
    TEST_ASSERT_EQUAL_INT32_MESSAGE(SENTINEL32, out, k->why);
    TEST_ASSERT_EQUAL_INT_MESSAGE(
        DRDC_W_SATURATED, drdc_fx_muldiv_s32_sat(k->a, k->b, k->c, &out),
        k->why);
    TEST_ASSERT_EQUAL_INT32_MESSAGE(k->limit, out, k->why);
  }
  {
    int32_t out = SENTINEL32;

    /* -(2^32 - 1) / 2 = -2^31 + 0.5 rounds to -2^31: INT32_MIN fits */
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_muldiv_s32(-65535, 65537, 2, &out));
    TEST_ASSERT_EQUAL_INT32(INT32_MIN, out);
  }
}

static void test_muldiv_s64_beyond_int64_overflows_or_saturates(void)
{
  static const struct case64 cases[] = {
      {INT64_MIN, 1, -1, INT64_MAX, "-2^63 / -1 = 2^63"},
      {INT64_MAX, INT64_MAX, 1, INT64_MAX, "(2^63 - 1)^2: beyond 64 bits"},
      /* (2^32 - 1)(2^32 + 1) = 2^64 - 1; / 2 = 2^63 - 0.5, the tie rounds
       * away from zero onto 2^63 */
      {INT64_C(4294967295), INT64_C(4294967297), 2, INT64_MAX,
       "2^63 - 0.5 rounds to 2^63"},
      {INT64_MIN, 2, 1, INT64_MIN, "-2^64"},
      {INT64_MAX, INT64_MIN, 1, INT64_MIN, "(2^63 - 1) -2^63: beyond 64 bits"},
      /* (2^64 + 1) / -2 = -2^63 - 0.5 rounds to -2^63 - 1; 2^64 + 1 =
       * 274177 * 67280421310721 */
      {INT64_C(274177), INT64_C(67280421310721), -2, INT64_MIN,
       "-2^63 - 0.5 rounds to -2^63 - 1"},
  };
  size_t i;

  for (i = 0; i < COUNT(cases); i++) {
    const struct case64 *k = &cases[i];
    int64_t out = SENTINEL64;

    TEST_ASSERT_EQUAL_INT_MESSAGE(
        DRDC_E_OVERFLOW, drdc_fx_muldiv_s64(k->a, k->b, k->c, &out), k->why);
    TEST_ASSERT_EQUAL_INT64_MESSAGE(SENTINEL64, out, k->why);
    TEST_ASSERT_EQUAL_INT_MESSAGE(
        DRDC_W_SATURATED, drdc_fx_muldiv_s64_sat(k->a, k->b, k->c, &out),
        k->why);
    TEST_ASSERT_EQUAL_INT64_MESSAGE(k->limit, out, k->why);
  }
  {
    int64_t out = SENTINEL64;

    /* -(2^64 - 1) / 2 = -2^63 + 0.5 rounds to -2^63: INT64_MIN fits */
    TEST_ASSERT_EQUAL_INT(
        DRDC_OK,
        drdc_fx_muldiv_s64(-INT64_C(4294967295), INT64_C(4294967297), 2, &out));
    TEST_ASSERT_EQUAL_INT64(INT64_MIN, out);
  }
}

void suite_fixed_bad_input(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_null_out_gives_null);
  RUN_TEST(test_mul_q1_30_beyond_2_overflows_or_saturates);
  RUN_TEST(test_mul_q15_16_beyond_32768_overflows_or_saturates);
  RUN_TEST(test_mul_q47_16_beyond_2_47_overflows_or_saturates);
  RUN_TEST(test_div_q1_30_beyond_2_overflows_or_saturates);
  RUN_TEST(test_div_q15_16_beyond_32768_overflows_or_saturates);
  RUN_TEST(test_div_q47_16_beyond_2_47_overflows_or_saturates);
  RUN_TEST(test_muldiv_s32_beyond_int32_overflows_or_saturates);
  RUN_TEST(test_muldiv_s64_beyond_int64_overflows_or_saturates);
}
