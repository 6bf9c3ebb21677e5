/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time_iso8601
 * @brief ISO 8601 / RFC 3339 UTC text: YYYY-MM-DDTHH:MM:SS[.fffffffff]Z.
 */
#ifndef DRDC_TIME_ISO8601_H
#define DRDC_TIME_ISO8601_H

#include <stddef.h>
#include <stdint.h>

#include <drdc/time.h>

/**
 * @defgroup drdc_time_iso8601 ISO 8601 text
 *
 * One form only, the extended UTC form with four-digit years:
 * `YYYY-MM-DDTHH:MM:SS[.f...]Z`, 1 to 9 fraction digits, upper-case `T`
 * and `Z`, no offset other than `Z`, no spaces. Second 60 is written and
 * read only at a leap second.
 * @{
 */

/** Buffer size for the longest text with 9 fraction digits, NUL
 *  included: "9999-12-31T23:59:60.999999999Z". */
#define DRDC_TIME_ISO8601_SIZE 31

/**
 * Format a UTC instant as ISO 8601 text.
 *
 * @param leap   leap state (validates 23:59:60), NULL for the built-in one
 * @param utc    valid UTC instant (drdc_time_check())
 * @param digits fraction digits 0..9; 0 writes no '.'; the fraction is
 *               truncated, never rounded (so a second never rolls over)
 * @param[out] buf  text, NUL-terminated; unchanged on error
 * @param size  size of `buf` in bytes: 21 + digits (+1 for the '.' when
 *              digits > 0) at least
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `utc` or `buf` is NULL
 * @retval DRDC_E_RANGE `digits` outside 0..9
 * @retval DRDC_E_BUFFER `size` too small; nothing written
 * @retval other the status of drdc_time_check()
 *
 * @code
 * char text[DRDC_TIME_ISO8601_SIZE];
 * drdc_time_t t = { 1483228799, 1500000000 };
 * drdc_time_iso8601_format(NULL, &t, 9, text, sizeof text);
 * // text = "2016-12-31T23:59:60.500000000Z"
 * @endcode
 */
drdc_status_t drdc_time_iso8601_format(const drdc_time_leap_t *leap,
                                       const drdc_time_t *utc, int32_t digits,
                                       char *buf, size_t size);

/**
 * Parse ISO 8601 text (the form above) into a UTC instant.
 *
 * The whole NUL-terminated string must be the time: anything after the
 * `Z` is an error of its own.
 *
 * @param leap leap state (second 60 only at a leap second), NULL for the
 *             built-in one
 * @param text NUL-terminated text
 * @param[out] utc instant; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `text` or `utc` is NULL
 * @retval DRDC_E_SYNTAX the text is not of the form (a missing field,
 *         a non-digit, a wrong separator, no `Z`, no digit or more than
 *         nine after the '.')
 * @retval DRDC_E_TRAILING well-formed text followed by more characters
 * @retval DRDC_E_YEAR, DRDC_E_MONTH, DRDC_E_DAY, DRDC_E_HOUR,
 *         DRDC_E_MINUTE, DRDC_E_SECOND  a field out of range, as
 *         drdc_time_civil_check() (year 0000 is DRDC_E_YEAR)
 *
 * Accuracy: exact; round trips with drdc_time_iso8601_format(digits 9).
 */
drdc_status_t drdc_time_iso8601_parse(const drdc_time_leap_t *leap,
                                      const char *text, drdc_time_t *utc);

/** @} */

#endif /* DRDC_TIME_ISO8601_H */
