/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time_scales
 * @brief UTC <-> Unix/POSIX seconds (a leap second maps to the next
 *        midnight, as the POSIX formula does with tm_sec = 60).
 */
#include <drdc/time_scales.h>

#include "time_impl.h"

drdc_status_t drdc_time_utc_to_unix(const drdc_time_leap_t *leap,
                                    const drdc_time_t *utc,
                                    drdc_time_count_t *unix_time)
{
  drdc_time_count_t r;
  drdc_status_t st;

  if (unix_time == NULL) {
    return DRDC_E_NULL;
  }
  st = drdc_time_check(leap, utc);
  if (st != DRDC_OK) {
    return st;
  }
  r.sec = utc->sec;
  r.nsec = utc->nsec;
  if (r.nsec >= DRDC_NS_PER_SECOND) {
    r.sec += 1;
    r.nsec -= DRDC_NS_PER_SECOND;
  }
  *unix_time = r;
  return DRDC_OK;
}

drdc_status_t drdc_time_unix_to_utc(const drdc_time_count_t *unix_time,
                                    drdc_time_t *utc)
{
  if ((unix_time == NULL) || (utc == NULL)) {
    return DRDC_E_NULL;
  }
  if ((unix_time->nsec < 0) || (unix_time->nsec >= DRDC_NS_PER_SECOND)) {
    return DRDC_E_NANOSECOND;
  }
  if ((unix_time->sec < UTC_SEC_MIN) || (unix_time->sec >= UTC_SEC_END)) {
    return DRDC_E_RANGE;
  }
  utc->sec = unix_time->sec;
  utc->nsec = unix_time->nsec;
  return DRDC_OK;
}
