/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief WGS-84 geodesy: geographic <-> UTM/UPS by the transverse
 *        Mercator (Krueger series, 6th order) and polar stereographic
 *        projections, zone rules, meridian convergence and point scale.
 */
#ifndef DRDC_GEO_H
#define DRDC_GEO_H

#include <stdbool.h>
#include <stdint.h>

#include <drdc/fixed_types.h>
#include <drdc/status.h>
#include <drdc/types.h>

/**
 * @defgroup drdc_geo Geodesy: UTM, UPS and transverse Mercator on WGS-84
 *
 * **Ellipsoid**: WGS-84, a = 6 378 137 m, 1/f = 298.257223563.
 *
 * **Representations** (docs/conventions.md): latitude and longitude are
 * drdc_nas_t (nano-arcseconds, north and east positive), so every zone
 * and band edge is an exact value; eastings, northings and projected
 * coordinates are drdc_q47_16_t metres (LSB 15 um); the meridian
 * convergence is drdc_nas_t (the angle from true north clockwise to grid
 * north, GeographicLib's gamma); the point scale is drdc_q5_58_t
 * (LSB 3.5e-18).
 *
 * **Order**: these functions take latitude first, as GeographicLib does;
 * the pose structures of geo_pose.h keep the paper's order, longitude first
 * (docs/conventions.md, section 9: initialise them by field name).
 *
 * **Method**: the conformal latitude by its Fourier series (8 terms,
 * exact for WGS-84), the spherical transverse Mercator, Krueger's series
 * to 6th order in n (Krueger 1912; Karney, "Transverse Mercator with an
 * accuracy of a few nanometers", J. Geodesy 85, 2011; as GeographicLib's
 * TransverseMercator), all in Q5.58 with 128-bit products
 * (drdc_fx_muldiv_s64()); sin/cos/atan2/sqrt are refined to 2^-58 from
 * the fixed/ primitives. UPS: polar stereographic,
 * k0 = 0.994, false easting and northing 2 000 000 m, through the same
 * conformal latitude. No floating point.
 *
 * **Accuracy** against GeographicLib 2.1.2 (GeoConvert,
 * TransverseMercatorProj -s) on the vectors of tests/geo: see each
 * function.
 * @{
 */

/** Zone argument of drdc_geo_to_utm(): the standard zone of the point. */
#define DRDC_GEO_ZONE_STANDARD (-1)
/** Zone number of UPS (the polar caps) in drdc_geo_utm_t and as the zone
 *  argument of drdc_geo_to_utm() (forces UPS). */
#define DRDC_GEO_ZONE_UPS 0
/** Smallest UTM zone number. */
#define DRDC_GEO_ZONE_MIN 1
/** Largest UTM zone number. */
#define DRDC_GEO_ZONE_MAX 60

/** A UTM or UPS position (the {W-UTM} grid part): zone, hemisphere,
 *  easting and northing in metres. UTM: false easting 500 000 m, false
 *  northing 0 m (north) or 10 000 000 m (south). UPS (zone 0): false
 *  easting and northing 2 000 000 m. */
typedef struct drdc_geo_utm {
  int32_t zone;           /**< UTM zone 1..60, or 0 (DRDC_GEO_ZONE_UPS) */
  bool north;             /**< true: northern hemisphere (latitude >= 0) */
  drdc_q47_16_t easting;  /**< easting, metres, Q47.16 */
  drdc_q47_16_t northing; /**< northing, metres, Q47.16 */
} drdc_geo_utm_t;

/**
 * Standard UTM zone of a point, as GeoConvert chooses it: 6-degree zones
 * from longitude -180 (zone 1), zone 32 for 56 <= lat < 64 and
 * 3 <= lon < 12 (Norway), zones 31, 33, 35, 37 for 72 <= lat < 84 and
 * 0 <= lon < 42 (Svalbard). A point on an edge belongs to the zone east
 * (or north) of it. Latitudes >= 84 or < -80 give 0 (UPS).
 *
 * @param lat latitude, nas, [-90, 90] degrees.
 * @param lon longitude, nas, [-540, 540) degrees.
 * @param[out] zone 1..60, or 0 for the polar (UPS) caps.
 * @retval DRDC_OK zone written.
 * @retval DRDC_E_NULL zone is NULL.
 * @retval DRDC_E_LATITUDE lat outside [-90, 90] degrees.
 * @retval DRDC_E_LONGITUDE lon outside [-540, 540) degrees.
 *
 * Exact (integer comparisons on nas). Example: lat 60, lon 5 gives 32.
 */
drdc_status_t drdc_geo_utm_zone(drdc_nas_t lat, drdc_nas_t lon, int32_t *zone);

/**
 * Transverse Mercator on WGS-84 with k0 = 0.9996, no false origin: x east
 * and y north of the central meridian's point on the equator.
 *
 * @param lat latitude, nas, [-90, 90] degrees.
 * @param dlon longitude from the central meridian, nas, [-90, 90] degrees.
 * @param[out] x easting from the central meridian, metres, Q47.16.
 * @param[out] y northing from the equator, metres, Q47.16.
 * @param[out] convergence meridian convergence, nas; may be NULL.
 * @param[out] scale point scale factor, Q5.58; may be NULL.
 * @retval DRDC_OK outputs written.
 * @retval DRDC_E_NULL x or y is NULL.
 * @retval DRDC_E_LATITUDE lat outside [-90, 90] degrees.
 * @retval DRDC_E_LONGITUDE dlon outside [-90, 90] degrees.
 * @retval DRDC_E_RANGE the point is too far from the central meridian for
 *         the series (cos(chi) |sin(dlon)| > tanh 0.34, about 2 100 km).
 *
 * Outputs unchanged on error. Accuracy (measured on 1 000 points up to
 * 500 km outside a UTM zone against TransverseMercatorProj -s -k 0.9996
 * -p 9): x, y within 1 LSB (15 um); convergence within 1 nas; scale within
 * 262 LSB of Q5.58 (9.1e-16).
 */
drdc_status_t drdc_geo_tm_forward(drdc_nas_t lat, drdc_nas_t dlon,
                                  drdc_q47_16_t *x, drdc_q47_16_t *y,
                                  drdc_nas_t *convergence, drdc_q5_58_t *scale);

/**
 * Geographic -> UTM/UPS, as GeoConvert -u (with -z zone when forced).
 *
 * @param lat latitude, nas, [-90, 90] degrees.
 * @param lon longitude, nas, [-540, 540) degrees.
 * @param zone DRDC_GEO_ZONE_STANDARD for drdc_geo_utm_zone() (UPS at
 *        lat >= 84 and lat < -80), DRDC_GEO_ZONE_UPS to force UPS, or a
 *        zone 1..60 to force (a neighbouring zone, for instance).
 * @param[out] out zone, hemisphere (north when lat >= 0), easting and
 *        northing.
 * @param[out] convergence meridian convergence, nas; may be NULL.
 * @param[out] scale point scale factor, Q5.58; may be NULL.
 * @retval DRDC_OK outputs written.
 * @retval DRDC_E_NULL out is NULL.
 * @retval DRDC_E_LATITUDE lat outside [-90, 90] degrees.
 * @retval DRDC_E_LONGITUDE lon outside [-540, 540) degrees.
 * @retval DRDC_E_ZONE zone is not DRDC_GEO_ZONE_STANDARD, DRDC_GEO_ZONE_UPS
 *         or 1..60.
 * @retval DRDC_E_RANGE the point is outside the zone's range, GeoConvert's
 *         limits: UTM easting outside [0, 1 000 000] m or northing outside
 *         [-9 100 000, 9 600 000] m (north) / [900 000, 19 600 000] m
 *         (south); UPS easting or northing outside [1 200 000,
 *         2 800 000] m (north) / [700 000, 3 300 000] m (south).
 *
 * Outputs unchanged on error. Accuracy (measured on 22 000 random points,
 * 2 094 edge and pole points and 600 forced-zone points against
 * GeoConvert -p 9): easting and northing within 1 LSB (15 um) in UTM and
 * UPS; convergence within 1 nas (2.8e-13 degree); scale within 307 LSB
 * of Q5.58 (1.1e-15, the oracle prints 16 decimals).
 *
 * Example: lat 10, lon 20 gives zone 34 north, easting 390 399.2275 m,
 * northing 1 105 578.5892 m.
 */
drdc_status_t drdc_geo_to_utm(drdc_nas_t lat, drdc_nas_t lon, int32_t zone,
                              drdc_geo_utm_t *out, drdc_nas_t *convergence,
                              drdc_q5_58_t *scale);

/**
 * UTM/UPS -> geographic, as GeoConvert with UTM/UPS input.
 *
 * @param in zone 1..60 or 0 (UPS), hemisphere, easting and northing
 *        within GeoConvert's limits: UTM easting [0, 1 000 000] m,
 *        northing [-9 100 000, 9 600 000] m (north) or [900 000,
 *        19 600 000] m (south); UPS [1 200 000, 2 800 000] m (north) or
 *        [700 000, 3 300 000] m (south) for both.
 * @param[out] lat latitude, nas.
 * @param[out] lon longitude, nas, in [-180, 180] degrees (180 at the
 *        north pole, 0 at the south pole, as GeoConvert).
 * @param[out] convergence meridian convergence, nas; may be NULL.
 * @param[out] scale point scale factor, Q5.58; may be NULL.
 * @retval DRDC_OK outputs written.
 * @retval DRDC_E_NULL in, lat or lon is NULL.
 * @retval DRDC_E_ZONE in->zone outside 0..60.
 * @retval DRDC_E_EASTING in->easting outside the range of its zone.
 * @retval DRDC_E_NORTHING in->northing outside the range of its zone and
 *         hemisphere.
 *
 * Outputs unchanged on error. Accuracy (measured on the 24 694 forward
 * results, rounded to Q47.16, against GeoConvert -p 9 on the same input):
 * latitude and longitude within 1 nas (2.8e-13 degree); in UTM the
 * convergence within 2 079 nas (5.8e-10 degree) and the scale within
 * 25 141 LSB of Q5.58 (8.7e-14) of the forward values at the unrounded
 * point (the 15 um input rounding, not the method). In UTM the
 * convergence and scale come from the derivative of the reverse series
 * (as GeographicLib's reverse); at the grid point itself they are within
 * 0.84 nas and 334 LSB (1.2e-15) of GeoConvert -c -p 12 (20 000 random
 * points of every zone and both hemispheres). In UPS they are those of
 * the forward projection at the reverse's latitude and longitude.
 */
drdc_status_t drdc_geo_from_utm(const drdc_geo_utm_t *in, drdc_nas_t *lat,
                                drdc_nas_t *lon, drdc_nas_t *convergence,
                                drdc_q5_58_t *scale);

/** @} */

#endif /* DRDC_GEO_H */
