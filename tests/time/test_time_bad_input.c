/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Bad-input rows of the time scales that the other suites do not
 *        name (docs/bad-input.md): NULL pointers, nanoseconds out of range,
 *        counts outside the calendar, and the expiry warning. Each status
 *        is matched exactly and outputs are checked unchanged on errors.
 */
#include <stddef.h>

#include <drdc/time.h>
#include <drdc/time_leap.h>
#include <drdc/time_scales.h>

#include "suites.h"
#include "unity.h"

/* 2024-06-30T12:00:00Z, inside the table */
static const drdc_time_t noon = {INT64_C(1719748800), 0};

static void test_null_pointers_give_null(void)
{
  drdc_time_t utc = {1, 2};
  drdc_time_count_t count = {3, 4};
  drdc_time_gps_t gps = {5, 6, 7};
  drdc_time_civil_t civil = {8, 8, 8, 8, 8, 8, 8};
  drdc_time_rtems_tod_t tod = {9, 9, 9, 9, 9, 9, 9};

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_check(NULL, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_to_civil(NULL, NULL, &civil));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_to_civil(NULL, &noon, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_utc_to_tai(NULL, NULL, &count));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_utc_to_tai(NULL, &noon, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_tai_to_utc(NULL, NULL, &utc));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_tai_to_utc(NULL, &count, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_utc_to_gps(NULL, NULL, &gps));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_utc_to_gps(NULL, &noon, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_gps_to_utc(NULL, NULL, &utc));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_gps_to_utc(NULL, &gps, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_unix_to_utc(NULL, &utc));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_unix_to_utc(&count, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_time_utc_to_rtems(NULL, NULL, &count));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_utc_to_rtems(NULL, &noon, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_rtems_to_utc(NULL, &utc));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_rtems_to_utc(&count, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_time_utc_to_rtems_tod(NULL, NULL, 100u, &tod));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_time_utc_to_rtems_tod(NULL, &noon, 100u, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_time_rtems_tod_to_utc(NULL, 100u, &utc));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_time_rtems_tod_to_utc(&tod, 100u, NULL));
  /* nothing was written */
  TEST_ASSERT_EQUAL_INT64(1, utc.sec);
  TEST_ASSERT_EQUAL_INT32(2, utc.nsec);
  TEST_ASSERT_EQUAL_INT64(3, count.sec);
  TEST_ASSERT_EQUAL_INT32(5, gps.week);
  TEST_ASSERT_EQUAL_INT32(8, civil.year);
  TEST_ASSERT_EQUAL_UINT32(9u, tod.year);
}

static void test_counts_with_bad_nanoseconds_give_nanosecond(void)
{
  static const int32_t bad_nsec[] = {-1, 1000000000, INT32_MIN, INT32_MAX};
  size_t i;

  for (i = 0; i < sizeof bad_nsec / sizeof bad_nsec[0]; i++) {
    drdc_time_count_t count = {INT64_C(1719748800), bad_nsec[i]};
    drdc_time_t utc = {1, 2};

    TEST_ASSERT_EQUAL_INT(DRDC_E_NANOSECOND,
                          drdc_time_tai_to_utc(NULL, &count, &utc));
    TEST_ASSERT_EQUAL_INT(DRDC_E_NANOSECOND,
                          drdc_time_unix_to_utc(&count, &utc));
    TEST_ASSERT_EQUAL_INT(DRDC_E_NANOSECOND,
                          drdc_time_rtems_to_utc(&count, &utc));
    TEST_ASSERT_EQUAL_INT64(1, utc.sec);
    TEST_ASSERT_EQUAL_INT32(2, utc.nsec);
  }
}

static void test_counts_outside_the_calendar_give_range(void)
{
  /* one second after 9999-12-31T23:59:59 and far beyond either end */
  static const int64_t bad_sec[] = {INT64_C(253402300800), INT64_MAX, INT64_MIN,
                                    INT64_C(-62135596801) - INT64_C(567993600)};
  size_t i;

  for (i = 0; i < sizeof bad_sec / sizeof bad_sec[0]; i++) {
    drdc_time_count_t count = {bad_sec[i], 0};
    drdc_time_t utc = {1, 2};

    TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_time_unix_to_utc(&count, &utc));
    TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_time_rtems_to_utc(&count, &utc));
    TEST_ASSERT_EQUAL_INT64(1, utc.sec);
  }
}

/* Past the built-in table's expiry day the GPS conversions still answer,
 * with the last known offset (37 s - 19 s = 18 s), and say so. */
static void test_gps_past_the_expiry_warns_and_writes(void)
{
  drdc_time_t after;
  drdc_time_t back = {0, 0};
  drdc_time_gps_t gps = {0, 0, 0};

  after.sec =
      (int64_t)(DRDC_TIME_LEAP_BUILTIN_EXPIRY_DAY + 10) * INT64_C(86400);
  after.nsec = 0;
  TEST_ASSERT_EQUAL_INT(DRDC_W_LEAP_EXPIRED,
                        drdc_time_utc_to_gps(NULL, &after, &gps));
  /* GPS = UTC + 18 s since 2017: (sec - 315964800 + 18) split in weeks */
  TEST_ASSERT_EQUAL_INT32(
      (int32_t)((after.sec - INT64_C(315964800) + 18) / 604800), gps.week);
  TEST_ASSERT_EQUAL_INT32(
      (int32_t)((after.sec - INT64_C(315964800) + 18) % 604800), gps.tow);
  TEST_ASSERT_EQUAL_INT(DRDC_W_LEAP_EXPIRED,
                        drdc_time_gps_to_utc(NULL, &gps, &back));
  TEST_ASSERT_EQUAL_INT64(after.sec, back.sec);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_utc_to_gps(NULL, &noon, &gps));
}

void suite_time_bad_input(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_null_pointers_give_null);
  RUN_TEST(test_counts_with_bad_nanoseconds_give_nanosecond);
  RUN_TEST(test_counts_outside_the_calendar_give_range);
  RUN_TEST(test_gps_past_the_expiry_warns_and_writes);
}
