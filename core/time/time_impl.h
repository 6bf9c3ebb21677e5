/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time
 * @brief Internal constants and helpers shared by the time module.
 */
#ifndef DRDC_TIME_IMPL_H
#define DRDC_TIME_IMPL_H

#include <stddef.h>
#include <stdint.h>

#include <drdc/time.h>
#include <drdc/time_leap.h>

/* UTC days have 86 400 POSIX seconds; leap seconds live in nsec. */
#define SECONDS_PER_DAY  86400
#define SECONDS_PER_WEEK 604800
/* Days from 1958-01-01 (TAI epoch) to 1970-01-01: 12 years, 3 leap days. */
#define DAYS_1958_TO_1970 4383
/* Days from 1970-01-01 to 1980-01-06 (GPS epoch, a Sunday). */
#define DAYS_1970_TO_GPS 3657
/* Days from 1970-01-01 to 1988-01-01 (RTEMS epoch). */
#define DAYS_1970_TO_RTEMS 6574
/* TAI - GPS: GPS time was set to UTC at its epoch, when TAI-UTC was 19 s. */
#define TAI_MINUS_GPS 19

/* UTC seconds (since 1970) of 0001-01-01T00:00:00 and of the first second
 * after 9999-12-31T23:59:59: the calendar range of a drdc_time_t. */
#define UTC_SEC_MIN ((int64_t)DRDC_TIME_DAYS_MIN * SECONDS_PER_DAY)
#define UTC_SEC_END (((int64_t)DRDC_TIME_DAYS_MAX + 1) * SECONDS_PER_DAY)

/* The leap state behind a possibly NULL argument. */
const drdc_time_leap_t *drdc_time_leap_or_builtin(const drdc_time_leap_t *l);

/* Entry i of a state: the built-in table first, then the extra ones. */
drdc_time_leap_entry_t drdc_time_leap_entry(const drdc_time_leap_t *l,
                                            int32_t i);

/* Number of entries of a state. */
int32_t drdc_time_leap_count(const drdc_time_leap_t *l);

/* Index of the entry in force on UTC day `day`, -1 before the first. */
int32_t drdc_time_leap_index(const drdc_time_leap_t *l, int32_t day);

/* Floor division and its non-negative remainder (b > 0), as C99's `/`
 * truncates toward zero. */
static inline int64_t drdc_time_floor_div(int64_t a, int64_t b)
{
  int64_t q = a / b;

  if ((a % b) < 0) {
    q -= 1;
  }
  return q;
}

static inline int64_t drdc_time_floor_mod(int64_t a, int64_t b)
{
  int64_t r = a % b;

  if (r < 0) {
    r += b;
  }
  return r;
}

#endif /* DRDC_TIME_IMPL_H */
