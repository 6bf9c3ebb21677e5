/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief WGS-84 geodesy: geographic <-> UTM by the transverse Mercator
 *        projection (Krueger series, 6th order), zone rules, meridian
 *        convergence and point scale.
 */
#ifndef DRDC_GEO_H
#define DRDC_GEO_H

#include <stdbool.h>
#include <stdint.h>

#include <drdc/fixed_types.h>
#include <drdc/status.h>
#include <drdc/types.h>

/**
 * @defgroup drdc_geo Geodesy: UTM and transverse Mercator on WGS-84
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
 * **Method**: the conformal latitude by its Fourier series (8 terms,
 * exact for WGS-84), the spherical transverse Mercator, Krueger's series
 * to 6th order in n (as GeographicLib's TransverseMercator), all in Q5.58
 * with 128-bit products (drdc_fx_muldiv_s64()); sin/cos/atan2/sqrt are
 * refined to 2^-58 from the fixed/ primitives. No floating point.
 *
 * **Accuracy** against GeographicLib 2.1.2 (GeoConvert,
 * TransverseMercatorProj -s) on the vectors of tests/geo: see each
 * function.
 * @{
 */

/** Zone argument of drdc_geo_to_utm(): the standard zone of the point. */
#define DRDC_GEO_ZONE_STANDARD (-1)
/** Smallest UTM zone number. */
#define DRDC_GEO_ZONE_MIN 1
/** Largest UTM zone number. */
#define DRDC_GEO_ZONE_MAX 60

/** A UTM position (the {W-UTM} grid part): zone, hemisphere, easting and
 *  northing in metres with false easting 500 000 m and false northing
 *  0 m (north) or 10 000 000 m (south). */
typedef struct drdc_geo_utm {
  int32_t zone;           /**< UTM zone 1..60 */
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
drdc_status_t drdc_geo_utm_zone(drdc_nas_t lat, drdc_nas_t lon,
                                int32_t *zone);

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
 * Outputs unchanged on error. Accuracy (measured, tests/geo): x, y within
 * 2 LSB (30 um) of TransverseMercatorProj -s up to 1 000 km from the
 * central meridian; convergence within 1e-9 degree; scale within 1e-15.
 */
drdc_status_t drdc_geo_tm_forward(drdc_nas_t lat, drdc_nas_t dlon,
                                  drdc_q47_16_t *x, drdc_q47_16_t *y,
                                  drdc_nas_t *convergence,
                                  drdc_q5_58_t *scale);

/**
 * Geographic -> UTM, as GeoConvert -u (with -z zone when forced).
 *
 * @param lat latitude, nas, [-90, 90] degrees.
 * @param lon longitude, nas, [-540, 540) degrees.
 * @param zone DRDC_GEO_ZONE_STANDARD for drdc_geo_utm_zone(), or a zone
 *        1..60 to force (a neighbouring zone, for instance).
 * @param[out] out zone, hemisphere (north when lat >= 0), easting and
 *        northing.
 * @param[out] convergence meridian convergence, nas; may be NULL.
 * @param[out] scale point scale factor, Q5.58; may be NULL.
 * @retval DRDC_OK outputs written.
 * @retval DRDC_E_NULL out is NULL.
 * @retval DRDC_E_LATITUDE lat outside [-90, 90] degrees.
 * @retval DRDC_E_LONGITUDE lon outside [-540, 540) degrees.
 * @retval DRDC_E_ZONE zone is neither DRDC_GEO_ZONE_STANDARD nor 1..60,
 *         or the standard zone of the point is UPS (lat >= 84 or < -80).
 * @retval DRDC_E_RANGE the point is outside the forced zone's range:
 *         easting outside [0, 1 000 000] m or northing outside
 *         [-9 100 000, 9 600 000] m (north) / [900 000, 19 600 000] m
 *         (south), GeoConvert's limits.
 *
 * Outputs unchanged on error. Accuracy (measured, tests/geo, GeoConvert
 * -p 9): easting and northing within 2 LSB (30 um); convergence within
 * 1e-9 degree; scale within 1e-15.
 *
 * Example: lat 10, lon 20 gives zone 34 north, easting 390 399.2275 m,
 * northing 1 105 578.5892 m.
 */
drdc_status_t drdc_geo_to_utm(drdc_nas_t lat, drdc_nas_t lon, int32_t zone,
                              drdc_geo_utm_t *out, drdc_nas_t *convergence,
                              drdc_q5_58_t *scale);

/**
 * UTM -> geographic, as GeoConvert with UTM input.
 *
 * @param in zone 1..60, hemisphere, easting in [0, 1 000 000] m, northing
 *        in [-9 100 000, 9 600 000] m (north) or [900 000, 19 600 000] m
 *        (south), GeoConvert's limits.
 * @param[out] lat latitude, nas.
 * @param[out] lon longitude, nas, in [-180, 180) degrees.
 * @param[out] convergence meridian convergence, nas; may be NULL.
 * @param[out] scale point scale factor, Q5.58; may be NULL.
 * @retval DRDC_OK outputs written.
 * @retval DRDC_E_NULL in, lat or lon is NULL.
 * @retval DRDC_E_ZONE in->zone outside 1..60.
 * @retval DRDC_E_EASTING in->easting outside [0, 1 000 000] m.
 * @retval DRDC_E_NORTHING in->northing outside the hemisphere's range.
 *
 * Outputs unchanged on error. Accuracy (measured, tests/geo): latitude and
 * longitude within 1e-11 degree of GeoConvert; convergence within 1e-9
 * degree; scale within 1e-15.
 */
drdc_status_t drdc_geo_from_utm(const drdc_geo_utm_t *in, drdc_nas_t *lat,
                                drdc_nas_t *lon, drdc_nas_t *convergence,
                                drdc_q5_58_t *scale);

/** @} */

#endif /* DRDC_GEO_H */
