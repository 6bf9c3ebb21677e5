/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief drdc_fx_format(): every vector of tests/ref/gen_fixed_format.py
 *        (Python's decimal module) exactly, and its bad inputs.
 */
#include <drdc/fixed_format.h>

#include <stddef.h>
#include <string.h>

#include "suites.h"
#include "unity.h"
#include "vectors_format.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

/* (the PowerPC board's C library subset has no strlen) */
static size_t text_length(const char *s)
{
  size_t n = 0;

  while (s[n] != '\0') {
    n++;
  }
  return n;
}

static void test_format_matches_exact_decimal_rounding(void)
{
  size_t i;

  for (i = 0; i < COUNT(format_vectors); i++) {
    const struct format_vector *v = &format_vectors[i];
    char buf[DRDC_FX_FORMAT_MAX];
    size_t length = 0;

    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_fx_format(v->value, v->frac_bits, v->decimals,
                                         buf, sizeof buf, &length));
    TEST_ASSERT_EQUAL_STRING(v->text, buf);
    TEST_ASSERT_EQUAL_size_t(text_length(v->text), length);
  }
}

static void test_format_buffer_too_short_gives_buffer(void)
{
  /* The text fits a buffer of exactly its length plus one, and not one
   * byte less: DRDC_E_BUFFER, buf and length untouched. */
  char buf[DRDC_FX_FORMAT_MAX];
  size_t length = 99;

  memset(buf, 'x', sizeof buf);
  TEST_ASSERT_EQUAL_INT(DRDC_E_BUFFER,
                        drdc_fx_format(-98304, 16, 3, buf, 6, &length));
  TEST_ASSERT_EQUAL_CHAR('x', buf[0]);
  TEST_ASSERT_EQUAL_size_t(99, length);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_format(-98304, 16, 3, buf, 7, NULL));
  TEST_ASSERT_EQUAL_STRING("-1.500", buf);
  TEST_ASSERT_EQUAL_INT(DRDC_E_BUFFER,
                        drdc_fx_format(0, 0, 0, buf, 0, &length));
  /* the longest text fits DRDC_FX_FORMAT_MAX */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_format(INT64_MIN, 0, 18, buf,
                                                DRDC_FX_FORMAT_MAX, &length));
  TEST_ASSERT_EQUAL_size_t(DRDC_FX_FORMAT_MAX - 1, length);
}

static void test_format_null_buf_gives_null(void)
{
  size_t length = 99;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_fx_format(1, 0, 0, NULL, 40, &length));
  TEST_ASSERT_EQUAL_size_t(99, length);
}

static void test_format_frac_bits_or_decimals_beyond_give_range(void)
{
  char buf[DRDC_FX_FORMAT_MAX] = "untouched";
  size_t length = 99;

  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_fx_format(1, 61, 0, buf, sizeof buf, &length));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_fx_format(1, 0, 19, buf, sizeof buf, &length));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE, drdc_fx_format(1, UINT32_MAX, 0, buf, sizeof buf, &length));
  TEST_ASSERT_EQUAL_STRING("untouched", buf);
  TEST_ASSERT_EQUAL_size_t(99, length);
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_fx_format(1, 60, 18, buf, sizeof buf, &length));
}

void suite_fixed_format(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_format_matches_exact_decimal_rounding);
  RUN_TEST(test_format_buffer_too_short_gives_buffer);
  RUN_TEST(test_format_null_buf_gives_null);
  RUN_TEST(test_format_frac_bits_or_decimals_beyond_give_range);
}
