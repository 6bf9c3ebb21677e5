/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time
 * @brief Day count <-> proleptic Gregorian date, exact integers.
 *
 * Both directions count in 400-year eras from 0000-03-01: starting the year
 * in March puts the leap day last, so the day of year is a linear formula
 * of the month (153 days per 5 months) and no month table is needed.
 */
#include <drdc/time.h>

#include <stddef.h>

/* A Gregorian era repeats every 400 years: 400 * 365 + 97 leap days. */
#define DAYS_PER_400Y 146097
/* Days from 0000-03-01 (the first era's start) to 1970-01-01. */
#define DAYS_0000_03_01_TO_EPOCH 719468

int drdc_time_is_leap_year(int32_t year)
{
  return ((year % 4) == 0) && (((year % 100) != 0) || ((year % 400) == 0));
}

static int32_t days_in_month(int32_t year, int32_t month)
{
  static const uint8_t days[12] = {31, 28, 31, 30, 31, 30,
                                   31, 31, 30, 31, 30, 31};

  if ((month == 2) && drdc_time_is_leap_year(year)) {
    return 29;
  }
  return (int32_t)days[month - 1];
}

drdc_status_t drdc_time_days_from_civil(int32_t year, int32_t month,
                                        int32_t day, int32_t *days)
{
  int32_t y;
  int32_t month_from_march;
  int32_t era;
  int32_t year_of_era;
  int32_t day_of_year;
  int32_t day_of_era;

  if (days == NULL) {
    return DRDC_E_NULL;
  }
  if ((year < DRDC_YEAR_MIN) || (year > DRDC_YEAR_MAX)) {
    return DRDC_E_YEAR;
  }
  if ((month < 1) || (month > 12)) {
    return DRDC_E_MONTH;
  }
  if ((day < 1) || (day > days_in_month(year, month))) {
    return DRDC_E_DAY;
  }

  /* January and February belong to the previous March-based year and are
   * its months 10 and 11. year >= 1 makes y >= 0, so the divisions below
   * never see a negative. */
  if (month <= 2) {
    y = year - 1;
    month_from_march = month + 9;
  } else {
    y = year;
    month_from_march = month - 3;
  }
  era = y / 400;
  year_of_era = y - (era * 400);
  day_of_year = ((((153 * month_from_march) + 2) / 5) + (day - 1));
  day_of_era = (year_of_era * 365) + (year_of_era / 4) - (year_of_era / 100) +
               day_of_year;
  *days = (era * DAYS_PER_400Y) + day_of_era - DAYS_0000_03_01_TO_EPOCH;
  return DRDC_OK;
}

drdc_status_t drdc_time_civil_from_days(int32_t days, int32_t *year,
                                        int32_t *month, int32_t *day)
{
  int32_t z;
  int32_t era;
  int32_t day_of_era;
  int32_t year_of_era;
  int32_t day_of_year;
  int32_t mp;
  int32_t m;

  if ((days < DRDC_TIME_DAYS_MIN) || (days > DRDC_TIME_DAYS_MAX)) {
    return DRDC_E_RANGE;
  }
  /* days >= DRDC_TIME_DAYS_MIN makes z >= 306: no negative division. */
  z = days + DAYS_0000_03_01_TO_EPOCH;
  era = z / DAYS_PER_400Y;
  day_of_era = z - (era * DAYS_PER_400Y);
  /* Remove the leap days before this day of the era, then divide by 365:
   * one leap day per 1460 days, none per 36524, one per 146096. */
  year_of_era = (day_of_era - (day_of_era / 1460) + (day_of_era / 36524) -
                 (day_of_era / 146096)) /
                365;
  day_of_year = day_of_era -
                ((365 * year_of_era) + (year_of_era / 4) - (year_of_era / 100));
  mp = ((5 * day_of_year) + 2) / 153; /* month from March, 0..11 */
  if (mp < 10) {
    m = mp + 3;
  } else {
    m = mp - 9;
  }

  if (year != NULL) {
    *year = year_of_era + (era * 400);
    if (m <= 2) {
      *year += 1; /* January and February end the March-based year */
    }
  }
  if (month != NULL) {
    *month = m;
  }
  if (day != NULL) {
    *day = day_of_year - (((153 * mp) + 2) / 5) + 1;
  }
  return DRDC_OK;
}
