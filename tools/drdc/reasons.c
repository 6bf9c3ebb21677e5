/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The reasons of `drdc nmea`'s and `drdc time`'s ERROR lines, by
 *        status (reasons.h).
 */
#include "reasons.h"

const char *drdc_tool_nmea_reason(drdc_status_t st)
{
  switch (st) {
  case DRDC_E_SYNTAX:
    return "malformed sentence or field";
  case DRDC_E_CHARACTER:
    return "character outside printable ASCII";
  case DRDC_E_TRUNCATED:
    return "sentence ends before its checksum";
  case DRDC_E_OVERLONG:
    return "sentence too long";
  case DRDC_E_TRAILING:
    return "text after the checksum";
  case DRDC_E_CHECKSUM:
    return "checksum does not match";
  case DRDC_E_SENTENCE:
    return "sentence type or talker not decoded";
  case DRDC_E_NO_FIX:
    return "the receiver reports no fix";
  case DRDC_E_MISSING_FIELD:
    return "required field empty or missing";
  case DRDC_E_HOUR:
  case DRDC_E_MINUTE:
  case DRDC_E_SECOND:
    return "time or angle field out of range";
  case DRDC_E_DAY:
  case DRDC_E_MONTH:
  case DRDC_E_YEAR:
    return "date field out of range";
  case DRDC_E_RANGE:
    return "value out of range";
  default:
    return "cannot decode";
  }
}

const char *drdc_tool_time_reason(drdc_status_t st)
{
  switch (st) {
  case DRDC_E_RANGE:
    return "outside the supported range";
  case DRDC_E_YEAR:
    return "year outside 0001..9999";
  case DRDC_E_MONTH:
    return "month outside 01..12";
  case DRDC_E_DAY:
    return "day outside the month";
  case DRDC_E_HOUR:
    return "hour outside 00..23";
  case DRDC_E_MINUTE:
    return "minute outside 00..59";
  case DRDC_E_SECOND:
    return "second outside 00..59, or 60 on a day without a leap second";
  case DRDC_E_NANOSECOND:
    return "fraction of a second out of range";
  case DRDC_E_WEEK:
    return "GPS week negative or too large";
  case DRDC_E_TIME_OF_WEEK:
    return "time of week outside [0, 604800)";
  case DRDC_E_SYNTAX:
    return "malformed time";
  case DRDC_E_TRAILING:
    return "unexpected text after the time";
  default:
    return "conversion failed";
  }
}
