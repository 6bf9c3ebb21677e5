/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time
 * @brief UTC time standard: calendar arithmetic (proleptic Gregorian),
 *        time of day and UTC <-> broken-down time.
 */
#ifndef DRDC_TIME_H
#define DRDC_TIME_H

#include <stdint.h>

#include <drdc/types.h>
#include <drdc/time_leap.h>

/**
 * @defgroup drdc_time Time
 *
 * Calendar dates are proleptic Gregorian (Gregorian rules extended before
 * 1582), years DRDC_YEAR_MIN..DRDC_YEAR_MAX. A day count is the number of
 * days since 1970-01-01 (negative before it). All arithmetic is exact
 * integer arithmetic: there is no error bound because there is no error.
 * @{
 */

/** Day count of 0001-01-01, the first day of DRDC_YEAR_MIN. */
#define DRDC_TIME_DAYS_MIN INT32_C(-719162)
/** Day count of 9999-12-31, the last day of DRDC_YEAR_MAX. */
#define DRDC_TIME_DAYS_MAX INT32_C(2932896)

/**
 * Days since 1970-01-01 of a civil date.
 *
 * @param year  year, DRDC_YEAR_MIN..DRDC_YEAR_MAX
 * @param month month, 1..12
 * @param day   day of month, 1..28, 29, 30 or 31 as the month has
 * @param[out] days days since 1970-01-01, DRDC_TIME_DAYS_MIN..
 *             DRDC_TIME_DAYS_MAX; unchanged on error
 *
 * @retval DRDC_OK        `*days` written
 * @retval DRDC_E_NULL    `days` is NULL
 * @retval DRDC_E_YEAR    year out of range
 * @retval DRDC_E_MONTH   month out of range
 * @retval DRDC_E_DAY     day is 0 or past the month's end (Feb 29 in a
 *                        common year included)
 *
 * Accuracy: exact. Checked against Python's datetime.date.toordinal() for
 * every day of 1900..2100, both calendar ends and random dates.
 *
 * @code
 * int32_t d;
 * drdc_time_days_from_civil(2000, 3, 1, &d);   // d == 11017
 * @endcode
 */
drdc_status_t drdc_time_days_from_civil(int32_t year, int32_t month,
                                        int32_t day, int32_t *days);

/**
 * Civil date of a day count; inverse of drdc_time_days_from_civil().
 *
 * @param days days since 1970-01-01, DRDC_TIME_DAYS_MIN..DRDC_TIME_DAYS_MAX
 * @param[out] year  year; may be NULL when not wanted
 * @param[out] month month 1..12; may be NULL
 * @param[out] day   day of month; may be NULL
 *
 * @retval DRDC_OK      outputs written
 * @retval DRDC_E_RANGE `days` outside the calendar range; outputs unchanged
 *
 * Accuracy: exact (same checks as drdc_time_days_from_civil()).
 */
drdc_status_t drdc_time_civil_from_days(int32_t days, int32_t *year,
                                        int32_t *month, int32_t *day);

/**
 * Whether a year is a Gregorian leap year (divisible by 4, except
 * centuries not divisible by 400).
 *
 * @param year any year; the rule is applied as is.
 * @return 1 for a leap year, 0 otherwise.
 */
int drdc_time_is_leap_year(int32_t year);

/** Day of week of a day count: 0 = Sunday .. 6 = Saturday (as struct tm).
 *
 * @param days days since 1970-01-01 (a Thursday), any value
 * @return 0..6; exact for every int32_t. */
int32_t drdc_time_day_of_week(int32_t days);

/**
 * Day of year of a civil date, 1..365 (366 in a leap year).
 *
 * @param year, month, day a date as for drdc_time_days_from_civil()
 * @param[out] yday day of year; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL, DRDC_E_YEAR, DRDC_E_MONTH, DRDC_E_DAY as
 *         drdc_time_days_from_civil()
 */
drdc_status_t drdc_time_day_of_year(int32_t year, int32_t month, int32_t day,
                                    int32_t *yday);

/**
 * Broken-down UTC time: a civil date and a time of day.
 *
 * `second` is 0..59, or 60 during a positive leap second (23:59:60 of a
 * day that ends with one); `nsec` is 0..999 999 999 in every second,
 * 23:59:60 included.
 */
typedef struct drdc_time_civil {
  int32_t year;   /**< DRDC_YEAR_MIN..DRDC_YEAR_MAX */
  int32_t month;  /**< 1..12 */
  int32_t day;    /**< 1..days in the month */
  int32_t hour;   /**< 0..23 */
  int32_t minute; /**< 0..59 */
  int32_t second; /**< 0..59, 60 only in a leap second */
  int32_t nsec;   /**< 0..999 999 999 */
} drdc_time_civil_t;

/**
 * Check that a drdc_time_t is a UTC instant.
 *
 * Valid: `sec` within 0001-01-01T00:00:00 .. 9999-12-31T23:59:59,
 * `nsec` in [0, 1e9), or in [1e9, 2e9) when `sec` is 23:59:59 of a day
 * that ends with a positive leap second; 23:59:59 of a day that ends
 * with a negative leap second does not exist.
 *
 * @param leap leap state, NULL for the built-in one
 * @param utc  instant to check
 * @retval DRDC_OK           valid
 * @retval DRDC_E_NULL       `utc` is NULL
 * @retval DRDC_E_RANGE      `sec` outside the calendar range
 * @retval DRDC_E_NANOSECOND `nsec` negative, >= 2e9, or >= 1e9 in a
 *         second that is not 23:59:59
 * @retval DRDC_E_SECOND     a leap second (nsec >= 1e9) on a day without
 *         one, or 23:59:59 of a day with a negative leap second
 */
drdc_status_t drdc_time_check(const drdc_time_leap_t *leap,
                              const drdc_time_t *utc);

/**
 * Check broken-down UTC time, field by field in the order year, month,
 * day, hour, minute, second, nanosecond (RTEMS _TOD_Validate style).
 *
 * @param leap  leap state, NULL for the built-in one: second 60 is valid
 *              only at 23:59 of a day the state ends with a positive leap
 *              second, second 59 is invalid at 23:59 of a day that ends
 *              with a negative one
 * @param civil time to check
 * @retval DRDC_OK valid
 * @retval DRDC_E_NULL       `civil` is NULL
 * @retval DRDC_E_YEAR       year outside DRDC_YEAR_MIN..DRDC_YEAR_MAX
 * @retval DRDC_E_MONTH      month outside 1..12
 * @retval DRDC_E_DAY        day 0 or past the month's end
 * @retval DRDC_E_HOUR       hour outside 0..23
 * @retval DRDC_E_MINUTE     minute outside 0..59
 * @retval DRDC_E_SECOND     second outside 0..60, 60 other than at the
 *         end of a day with a positive leap second, or 59 at the end of a
 *         day with a negative one
 * @retval DRDC_E_NANOSECOND nsec outside 0..999 999 999
 */
drdc_status_t drdc_time_civil_check(const drdc_time_leap_t *leap,
                                    const drdc_time_civil_t *civil);

/**
 * Broken-down UTC time -> drdc_time_t.
 *
 * 23:59:60.f becomes {sec of 23:59:59, 1e9 + f}.
 *
 * @param leap  leap state, NULL for the built-in one
 * @param civil time, valid by drdc_time_civil_check()
 * @param[out] utc instant; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `civil` or `utc` is NULL
 * @retval other the status of drdc_time_civil_check()
 *
 * Accuracy: exact. Checked against Python's datetime/calendar.timegm and
 * ERFA's leap-second days.
 *
 * @code
 * drdc_time_civil_t c = { 2016, 12, 31, 23, 59, 60, 500000000 };
 * drdc_time_t t;
 * drdc_time_from_civil(NULL, &c, &t);  // t = {1483228799, 1500000000}
 * @endcode
 */
drdc_status_t drdc_time_from_civil(const drdc_time_leap_t *leap,
                                   const drdc_time_civil_t *civil,
                                   drdc_time_t *utc);

/**
 * drdc_time_t -> broken-down UTC time; inverse of drdc_time_from_civil().
 *
 * @param leap leap state, NULL for the built-in one
 * @param utc  instant, valid by drdc_time_check()
 * @param[out] civil time; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `utc` or `civil` is NULL
 * @retval other the status of drdc_time_check()
 *
 * Accuracy: exact (same checks as drdc_time_from_civil()).
 */
drdc_status_t drdc_time_to_civil(const drdc_time_leap_t *leap,
                                 const drdc_time_t *utc,
                                 drdc_time_civil_t *civil);

/** @} */

#endif /* DRDC_TIME_H */
