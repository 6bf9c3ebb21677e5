/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_status
 * @brief Status codes returned by every libdrdc-fx function that can fail.
 */
#ifndef DRDC_STATUS_H
#define DRDC_STATUS_H

#include <stdbool.h>

/**
 * @defgroup drdc_status Status codes
 *
 * Every function that can fail returns a drdc_status_t and writes its
 * results through pointers. Errors (DRDC_E_*) leave every output unchanged
 * unless the function's documentation says otherwise. Warnings (DRDC_W_*)
 * write the outputs and tell the caller something about them; test them
 * with drdc_status_is_error(). No error is ever encoded inside a valid
 * result. Values are stable: new codes are only ever appended.
 * @{
 */

/** Outcome of a library call. Zero is success; every other value names
 *  one kind of failure so firmware can tell them apart. */
typedef enum drdc_status {
  DRDC_OK = 0,         /**< success, outputs written */
  DRDC_E_NULL = 1,     /**< a required pointer argument is NULL */
  DRDC_E_RANGE = 2,    /**< an input lies outside the documented domain */
  DRDC_E_OVERFLOW = 3, /**< the result does not fit the output format */
  /** a mathematical domain error (sqrt of a negative, asin beyond 1, atanh at
   *  +-1, atan2(0, 0)) */
  DRDC_E_DOMAIN = 4,
  DRDC_E_DIVIDE_BY_ZERO = 5, /**< a divisor is zero */
  DRDC_E_YEAR = 6,           /**< year outside DRDC_YEAR_MIN..DRDC_YEAR_MAX */
  DRDC_E_MONTH = 7,          /**< month outside 1..12 */
  DRDC_E_DAY = 8,            /**< day outside 1..days in that month */
  DRDC_E_HOUR = 9,           /**< hour outside 0..23 */
  DRDC_E_MINUTE = 10,        /**< minute outside 0..59 */
  /** second outside 0..59, or 60 on a day without a leap second */
  DRDC_E_SECOND = 11,
  /** nanoseconds outside 0..999 999 999 (or the leap-second range) */
  DRDC_E_NANOSECOND = 12,
  DRDC_E_WEEK = 13, /**< GPS week negative or beyond the supported range */
  DRDC_E_TIME_OF_WEEK = 14, /**< GPS time of week negative or >= 604 800 s */
  /** RTEMS ticks outside 0..ticks per second - 1, or a bad ticks-per-second */
  DRDC_E_TICKS = 15,
  /** a leap-second table or GPS UTC parameters are malformed */
  DRDC_E_LEAP_TABLE = 16,
  DRDC_E_SYNTAX = 17, /**< malformed text */
  /** well-formed text followed by unexpected characters */
  DRDC_E_TRAILING = 18,
  DRDC_E_BUFFER = 19, /**< an output buffer is too short; nothing was written */
  /** warning: the instant lies past the leap-second table's expiry; the last
   *  known offset was used and the outputs ARE written */
  DRDC_W_LEAP_EXPIRED = 20,
  /** warning: the result was clamped to the output format's limit by a
   *  function whose name ends in _sat; the outputs ARE written */
  DRDC_W_SATURATED = 21,
  DRDC_E_UNKNOWN_UNIT = 22, /**< a unit name is not in the unit table */
  /** two units (or a value and a unit) measure different quantities */
  DRDC_E_DIMENSION = 23,
  DRDC_E_CHECKSUM = 24, /**< a message's checksum does not match its text */
  /** text ends before a complete message (e.g. no checksum or line end) */
  DRDC_E_TRUNCATED = 25,
  DRDC_E_OVERLONG = 26, /**< a message is longer than its standard allows */
  /** a character outside the allowed set (e.g. non-ASCII in NMEA 0183) */
  DRDC_E_CHARACTER = 27,
  DRDC_E_MISSING_FIELD = 28, /**< a required field is empty or absent */
  DRDC_E_NO_FIX = 29,        /**< the receiver reports no valid position fix */
  /** a message of a type or from a talker this function does not decode */
  DRDC_E_SENTENCE = 30,
  DRDC_E_LATITUDE = 31, /**< a latitude outside [-90, 90] degrees */
  /** a longitude outside [-540, 540) degrees */
  DRDC_E_LONGITUDE = 32,
  /** a UTM zone outside 1..60 (or a zone code the function does not take) */
  DRDC_E_ZONE = 33,
  DRDC_E_EASTING = 34,  /**< an easting outside the zone's range */
  DRDC_E_NORTHING = 35, /**< a northing outside the zone's range */
  /** a 100 km MGRS square that does not lie in its latitude band */
  DRDC_E_BAND = 36,
  /** malformed MGRS text: a letter outside its set, an odd or too large
   *  digit count, missing letters */
  DRDC_E_MGRS = 37,
  /** a height outside +-10 000 km (ellipsoidal) */
  DRDC_E_HEIGHT = 38,
  DRDC_STATUS_COUNT = 39 /**< number of status codes (not a status) */
} drdc_status_t;

/**
 * Name of a status code, for logs: "DRDC_OK", "DRDC_E_RANGE", ...
 *
 * @param status any value; values that are not a status give "DRDC_E_?".
 * @return a static, NUL-terminated string; never NULL.
 */
const char *drdc_status_name(drdc_status_t status);

/**
 * Whether `status` is a warning: DRDC_W_LEAP_EXPIRED or DRDC_W_SATURATED,
 * the outputs written. The warnings keep their numbers among the errors'
 * (values are stable), so test with this function, never with a range.
 *
 * @param status the value a library call returned (evaluated once)
 * @return true for a DRDC_W_* code, false for DRDC_OK and every error
 */
static inline bool drdc_status_is_warning(drdc_status_t status)
{
  return (status == DRDC_W_LEAP_EXPIRED) || (status == DRDC_W_SATURATED);
}

/**
 * Whether `status` is an error (outputs unchanged), as opposed to DRDC_OK
 * or a warning (outputs written). Codes appended after the warnings, and
 * values that are no status at all, count as errors.
 *
 * @param status the value a library call returned (evaluated once)
 * @return true for a DRDC_E_* code, false for DRDC_OK and the warnings
 */
static inline bool drdc_status_is_error(drdc_status_t status)
{
  return (status != DRDC_OK) && !drdc_status_is_warning(status);
}

/** @} */

#endif /* DRDC_STATUS_H */
