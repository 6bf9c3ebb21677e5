/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_status
 * @brief Names of the status codes.
 */
#include <drdc/status.h>

const char *drdc_status_name(drdc_status_t status)
{
  /* Indexed by the enum value; the enum is dense from 0. */
  static const char *const names[DRDC_STATUS_COUNT] = {
      "DRDC_OK",           "DRDC_E_NULL",          "DRDC_E_RANGE",
      "DRDC_E_OVERFLOW",   "DRDC_E_DOMAIN",        "DRDC_E_DIVIDE_BY_ZERO",
      "DRDC_E_YEAR",       "DRDC_E_MONTH",         "DRDC_E_DAY",
      "DRDC_E_HOUR",       "DRDC_E_MINUTE",        "DRDC_E_SECOND",
      "DRDC_E_NANOSECOND", "DRDC_E_WEEK",          "DRDC_E_TIME_OF_WEEK",
      "DRDC_E_TICKS",      "DRDC_E_LEAP_TABLE",    "DRDC_E_SYNTAX",
      "DRDC_E_TRAILING",   "DRDC_E_BUFFER",        "DRDC_W_LEAP_EXPIRED",
      "DRDC_W_SATURATED",  "DRDC_E_UNKNOWN_UNIT",  "DRDC_E_DIMENSION",
      "DRDC_E_CHECKSUM",   "DRDC_E_TRUNCATED",     "DRDC_E_OVERLONG",
      "DRDC_E_CHARACTER",  "DRDC_E_MISSING_FIELD", "DRDC_E_NO_FIX",
      "DRDC_E_SENTENCE",   "DRDC_E_LATITUDE",      "DRDC_E_LONGITUDE",
      "DRDC_E_ZONE",       "DRDC_E_EASTING",       "DRDC_E_NORTHING",
      "DRDC_E_BAND",       "DRDC_E_MGRS",          "DRDC_E_HEIGHT",
  };
  unsigned index = (unsigned)status;

  return (index < (unsigned)DRDC_STATUS_COUNT) ? names[index] : "DRDC_E_?";
}
