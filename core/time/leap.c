/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time_leap
 * @brief Caller-owned leap-second state: initialisation and TAI-UTC
 *        lookup; the run-time update from GPS UTC parameters in
 *        leap_update.c.
 */
#include <drdc/time_scales.h>

#include "time_impl.h"

drdc_status_t drdc_time_leap_init(drdc_time_leap_t *leap)
{
  if (leap == NULL) {
    return DRDC_E_NULL;
  }
  /* Field by field: a struct copy may become a memcpy() call, and the
   * core links no libc. The unused `extra` entries are left as they are. */
  leap->table = drdc_time_leap_builtin()->table;
  leap->table_count = DRDC_TIME_LEAP_BUILTIN_COUNT;
  leap->extra_count = 0;
  leap->expiry_day = DRDC_TIME_LEAP_BUILTIN_EXPIRY_DAY;
  return DRDC_OK;
}

drdc_status_t drdc_time_leap_offset(const drdc_time_leap_t *leap,
                                    const drdc_time_t *utc, int32_t *tai_utc)
{
  const drdc_time_leap_t *l = drdc_time_leap_or_builtin(leap);
  int32_t day;
  drdc_status_t st;

  if (tai_utc == NULL) {
    return DRDC_E_NULL;
  }
  st = drdc_time_check(l, utc);
  if (st != DRDC_OK) {
    return st;
  }
  day = (int32_t)drdc_time_floor_div(utc->sec, SECONDS_PER_DAY);
  if (day < DRDC_TIME_LEAP_FIRST_DAY) {
    return DRDC_E_RANGE;
  }
  *tai_utc = drdc_time_leap_entry(l, drdc_time_leap_index(l, day)).tai_utc;
  return (day >= l->expiry_day) ? DRDC_W_LEAP_EXPIRED : DRDC_OK;
}
