/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Tests of drdc_time_days_from_civil() and its inverse: reference
 *        table from Python's datetime, the whole calendar by the next-day
 *        rule, and named bad inputs.
 */
#include <drdc/time.h>

#include "suites.h"
#include "unity.h"
#include "vectors_civil.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

static void test_days_from_civil_matches_datetime(void)
{
  size_t i;

  for (i = 0; i < COUNT(civil_vectors); i++) {
    const struct civil_vector *v = &civil_vectors[i];
    int32_t days = 0;

    TEST_ASSERT_EQUAL_INT(
        DRDC_OK, drdc_time_days_from_civil(v->year, v->month, v->day, &days));
    TEST_ASSERT_EQUAL_INT32(v->days, days);
  }
}

static void test_civil_from_days_matches_datetime(void)
{
  size_t i;

  for (i = 0; i < COUNT(civil_vectors); i++) {
    const struct civil_vector *v = &civil_vectors[i];
    int32_t y = 0;
    int32_t m = 0;
    int32_t d = 0;

    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_time_civil_from_days(v->days, &y, &m, &d));
    TEST_ASSERT_EQUAL_INT32(v->year, y);
    TEST_ASSERT_EQUAL_INT32(v->month, m);
    TEST_ASSERT_EQUAL_INT32(v->day, d);
  }
}

/* Walk every day of the calendar: from 0001-01-01 each day count must give
 * the day after the previous one (month lengths by the leap rule) and map
 * back to its own count. With the anchors of the reference table this
 * covers all 3 652 059 days. */
static void test_every_day_follows_the_previous(void)
{
  static const int32_t month_days[13] = {0,  31, 28, 31, 30, 31, 30,
                                         31, 31, 30, 31, 30, 31};
  int32_t y = 1;
  int32_t m = 1;
  int32_t d = 1;
  int32_t days;
  int32_t first_bad = INT32_MIN; /* day count of the first mismatch */

  /* Plain comparisons in the loop: an assertion per day would spend most
   * of the run inside Unity. */
  for (days = DRDC_TIME_DAYS_MIN; days <= DRDC_TIME_DAYS_MAX; days++) {
    int32_t gy = 0;
    int32_t gm = 0;
    int32_t gd = 0;
    int32_t back = 0;
    int32_t last;

    if ((drdc_time_civil_from_days(days, &gy, &gm, &gd) != DRDC_OK) ||
        (gy != y) || (gm != m) || (gd != d) ||
        (drdc_time_days_from_civil(y, m, d, &back) != DRDC_OK) ||
        (back != days)) {
      first_bad = days;
      break;
    }
    last = month_days[m];
    if ((m == 2) && ((y % 4 == 0) && ((y % 100 != 0) || (y % 400 == 0)))) {
      last = 29;
    }
    d++;
    if (d > last) {
      d = 1;
      m++;
      if (m > 12) {
        m = 1;
        y++;
      }
    }
  }
  TEST_ASSERT_EQUAL_INT32_MESSAGE(INT32_MIN, first_bad,
                                  "first day count where the walk broke");
  TEST_ASSERT_EQUAL_INT32(10000, y); /* walked exactly to 10000-01-01 */
}

static void test_unix_epoch_is_day_zero(void)
{
  int32_t days = -1;

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_days_from_civil(1970, 1, 1, &days));
  TEST_ASSERT_EQUAL_INT32(0, days);
}

/* Named bad inputs: each gives its own status and leaves the output. */
static void test_bad_dates_give_their_status(void)
{
  static const struct {
    int32_t year, month, day;
    drdc_status_t status;
  } bad[] = {
      {2024, 13, 1, DRDC_E_MONTH}, /* month 13 */
      {2024, 0, 1, DRDC_E_MONTH},  /* month 0 */
      {2024, 1, 0, DRDC_E_DAY},    /* day 0 */
      {2024, 1, 32, DRDC_E_DAY},   /* past the month's end */
      {2023, 2, 29, DRDC_E_DAY},   /* Feb 29 in a common year */
      {1900, 2, 29, DRDC_E_DAY},   /* century that is not a leap year */
      {2000, 2, 30, DRDC_E_DAY},   /* Feb 30 even in a leap year */
      {2024, 4, 31, DRDC_E_DAY},   /* 30-day month */
      {0, 1, 1, DRDC_E_YEAR},      /* before DRDC_YEAR_MIN */
      {10000, 1, 1, DRDC_E_YEAR},  /* after DRDC_YEAR_MAX */
      {INT32_MIN, INT32_MIN, INT32_MIN, DRDC_E_YEAR},
      {INT32_MAX, INT32_MAX, INT32_MAX, DRDC_E_YEAR},
  };
  size_t i;

  for (i = 0; i < COUNT(bad); i++) {
    int32_t days = 12345;

    TEST_ASSERT_EQUAL_INT(bad[i].status,
                          drdc_time_days_from_civil(bad[i].year, bad[i].month,
                                                    bad[i].day, &days));
    TEST_ASSERT_EQUAL_INT32(12345, days);
  }
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_time_days_from_civil(2024, 2, 29, NULL));
}

static void test_bad_day_counts_give_range(void)
{
  int32_t y = 7;
  int32_t m = 7;
  int32_t d = 7;

  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_time_civil_from_days(
                                          DRDC_TIME_DAYS_MIN - 1, &y, &m, &d));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_time_civil_from_days(
                                          DRDC_TIME_DAYS_MAX + 1, &y, &m, &d));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_time_civil_from_days(INT32_MIN, &y, &m, &d));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_time_civil_from_days(INT32_MAX, &y, &m, &d));
  TEST_ASSERT_EQUAL_INT32(7, y);
  TEST_ASSERT_EQUAL_INT32(7, m);
  TEST_ASSERT_EQUAL_INT32(7, d);
  /* every output may be NULL */
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_time_civil_from_days(0, NULL, NULL, NULL));
}

static void test_status_names(void)
{
  TEST_ASSERT_EQUAL_STRING("DRDC_OK", drdc_status_name(DRDC_OK));
  TEST_ASSERT_EQUAL_STRING("DRDC_E_DAY", drdc_status_name(DRDC_E_DAY));
  TEST_ASSERT_EQUAL_STRING("DRDC_E_?", drdc_status_name(DRDC_STATUS_COUNT));
  TEST_ASSERT_EQUAL_STRING("DRDC_E_?", drdc_status_name((drdc_status_t)-1));
}

/* The name of each code says its kind: DRDC_OK, DRDC_W_* (warning) or
 * DRDC_E_* (error). */
static void test_status_kinds_follow_their_names(void)
{
  int code;

  for (code = 0; code < (int)DRDC_STATUS_COUNT; code++) {
    drdc_status_t s = (drdc_status_t)code;
    const char *name = drdc_status_name(s);
    bool warning = (name[5] == 'W') && (name[6] == '_');
    bool error = (name[5] == 'E') && (name[6] == '_');

    TEST_ASSERT_EQUAL_INT(warning, drdc_status_is_warning(s));
    TEST_ASSERT_EQUAL_INT(error, drdc_status_is_error(s));
    TEST_ASSERT_EQUAL_INT(code == 0, !warning && !error);
  }
  TEST_ASSERT_TRUE(drdc_status_is_error(DRDC_STATUS_COUNT));
}

static int status_calls;

static drdc_status_t counted(drdc_status_t s)
{
  status_calls++;
  return s;
}

/* Regression: drdc_status_is_error() was a macro that evaluated its
 * argument up to three times, so a call inside it ran again. */
static void test_status_is_error_evaluates_its_argument_once(void)
{
  status_calls = 0;
  TEST_ASSERT_TRUE(drdc_status_is_error(counted(DRDC_E_RANGE)));
  TEST_ASSERT_EQUAL_INT(1, status_calls);
  status_calls = 0;
  TEST_ASSERT_FALSE(drdc_status_is_error(counted(DRDC_W_SATURATED)));
  TEST_ASSERT_EQUAL_INT(1, status_calls);
  status_calls = 0;
  TEST_ASSERT_TRUE(drdc_status_is_warning(counted(DRDC_W_LEAP_EXPIRED)));
  TEST_ASSERT_EQUAL_INT(1, status_calls);
}

void suite_time_civil(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_days_from_civil_matches_datetime);
  RUN_TEST(test_civil_from_days_matches_datetime);
  RUN_TEST(test_every_day_follows_the_previous);
  RUN_TEST(test_unix_epoch_is_day_zero);
  RUN_TEST(test_bad_dates_give_their_status);
  RUN_TEST(test_bad_day_counts_give_range);
  RUN_TEST(test_status_names);
  RUN_TEST(test_status_kinds_follow_their_names);
  RUN_TEST(test_status_is_error_evaluates_its_argument_once);
}
