/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_jaus_date
 * @brief JAUS 16-bit date stamp: pack and unpack a UTC calendar date.
 */
#ifndef DRDC_JAUS_DATE_H
#define DRDC_JAUS_DATE_H

#include <stdint.h>

#include <drdc/status.h>
#include <drdc/time.h>

/**
 * @defgroup drdc_jaus_date JAUS date stamp
 *
 * The JAUS date stamp is a uint16_t of UTC calendar fields:
 *
 * | bits | field | range |
 * |---|---|---|
 * | 0-4  | day of month | 1..31 |
 * | 5-8  | month | 1..12 (January is 1: not 0-based) |
 * | 9-15 | year - 2000 | 0..127 (2000..2127) |
 *
 * Packing takes a valid proleptic Gregorian date; unpacking checks every
 * field, including the day against the month's length (29 February only
 * in leap years). It pairs with the 32-bit time stamp of time_jaus.h.
 * Byte order on the wire is the message packer's business (JAUS is
 * little-endian); these functions work on the integer value.
 * @{
 */

/** First year of the date stamp (year field 0). */
#define DRDC_JAUS_DATE_YEAR_MIN 2000
/** Last year of the date stamp (year field 127). */
#define DRDC_JAUS_DATE_YEAR_MAX 2127

/**
 * Pack a calendar date into a JAUS date stamp.
 *
 * @param year  2000..2127
 * @param month 1..12
 * @param day   1..days in the month
 * @param[out] stamp date stamp; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `stamp` is NULL
 * @retval DRDC_E_YEAR year outside 2000..2127
 * @retval DRDC_E_MONTH month outside 1..12
 * @retval DRDC_E_DAY day 0 or past the month's end
 *
 * @code
 * uint16_t s;
 * drdc_jaus_date_pack(2024, 2, 29, &s);  // s = 24 << 9 | 2 << 5 | 29
 * @endcode
 */
drdc_status_t drdc_jaus_date_pack(int32_t year, int32_t month, int32_t day,
                                  uint16_t *stamp);

/**
 * Split a JAUS date stamp into a calendar date and check it.
 *
 * @param stamp date stamp
 * @param[out] year  2000..2127; unchanged on error
 * @param[out] month 1..12; unchanged on error
 * @param[out] day   1..31; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL an output pointer is NULL
 * @retval DRDC_E_MONTH month field 0 or 13..15
 * @retval DRDC_E_DAY day field 0 or past the month's end
 *
 * Accuracy: exact; every one of the 65 536 stamps is checked against the
 * month lengths of Python's calendar.monthrange (tests/ref/gen_jaus.py,
 * tests/jaus/test_jaus_date.c).
 */
drdc_status_t drdc_jaus_date_unpack(uint16_t stamp, int32_t *year,
                                    int32_t *month, int32_t *day);

/** @} */

#endif /* DRDC_JAUS_DATE_H */
