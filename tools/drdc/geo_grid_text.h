/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief UTM/UPS text of drdc geo: the zone+hemisphere word and metres
 *        read as GeoConvert reads them, and GeoConvert's messages for
 *        coordinates and points out of a zone's range.
 */
#ifndef DRDC_TOOL_GEO_GRID_TEXT_H
#define DRDC_TOOL_GEO_GRID_TEXT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include <drdc/geo.h>
#include <drdc/status.h>

#include "geo_text.h"

/**
 * Read GeoConvert's zone+hemisphere text: 1..60 (at most 2 digits, no
 * sign) or nothing for UPS, then n, s, north or south in any case.
 *
 * @return true and *zone (0 for UPS), *north written; or false and
 *         GeoConvert's message in why.
 */
bool geo_grid_read_zone(const char *s, int *zone, bool *north, char *why,
                        size_t why_size);

/**
 * Read metres of UTM/UPS input with geo_text_read_metres(); the number
 * is what GeoConvert's stream reads ([+-]digits[.digits], an exponent
 * only with its digits), and its messages for what is not one or has
 * more after it. Beyond 1e12 m a message of drdc's own. *rest is what
 * the rounding to Q47.16 dropped, in 2^-48 m (geo_text_read_metres()).
 */
bool geo_grid_read_metres(const char *text, int64_t *q16, int64_t *rest,
                          bool *exact, char *why, size_t why_size);

/**
 * GeoConvert's message for UTM/UPS coordinates u that the library
 * refused with st (DRDC_E_EASTING or DRDC_E_NORTHING): the kilometres
 * as printf's %g, the range of the zone and hemisphere.
 *
 * @return false, for `return geo_grid_range_error(...)`.
 */
bool geo_grid_range_error(const drdc_geo_utm_t *u, drdc_status_t st, char *why,
                          size_t why_size);

/**
 * The same, quoting value / unit km (unit > 0; a '-' when value < 0, or
 * value is 0 and `negative`) instead of u's coordinate: the input's own
 * value where it is finer than Q47.16.
 *
 * @return false.
 */
bool geo_grid_range_error_at(const drdc_geo_utm_t *u, drdc_status_t st,
                             int64_t value, int64_t unit, bool negative,
                             char *why, size_t why_size);

/**
 * The same for MGRS output from u, whose ranges are narrower and half
 * open; GeoConvert quotes whole kilometres (rounded down) here.
 *
 * @return false.
 */
bool geo_grid_mgrs_range_error(const drdc_geo_utm_t *u, drdc_status_t st,
                               char *why, size_t why_size);

/**
 * GeoConvert's message for a point that zone (0 for UPS, or 1..60)
 * cannot hold, quoting latitude and longitude as printf's %g.
 *
 * @param east the longitude east of the zone's central meridian, nas,
 *        reduced to [-180, 180) degrees (UTM only).
 * @return false.
 */
bool geo_grid_zone_error(const geo_text_angle_t *lat_in,
                         const geo_text_angle_t *lon_in, int64_t east, int zone,
                         char *why, size_t why_size);

#endif /* DRDC_TOOL_GEO_GRID_TEXT_H */
