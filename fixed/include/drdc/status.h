/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_status
 * @brief Status codes returned by every libdrdc-fx function that can fail.
 */
#ifndef DRDC_STATUS_H
#define DRDC_STATUS_H

/**
 * @defgroup drdc_status Status codes
 *
 * Every function that can fail returns a drdc_status_t and writes its
 * results through pointers. On any status other than DRDC_OK the outputs
 * are left unchanged unless the function's documentation says otherwise.
 * No error is ever encoded inside a valid result.
 * @{
 */

/** Outcome of a library call. Zero is success; every other value names
 *  one kind of failure so firmware can tell them apart. */
typedef enum drdc_status {
  DRDC_OK = 0,            /**< success, outputs written */
  DRDC_E_NULL = 1,        /**< a required pointer argument is NULL */
  DRDC_E_RANGE = 2,       /**< an input lies outside the documented domain */
  DRDC_E_OVERFLOW = 3,    /**< the result does not fit the output format */
  DRDC_E_YEAR = 4,        /**< year outside DRDC_YEAR_MIN..DRDC_YEAR_MAX */
  DRDC_E_MONTH = 5,       /**< month outside 1..12 */
  DRDC_E_DAY = 6,         /**< day outside 1..days in that month */
  DRDC_STATUS_COUNT = 7   /**< number of status codes (not a status) */
} drdc_status_t;

/**
 * Name of a status code, for logs: "DRDC_OK", "DRDC_E_RANGE", ...
 *
 * @param status any value; values that are not a status give "DRDC_E_?".
 * @return a static, NUL-terminated string; never NULL.
 */
const char *drdc_status_name(drdc_status_t status);

/** @} */

#endif /* DRDC_STATUS_H */
