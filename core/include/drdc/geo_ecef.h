/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief WGS-84 geodetic <-> ECEF, and local tangent planes (ENU, NED) at
 *        a reference point.
 *
 * **Heights** are ellipsoidal (above WGS-84) in every function here. The
 * libdrdc standard's {W} height is above mean sea level: convert with the
 * geoid separation N of the place, which the caller supplies (from a GNSS
 * receiver's GGA field 11 or a geoid model): ellipsoidal = MSL + N.
 */
#ifndef DRDC_GEO_ECEF_H
#define DRDC_GEO_ECEF_H

#include <drdc/geo.h>
#include <drdc/orient.h>

/**
 * @addtogroup drdc_geo
 * @{
 */

/** Largest |height| the conversions take: 10 000 km (Q47.16 metres). */
#define DRDC_GEO_HEIGHT_MAX (INT64_C(10000000) * INT64_C(65536))

/** A geodetic position: latitude and longitude (nas) and ellipsoidal
 *  height (Q47.16 metres). */
typedef struct drdc_geo_point {
  drdc_nas_t lat;       /**< latitude, nas, [-90, 90] degrees */
  drdc_nas_t lon;       /**< longitude, nas, [-540, 540) degrees */
  drdc_q47_16_t height; /**< height above the ellipsoid, Q47.16 m */
} drdc_geo_point_t;

/**
 * Geodetic -> Earth-centred, Earth-fixed: X towards (0, 0), Y towards
 * (0, 90 E), Z towards the north pole, metres.
 *
 * @param p latitude [-90, 90], longitude [-540, 540) degrees, height
 *        within +-DRDC_GEO_HEIGHT_MAX.
 * @param[out] ecef X, Y, Z in Q47.16 metres.
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL p or ecef is NULL.
 * @retval DRDC_E_LATITUDE p->lat outside [-90, 90] degrees.
 * @retval DRDC_E_LONGITUDE p->lon outside [-540, 540) degrees.
 * @retval DRDC_E_HEIGHT p->height beyond +-10 000 km.
 *
 * Output unchanged on error. Accuracy (measured against GeographicLib
 * CartConvert on 2 000 random points, heights -10 km..10 000 km): 1 LSB
 * (15 um).
 */
drdc_status_t drdc_geo_to_ecef(const drdc_geo_point_t *p,
                               drdc_vec3_q47_16_t *ecef);

/**
 * ECEF -> geodetic by Bowring's iteration (B. R. Bowring, Survey Review
 * 23 (181), 1976): from the parametric latitude beta_0 = atan2(a Z, b p)
 * (p = hypot(X, Y)), two steps of
 * phi = atan2(Z + e'^2 b sin^3 beta, p - e^2 a cos^3 beta),
 * tan beta = (b / a) tan phi (it converges cubically: within 1.4e-19 rad
 * after two steps for heights -10 km .. 10 000 km, by mpmath), a third
 * step for points more than 50 km below the ellipsoid; then
 * h = p cos phi + Z sin phi - a sqrt(1 - e^2 sin^2 phi). The lengths and
 * unit vectors use reciprocal square roots by Newton steps from a 32-bit
 * seed (no Q5.58 division or square root), and two atan2 in all. Cycles
 * per target: docs/performance.md.
 *
 * @param ecef X, Y, Z in Q47.16 metres.
 * @param[out] p latitude, longitude in [-180, 180] (0 on the polar
 *        axis) and ellipsoidal height.
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL ecef or p is NULL.
 * @retval DRDC_E_HEIGHT the point is more than 10 000 km from the
 *         ellipsoid, or within 1 000 km of the Earth's centre (where
 *         geodetic coordinates are of no use).
 *
 * Output unchanged on error. Accuracy (measured against CartConvert -r
 * on the forward results, 2 009 points, heights -10 km .. 10 000 km):
 * latitude and longitude within 1 nas, height equal to CartConvert's
 * rounded to Q47.16 (0 LSB); the ECEF round trip through
 * drdc_geo_to_ecef() exact (0 LSB).
 */
drdc_status_t drdc_geo_from_ecef(const drdc_vec3_q47_16_t *ecef,
                                 drdc_geo_point_t *p);

/**
 * Geodetic -> local tangent plane East-North-Up at ref (GeographicLib's
 * LocalCartesian).
 *
 * @param ref the origin of the plane.
 * @param p the point.
 * @param[out] enu east, north, up in Q15.16 metres.
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL ref, p or enu is NULL.
 * @retval DRDC_E_LATITUDE a latitude outside [-90, 90] degrees.
 * @retval DRDC_E_LONGITUDE a longitude outside [-540, 540) degrees.
 * @retval DRDC_E_HEIGHT a height beyond +-10 000 km.
 * @retval DRDC_E_OVERFLOW a component beyond the Q15.16 range (32 km).
 *
 * Output unchanged on error. Accuracy (measured against CartConvert -l
 * within 30 km): 1 LSB (15 um).
 */
drdc_status_t drdc_geo_to_enu(const drdc_geo_point_t *ref,
                              const drdc_geo_point_t *p,
                              drdc_vec3_q15_16_t *enu);

/**
 * Local East-North-Up at ref -> geodetic.
 *
 * @param ref the origin of the plane.
 * @param enu east, north, up in Q15.16 metres.
 * @param[out] p the point.
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL ref, enu or p is NULL.
 * @retval DRDC_E_LATITUDE ref->lat outside [-90, 90] degrees.
 * @retval DRDC_E_LONGITUDE ref->lon outside [-540, 540) degrees.
 * @retval DRDC_E_HEIGHT ref->height, or the point's height, beyond
 *         +-10 000 km.
 *
 * Output unchanged on error. Accuracy: the round trip with
 * drdc_geo_to_enu() within 1 LSB (1 000 points).
 */
drdc_status_t drdc_geo_from_enu(const drdc_geo_point_t *ref,
                                const drdc_vec3_q15_16_t *enu,
                                drdc_geo_point_t *p);

/**
 * Geodetic -> local North-East-Down at ref: (north, east, -up) of
 * drdc_geo_to_enu().
 *
 * @param ref the origin of the plane.
 * @param p the point.
 * @param[out] ned north, east, down in Q15.16 metres.
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL ref, p or ned is NULL.
 * @retval DRDC_E_LATITUDE a latitude outside [-90, 90] degrees.
 * @retval DRDC_E_LONGITUDE a longitude outside [-540, 540) degrees.
 * @retval DRDC_E_HEIGHT a height beyond +-10 000 km.
 * @retval DRDC_E_OVERFLOW a component beyond the Q15.16 range (32 km).
 */
drdc_status_t drdc_geo_to_ned(const drdc_geo_point_t *ref,
                              const drdc_geo_point_t *p,
                              drdc_vec3_q15_16_t *ned);

/**
 * Local North-East-Down at ref -> geodetic.
 *
 * @param ref the origin of the plane.
 * @param ned north, east, down in Q15.16 metres.
 * @param[out] p the point.
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL ref, ned or p is NULL.
 * @retval DRDC_E_LATITUDE ref->lat outside [-90, 90] degrees.
 * @retval DRDC_E_LONGITUDE ref->lon outside [-540, 540) degrees.
 * @retval DRDC_E_HEIGHT ref->height, or the point's height, beyond
 *         +-10 000 km.
 */
drdc_status_t drdc_geo_from_ned(const drdc_geo_point_t *ref,
                                const drdc_vec3_q15_16_t *ned,
                                drdc_geo_point_t *p);

/** @} */

#endif /* DRDC_GEO_ECEF_H */
