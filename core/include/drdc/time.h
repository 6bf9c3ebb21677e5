/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time
 * @brief UTC time standard: calendar arithmetic (proleptic Gregorian).
 */
#ifndef DRDC_TIME_H
#define DRDC_TIME_H

#include <stdint.h>

#include <drdc/types.h>

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

/** @} */

#endif /* DRDC_TIME_H */
