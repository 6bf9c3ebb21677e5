/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Named conditions of the time module: the bad-input catalogue
 *        (each with its own status, outputs unchanged), leap-second
 *        edges, Unix and RTEMS at a leap second, RTEMS ticks, the GPS
 *        week pivot and the run-time leap-second update.
 */
#include <drdc/time_scales.h>

#include "suites.h"
#include "unity.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))
#define NS       INT32_C(1000000000)
/* UTC seconds of some days (from Python's calendar.timegm). */
#define UTC_2016_12_31_235959 INT64_C(1483228799)
#define UTC_2015_12_31_235959 INT64_C(1451606399)
#define UTC_2027_06_28        INT64_C(1814140800)
#define UTC_2027_06_30        INT64_C(1814313600)
#define UTC_2027_07_01        INT64_C(1814400000)
#define UTC_2020_01_01        INT64_C(1577836800)
#define DAY_2027_07_01        INT32_C(21000)

static void test_bad_civil_times_give_their_status(void)
{
  static const struct {
    drdc_time_civil_t c;
    drdc_status_t status;
  } bad[] = {
      {{2024, 13, 1, 0, 0, 0, 0}, DRDC_E_MONTH},    /* month 13 */
      {{2024, 0, 1, 0, 0, 0, 0}, DRDC_E_MONTH},     /* month 0 */
      {{2024, 1, 0, 0, 0, 0, 0}, DRDC_E_DAY},       /* day 0 */
      {{2023, 2, 29, 0, 0, 0, 0}, DRDC_E_DAY},      /* Feb 29, common */
      {{2100, 2, 29, 0, 0, 0, 0}, DRDC_E_DAY},      /* 2100 is common */
      {{0, 1, 1, 0, 0, 0, 0}, DRDC_E_YEAR},         /* year 0 */
      {{10000, 1, 1, 0, 0, 0, 0}, DRDC_E_YEAR},     /* year 10000 */
      {{INT32_MIN, 1, 1, 0, 0, 0, 0}, DRDC_E_YEAR}, /* nothing wraps */
      {{2024, 1, 1, 24, 0, 0, 0}, DRDC_E_HOUR},     /* hour 24 */
      {{2024, 1, 1, -1, 0, 0, 0}, DRDC_E_HOUR},
      {{2024, 1, 1, 0, 60, 0, 0}, DRDC_E_MINUTE}, /* minute 60 */
      {{2024, 1, 1, 0, 0, 61, 0}, DRDC_E_SECOND}, /* second 61 */
      {{2024, 1, 1, 0, 0, -1, 0}, DRDC_E_SECOND},
      {{2015, 12, 31, 23, 59, 60, 0}, DRDC_E_SECOND}, /* no leap that day */
      {{2016, 12, 31, 23, 58, 60, 0}, DRDC_E_SECOND}, /* 60 not at 23:59 */
      {{2016, 12, 31, 12, 59, 60, 0}, DRDC_E_SECOND},
      {{2024, 1, 1, 0, 0, 0, NS}, DRDC_E_NANOSECOND}, /* 1e9 ns */
      {{2024, 1, 1, 0, 0, 0, -1}, DRDC_E_NANOSECOND},
      {{2016, 12, 31, 23, 59, 60, NS}, DRDC_E_NANOSECOND},
  };
  size_t i;

  for (i = 0; i < COUNT(bad); i++) {
    drdc_time_t t = {7, 7};

    TEST_ASSERT_EQUAL_INT(bad[i].status,
                          drdc_time_civil_check(NULL, &bad[i].c));
    TEST_ASSERT_EQUAL_INT(bad[i].status,
                          drdc_time_from_civil(NULL, &bad[i].c, &t));
    TEST_ASSERT_EQUAL_INT64(7, t.sec);
    TEST_ASSERT_EQUAL_INT32(7, t.nsec);
  }
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_civil_check(NULL, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_time_from_civil(NULL, &bad[0].c, NULL));
}

static void test_bad_utc_instants_give_their_status(void)
{
  static const struct {
    drdc_time_t t;
    drdc_status_t status;
  } bad[] = {
      {{UTC_2016_12_31_235959 - 1, NS}, DRDC_E_NANOSECOND}, /* :58 + 1 s */
      {{UTC_2015_12_31_235959, NS}, DRDC_E_SECOND},         /* no leap second */
      {{UTC_2016_12_31_235959, 2 * NS}, DRDC_E_NANOSECOND},
      {{UTC_2016_12_31_235959, -1}, DRDC_E_NANOSECOND},
      {{INT64_C(-62135596801), 0}, DRDC_E_RANGE}, /* before year 1 */
      {{INT64_C(253402300800), 0}, DRDC_E_RANGE}, /* year 10000 */
      {{INT64_MIN, 0}, DRDC_E_RANGE},
      {{INT64_MAX, 0}, DRDC_E_RANGE},
  };
  size_t i;

  for (i = 0; i < COUNT(bad); i++) {
    drdc_time_civil_t c = {7, 7, 7, 7, 7, 7, 7};
    drdc_time_count_t k = {7, 7};
    drdc_time_gps_t g = {7, 7, 7};

    TEST_ASSERT_EQUAL_INT(bad[i].status, drdc_time_check(NULL, &bad[i].t));
    TEST_ASSERT_EQUAL_INT(bad[i].status,
                          drdc_time_to_civil(NULL, &bad[i].t, &c));
    TEST_ASSERT_EQUAL_INT(bad[i].status,
                          drdc_time_utc_to_tai(NULL, &bad[i].t, &k));
    TEST_ASSERT_EQUAL_INT(bad[i].status,
                          drdc_time_utc_to_gps(NULL, &bad[i].t, &g));
    TEST_ASSERT_EQUAL_INT(bad[i].status,
                          drdc_time_utc_to_unix(NULL, &bad[i].t, &k));
    TEST_ASSERT_EQUAL_INT(bad[i].status,
                          drdc_time_utc_to_rtems(NULL, &bad[i].t, &k));
    TEST_ASSERT_EQUAL_INT32(7, c.year);
    TEST_ASSERT_EQUAL_INT32(7, c.nsec);
    TEST_ASSERT_EQUAL_INT64(7, k.sec);
    TEST_ASSERT_EQUAL_INT32(7, g.week);
  }
}

static void test_bad_gps_times_give_their_status(void)
{
  static const struct {
    drdc_time_gps_t g;
    drdc_status_t status;
  } bad[] = {
      {{2000, 604800, 0}, DRDC_E_TIME_OF_WEEK}, /* TOW >= 604 800 */
      {{2000, -1, 0}, DRDC_E_TIME_OF_WEEK},
      {{-1, 0, 0}, DRDC_E_WEEK}, /* negative week */
      {{INT32_MIN, 0, 0}, DRDC_E_WEEK},
      {{DRDC_TIME_GPS_WEEK_MAX + 1, 0, 0}, DRDC_E_WEEK},
      {{2000, 0, NS}, DRDC_E_NANOSECOND},
      {{2000, 0, -1}, DRDC_E_NANOSECOND},
  };
  size_t i;

  for (i = 0; i < COUNT(bad); i++) {
    drdc_time_t t = {7, 7};

    TEST_ASSERT_EQUAL_INT(bad[i].status,
                          drdc_time_gps_to_utc(NULL, &bad[i].g, &t));
    TEST_ASSERT_EQUAL_INT64(7, t.sec);
  }
}

static void test_before_1972_and_before_gps_epoch_are_range_errors(void)
{
  drdc_time_t t = {INT64_C(63071999), 0}; /* 1971-12-31T23:59:59 */
  drdc_time_count_t k = {7, 7};
  drdc_time_gps_t g = {7, 7, 7};
  int32_t off = 7;

  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_time_leap_offset(NULL, &t, &off));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_time_utc_to_tai(NULL, &t, &k));
  t.sec = INT64_C(315964799); /* 1980-01-05T23:59:59 */
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_time_utc_to_gps(NULL, &t, &g));
  /* TAI of 1972-01-01T00:00:00 UTC is 00:00:10 TAI; a second earlier
   * has no integer offset */
  k.sec = (INT64_C(730) * 86400) + 10 + DRDC_TIME_TAI_EPOCH_TO_UNIX - 1;
  k.nsec = 0;
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_time_tai_to_utc(NULL, &k, &t));
  TEST_ASSERT_EQUAL_INT64(INT64_C(315964799), t.sec);
  k.sec += 1;
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_tai_to_utc(NULL, &k, &t));
  TEST_ASSERT_EQUAL_INT64(INT64_C(63072000), t.sec);
  k.sec = INT64_MAX;
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_time_tai_to_utc(NULL, &k, &t));
  k.sec = INT64_MIN;
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_time_tai_to_utc(NULL, &k, &t));
  TEST_ASSERT_EQUAL_INT32(7, off);
  TEST_ASSERT_EQUAL_INT32(7, g.week);
}

static void test_leap_second_in_unix_and_rtems_is_the_next_midnight(void)
{
  drdc_time_t leap = {UTC_2016_12_31_235959, NS + 250000000};
  drdc_time_t back = {0, 0};
  drdc_time_count_t k = {0, 0};
  drdc_time_rtems_tod_t tod;

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_utc_to_unix(NULL, &leap, &k));
  TEST_ASSERT_EQUAL_INT64(UTC_2016_12_31_235959 + 1, k.sec);
  TEST_ASSERT_EQUAL_INT32(250000000, k.nsec);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_unix_to_utc(&k, &back));
  TEST_ASSERT_EQUAL_INT64(UTC_2016_12_31_235959 + 1,
                          back.sec); /* 00:00:00.25 */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_utc_to_rtems(NULL, &leap, &k));
  TEST_ASSERT_EQUAL_INT64(
      UTC_2016_12_31_235959 + 1 - DRDC_TIME_RTEMS_EPOCH_UNIX, k.sec);
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_time_utc_to_rtems_tod(NULL, &leap, 100, &tod));
  TEST_ASSERT_EQUAL_UINT32(2017, tod.year);
  TEST_ASSERT_EQUAL_UINT32(1, tod.month);
  TEST_ASSERT_EQUAL_UINT32(1, tod.day);
  TEST_ASSERT_EQUAL_UINT32(0, tod.hour);
  TEST_ASSERT_EQUAL_UINT32(0, tod.second);
  TEST_ASSERT_EQUAL_UINT32(25, tod.ticks);
}

static void test_rtems_time_of_day(void)
{
  /* 2024-02-29T12:34:56.123456789Z */
  drdc_time_t t = {INT64_C(1709210096), 123456789};
  drdc_time_t back = {0, 0};
  drdc_time_rtems_tod_t tod;
  drdc_time_rtems_tod_t bad;

  TEST_ASSERT_EQUAL_INT(
      DRDC_OK, drdc_time_utc_to_rtems_tod(NULL, &t, 1000000000u, &tod));
  TEST_ASSERT_EQUAL_UINT32(2024, tod.year);
  TEST_ASSERT_EQUAL_UINT32(2, tod.month);
  TEST_ASSERT_EQUAL_UINT32(29, tod.day);
  TEST_ASSERT_EQUAL_UINT32(12, tod.hour);
  TEST_ASSERT_EQUAL_UINT32(34, tod.minute);
  TEST_ASSERT_EQUAL_UINT32(56, tod.second);
  TEST_ASSERT_EQUAL_UINT32(123456789, tod.ticks);
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_time_rtems_tod_to_utc(&tod, 1000000000u, &back));
  TEST_ASSERT_EQUAL_INT64(t.sec, back.sec);
  TEST_ASSERT_EQUAL_INT32(t.nsec, back.nsec); /* exact: 1e9 divides 1e9 */
  /* three ticks a second: truncation toward the start of the second */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_utc_to_rtems_tod(NULL, &t, 3, &tod));
  TEST_ASSERT_EQUAL_UINT32(0, tod.ticks);
  t.nsec = 999999999;
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_utc_to_rtems_tod(NULL, &t, 3, &tod));
  TEST_ASSERT_EQUAL_UINT32(2, tod.ticks);
  tod.ticks = 1;
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_rtems_tod_to_utc(&tod, 3, &back));
  TEST_ASSERT_EQUAL_INT32(333333333, back.nsec);

  /* the catalogue, each with its status, output unchanged */
  back.sec = 7;
  bad = tod;
  TEST_ASSERT_EQUAL_INT(DRDC_E_TICKS,
                        drdc_time_rtems_tod_to_utc(&bad, 0, &back));
  TEST_ASSERT_EQUAL_INT(DRDC_E_TICKS,
                        drdc_time_rtems_tod_to_utc(&bad, 1000000001u, &back));
  bad.ticks = 3;
  TEST_ASSERT_EQUAL_INT(DRDC_E_TICKS,
                        drdc_time_rtems_tod_to_utc(&bad, 3, &back));
  bad = tod;
  bad.year = 1987;
  TEST_ASSERT_EQUAL_INT(DRDC_E_YEAR,
                        drdc_time_rtems_tod_to_utc(&bad, 3, &back));
  bad.year = UINT32_MAX;
  TEST_ASSERT_EQUAL_INT(DRDC_E_YEAR,
                        drdc_time_rtems_tod_to_utc(&bad, 3, &back));
  bad = tod;
  bad.month = 13;
  TEST_ASSERT_EQUAL_INT(DRDC_E_MONTH,
                        drdc_time_rtems_tod_to_utc(&bad, 3, &back));
  bad = tod;
  bad.day = 30; /* February */
  TEST_ASSERT_EQUAL_INT(DRDC_E_DAY, drdc_time_rtems_tod_to_utc(&bad, 3, &back));
  bad = tod;
  bad.hour = 24;
  TEST_ASSERT_EQUAL_INT(DRDC_E_HOUR,
                        drdc_time_rtems_tod_to_utc(&bad, 3, &back));
  bad = tod;
  bad.minute = 60;
  TEST_ASSERT_EQUAL_INT(DRDC_E_MINUTE,
                        drdc_time_rtems_tod_to_utc(&bad, 3, &back));
  bad = tod;
  bad.second = 60;
  TEST_ASSERT_EQUAL_INT(DRDC_E_SECOND,
                        drdc_time_rtems_tod_to_utc(&bad, 3, &back));
  TEST_ASSERT_EQUAL_INT64(7, back.sec);
  t.sec = INT64_C(567993599); /* 1987-12-31T23:59:59 */
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_time_utc_to_rtems_tod(NULL, &t, 3, &tod));
  TEST_ASSERT_EQUAL_INT(DRDC_E_TICKS,
                        drdc_time_utc_to_rtems_tod(NULL, &t, 0, &tod));
}

static void test_gps_week_resolves_against_the_pivot(void)
{
  drdc_time_t pivot = {UTC_2020_01_01, 0}; /* GPS week 2086 */
  int32_t week = 7;

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_gps_week_resolve(38, &pivot, &week));
  TEST_ASSERT_EQUAL_INT32(2086, week);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_gps_week_resolve(37, &pivot, &week));
  TEST_ASSERT_EQUAL_INT32(3109, week);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_gps_week_resolve(0, &pivot, &week));
  TEST_ASSERT_EQUAL_INT32(3072, week); /* 2038-11-21 */
  pivot.sec = INT64_C(935280000);      /* 1999-08-22: first rollover */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_gps_week_resolve(0, &pivot, &week));
  TEST_ASSERT_EQUAL_INT32(1024, week);
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_time_gps_week_resolve(1023, &pivot, &week));
  TEST_ASSERT_EQUAL_INT32(2047, week);
  week = 7;
  TEST_ASSERT_EQUAL_INT(DRDC_E_WEEK,
                        drdc_time_gps_week_resolve(1024, &pivot, &week));
  TEST_ASSERT_EQUAL_INT(DRDC_E_WEEK,
                        drdc_time_gps_week_resolve(-1, &pivot, &week));
  pivot.sec = INT64_C(315964799); /* before the GPS epoch */
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_time_gps_week_resolve(0, &pivot, &week));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_time_gps_week_resolve(0, NULL, &week));
  TEST_ASSERT_EQUAL_INT32(7, week);
}

static void test_day_of_week_and_year(void)
{
  int32_t yday = 0;

  TEST_ASSERT_EQUAL_INT32(4, drdc_time_day_of_week(0));     /* Thursday */
  TEST_ASSERT_EQUAL_INT32(3, drdc_time_day_of_week(-1));    /* Wednesday */
  TEST_ASSERT_EQUAL_INT32(0, drdc_time_day_of_week(3657));  /* 1980-01-06 */
  TEST_ASSERT_EQUAL_INT32(6, drdc_time_day_of_week(10957)); /* 2000-01-01 */
  TEST_ASSERT_EQUAL_INT32(
      1, drdc_time_day_of_week(DRDC_TIME_DAYS_MIN)); /* Monday */
  TEST_ASSERT_EQUAL_INT32(5, drdc_time_day_of_week(INT32_MAX));
  /* a negative remainder corrected, then the epoch's 4 wrapped or not */
  TEST_ASSERT_EQUAL_INT32(2, drdc_time_day_of_week(INT32_MIN));
  TEST_ASSERT_EQUAL_INT32(4, drdc_time_day_of_week(-7));
  TEST_ASSERT_EQUAL_INT32(3, drdc_time_day_of_week(-8));
  TEST_ASSERT_EQUAL_INT32(0, drdc_time_day_of_week(3));
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_day_of_year(2024, 12, 31, &yday));
  TEST_ASSERT_EQUAL_INT32(366, yday);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_day_of_year(2023, 12, 31, &yday));
  TEST_ASSERT_EQUAL_INT32(365, yday);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_day_of_year(2000, 3, 1, &yday));
  TEST_ASSERT_EQUAL_INT32(61, yday);
  TEST_ASSERT_EQUAL_INT(DRDC_E_DAY, drdc_time_day_of_year(2023, 2, 29, &yday));
  TEST_ASSERT_EQUAL_INT32(61, yday);
}

static void test_past_expiry_warns_and_writes(void)
{
  drdc_time_t t = {UTC_2027_06_28 - 1, 0};
  drdc_time_count_t k = {0, 0};
  int32_t off = 0;

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_leap_offset(NULL, &t, &off));
  TEST_ASSERT_EQUAL_INT32(37, off);
  t.sec += 1;
  off = 0;
  TEST_ASSERT_EQUAL_INT(DRDC_W_LEAP_EXPIRED,
                        drdc_time_leap_offset(NULL, &t, &off));
  TEST_ASSERT_EQUAL_INT32(37, off);
  TEST_ASSERT_EQUAL_INT(DRDC_W_LEAP_EXPIRED,
                        drdc_time_utc_to_tai(NULL, &t, &k));
  TEST_ASSERT_EQUAL_INT64(UTC_2027_06_28 + 37 + DRDC_TIME_TAI_EPOCH_TO_UNIX,
                          k.sec);
  TEST_ASSERT_FALSE(drdc_status_is_error(DRDC_W_LEAP_EXPIRED));
}

static void test_gps_update_confirms_and_extends(void)
{
  drdc_time_leap_t leap;
  drdc_time_t t = {UTC_2027_06_28, 0};
  int32_t off = 0;

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_leap_init(&leap));
  /* What satellites broadcast since 2017: 18 s, event week 1929 (137),
   * day 7, 18 s; received in week 2500, long after the event */
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_time_leap_update_gps(&leap, 2500, 18, 137, 7, 18));
  TEST_ASSERT_EQUAL_INT32(0, leap.extra_count);
  TEST_ASSERT_EQUAL_INT32(3657 + (2501 * 7), leap.expiry_day);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_leap_offset(&leap, &t, &off));
  TEST_ASSERT_EQUAL_INT32(37, off);
  /* in week 1930 the event itself is resolvable and is the known one */
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_time_leap_update_gps(&leap, 1930, 18, 137, 7, 18));
  TEST_ASSERT_EQUAL_INT32(3657 + (2501 * 7),
                          leap.expiry_day); /* never shrinks */
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_leap_init(NULL));
}

static void test_gps_update_schedules_a_new_leap_second(void)
{
  drdc_time_leap_t leap;
  drdc_time_civil_t c = {2027, 6, 30, 23, 59, 60, 0};
  drdc_time_t t = {0, 0};
  drdc_time_t back = {0, 0};
  drdc_time_count_t k = {0, 0};

  drdc_time_leap_init(&leap);
  TEST_ASSERT_EQUAL_INT(DRDC_E_SECOND, drdc_time_from_civil(&leap, &c, &t));
  /* announced in week 2450: 2027-06-30 is day 4 of week 2477 (173) */
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_time_leap_update_gps(&leap, 2450, 18, 173, 4, 19));
  TEST_ASSERT_EQUAL_INT32(1, leap.extra_count);
  TEST_ASSERT_EQUAL_INT32(DAY_2027_07_01, leap.extra[0].day);
  TEST_ASSERT_EQUAL_INT32(38, leap.extra[0].tai_utc);
  TEST_ASSERT_EQUAL_INT32(DAY_2027_07_01, leap.expiry_day);
  TEST_ASSERT_EQUAL_INT(1, drdc_time_leap_day_end(&leap, DAY_2027_07_01 - 1));
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_from_civil(&leap, &c, &t));
  TEST_ASSERT_EQUAL_INT64(UTC_2027_07_01 - 1, t.sec);
  TEST_ASSERT_EQUAL_INT32(NS, t.nsec);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_utc_to_tai(&leap, &t, &k));
  TEST_ASSERT_EQUAL_INT64(UTC_2027_07_01 - 1 + 38 + DRDC_TIME_TAI_EPOCH_TO_UNIX,
                          k.sec);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_tai_to_utc(&leap, &k, &back));
  TEST_ASSERT_EQUAL_INT64(t.sec, back.sec);
  TEST_ASSERT_EQUAL_INT32(NS, back.nsec);
  k.sec += 1; /* 2027-07-01T00:00:00 */
  TEST_ASSERT_EQUAL_INT(DRDC_W_LEAP_EXPIRED,
                        drdc_time_tai_to_utc(&leap, &k, &back));
  TEST_ASSERT_EQUAL_INT64(UTC_2027_07_01, back.sec);
  TEST_ASSERT_EQUAL_INT32(0, back.nsec);
  /* the same broadcast again changes nothing; after the event the
   * satellites send 19, 173, 4, 19: also the known event */
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_time_leap_update_gps(&leap, 2460, 18, 173, 4, 19));
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_time_leap_update_gps(&leap, 2480, 19, 173, 4, 19));
  TEST_ASSERT_EQUAL_INT32(1, leap.extra_count);
  TEST_ASSERT_EQUAL_INT32(3657 + (2481 * 7), leap.expiry_day);
  /* the built-in state did not change */
  TEST_ASSERT_EQUAL_INT(0, drdc_time_leap_day_end(NULL, DAY_2027_07_01 - 1));
}

static void test_gps_update_learns_a_missed_leap_second(void)
{
  drdc_time_leap_t leap;

  drdc_time_leap_init(&leap);
  /* first broadcast seen after the event: 19 s now, event 2027-06-30 */
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_time_leap_update_gps(&leap, 2480, 19, 173, 4, 19));
  TEST_ASSERT_EQUAL_INT32(1, leap.extra_count);
  TEST_ASSERT_EQUAL_INT32(DAY_2027_07_01, leap.extra[0].day);
  TEST_ASSERT_EQUAL_INT32(38, leap.extra[0].tai_utc);
}

static void test_gps_update_negative_leap_second(void)
{
  drdc_time_leap_t leap;
  drdc_time_civil_t c = {2027, 6, 30, 23, 59, 59, 0};
  drdc_time_t t = {0, 0};
  drdc_time_count_t k = {0, 0};
  drdc_time_t back = {0, 0};

  drdc_time_leap_init(&leap);
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_time_leap_update_gps(&leap, 2450, 18, 173, 4, 17));
  TEST_ASSERT_EQUAL_INT(-1, drdc_time_leap_day_end(&leap, DAY_2027_07_01 - 1));
  /* 23:59:59 does not exist that day */
  TEST_ASSERT_EQUAL_INT(DRDC_E_SECOND, drdc_time_from_civil(&leap, &c, &t));
  c.second = 58;
  c.nsec = 999999999;
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_from_civil(&leap, &c, &t));
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_utc_to_tai(&leap, &t, &k));
  /* one nanosecond later in TAI is the next midnight, offset 36 */
  k.sec += 1;
  k.nsec = 0;
  TEST_ASSERT_EQUAL_INT(DRDC_W_LEAP_EXPIRED,
                        drdc_time_tai_to_utc(&leap, &k, &back));
  TEST_ASSERT_EQUAL_INT64(UTC_2027_07_01, back.sec);
  TEST_ASSERT_EQUAL_INT32(0, back.nsec);
}

/* The parts of a state an update may change (struct copies would call
 * memcpy(), which the bare-metal PowerPC image does not have). */
struct leap_snapshot {
  int32_t extra_count;
  int32_t expiry_day;
  int32_t last_day;
  int32_t last_tai_utc;
};

static struct leap_snapshot snapshot(const drdc_time_leap_t *l)
{
  struct leap_snapshot s;

  s.extra_count = l->extra_count;
  s.expiry_day = l->expiry_day;
  s.last_day = (l->extra_count > 0) ? l->extra[l->extra_count - 1].day : 0;
  s.last_tai_utc =
      (l->extra_count > 0) ? l->extra[l->extra_count - 1].tai_utc : 0;
  return s;
}

static void assert_unchanged(struct leap_snapshot before,
                             const drdc_time_leap_t *l)
{
  struct leap_snapshot now = snapshot(l);

  TEST_ASSERT_EQUAL_INT32(before.extra_count, now.extra_count);
  TEST_ASSERT_EQUAL_INT32(before.expiry_day, now.expiry_day);
  TEST_ASSERT_EQUAL_INT32(before.last_day, now.last_day);
  TEST_ASSERT_EQUAL_INT32(before.last_tai_utc, now.last_tai_utc);
}

static void test_gps_update_rejects_bad_parameters(void)
{
  static const struct {
    int32_t week_now, dt_ls, wn_lsf, dn, dt_lsf;
    drdc_status_t status;
  } bad[] = {
      {-1, 18, 173, 4, 19, DRDC_E_WEEK},
      {DRDC_TIME_GPS_WEEK_MAX + 1, 18, 173, 4, 19, DRDC_E_WEEK},
      {2450, 18, 173, 0, 19, DRDC_E_LEAP_TABLE}, /* DN 0 */
      {2450, 18, 173, 8, 19, DRDC_E_LEAP_TABLE}, /* DN 8 */
      {2450, 18, 256, 4, 19, DRDC_E_LEAP_TABLE}, /* WN_LSF 9 bits */
      {2450, 18, -1, 4, 19, DRDC_E_LEAP_TABLE},
      {2450, 18, 173, 4, 20, DRDC_E_LEAP_TABLE},   /* a 2 s step */
      {2450, 128, 173, 4, 127, DRDC_E_LEAP_TABLE}, /* not an int8 */
      {2450, 20, 173, 4, 21, DRDC_E_LEAP_TABLE},   /* 20 s does not follow 37 */
      {2450, 20, 173, 4, 20, DRDC_E_LEAP_TABLE},   /* 39 s: a jump of two */
      /* a known date (2016-12-31 = week 1929 day 7) with another offset */
      {1930, 18, 137, 7, 19, DRDC_E_LEAP_TABLE},
      /* the day before a known leap second announced as one */
      {1930, 17, 137, 6, 18, DRDC_E_LEAP_TABLE},
  };
  drdc_time_leap_t leap;
  size_t i;

  drdc_time_leap_init(&leap);
  for (i = 0; i < COUNT(bad); i++) {
    struct leap_snapshot before = snapshot(&leap);

    TEST_ASSERT_EQUAL_INT(bad[i].status,
                          drdc_time_leap_update_gps(&leap, bad[i].week_now,
                                                    bad[i].dt_ls, bad[i].wn_lsf,
                                                    bad[i].dn, bad[i].dt_lsf));
    assert_unchanged(before, &leap);
  }
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_time_leap_update_gps(NULL, 2450, 18, 173, 4, 19));
}

static void test_gps_update_overflow_when_full(void)
{
  drdc_time_leap_t leap;
  struct leap_snapshot before;
  int32_t i;

  drdc_time_leap_init(&leap);
  /* one leap second every 52 weeks from week 2470 */
  for (i = 0; i < DRDC_TIME_LEAP_EXTRA_MAX; i++) {
    int32_t week = 2470 + (52 * i);

    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_time_leap_update_gps(&leap, week - 10, 18 + i,
                                                    week % 256, 7, 19 + i));
  }
  TEST_ASSERT_EQUAL_INT32(DRDC_TIME_LEAP_EXTRA_MAX, leap.extra_count);
  before = snapshot(&leap);
  i = 2470 + (52 * DRDC_TIME_LEAP_EXTRA_MAX);
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_OVERFLOW,
      drdc_time_leap_update_gps(&leap, i - 10, 18 + DRDC_TIME_LEAP_EXTRA_MAX,
                                i % 256, 7, 19 + DRDC_TIME_LEAP_EXTRA_MAX));
  assert_unchanged(before, &leap);
}

void suite_time_named(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_bad_civil_times_give_their_status);
  RUN_TEST(test_bad_utc_instants_give_their_status);
  RUN_TEST(test_bad_gps_times_give_their_status);
  RUN_TEST(test_before_1972_and_before_gps_epoch_are_range_errors);
  RUN_TEST(test_leap_second_in_unix_and_rtems_is_the_next_midnight);
  RUN_TEST(test_rtems_time_of_day);
  RUN_TEST(test_gps_week_resolves_against_the_pivot);
  RUN_TEST(test_day_of_week_and_year);
  RUN_TEST(test_past_expiry_warns_and_writes);
  RUN_TEST(test_gps_update_confirms_and_extends);
  RUN_TEST(test_gps_update_schedules_a_new_leap_second);
  RUN_TEST(test_gps_update_learns_a_missed_leap_second);
  RUN_TEST(test_gps_update_negative_leap_second);
  RUN_TEST(test_gps_update_rejects_bad_parameters);
  RUN_TEST(test_gps_update_overflow_when_full);
}
