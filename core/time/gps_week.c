/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time_scales
 * @brief 10-bit GPS week resolution: apart from gps.c, whose conversions
 *        are timed, so that it can be compiled for flash.
 */
#include <drdc/time_scales.h>

#include "time_impl.h"

drdc_status_t drdc_time_gps_week_resolve(int32_t week10,
                                         const drdc_time_t *pivot,
                                         int32_t *week)
{
  int32_t day;
  int32_t pivot_week;
  int32_t w;

  if ((pivot == NULL) || (week == NULL)) {
    return DRDC_E_NULL;
  }
  if ((week10 < 0) || (week10 >= DRDC_TIME_GPS_WEEK_ROLLOVER)) {
    return DRDC_E_WEEK;
  }
  if (drdc_time_check(NULL, pivot) != DRDC_OK) {
    return DRDC_E_RANGE;
  }
  day = (int32_t)drdc_time_floor_div(pivot->sec, SECONDS_PER_DAY);
  if (day < DAYS_1970_TO_GPS) {
    return DRDC_E_RANGE;
  }
  pivot_week = (day - DAYS_1970_TO_GPS) / 7;
  /* Both operands of % are non-negative here. */
  w = pivot_week + ((week10 - (pivot_week % DRDC_TIME_GPS_WEEK_ROLLOVER) +
                     DRDC_TIME_GPS_WEEK_ROLLOVER) %
                    DRDC_TIME_GPS_WEEK_ROLLOVER);
  if (w > DRDC_TIME_GPS_WEEK_MAX) {
    return DRDC_E_WEEK;
  }
  *week = w;
  return DRDC_OK;
}
