/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time_scales
 * @brief UTC <-> RTEMS seconds since 1988-01-01 and the RTEMS time-of-day
 *        record with ticks.
 */
#include <drdc/time_scales.h>

#include "time_impl.h"

drdc_status_t drdc_time_utc_to_rtems(const drdc_time_leap_t *leap,
                                     const drdc_time_t *utc,
                                     drdc_time_count_t *rtems)
{
  drdc_time_count_t u;
  drdc_status_t st;

  if (rtems == NULL) {
    return DRDC_E_NULL;
  }
  st = drdc_time_utc_to_unix(leap, utc, &u);
  if (st != DRDC_OK) {
    return st;
  }
  rtems->sec = u.sec - DRDC_TIME_RTEMS_EPOCH_UNIX;
  rtems->nsec = u.nsec;
  return DRDC_OK;
}

drdc_status_t drdc_time_rtems_to_utc(const drdc_time_count_t *rtems,
                                     drdc_time_t *utc)
{
  drdc_time_count_t u;

  if ((rtems == NULL) || (utc == NULL)) {
    return DRDC_E_NULL;
  }
  /* Range first, so the epoch shift cannot overflow. */
  if ((rtems->sec < (UTC_SEC_MIN - DRDC_TIME_RTEMS_EPOCH_UNIX)) ||
      (rtems->sec >= (UTC_SEC_END - DRDC_TIME_RTEMS_EPOCH_UNIX))) {
    return ((rtems->nsec < 0) || (rtems->nsec >= DRDC_NS_PER_SECOND))
               ? DRDC_E_NANOSECOND
               : DRDC_E_RANGE;
  }
  u.sec = rtems->sec + DRDC_TIME_RTEMS_EPOCH_UNIX;
  u.nsec = rtems->nsec;
  return drdc_time_unix_to_utc(&u, utc);
}

drdc_status_t drdc_time_utc_to_rtems_tod(const drdc_time_leap_t *leap,
                                         const drdc_time_t *utc,
                                         uint32_t ticks_per_second,
                                         drdc_time_rtems_tod_t *tod)
{
  drdc_time_count_t u;
  drdc_time_t t;
  drdc_time_civil_t c;
  drdc_status_t st;

  if (tod == NULL) {
    return DRDC_E_NULL;
  }
  if ((ticks_per_second == 0u) ||
      (ticks_per_second > (uint32_t)DRDC_NS_PER_SECOND)) {
    return DRDC_E_TICKS;
  }
  st = drdc_time_utc_to_unix(leap, utc, &u);
  if (st != DRDC_OK) {
    return st;
  }
  if ((u.sec < DRDC_TIME_RTEMS_EPOCH_UNIX) || (u.sec >= UTC_SEC_END)) {
    return DRDC_E_RANGE;
  }
  t.sec = u.sec;
  t.nsec = u.nsec; /* < 1e9: never a leap second */
  st = drdc_time_to_civil(NULL, &t, &c);
  if (st != DRDC_OK) {
    return st;
  }
  tod->year = (uint32_t)c.year;
  tod->month = (uint32_t)c.month;
  tod->day = (uint32_t)c.day;
  tod->hour = (uint32_t)c.hour;
  tod->minute = (uint32_t)c.minute;
  tod->second = (uint32_t)c.second;
  /* nsec < 1e9 and ticks_per_second <= 1e9: the product is < 1e18. */
  tod->ticks = (uint32_t)(((uint64_t)(uint32_t)c.nsec * ticks_per_second) /
                          (uint64_t)DRDC_NS_PER_SECOND);
  return DRDC_OK;
}

drdc_status_t drdc_time_rtems_tod_to_utc(const drdc_time_rtems_tod_t *tod,
                                         uint32_t ticks_per_second,
                                         drdc_time_t *utc)
{
  drdc_time_civil_t c;
  uint64_t nsec;

  if ((tod == NULL) || (utc == NULL)) {
    return DRDC_E_NULL;
  }
  if ((ticks_per_second == 0u) ||
      (ticks_per_second > (uint32_t)DRDC_NS_PER_SECOND)) {
    return DRDC_E_TICKS;
  }
  /* Bound every unsigned field before it becomes an int32_t. */
  if ((tod->year < (uint32_t)DRDC_TIME_RTEMS_YEAR_MIN) ||
      (tod->year > (uint32_t)DRDC_YEAR_MAX)) {
    return DRDC_E_YEAR;
  }
  if ((tod->month < 1u) || (tod->month > 12u)) {
    return DRDC_E_MONTH;
  }
  if ((tod->day < 1u) || (tod->day > 31u)) {
    return DRDC_E_DAY;
  }
  if (tod->hour > 23u) {
    return DRDC_E_HOUR;
  }
  if (tod->minute > 59u) {
    return DRDC_E_MINUTE;
  }
  if (tod->second > 59u) {
    return DRDC_E_SECOND;
  }
  if (tod->ticks >= ticks_per_second) {
    return DRDC_E_TICKS;
  }
  c.year = (int32_t)tod->year;
  c.month = (int32_t)tod->month;
  c.day = (int32_t)tod->day;
  c.hour = (int32_t)tod->hour;
  c.minute = (int32_t)tod->minute;
  c.second = (int32_t)tod->second;
  /* ticks < ticks_per_second <= 1e9: the product is < 1e18. */
  nsec =
      ((uint64_t)tod->ticks * (uint64_t)DRDC_NS_PER_SECOND) / ticks_per_second;
  c.nsec = (int32_t)nsec; /* < 1e9 */
  return drdc_time_from_civil(NULL, &c, utc);
}
