/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time_jaus
 * @brief JAUS 32-bit time stamp: pack, unpack, and back to a full UTC
 *        time given a reference time within half a month.
 */
#ifndef DRDC_TIME_JAUS_H
#define DRDC_TIME_JAUS_H

#include <stdint.h>

#include <drdc/time.h>

/**
 * @defgroup drdc_time_jaus JAUS time stamp
 *
 * The JAUS time stamp is a uint32_t of UTC fields:
 *
 * | bits | field | range |
 * |---|---|---|
 * | 0-9   | milliseconds | 0..999 |
 * | 10-15 | seconds      | 0..59 (60 in a leap second, see below) |
 * | 16-21 | minutes      | 0..59 |
 * | 22-26 | hours        | 0..23 |
 * | 27-31 | day of month | 1..31 |
 *
 * Resolution 1 ms; packing truncates the nanoseconds. The JAUS field
 * range of the seconds is 0..59, but a leap second is a real UTC second:
 * it is packed as second 60, which the 6-bit field holds, so the stamp
 * stays monotonic and unique. Month and year are not in the stamp;
 * drdc_time_jaus_to_utc() takes them from a reference time.
 * @{
 */

/** The fields of a JAUS time stamp. */
typedef struct drdc_time_jaus_fields {
  uint32_t day;    /**< day of month, 1..31 */
  uint32_t hour;   /**< 0..23 */
  uint32_t minute; /**< 0..59 */
  uint32_t second; /**< 0..60 */
  uint32_t msec;   /**< 0..999 */
} drdc_time_jaus_fields_t;

/** Largest distance in seconds between the resolved time and the
 *  reference: 16 days, a little more than half of the longest month, so
 *  any reference within half a month of the stamped time resolves. */
#define DRDC_TIME_JAUS_WINDOW_SECONDS INT32_C(1382400)

/**
 * Pack a UTC instant into a JAUS time stamp.
 *
 * @param leap leap state (validates 23:59:60), NULL for the built-in one
 * @param utc  valid UTC instant
 * @param[out] stamp time stamp; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `utc` or `stamp` is NULL
 * @retval other the status of drdc_time_check()
 *
 * @code
 * drdc_time_t t = { 1483228799, 1500000000 }; // 2016-12-31T23:59:60.5
 * uint32_t s;
 * drdc_time_jaus_pack(NULL, &t, &s);
 * // s = 31 << 27 | 23 << 22 | 59 << 16 | 60 << 10 | 500 = 0xFDFBF1F4
 * @endcode
 */
drdc_status_t drdc_time_jaus_pack(const drdc_time_leap_t *leap,
                                  const drdc_time_t *utc, uint32_t *stamp);

/**
 * Split a JAUS time stamp into its fields and check each.
 *
 * @param stamp time stamp
 * @param[out] fields fields; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `fields` is NULL
 * @retval DRDC_E_DAY day 0
 * @retval DRDC_E_HOUR hour 24..31
 * @retval DRDC_E_MINUTE minute 60..63
 * @retval DRDC_E_SECOND second 61..63
 * @retval DRDC_E_NANOSECOND milliseconds 1000..1023
 */
drdc_status_t drdc_time_jaus_unpack(uint32_t stamp,
                                    drdc_time_jaus_fields_t *fields);

/**
 * Full UTC time of a JAUS time stamp, by a reference time.
 *
 * The month is the reference's, the one before or the one after: the
 * candidate nearest to the reference is taken (the earlier one on a tie),
 * and it must lie within DRDC_TIME_JAUS_WINDOW_SECONDS of it. A day the
 * month does not have (31 in April) rules that month out.
 *
 * Candidates are at least 28 days apart, so the result is the stamped
 * time whenever the reference is less than 14 days (half the shortest
 * month) from it; between 14 and 16 days it is the nearest candidate,
 * which in February may be the month before or after.
 *
 * @param leap  leap state (second 60 only at a leap second), NULL for the
 *              built-in one
 * @param stamp time stamp
 * @param ref   valid UTC instant within half a month of the stamped time
 * @param[out] utc instant with nsec = milliseconds * 1e6; unchanged on
 *             error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_DAY, DRDC_E_HOUR, DRDC_E_MINUTE, DRDC_E_NANOSECOND as
 *         drdc_time_jaus_unpack()
 * @retval DRDC_E_SECOND second 61..63 (as drdc_time_jaus_unpack()), or
 *         second 60 and no candidate day ends with a leap second
 * @retval DRDC_E_RANGE no candidate within the window, or `ref` invalid
 *
 * Accuracy: exact to the millisecond; checked on 10 000 random instants
 * 1972..2100 with references up to 14 days - 1 s away on either side
 * (stamps from Python's datetime fields).
 */
drdc_status_t drdc_time_jaus_to_utc(const drdc_time_leap_t *leap,
                                    uint32_t stamp, const drdc_time_t *ref,
                                    drdc_time_t *utc);

/** @} */

#endif /* DRDC_TIME_JAUS_H */
