/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time
 * @brief Day of week and day of year.
 */
#include "time_impl.h"

/* 1970-01-01 was a Thursday (4 with Sunday = 0). */
#define WEEKDAY_OF_EPOCH 4

int32_t drdc_time_day_of_week(int32_t days)
{
  /* int64 so that days + 4 cannot overflow at INT32_MAX. */
  return (int32_t)drdc_time_floor_mod((int64_t)days + WEEKDAY_OF_EPOCH, 7);
}

drdc_status_t drdc_time_day_of_year(int32_t year, int32_t month, int32_t day,
                                    int32_t *yday)
{
  int32_t d;
  int32_t jan1;
  drdc_status_t st;

  if (yday == NULL) {
    return DRDC_E_NULL;
  }
  st = drdc_time_days_from_civil(year, month, day, &d);
  if (st != DRDC_OK) {
    return st;
  }
  (void)drdc_time_days_from_civil(year, 1, 1, &jan1); /* valid: year is */
  *yday = d - jan1 + 1;
  return DRDC_OK;
}
