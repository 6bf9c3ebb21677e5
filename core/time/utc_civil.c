/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time
 * @brief Validation of broken-down UTC time and the conversion between it
 *        and UTC instants (leap second as 23:59:60): apart from utc.c,
 *        whose instant check is on the timed conversions, so that these
 *        can be compiled for flash.
 */
#include "time_impl.h"

#define SECONDS_PER_HOUR   3600
#define SECONDS_PER_MINUTE 60

drdc_status_t drdc_time_civil_check(const drdc_time_leap_t *leap,
                                    const drdc_time_civil_t *c)
{
  int32_t day;
  drdc_status_t st;

  if (c == NULL) {
    return DRDC_E_NULL;
  }
  st = drdc_time_days_from_civil(c->year, c->month, c->day, &day);
  if (st != DRDC_OK) {
    return st;
  }
  if ((c->hour < 0) || (c->hour > 23)) {
    return DRDC_E_HOUR;
  }
  if ((c->minute < 0) || (c->minute > 59)) {
    return DRDC_E_MINUTE;
  }
  if ((c->second < 0) || (c->second > 60)) {
    return DRDC_E_SECOND;
  }
  if ((c->hour == 23) && (c->minute == 59) && (c->second >= 59)) {
    int end = drdc_time_leap_day_end(leap, day);

    if ((c->second == 60) ? (end <= 0) : (end < 0)) {
      return DRDC_E_SECOND;
    }
  } else if (c->second == 60) {
    return DRDC_E_SECOND;
  } else {
    /* seconds 0..59 before 23:59:59 exist on every day */
  }
  if ((c->nsec < 0) || (c->nsec >= DRDC_NS_PER_SECOND)) {
    return DRDC_E_NANOSECOND;
  }
  return DRDC_OK;
}

drdc_status_t drdc_time_from_civil(const drdc_time_leap_t *leap,
                                   const drdc_time_civil_t *civil,
                                   drdc_time_t *utc)
{
  int32_t day;
  int32_t second;
  int32_t nsec;
  drdc_status_t st;

  if (utc == NULL) {
    return DRDC_E_NULL;
  }
  st = drdc_time_civil_check(leap, civil);
  if (st != DRDC_OK) {
    return st;
  }
  (void)drdc_time_days_from_civil(civil->year, civil->month, civil->day, &day);
  second = civil->second;
  nsec = civil->nsec;
  if (second == 60) { /* 23:59:60.f is 23:59:59 + (1 + f) */
    second = 59;
    nsec += DRDC_NS_PER_SECOND;
  }
  utc->sec = ((int64_t)day * SECONDS_PER_DAY) +
             ((int64_t)civil->hour * SECONDS_PER_HOUR) +
             ((int64_t)civil->minute * SECONDS_PER_MINUTE) + second;
  utc->nsec = nsec;
  return DRDC_OK;
}

drdc_status_t drdc_time_to_civil(const drdc_time_leap_t *leap,
                                 const drdc_time_t *utc,
                                 drdc_time_civil_t *civil)
{
  int32_t day;
  int32_t sod;
  drdc_time_civil_t c;
  drdc_status_t st;

  if (civil == NULL) {
    return DRDC_E_NULL;
  }
  st = drdc_time_check(leap, utc);
  if (st != DRDC_OK) {
    return st;
  }
  day = (int32_t)drdc_time_floor_div(utc->sec, SECONDS_PER_DAY);
  sod = (int32_t)(utc->sec - ((int64_t)day * SECONDS_PER_DAY));
  (void)drdc_time_civil_from_days(day, &c.year, &c.month, &c.day);
  c.hour = sod / SECONDS_PER_HOUR;
  c.minute = (sod % SECONDS_PER_HOUR) / SECONDS_PER_MINUTE;
  c.second = sod % SECONDS_PER_MINUTE;
  c.nsec = utc->nsec;
  if (c.nsec >= DRDC_NS_PER_SECOND) { /* checked: only at 23:59:59 */
    c.second = 60;
    c.nsec -= DRDC_NS_PER_SECOND;
  }
  *civil = c;
  return DRDC_OK;
}
