/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_rtems
 * @brief RTEMS glue: conversions between drdc_time_t and the RTEMS clock.
 */
/* struct timespec is POSIX: visible in <time.h> only when asked for. */
#define _POSIX_C_SOURCE 200809L

#include "drdc_rtems.h"

#include <drdc/time_scales.h>

#include <stddef.h>

drdc_status_t drdc_rtems_utc_from_tod(const rtems_time_of_day *tod,
                                      drdc_time_t *utc)
{
  drdc_time_rtems_tod_t t;

  if ((tod == NULL) || (utc == NULL)) {
    return DRDC_E_NULL;
  }
  t.year = tod->year;
  t.month = tod->month;
  t.day = tod->day;
  t.hour = tod->hour;
  t.minute = tod->minute;
  t.second = tod->second;
  t.ticks = tod->ticks;
  return drdc_time_rtems_tod_to_utc(&t, rtems_clock_get_ticks_per_second(),
                                    utc);
}

drdc_status_t drdc_rtems_tod_from_utc(const drdc_time_leap_t *leap,
                                      const drdc_time_t *utc,
                                      rtems_time_of_day *tod)
{
  drdc_time_rtems_tod_t t;
  drdc_status_t st;

  if ((utc == NULL) || (tod == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc_time_utc_to_rtems_tod(leap, utc, rtems_clock_get_ticks_per_second(),
                                  &t);
  if (!drdc_status_is_error(st)) {
    tod->year = t.year;
    tod->month = t.month;
    tod->day = t.day;
    tod->hour = t.hour;
    tod->minute = t.minute;
    tod->second = t.second;
    tod->ticks = t.ticks;
  }
  return st;
}

drdc_status_t drdc_rtems_utc_from_timespec(const struct timespec *ts,
                                           drdc_time_t *utc)
{
  drdc_time_count_t count;

  if ((ts == NULL) || (utc == NULL)) {
    return DRDC_E_NULL;
  }
  if ((ts->tv_nsec < 0) || (ts->tv_nsec >= DRDC_NS_PER_SECOND)) {
    return DRDC_E_NANOSECOND;
  }
  count.sec = (int64_t)ts->tv_sec;
  count.nsec = (int32_t)ts->tv_nsec;
  return drdc_time_unix_to_utc(&count, utc);
}

drdc_status_t drdc_rtems_timespec_from_utc(const drdc_time_leap_t *leap,
                                           const drdc_time_t *utc,
                                           struct timespec *ts)
{
  drdc_time_count_t count;
  drdc_status_t st;

  if ((utc == NULL) || (ts == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc_time_utc_to_unix(leap, utc, &count);
  if (drdc_status_is_error(st)) {
    return st;
  }
  /* time_t is 64 bits on RTEMS 6; refuse rather than wrap elsewhere */
  if ((int64_t)(time_t)count.sec != count.sec) {
    return DRDC_E_OVERFLOW;
  }
  ts->tv_sec = (time_t)count.sec;
  ts->tv_nsec = (long)count.nsec;
  return st;
}

drdc_status_t drdc_rtems_clock_get_utc(drdc_time_t *utc)
{
  rtems_time_of_day tod;

  if (utc == NULL) {
    return DRDC_E_NULL;
  }
  if (rtems_clock_get_tod(&tod) != RTEMS_SUCCESSFUL) {
    return DRDC_E_RANGE;
  }
  return drdc_rtems_utc_from_tod(&tod, utc);
}

drdc_status_t drdc_rtems_clock_set_utc(const drdc_time_leap_t *leap,
                                       const drdc_time_t *utc)
{
  rtems_time_of_day tod;
  drdc_status_t st;

  if (utc == NULL) {
    return DRDC_E_NULL;
  }
  st = drdc_rtems_tod_from_utc(leap, utc, &tod);
  if (drdc_status_is_error(st)) {
    return st;
  }
  if (rtems_clock_set(&tod) != RTEMS_SUCCESSFUL) {
    return DRDC_E_RANGE;
  }
  return st;
}
