/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_jaus_date
 * @brief JAUS 16-bit date stamp <-> calendar date.
 */
#include <stddef.h>

#include <drdc/jaus_date.h>

#define DAY_MASK    0x1Fu
#define MONTH_SHIFT 5u
#define MONTH_MASK  0x0Fu
#define YEAR_SHIFT  9u
#define YEAR_MASK   0x7Fu

drdc_status_t drdc_jaus_date_pack(int32_t year, int32_t month, int32_t day,
                                  uint16_t *stamp)
{
  int32_t days = 0;
  drdc_status_t st;
  uint32_t s;
  int32_t offset;

  if (stamp == NULL) {
    return DRDC_E_NULL;
  }
  if ((year < DRDC_JAUS_DATE_YEAR_MIN) || (year > DRDC_JAUS_DATE_YEAR_MAX)) {
    return DRDC_E_YEAR;
  }
  /* the calendar checks month and day (29 February in leap years) */
  st = drdc_time_days_from_civil(year, month, day, &days);
  if (st != DRDC_OK) {
    return st;
  }
  offset = year - DRDC_JAUS_DATE_YEAR_MIN;
  s = ((uint32_t)offset << YEAR_SHIFT) | ((uint32_t)month << MONTH_SHIFT) |
      (uint32_t)day;
  *stamp = (uint16_t)s;
  return DRDC_OK;
}

drdc_status_t drdc_jaus_date_unpack(uint16_t stamp, int32_t *year,
                                    int32_t *month, int32_t *day)
{
  uint32_t s = (uint32_t)stamp;
  uint32_t yf = (s >> YEAR_SHIFT) & YEAR_MASK;
  uint32_t mf = (s >> MONTH_SHIFT) & MONTH_MASK;
  uint32_t df = s & DAY_MASK;
  int32_t y = (int32_t)yf + DRDC_JAUS_DATE_YEAR_MIN;
  int32_t m = (int32_t)mf;
  int32_t d = (int32_t)df;
  int32_t days = 0;
  drdc_status_t st;

  if ((year == NULL) || (month == NULL) || (day == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc_time_days_from_civil(y, m, d, &days);
  if (st != DRDC_OK) {
    return st;
  }
  *year = y;
  *month = m;
  *day = d;
  return DRDC_OK;
}
