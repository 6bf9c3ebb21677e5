/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Tests of the fix16_t interop: same bits both ways, libfixmath's
 *        overflow marker refused both ways, outputs unchanged on error.
 */
#include <drdc/fixed.h>
#include <drdc/fixed_fix16.h>

#include <stddef.h>

#include "suites.h"
#include "unity.h"

static void test_same_bits_both_ways(void)
{
  static const int32_t values[] = {
      0, 1, -1, 0x10000, -0x10000, INT32_MAX, INT32_MIN + 1, 0x3243F};
  size_t i;

  for (i = 0; i < sizeof(values) / sizeof(values[0]); i++) {
    drdc_q15_16_t q = 0;
    int32_t f = 0;

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_q15_16_from_fix16(values[i], &q));
    TEST_ASSERT_EQUAL_INT32(values[i], q);
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_fix16_from_q15_16(q, &f));
    TEST_ASSERT_EQUAL_INT32(values[i], f);
  }
}

/* fix16_overflow (0x80000000) is an error coming in, and -32768.0 cannot
 * go out because libfixmath would read it as fix16_overflow. */
static void test_overflow_marker_refused(void)
{
  drdc_q15_16_t q = 9;
  int32_t f = 9;

  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_fx_q15_16_from_fix16(INT32_MIN, &q));
  TEST_ASSERT_EQUAL_INT32(9, q);
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_fx_fix16_from_q15_16(INT32_MIN, &f));
  TEST_ASSERT_EQUAL_INT32(9, f);
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_q15_16_from_fix16(0, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_fix16_from_q15_16(0, NULL));
}

void suite_fixed_fix16(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_same_bits_both_ways);
  RUN_TEST(test_overflow_marker_refused);
}
