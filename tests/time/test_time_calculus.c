/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Delta derivative and delta integral against exact rationals,
 *        and their named conditions (equal and decreasing stamps, n,
 *        overflow of the integral).
 */
#include <drdc/time_calculus.h>

#include "suites.h"
#include "unity.h"
#include "vectors_calculus.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

static void test_match_exact_rationals(void)
{
  size_t i;
  size_t k;

  for (i = 0; i < COUNT(calculus_vectors); i++) {
    const struct calculus_vector *v = &calculus_vectors[i];
    int64_t d[CALCULUS_LENGTH - 1];
    int64_t integral = 0;

    TEST_ASSERT_EQUAL_INT(
        DRDC_OK, drdc_time_delta_derivative(v->t_ns, v->f, CALCULUS_LENGTH, d));
    for (k = 0; k + 1 < CALCULUS_LENGTH; k++) {
      TEST_ASSERT_EQUAL_INT64(v->deriv[k], d[k]);
    }
    TEST_ASSERT_EQUAL_INT(
        DRDC_OK,
        drdc_time_delta_integral(v->t_ns, v->f, CALCULUS_LENGTH, &integral));
    TEST_ASSERT_EQUAL_INT64(v->integral, integral);
  }
}

static void test_header_example_and_rounding(void)
{
  static const int64_t t[3] = {0, 500000000, 2000000000};
  static const int32_t f[3] = {0, 10, 13};
  static const int64_t t3[2] = {0, 3};
  static const int32_t half[2] = {0, -1};
  int64_t d[2];
  int64_t integral = 0;

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_delta_derivative(t, f, 3, d));
  TEST_ASSERT_EQUAL_INT64(20, d[0]);
  TEST_ASSERT_EQUAL_INT64(2, d[1]);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_delta_integral(t, f, 3, &integral));
  TEST_ASSERT_EQUAL_INT64(15, integral); /* 0 * 0.5 + 10 * 1.5 */
  /* -1e9 / 3 = -333333333.33 -> -333333333 */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_delta_derivative(t3, half, 2, d));
  TEST_ASSERT_EQUAL_INT64(-333333333, d[0]);
  /* one sample: the integral over [t_0, t_0] is 0 */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_delta_integral(t, f, 1, &integral));
  TEST_ASSERT_EQUAL_INT64(0, integral);
}

static void test_bad_scales_give_their_status(void)
{
  static const int64_t equal[3] = {0, 5, 5};
  static const int64_t backwards[3] = {0, 5, 4};
  static const int64_t whole[2] = {INT64_MIN, INT64_MAX};
  static const int32_t f[3] = {INT32_MAX, INT32_MAX, 1};
  static const int32_t fneg[2] = {INT32_MIN, 0};
  int64_t d[2] = {7, 7};
  int64_t integral = 7;

  TEST_ASSERT_EQUAL_INT(DRDC_E_DIVIDE_BY_ZERO,
                        drdc_time_delta_derivative(equal, f, 3, d));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_time_delta_derivative(backwards, f, 3, d));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_time_delta_derivative(equal, f, 1, d));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_delta_derivative(NULL, f, 3, d));
  TEST_ASSERT_EQUAL_INT64(7, d[0]);
  TEST_ASSERT_EQUAL_INT64(7, d[1]);
  TEST_ASSERT_EQUAL_INT(DRDC_E_DIVIDE_BY_ZERO,
                        drdc_time_delta_integral(equal, f, 3, &integral));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_time_delta_integral(backwards, f, 3, &integral));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_time_delta_integral(equal, f, 0, &integral));
  /* (2^31 - 1) * (2^64 - 1) ns = 3.96e19 units x s: does not fit */
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_time_delta_integral(whole, f, 2, &integral));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_time_delta_integral(whole, fneg, 2, &integral));
  TEST_ASSERT_EQUAL_INT64(7, integral);
  /* the whole int64 range as one step still has an exact derivative */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_delta_derivative(whole, fneg, 2, d));
  TEST_ASSERT_EQUAL_INT64(0, d[0]); /* 2^31 * 1e9 / (2^64 - 1) = 0.116 */
}

void suite_time_calculus(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_match_exact_rationals);
  RUN_TEST(test_header_example_and_rounding);
  RUN_TEST(test_bad_scales_give_their_status);
}
