/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Internal interface between the geodetic <-> ECEF conversions
 *        (ecef.c) and the tangent-plane conversions (tangent_plane.c).
 *
 * Lengths are Q27.36 metres (2^-36 m) inside: 20 fraction bits more
 * than the Q47.16 of the public API, so that the rotations into and out
 * of a tangent plane and the inverse's hypot(X, Y) lose nothing to the
 * final rounding, and still 2^27 m (134 000 km) of range, four times the
 * largest accepted coordinate (2^41 Q47.16, 33 554 km).
 */
#ifndef DRDC_GEO_ECEF_IMPL_H
#define DRDC_GEO_ECEF_IMPL_H

#include <stdint.h>

#include <drdc/geo_ecef.h>

#include "geo_impl.h"

/** 2^20: Q47.16 -> Q27.36 metres. */
#define GEO_Q36_PER_Q16 INT64_C(1048576)

/** An ECEF point or difference of points, Q27.36 metres. */
typedef struct geo_ecef_q36 {
  int64_t x; /**< towards latitude 0, longitude 0 */
  int64_t y; /**< towards latitude 0, longitude 90 E */
  int64_t z; /**< towards the north pole */
} geo_ecef_q36_t;

/** The checks of drdc_geo_to_ecef() on a point, in this order:
 *  DRDC_E_LATITUDE, DRDC_E_LONGITUDE, DRDC_E_HEIGHT, else DRDC_OK. */
drdc_status_t drdc__geo_check_point(const drdc_geo_point_t *p);

/** ECEF of a point that passed drdc__geo_check_point(), Q27.36 metres
 *  (|x|, |y|, |z| at most a + 10 000 km, below 2^60). */
void drdc__geo_ecef_q36(const drdc_geo_point_t *p, geo_ecef_q36_t *e);

/**
 * Geodetic of the ECEF point e (Q27.36, |x|, |y|, |z| < 2^61) by
 * Bowring's iteration: latitude, longitude (atan2's range, 0 on the
 * polar axis) and ellipsoidal height into *p, written only on DRDC_OK;
 * DRDC_E_HEIGHT within 1 000 km of the Earth's centre or for a height
 * beyond +-DRDC_GEO_HEIGHT_MAX.
 */
drdc_status_t drdc__geo_geodetic_q36(const geo_ecef_q36_t *e,
                                     drdc_geo_point_t *p);

/** The longitude of a checked point (|lon| < 540 degrees) reduced by a
 *  whole turn to [-180, 180), in radians (Q5.58): sin and cos are most
 *  accurate near 0. */
static inline int64_t geo_lon_rad(drdc_nas_t lon)
{
  drdc_nas_t l = lon;

  if (l >= (180 * GEO_NAS_DEG)) {
    l = l - (360 * GEO_NAS_DEG);
  } else if (l < (-180 * GEO_NAS_DEG)) {
    l = l + (360 * GEO_NAS_DEG);
  } else {
    /* in range */
  }
  return drdc__geo_rad_from_nas(l);
}

#endif /* DRDC_GEO_ECEF_IMPL_H */
