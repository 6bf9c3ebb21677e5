/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The reasons `drdc nmea` and `drdc time` print beside a status on
 *        an `ERROR:` line. The Python package compiles the same file, so
 *        its DrdcError carries the tool's words.
 */
#ifndef DRDC_TOOL_REASONS_H
#define DRDC_TOOL_REASONS_H

#include <drdc/status.h>

/** What a status of drdc_nmea_parse() and its kin means on a line of
 *  `drdc nmea` ("checksum does not match"); "cannot decode" for a status
 *  the parser does not return. Never NULL. */
const char *drdc_tool_nmea_reason(drdc_status_t st);

/** What a status of the time conversions means on a line of `drdc time`
 *  ("day outside the month"); "conversion failed" for one they do not
 *  return. Never NULL. */
const char *drdc_tool_time_reason(drdc_status_t st);

#endif /* DRDC_TOOL_REASONS_H */
