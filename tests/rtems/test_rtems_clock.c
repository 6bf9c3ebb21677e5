/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The RTEMS glue (libdrdc_rtems.a) against a running RTEMS kernel:
 *        the clock set from GPS time and read back in UTC, across a leap
 *        second. Built into the RTEMS test-runner only.
 *
 * The instants and their civil fields are ERFA's (tests/time/vectors_time.h).
 * The clock is read back with RTEMS's own rtems_clock_get_tod(), so the
 * kernel, not the glue, says what was set. The clock runs between the set
 * and the read: a read may be later than the set by the time the test takes
 * (bounded by CLOCK_RUN_MAX_NS) and earlier by less than one tick (the set
 * truncates to ticks).
 */
#include <rtems.h>

#include <drdc/status.h>
#include <drdc/time.h>
#include <drdc/time_scales.h>

#include "drdc_rtems.h"
#include "suites.h"
#include "unity.h"
#include "../time/vectors_time.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))
#define NS       DRDC_NS_PER_SECOND
/* The RTEMS time of day: 1988 (the RTEMS epoch) up to 2099 in every RTEMS
 * release (later ones accept more). */
#define TOD_YEAR_FIRST 1988
#define TOD_YEAR_LAST  2099
/* Far more than a set and a read take under QEMU (a few microseconds). */
#define CLOCK_RUN_MAX_NS INT64_C(100000000)

/* The POSIX instant RTEMS keeps for v: a leap second 23:59:59 + 1.f reads
 * as 00:00:00.f of the next day, which is v's seconds plus one. */
static int64_t posix_ns(const struct time_special *v)
{
  int64_t sec = (int64_t)v->utc_sec;
  int32_t nsec = v->nsec;

  if (nsec >= NS) {
    sec += 1;
    nsec -= NS;
  }
  return (sec * NS) + nsec;
}

/* ERFA's row of the instant at whole second sec, if the table has it. */
static const struct time_special *row_at(int64_t sec)
{
  size_t i;

  for (i = 0; i < COUNT(time_specials); i++) {
    if (((int64_t)time_specials[i].utc_sec == sec) &&
        (time_specials[i].nsec == 0)) {
      return &time_specials[i];
    }
  }
  return NULL;
}

static void expect_tod_fields(const struct time_special *civil,
                              const rtems_time_of_day *tod)
{
  TEST_ASSERT_EQUAL_UINT32(civil->year, tod->year);
  TEST_ASSERT_EQUAL_UINT32(civil->month, tod->month);
  TEST_ASSERT_EQUAL_UINT32(civil->day, tod->day);
  TEST_ASSERT_EQUAL_UINT32(civil->hour, tod->hour);
  TEST_ASSERT_EQUAL_UINT32(civil->minute, tod->minute);
  TEST_ASSERT_EQUAL_UINT32(civil->second, tod->second);
}

/* Set the clock from the GPS time of v, then read it back twice: RTEMS's
 * time of day against ERFA's civil fields (where the read cannot have
 * passed into the next second), and the glue's UTC against v. */
static void set_from_gps_and_read_back(const struct time_special *v,
                                       int64_t tick_ns)
{
  drdc_time_t utc = {(int64_t)v->utc_sec, v->nsec};
  drdc_time_gps_t gps;
  drdc_time_t from_gps;
  drdc_time_t now;
  rtems_time_of_day tod;
  int64_t late_ns;

  /* beyond the leap table's expiry these succeed with a warning */
  TEST_ASSERT_FALSE(
      drdc_status_is_error(drdc_time_utc_to_gps(NULL, &utc, &gps)));
  TEST_ASSERT_FALSE(
      drdc_status_is_error(drdc_time_gps_to_utc(NULL, &gps, &from_gps)));
  TEST_ASSERT_EQUAL_INT64(utc.sec, from_gps.sec);
  TEST_ASSERT_EQUAL_INT32(utc.nsec, from_gps.nsec);
  TEST_ASSERT_FALSE(
      drdc_status_is_error(drdc_rtems_clock_set_utc(NULL, &from_gps)));
  TEST_ASSERT_EQUAL_INT(RTEMS_SUCCESSFUL, rtems_clock_get_tod(&tod));
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_rtems_clock_get_utc(&now));

  if ((posix_ns(v) % NS) < (NS - CLOCK_RUN_MAX_NS)) {
    const struct time_special *civil =
        (v->nsec >= NS) ? row_at((int64_t)v->utc_sec + 1) : v;
    if (civil != NULL) {
      expect_tod_fields(civil, &tod);
    }
  }
  /* RTEMS keeps no second 60: the glue reads POSIX time. */
  TEST_ASSERT_TRUE(now.nsec < NS);
  late_ns = ((now.sec * NS) + now.nsec) - posix_ns(v);
  TEST_ASSERT_TRUE(late_ns > -tick_ns);
  TEST_ASSERT_TRUE(late_ns < CLOCK_RUN_MAX_NS);
}

static void test_clock_set_from_gps_reads_back_erfa_utc(void)
{
  int64_t tick_ns = NS / (int64_t)rtems_clock_get_ticks_per_second();
  size_t tried = 0;
  size_t i;

  for (i = 0; i < COUNT(time_specials); i++) {
    const struct time_special *v = &time_specials[i];

    if ((v->year < TOD_YEAR_FIRST) || (v->year > TOD_YEAR_LAST)) {
      continue;
    }
    set_from_gps_and_read_back(v, tick_ns);
    tried++;
  }
  /* the table reaches from before 1988 to after 2017 */
  TEST_ASSERT_TRUE(tried > 100);
}

/* 2016-12-31T23:59:60.5 UTC (GPS week 1930, 17.5 s, the leap second of
 * IERS Bulletin C 52): RTEMS holds 2017-01-01T00:00:00.5, one tick's
 * truncation aside. */
static void test_clock_across_the_2016_leap_second(void)
{
  const drdc_time_gps_t gps = {1930, 17, 500000000};
  const drdc_time_t leap = {INT64_C(1483228799), 1500000000};
  drdc_time_t utc;
  rtems_time_of_day tod;

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_time_gps_to_utc(NULL, &gps, &utc));
  TEST_ASSERT_EQUAL_INT64(leap.sec, utc.sec);
  TEST_ASSERT_EQUAL_INT32(leap.nsec, utc.nsec);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_rtems_clock_set_utc(NULL, &utc));
  TEST_ASSERT_EQUAL_INT(RTEMS_SUCCESSFUL, rtems_clock_get_tod(&tod));
  TEST_ASSERT_EQUAL_UINT32(2017, tod.year);
  TEST_ASSERT_EQUAL_UINT32(1, tod.month);
  TEST_ASSERT_EQUAL_UINT32(1, tod.day);
  TEST_ASSERT_EQUAL_UINT32(0, tod.hour);
  TEST_ASSERT_EQUAL_UINT32(0, tod.minute);
  TEST_ASSERT_EQUAL_UINT32(0, tod.second);
  /* half a second of ticks, less the truncation and the run */
  TEST_ASSERT_UINT32_WITHIN(rtems_clock_get_ticks_per_second() / 10u,
                            rtems_clock_get_ticks_per_second() / 2u, tod.ticks);
}

static void test_clock_refuses_what_rtems_cannot_hold(void)
{
  const drdc_time_t before_epoch = {INT64_C(567993599), 0}; /* 1987 */
  drdc_time_t now;

  TEST_ASSERT_NOT_EQUAL_INT(DRDC_OK,
                            drdc_rtems_clock_set_utc(NULL, &before_epoch));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_rtems_clock_set_utc(NULL, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_rtems_clock_get_utc(NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_rtems_clock_get_utc(&now));
}

void suite_rtems_clock(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_clock_set_from_gps_reads_back_erfa_utc);
  RUN_TEST(test_clock_across_the_2016_leap_second);
  RUN_TEST(test_clock_refuses_what_rtems_cannot_hold);
}
