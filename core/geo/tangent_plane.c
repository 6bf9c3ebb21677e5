/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Geodetic <-> local tangent plane (ENU, NED) at a reference point.
 *
 * As GeographicLib's LocalCartesian (Karney): the ECEF difference of the
 * point and the reference, turned about the polar axis by the
 * reference's longitude and about the east axis by its latitude: the
 * rotation of the 3 x 3 matrix of LocalCartesian as two plane rotations,
 * with one sin/cos pair at a time. The inverse turns the other way and
 * adds the reference's ECEF. Differences and offsets are Q27.36, so the
 * Q15.16 result is rounded once.
 */
#include <drdc/geo_ecef.h>

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include <drdc/fixed_arith.h>

#include "geo_ecef_impl.h"

/* (a, b) turned by the angle t (radians, Q5.58): a_out = a cos t + b sin
 * t, b_out = b cos t - a sin t; |a|, |b| < 2^61 */
static void rotate_pair(int64_t t, int64_t a, int64_t b, int64_t *a_out,
                        int64_t *b_out)
{
  int64_t sin_t = 0;
  int64_t cos_t = 0;

  geo_sincos(t, &sin_t, &cos_t);
  *a_out = drdc__geo_mul(a, cos_t) + drdc__geo_mul(b, sin_t);
  *b_out = drdc__geo_mul(b, cos_t) - drdc__geo_mul(a, sin_t);
}

static bool fits_q15_16(int64_t v)
{
  return (v <= (int64_t)INT32_MAX) && (v >= (int64_t)INT32_MIN);
}

/* ENU (ned false) or NED (ned true) of p at ref in Q15.16, the pointers
 * checked; out written only on DRDC_OK */
static drdc_status_t plane_of(const drdc_geo_point_t *ref,
                              const drdc_geo_point_t *p, bool ned,
                              drdc_vec3_q15_16_t *out)
{
  geo_ecef_q36_t at_p;
  geo_ecef_q36_t at_ref;
  /* horizontal, along the reference's meridian, away from the axis */
  int64_t r;
  int64_t east;
  int64_t north;
  int64_t up;
  int64_t x;
  int64_t y;
  int64_t z;
  drdc_status_t st;

  st = drdc__geo_check_point(ref);
  if (st == DRDC_OK) {
    st = drdc__geo_check_point(p);
  }
  if (st != DRDC_OK) {
    return st;
  }
  drdc__geo_ecef_q36(p, &at_p);
  drdc__geo_ecef_q36(ref, &at_ref);
  /* about the polar axis by the longitude: (dx, dy) -> (r, east); about
   * east by the latitude: (r, dz) -> (up, north) */
  rotate_pair(geo_lon_rad(ref->lon), at_p.x - at_ref.x, at_p.y - at_ref.y, &r,
              &east);
  rotate_pair(drdc__geo_rad_from_nas(ref->lat), r, at_p.z - at_ref.z, &up,
              &north);
  east = drdc_fx_rshift_round_s64_inline(east, 20u);
  north = drdc_fx_rshift_round_s64_inline(north, 20u);
  up = drdc_fx_rshift_round_s64_inline(up, 20u);
  if (ned) {
    x = north;
    y = east;
    z = -up;
  } else {
    x = east;
    y = north;
    z = up;
  }
  if (!fits_q15_16(x) || !fits_q15_16(y) || !fits_q15_16(z)) {
    return DRDC_E_OVERFLOW;
  }
  out->x = (drdc_q15_16_t)x;
  out->y = (drdc_q15_16_t)y;
  out->z = (drdc_q15_16_t)z;
  return DRDC_OK;
}

/* ECEF (Q27.36) of the point at ENU (ned false) or NED (ned true) v
 * (Q15.16 metres) from the checked ref: the offset turned into ECEF axes
 * (about east by -latitude: (north, up) -> (dz, r), r horizontal away
 * from the axis; about the axis by -longitude: (east, r) -> (dy, dx))
 * and added to ref's ECEF */
static void ecef_of_offset(const drdc_geo_point_t *ref,
                           const drdc_vec3_q15_16_t *v, bool ned,
                           geo_ecef_q36_t *e)
{
  /* Q15.16 -> Q27.36, exact: |part| < 2^32 */
  int64_t north = (ned ? v->x : v->y) * GEO_Q36_PER_Q16;
  int64_t east = (ned ? v->y : v->x) * GEO_Q36_PER_Q16;
  int64_t up = (ned ? -(int64_t)v->z : (int64_t)v->z) * GEO_Q36_PER_Q16;
  geo_ecef_q36_t at_ref;
  int64_t r;
  int64_t dx;
  int64_t dy;
  int64_t dz;

  rotate_pair(drdc__geo_rad_from_nas(ref->lat), north, up, &dz, &r);
  rotate_pair(geo_lon_rad(ref->lon), east, r, &dy, &dx);
  drdc__geo_ecef_q36(ref, &at_ref);
  e->x = dx + at_ref.x;
  e->y = dy + at_ref.y;
  e->z = dz + at_ref.z;
}

/* Geodetic of ENU (ned false) or NED (ned true) v at ref, the pointers
 * checked: ref's checks first; p written only on DRDC_OK */
static drdc_status_t point_of_plane(const drdc_geo_point_t *ref,
                                    const drdc_vec3_q15_16_t *v, bool ned,
                                    drdc_geo_point_t *p)
{
  geo_ecef_q36_t e;
  drdc_status_t st = drdc__geo_check_point(ref);

  if (st != DRDC_OK) {
    return st;
  }
  ecef_of_offset(ref, v, ned, &e);
  return drdc__geo_geodetic_q36(&e, p);
}

drdc_status_t drdc_geo_to_enu(const drdc_geo_point_t *ref,
                              const drdc_geo_point_t *p,
                              drdc_vec3_q15_16_t *enu)
{
  if ((ref == NULL) || (p == NULL) || (enu == NULL)) {
    return DRDC_E_NULL;
  }
  return plane_of(ref, p, false, enu);
}

drdc_status_t drdc_geo_to_ned(const drdc_geo_point_t *ref,
                              const drdc_geo_point_t *p,
                              drdc_vec3_q15_16_t *ned)
{
  if ((ref == NULL) || (p == NULL) || (ned == NULL)) {
    return DRDC_E_NULL;
  }
  return plane_of(ref, p, true, ned);
}

drdc_status_t drdc_geo_from_enu(const drdc_geo_point_t *ref,
                                const drdc_vec3_q15_16_t *enu,
                                drdc_geo_point_t *p)
{
  if ((ref == NULL) || (enu == NULL) || (p == NULL)) {
    return DRDC_E_NULL;
  }
  return point_of_plane(ref, enu, false, p);
}

drdc_status_t drdc_geo_from_ned(const drdc_geo_point_t *ref,
                                const drdc_vec3_q15_16_t *ned,
                                drdc_geo_point_t *p)
{
  if ((ref == NULL) || (ned == NULL) || (p == NULL)) {
    return DRDC_E_NULL;
  }
  return point_of_plane(ref, ned, true, p);
}
