/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief JAUS date stamp: all 65 536 stamps against Python's month
 *        lengths, pack/unpack round trips, the bit layout, and the
 *        bad-input catalogue.
 */
#include <stddef.h>
#include <stdint.h>

#include <drdc/jaus_date.h>

#include "suites.h"
#include "unity.h"
#include "vectors_jaus_date.h"

/* Every stamp: the status the model gives, and back to the same stamp. */
static void test_every_stamp(void)
{
  uint32_t s;
  uint32_t valid = 0u;

  for (s = 0u; s <= 0xFFFFu; s++) {
    uint32_t yf = s >> 9;
    uint32_t mf = (s >> 5) & 0x0Fu;
    uint32_t df = s & 0x1Fu;
    drdc_status_t want = DRDC_OK;
    int32_t y = -1;
    int32_t m = -1;
    int32_t d = -1;
    uint16_t back = 0u;

    if ((mf == 0u) || (mf > 12u)) {
      want = DRDC_E_MONTH;
    } else if ((df == 0u) || (df > jaus_days_in_month[yf][mf - 1u])) {
      want = DRDC_E_DAY;
    } else {
      want = DRDC_OK;
    }
    TEST_ASSERT_EQUAL_INT(want, drdc_jaus_date_unpack((uint16_t)s, &y, &m, &d));
    if (want != DRDC_OK) {
      TEST_ASSERT_EQUAL_INT32(-1, y);
      continue;
    }
    valid++;
    TEST_ASSERT_EQUAL_INT32((int32_t)yf + 2000, y);
    TEST_ASSERT_EQUAL_INT32((int32_t)mf, m);
    TEST_ASSERT_EQUAL_INT32((int32_t)df, d);
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_jaus_date_pack(y, m, d, &back));
    TEST_ASSERT_EQUAL_HEX16(s, back);
  }
  /* 2000-01-01 .. 2127-12-31 */
  TEST_ASSERT_EQUAL_UINT32(46751u, valid);
}

static void test_layout(void)
{
  uint16_t s = 0u;

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_jaus_date_pack(2024, 2, 29, &s));
  TEST_ASSERT_EQUAL_HEX16((24u << 9) | (2u << 5) | 29u, s);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_jaus_date_pack(2000, 1, 1, &s));
  TEST_ASSERT_EQUAL_HEX16(0x0021u, s); /* January is 1, not 0 */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_jaus_date_pack(2127, 12, 31, &s));
  TEST_ASSERT_EQUAL_HEX16(0xFF9Fu, s);
}

static void test_drdc_jaus_date_pack_bad_input(void)
{
  uint16_t s = 7u;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_jaus_date_pack(2024, 1, 1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_YEAR, drdc_jaus_date_pack(1999, 12, 31, &s));
  TEST_ASSERT_EQUAL_INT(DRDC_E_YEAR, drdc_jaus_date_pack(2128, 1, 1, &s));
  TEST_ASSERT_EQUAL_INT(DRDC_E_MONTH, drdc_jaus_date_pack(2024, 0, 1, &s));
  TEST_ASSERT_EQUAL_INT(DRDC_E_MONTH, drdc_jaus_date_pack(2024, 13, 1, &s));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DAY, drdc_jaus_date_pack(2023, 2, 29, &s));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DAY, drdc_jaus_date_pack(2024, 4, 31, &s));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DAY, drdc_jaus_date_pack(2024, 4, 0, &s));
  TEST_ASSERT_EQUAL_HEX16(7u, s);
}

static void test_drdc_jaus_date_unpack_bad_input(void)
{
  int32_t y = 7;
  int32_t m = 7;
  int32_t d = 7;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_jaus_date_unpack(0x0021u, NULL, &m, &d));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_jaus_date_unpack(0x0021u, &y, NULL, &d));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_jaus_date_unpack(0x0021u, &y, &m, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_MONTH,
                        drdc_jaus_date_unpack(0x0001u, &y, &m, &d));
  TEST_ASSERT_EQUAL_INT(DRDC_E_MONTH,
                        drdc_jaus_date_unpack(0x01A1u, &y, &m, &d));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DAY, drdc_jaus_date_unpack(0x0020u, &y, &m, &d));
  /* 2023-02-29 */
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_DAY, drdc_jaus_date_unpack(
                      (uint16_t)((23u << 9) | (2u << 5) | 29u), &y, &m, &d));
  TEST_ASSERT_EQUAL_INT32(7, y);
  TEST_ASSERT_EQUAL_INT32(7, m);
  TEST_ASSERT_EQUAL_INT32(7, d);
}

void suite_jaus_date(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_every_stamp);
  RUN_TEST(test_layout);
  RUN_TEST(test_drdc_jaus_date_pack_bad_input);
  RUN_TEST(test_drdc_jaus_date_unpack_bad_input);
}
