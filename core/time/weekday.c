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
  /* floor_mod(days + 4, 7) in int32 (days + 4 could overflow at
   * INT32_MAX): the remainder of days corrected into [0, 7) first, so
   * no 64-bit division (a libgcc call at -Os) is needed. */
  int32_t w = days % 7;

  if (w < 0) {
    w += 7;
  }
  w += WEEKDAY_OF_EPOCH;
  if (w >= 7) {
    w -= 7;
  }
  return w;
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
