/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief GeoConvert's message for an MGRS string the library refused.
 */
#ifndef DRDC_TOOL_GEO_MGRS_TEXT_H
#define DRDC_TOOL_GEO_MGRS_TEXT_H

#include <stdbool.h>
#include <stddef.h>

#include <drdc/status.h>

/**
 * Write GeoConvert's message for `text`, which drdc_geo_mgrs_decode()
 * refused with `st`: the library says that the string is wrong, this
 * finds what GeoConvert names (the zone, band, column or row letter,
 * the digits) and quotes it as GeoConvert does.
 *
 * @return false, for `return geo_mgrs_error(...)`.
 */
bool geo_mgrs_error(const char *text, drdc_status_t st, char *why,
                    size_t why_size);

#endif /* DRDC_TOOL_GEO_MGRS_TEXT_H */
