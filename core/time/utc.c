/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time
 * @brief Validation of UTC instants (leap second as 23:59:60); broken-down
 *        UTC time in utc_civil.c.
 */
#include "time_impl.h"

/* 23:59:59 as seconds of the day: the second a leap second extends. */
#define LAST_SECOND_OF_DAY (SECONDS_PER_DAY - 1)

drdc_status_t drdc_time_check(const drdc_time_leap_t *leap,
                              const drdc_time_t *utc)
{
  int64_t sod;
  int32_t day;

  if (utc == NULL) {
    return DRDC_E_NULL;
  }
  if ((utc->sec < UTC_SEC_MIN) || (utc->sec >= UTC_SEC_END)) {
    return DRDC_E_RANGE;
  }
  if ((utc->nsec < 0) || (utc->nsec >= (2 * DRDC_NS_PER_SECOND))) {
    return DRDC_E_NANOSECOND;
  }
  /* In range: day fits int32 (DRDC_TIME_DAYS_MIN..MAX). */
  day = (int32_t)drdc_time_floor_div(utc->sec, SECONDS_PER_DAY);
  sod = utc->sec - ((int64_t)day * SECONDS_PER_DAY);
  if (sod == LAST_SECOND_OF_DAY) {
    int end = drdc_time_leap_day_end(leap, day);

    if (end < 0) {
      return DRDC_E_SECOND; /* 23:59:59 was skipped that day */
    }
    if ((utc->nsec >= DRDC_NS_PER_SECOND) && (end == 0)) {
      return DRDC_E_SECOND; /* 23:59:60 on a day without a leap second */
    }
  } else if (utc->nsec >= DRDC_NS_PER_SECOND) {
    return DRDC_E_NANOSECOND;
  } else {
    /* any other second of the day, nsec < 1e9 */
  }
  return DRDC_OK;
}
