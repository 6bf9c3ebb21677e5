/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Internal interface of the ECEF and tangent-plane conversions.
 */
#ifndef DRDC_GEO_ECEF_IMPL_H
#define DRDC_GEO_ECEF_IMPL_H

#include "geo_impl.h"

/** The checks of drdc_geo_to_ecef() on a point: DRDC_E_LATITUDE,
 *  DRDC_E_LONGITUDE or DRDC_E_HEIGHT out of range, else DRDC_OK. */
drdc_status_t drdc__geo_check_point(const drdc_geo_point_t *p);

/**
 * The ECEF coordinates of a checked point in Q27.36 (2^-36 m) added to
 * *x, *y, *z, or subtracted from them when sub: the difference of two
 * points is exactly that of their coordinates. The tangent-plane
 * conversions of ecef.c and pose.c accumulate one point at a time, so
 * that only one point and the three sums are on the stack.
 */
void drdc__geo_ecef_acc_q36(const drdc_geo_point_t *p, bool sub, int64_t *x,
                            int64_t *y, int64_t *z);

/**
 * ENU (ned false) or NED (ned true) in Q15.16 of the ECEF difference
 * d = p - ref (Q27.36, from drdc__geo_ecef_acc_q36(); turned in place, scratch)
 * at the checked ref. Returns DRDC_E_OVERFLOW (out unchanged) when a part
 * is outside Q15.16, else DRDC_OK.
 */
drdc_status_t drdc__geo_plane_turn(const drdc_geo_point_t *ref, bool ned,
                                   int64_t d[3], drdc_vec3_q15_16_t *out);

/**
 * The state of the inverse (ECEF -> geodetic, Bowring's iteration) in
 * Q27.36 lengths, or Q5.58 when (u, v) is a unit vector: one struct in
 * the frame of a caller of the deep chain, which the stages of ecef.c
 * reach by pointer (no level keeps copies of it). Its entry is an ECEF
 * point (u, v, z) = (x, y, z); p is scratch; on DRDC_OK
 * drdc__geo_geodetic_q36() leaves the geodetic point in it (v latitude, u
 * longitude, p height), so that its caller needs no point beside it.
 */
typedef struct geo_bowring {
  int64_t p; /**< distance from the polar axis */
  int64_t z; /**< distance from the equatorial plane */
  int64_t u; /**< a direction: horizontal part */
  int64_t v; /**< a direction: vertical part */
} geo_bowring_t;

/** A point's latitude and longitude (nas), its height kept apart. */
typedef struct geo_lat_lon {
  drdc_nas_t lat;
  drdc_nas_t lon;
} geo_lat_lon_t;

/**
 * The ECEF point (Q27.36) of an offset from a point given as ref's
 * latitude and longitude and, in b->p, its height (Q47.16), the offset in
 * b as north b->z, up b->u, east b->v (Q15.16 values, |v| < 2^32): the
 * point checked first (drdc__geo_check_point()'s statuses, b untouched on
 * error), then the offset scaled to Q27.36 and turned to ECEF axes in
 * place and the point's ECEF added, so that b->u, b->v, b->z hold x, y, z
 * (as drdc__geo_geodetic_q36() takes them); DRDC_OK.
 * The first half of drdc_geo_from_ned() and drdc_geo_from_enu(); its
 * sin/cos and roots run beside, not above, the inverse's chain.
 */
drdc_status_t drdc__geo_ecef_of_plane(const geo_lat_lon_t *ref,
                                      geo_bowring_t *b);

/**
 * Geodetic of the ECEF point in b (Q27.36, |x|, |y|, |z| < 2^61), the
 * second half of drdc_geo_from_ned() and drdc_geo_from_enu(): on DRDC_OK
 * the latitude (nas) in b->v, the longitude (nas, atan2's range) in b->u
 * and the ellipsoidal height (Q47.16) in b->p; DRDC_E_HEIGHT within
 * 1 000 km of the centre or beyond DRDC_GEO_HEIGHT_MAX (b is scratch
 * then).
 */
drdc_status_t drdc__geo_geodetic_q36(geo_bowring_t *b);

#endif /* DRDC_GEO_ECEF_IMPL_H */
