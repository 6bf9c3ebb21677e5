/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief MGRS (Military Grid Reference System) on the UTM/UPS of geo.h:
 *        encode at every precision (truncation) and decode with
 *        validation, as GeographicLib's MGRS.
 */
#ifndef DRDC_GEO_MGRS_H
#define DRDC_GEO_MGRS_H

#include <stddef.h>
#include <stdint.h>

#include <drdc/geo.h>

/**
 * @addtogroup drdc_geo
 * @{
 */

/** Coarsest MGRS precision: the grid zone designator alone ("38S"). */
#define DRDC_GEO_MGRS_PREC_MIN (-1)
/** Finest MGRS precision: 11 digits per coordinate (1 um). */
#define DRDC_GEO_MGRS_PREC_MAX 11
/** Longest MGRS text with its terminating NUL: 2 + 1 + 2 + 22 + 1. */
#define DRDC_GEO_MGRS_SIZE 28u

/**
 * Geographic -> MGRS in the standard UTM zone or UPS, as GeoConvert -m:
 * zone digits and latitude band letter (UTM) or A/B/Y/Z (UPS), the two
 * letters of the 100 km square, then prec digits of easting and of
 * northing, truncated (never rounded) to 10^(5 - prec) m.
 *
 * @param lat latitude, nas, [-90, 90] degrees.
 * @param lon longitude, nas, [-540, 540) degrees.
 * @param prec digits per coordinate, -1 (grid zone only), 0 (100 km
 *        square) .. 5 (1 m) .. 11 (1 um); GeoConvert's -p P is P + 5.
 * @param[out] text NUL-terminated MGRS, upper case.
 * @param size bytes at text (DRDC_GEO_MGRS_SIZE always suffices).
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL text is NULL.
 * @retval DRDC_E_LATITUDE lat outside [-90, 90] degrees.
 * @retval DRDC_E_LONGITUDE lon outside [-540, 540) degrees.
 * @retval DRDC_E_RANGE prec outside -1..11.
 * @retval DRDC_E_BUFFER size is too small for the text; nothing written.
 *
 * Text unchanged on error. Exactness: the digits truncate the UTM/UPS
 * easting and northing of drdc_geo_to_utm()'s transverse Mercator or UPS
 * before its rounding to Q47.16 (held in 2^-36 m: GeographicLib's own
 * 6th-order series evaluated in Q5.58), so the strings equal GeoConvert's
 * at every precision except where GeographicLib's coordinate (its own
 * error is about 5 nm) lies within a few nanometres of a 1 um boundary,
 * where its double arithmetic decides the last digit. Measured against
 * GeoConvert -m on 6 063 points x 13 precisions (tests/ref/gen_geo_mgrs.py):
 * identical at precisions -1..10; at 11 (1 um) 3 differ by one unit of
 * the last digit, each a point whose coordinate GeoConvert -u -p 9 prints
 * on the boundary itself (within 0.5 nm). On 120 000 random points (the
 * table's first 2 000 among them): precisions -1..9 identical, 10: 8,
 * 11: 85 differences, all where GeographicLib's coordinate is within
 * 2 nm of the boundary.
 *
 * Example: lat 33.3, lon 44.4, prec 5 gives "38SMB4414084706".
 */
drdc_status_t drdc_geo_mgrs_encode(drdc_nas_t lat, drdc_nas_t lon, int32_t prec,
                                   char *text, size_t size);

/**
 * UTM/UPS -> MGRS in the position's own zone (a forced or neighbouring
 * zone stays), as GeoConvert -m writes UTM input: the band letter from
 * the latitude of drdc_geo_from_utm().
 *
 * @param u zone 0..60, hemisphere, easting, northing.
 * @param prec digits per coordinate, -1..11.
 * @param[out] text NUL-terminated MGRS, upper case.
 * @param size bytes at text (DRDC_GEO_MGRS_SIZE always suffices).
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL u or text is NULL.
 * @retval DRDC_E_ZONE u->zone outside 0..60.
 * @retval DRDC_E_EASTING easting outside the zone's range or outside the
 *         MGRS limits (UTM 100 000 .. 899 999 m; UPS 1 300 000 ..
 *         2 699 999 m north, 800 000 .. 3 199 999 m south).
 * @retval DRDC_E_NORTHING northing outside the zone's range or outside
 *         the MGRS limits (UTM 0 .. 9 499 999 m north, 1 000 000 ..
 *         9 999 999 m south; UPS as the easting).
 * @retval DRDC_E_RANGE prec outside -1..11.
 * @retval DRDC_E_BUFFER size is too small for the text; nothing written.
 *
 * Text unchanged on error. Exactness: the digits truncate u's Q47.16
 * easting and northing exactly (no rounding is involved). GeoConvert
 * forms the micrometres as a double product, which rounds up to the next
 * 1 um where the exact value lies within 2^-9 um below it (coordinates
 * above 2^43 um = 8 796 km): on 60 000 random Q47.16 inputs in the MGRS
 * limits every text equals GeoConvert's at precisions up to 10, and 8
 * differ at 11, all such northings.
 */
drdc_status_t drdc_geo_mgrs_from_utm(const drdc_geo_utm_t *u, int32_t prec,
                                     char *text, size_t size);

/**
 * MGRS -> UTM/UPS, as GeographicLib's MGRS::Reverse: letters in either
 * case; the 100 km square's row is placed in the latitude band (with
 * GeographicLib's allowance for the bands' overlap and the 31X/32X,
 * 33X/34X, 35X/36X, 37X exceptions).
 *
 * @param text NUL-terminated MGRS.
 * @param[out] corner south-west corner of the cell the digits name, the
 *        nearest Q47.16 value; for a grid zone alone (prec -1),
 *        GeographicLib's representative point (band centre on the central
 *        meridian; 86 degrees on 90 E/W for UPS). Cells of 1 m and larger
 *        (prec <= 5) have exact corners, so the corner re-encodes to the
 *        same string; finer decimal corners are rounded to the 15.3 um
 *        step and may re-encode to the neighbouring cell (use the centre).
 * @param[out] centre centre of that cell (for prec -1 the same point);
 *        may be NULL.
 * @param[out] prec digits per coordinate, -1..11; may be NULL.
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL text or corner is NULL.
 * @retval DRDC_E_ZONE zone digits 0 or above 60.
 * @retval DRDC_E_MGRS malformed text: more than 2 zone digits, a band,
 *         column or row letter outside its set, a missing letter, a
 *         non-digit, an odd number of digits or more than 22 digits.
 * @retval DRDC_E_BAND the 100 km square's row does not lie in the latitude
 *         band (GeographicLib's "Block ... not in zone/band").
 *
 * Outputs unchanged on error. Exact up to the Q47.16 rounding of cells
 * finer than 1 m (to nearest).
 */
drdc_status_t drdc_geo_mgrs_decode(const char *text, drdc_geo_utm_t *corner,
                                   drdc_geo_utm_t *centre, int32_t *prec);

/** @} */

#endif /* DRDC_GEO_MGRS_H */
