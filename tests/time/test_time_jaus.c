/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief JAUS time stamps: bit layout, the leap second, month and year
 *        boundaries of the reference, and the bad-field catalogue.
 *        (Random instants are checked in test_time_scales.c, beside their
 *        vectors.)
 */
#include <drdc/time_jaus.h>

#include "suites.h"
#include "unity.h"

#define NS INT32_C(1000000000)
/* UTC seconds (calendar.timegm) */
#define UTC_2016_12_31_235959 INT64_C(1483228799)
#define UTC_2024_03_01        INT64_C(1709251200)
#define UTC_2024_12_31        INT64_C(1735603200)
#define UTC_2024_04_30        INT64_C(1714435200)

static uint32_t stamp_of(uint32_t d, uint32_t h, uint32_t m, uint32_t s,
                         uint32_t ms)
{
  return (d << 27) | (h << 22) | (m << 16) | (s << 10) | ms;
}

static void test_pack_layout_and_leap_second(void)
{
  drdc_time_t t = {UTC_2016_12_31_235959, NS + 500999999};
  drdc_time_t back = {0, 0};
  drdc_time_jaus_fields_t f;
  uint32_t s = 7;

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_jaus_pack(NULL, &t, &s));
  TEST_ASSERT_EQUAL_HEX32(0xFDFBF1F4u, s); /* 31 23:59:60.500 */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_jaus_unpack(s, &f));
  TEST_ASSERT_EQUAL_UINT32(31, f.day);
  TEST_ASSERT_EQUAL_UINT32(23, f.hour);
  TEST_ASSERT_EQUAL_UINT32(59, f.minute);
  TEST_ASSERT_EQUAL_UINT32(60, f.second);
  TEST_ASSERT_EQUAL_UINT32(500, f.msec);
  t.sec += 10 * 86400; /* reference ten days later */
  t.nsec = 0;
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_jaus_to_utc(NULL, s, &t, &back));
  TEST_ASSERT_EQUAL_INT64(UTC_2016_12_31_235959, back.sec);
  TEST_ASSERT_EQUAL_INT32(NS + 500000000, back.nsec);
  /* the same stamp a year earlier: 2015-12-31 had no leap second */
  t.sec -= 366 * 86400;
  back.sec = 7;
  TEST_ASSERT_EQUAL_INT(DRDC_E_SECOND,
                        drdc_time_jaus_to_utc(NULL, s, &t, &back));
  TEST_ASSERT_EQUAL_INT64(7, back.sec);
}

static void test_reference_across_month_and_year(void)
{
  drdc_time_t ref = {UTC_2024_03_01, 0};
  drdc_time_t t = {0, 0};

  /* day 29 23:00 seen from 2024-03-01: February 29 of the leap year */
  TEST_ASSERT_EQUAL_INT(
      DRDC_OK,
      drdc_time_jaus_to_utc(NULL, stamp_of(29, 23, 0, 0, 0), &ref, &t));
  TEST_ASSERT_EQUAL_INT64(UTC_2024_03_01 - 3600, t.sec);
  /* day 1 seen from 2024-12-31: 2025-01-01 */
  ref.sec = UTC_2024_12_31;
  TEST_ASSERT_EQUAL_INT(
      DRDC_OK, drdc_time_jaus_to_utc(NULL, stamp_of(1, 0, 0, 0, 1), &ref, &t));
  TEST_ASSERT_EQUAL_INT64(UTC_2024_12_31 + 86400, t.sec);
  TEST_ASSERT_EQUAL_INT32(1000000, t.nsec);
  /* day 31 seen from 2024-04-30: March 31 and May 31 are a month away */
  ref.sec = UTC_2024_04_30;
  t.sec = 7;
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE,
      drdc_time_jaus_to_utc(NULL, stamp_of(31, 0, 0, 0, 0), &ref, &t));
  TEST_ASSERT_EQUAL_INT64(7, t.sec);
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_jaus_to_utc(NULL, 0, NULL, &t));
}

static void test_bad_fields_give_their_status(void)
{
  static const struct {
    uint32_t stamp;
    drdc_status_t status;
  } bad[] = {
      {(0u << 27) | (1u << 22), DRDC_E_DAY},   /* day 0 */
      {(1u << 27) | (24u << 22), DRDC_E_HOUR}, /* hour 24 */
      {(1u << 27) | (31u << 22), DRDC_E_HOUR},
      {(1u << 27) | (60u << 16), DRDC_E_MINUTE}, /* minute 60 */
      {(1u << 27) | (61u << 10), DRDC_E_SECOND}, /* second 61 */
      {(1u << 27) | (63u << 10), DRDC_E_SECOND},
      {(1u << 27) | 1000u, DRDC_E_NANOSECOND}, /* 1000 ms */
      {(1u << 27) | 1023u, DRDC_E_NANOSECOND},
  };
  drdc_time_t ref = {UTC_2024_03_01, 0};
  size_t i;

  for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    drdc_time_jaus_fields_t f = {7, 7, 7, 7, 7};
    drdc_time_t t = {7, 7};

    TEST_ASSERT_EQUAL_INT(bad[i].status,
                          drdc_time_jaus_unpack(bad[i].stamp, &f));
    TEST_ASSERT_EQUAL_INT(bad[i].status,
                          drdc_time_jaus_to_utc(NULL, bad[i].stamp, &ref, &t));
    TEST_ASSERT_EQUAL_UINT32(7, f.day);
    TEST_ASSERT_EQUAL_INT64(7, t.sec);
  }
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_jaus_unpack(0, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_jaus_pack(NULL, &ref, NULL));
}

void suite_time_jaus(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_pack_layout_and_leap_second);
  RUN_TEST(test_reference_across_month_and_year);
  RUN_TEST(test_bad_fields_give_their_status);
}
