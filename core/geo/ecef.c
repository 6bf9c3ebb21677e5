/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Geodetic <-> ECEF on WGS-84 and the ENU / NED tangent planes.
 *
 * Forward: N = a / sqrt(1 - e^2 sin^2 phi), X = (N + h) cos phi cos lam,
 * Y = (N + h) cos phi sin lam, Z = (N (1 - e^2) + h) sin phi. Inverse:
 * Bowring's iteration from the parametric latitude atan2(a Z, b p), two
 * steps (three more than 50 km below the ellipsoid), then
 * h = p cos phi + Z sin phi - a sqrt(1 - e^2 sin^2 phi). Square roots as
 * reciprocal roots by Newton steps (rsqrt_q58()), so no Q5.58 division
 * or square root is left. Lengths are carried in Q27.36 inside (20 more
 * bits than Q47.16), so p = hypot(X, Y) and the local rotations lose
 * nothing to the output rounding. The helpers are split so that each
 * deep call (atan2, sin/cos, the roots) runs from a frame that keeps
 * only what it needs (issue 8's stack goal).
 */
#include <drdc/compiler.h>
#include <drdc/geo_ecef.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>
#include <drdc/fixed_sqrt.h>

#include "geo_ecef_impl.h"

/** a = 6 378 137 m in Q27.36. */
#define A_Q36 (INT64_C(6378137) * INT64_C(68719476736))
/** 2^20: Q47.16 -> Q27.36. */
#define Q36_PER_Q16 INT64_C(1048576)
/** Inputs of the inverse: |X|, |Y|, |Z| below 2^41 Q47.16 (33 554 km). */
#define ECEF_COORD_MAX INT64_C(2199023255552)
/** Within this of the centre (on both p and |Z|) there is no useful
 *  geodetic position: 1 000 km. */
#define ECEF_CORE (INT64_C(1000000) * INT64_C(65536))

/* the checks of a point's latitude, longitude and height, in that
 * order: one body for drdc__geo_check_point() and drdc__geo_ecef_of_plane() */
static inline drdc_status_t point_status(drdc_nas_t lat, drdc_nas_t lon,
                                         drdc_q47_16_t height)
{
  if ((lat > (90 * GEO_NAS_DEG)) || (lat < (-90 * GEO_NAS_DEG))) {
    return DRDC_E_LATITUDE;
  }
  if ((lon >= (540 * GEO_NAS_DEG)) || (lon < (-540 * GEO_NAS_DEG))) {
    return DRDC_E_LONGITUDE;
  }
  if ((height > DRDC_GEO_HEIGHT_MAX) || (height < -DRDC_GEO_HEIGHT_MAX)) {
    return DRDC_E_HEIGHT;
  }
  return DRDC_OK;
}

/* out of line (one copy for the functions of ecef.c and pose.c that
 * check points): a leaf, called before any deep chain starts */
DRDC_NOINLINE drdc_status_t drdc__geo_check_point(const drdc_geo_point_t *p)
{
  return point_status(p->lat, p->lon, p->height);
}

/* a longitude of a checked point (|lon| < 540 degrees) reduced by whole
 * turns to [-180, 180), in radians: sin/cos are most accurate near 0 */
static int64_t lon_rad(drdc_nas_t lon)
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

/* (a, b) <- (a c + b s, b c - a s) for c = cos t, s = sin t: the
 * products of turn(), out of line so that the two old values and a sum
 * it keeps across them are not on the stack under the sin/cos */
static DRDC_NOINLINE void turn_apply(const int64_t sc[2], int64_t *a,
                                     int64_t *b)
{
  int64_t a0 = *a;

  *a = drdc__geo_mul(a0, sc[1]) + drdc__geo_mul(*b, sc[0]);
  *b = drdc__geo_mul(*b, sc[1]) - drdc__geo_mul(a0, sc[0]);
}

/* The plane rotation by angle t (radians) in place: (a, b) <- (a cos t +
 * b sin t, b cos t - a sin t). Both tangent-plane conversions are two of
 * these (about the polar axis by the longitude, then about the east axis
 * by the latitude), so no 3 x 3 matrix or set of four sin/cos lives on
 * the stack. |a|, |b| < 2^61. */
static void turn(int64_t t, int64_t *a, int64_t *b)
{
  int64_t sc[2] = {0, 0};

  geo_sincos(t, &sc[0], &sc[1]);
  turn_apply(sc, a, b);
}

/* 1 / sqrt(x) for x in [1/4, 2) (Q5.58, the result at most 2): a seed
 * within 2^-15 relative from the Q1.30 root of x and a 32-bit quotient,
 * then Newton steps y (3 - x y^2) / 2, each squaring the relative error
 * (2^-29, then 2^-57 with the roundings). Three to four products a step;
 * no 64-bit division (drdc_fx_rsqrt_q1_30() takes a 64-bit quotient,
 * drdc_fx_sqrt_q5_58() two 128-bit ones). The Q1.30 root is
 * drdc_fx_sqrt_q1_30()'s own expression, the integer root of the Q1.30
 * value times 2^30, taken from drdc_fx_sqrt_u64() directly: the same
 * bits without a result slot or a wrapper frame on the deepest chain of
 * every ECEF and tangent-plane conversion. */
static int64_t rsqrt_q58(int64_t x, unsigned steps)
{
  /* x >> 28 as Q1.30 (x >= 0): floor, so in [2^28, 2^31), and its root
   * (rounded, as drdc_fx_sqrt_q1_30() gives it) in [2^29, 2^30.5) */
  uint32_t s30 = (uint32_t)drdc_fx_sqrt_u64(((uint64_t)x >> 28) << 30);
  uint32_t d;
  int64_t y;
  unsigned i;

  /* d = s 2^16 in [2^15, 2^16.5), and (2^32 - 1) / d = 2^16 / s within
   * 2^-15 relative, Q15.16 */
  d = s30 >> 14;
  d = 0xFFFFFFFFu / d;
  y = (int64_t)d * INT64_C(4398046511104);
  for (i = 0u; i < steps; i++) {
    y = drdc_fx_rshift_round_s64_inline(
        drdc__geo_mul(y, (3 * GEO_ONE) - drdc__geo_mul(x, drdc__geo_mul(y, y))),
        1u);
  }
  return y;
}

/* N = a / w = a / sqrt(w^2) (Q27.36 metres) at sin phi = s, w^2 = 1 -
 * e^2 sin^2 phi in [1 - e^2, 1]: no Q5.58 square root or quotient. One
 * body for acc_body() and acc_plane(). */
static inline int64_t prime_vertical_q36(int64_t s)
{
  return drdc__geo_mul(
      A_Q36,
      rsqrt_q58(GEO_ONE - drdc__geo_mul(GEO_E2, drdc__geo_mul(s, s)), 2u));
}

/* ECEF of a checked point in Q27.36, added to (*x, *y, *z), or subtracted
 * when sub (drdc__geo_mul() rounds symmetrically, so the difference of two
 * points is exactly that of their coordinates). The sin and cos of the
 * latitude, then those of the longitude, share one pair of slots, and
 * only cos phi and N + h are kept across the second sin/cos: the frame
 * under the roots and sin/cos of every tangent-plane chain stays small. */
static inline DRDC_ALWAYS_INLINE void acc_body(const drdc_geo_point_t *p,
                                               bool sub, int64_t *x, int64_t *y,
                                               int64_t *z)
{
  int64_t sc[2] = {0, 0};
  int64_t cphi;
  int64_t n;
  int64_t v;

  geo_sincos(drdc__geo_rad_from_nas(p->lat), &sc[0], &sc[1]);
  n = prime_vertical_q36(sc[0]);
  v = drdc__geo_mul(
      drdc__geo_mul(n, GEO_ONE - GEO_E2) + (p->height * Q36_PER_Q16), sc[0]);
  *z = sub ? (*z - v) : (*z + v);
  /* x, y += or -= (N + h) cos phi (cos lam, sin lam) */
  cphi = sc[1];
  n = n + (p->height * Q36_PER_Q16);
  geo_sincos(lon_rad(p->lon), &sc[0], &sc[1]);
  v = drdc__geo_mul(n, drdc__geo_mul(cphi, sc[1]));
  *x = sub ? (*x - v) : (*x + v);
  v = drdc__geo_mul(n, drdc__geo_mul(cphi, sc[0]));
  *y = sub ? (*y - v) : (*y + v);
}

/* geo_impl.h: acc_body(), one copy of its code per entry (the same
 * bits; no wrapper frame on the chains of drdc_geo_to_ecef() and of the
 * tangent-plane conversions) */
void drdc__geo_ecef_acc_q36(const drdc_geo_point_t *p, bool sub, int64_t *x,
                            int64_t *y, int64_t *z)
{
  acc_body(p, sub, x, y, z);
}

drdc_status_t drdc_geo_to_ecef(const drdc_geo_point_t *p,
                               drdc_vec3_q47_16_t *ecef)
{
  drdc_status_t st;

  if ((p == NULL) || (ecef == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc__geo_check_point(p);
  if (st != DRDC_OK) {
    return st;
  }
  /* nothing fails from here on: the output holds the Q27.36 sums, then
   * their Q47.16 rounding (no local copy on the stack) */
  ecef->x = 0;
  ecef->y = 0;
  ecef->z = 0;
  drdc__geo_ecef_acc_q36(p, false, &ecef->x, &ecef->y, &ecef->z);
  ecef->x = drdc_fx_rshift_round_s64_inline(ecef->x, 20u);
  ecef->y = drdc_fx_rshift_round_s64_inline(ecef->y, 20u);
  ecef->z = drdc_fx_rshift_round_s64_inline(ecef->z, 20u);
  return DRDC_OK;
}

/* |v| for v > INT64_MIN: its callers pass Q27.36 values below 2^62 in
 * magnitude (drdc_geo_from_ecef() checks its input without it) */
static int64_t ecef_abs64(int64_t v)
{
  return (v < 0) ? -v : v;
}

/* (*a, *b) scaled by one power of two so the larger magnitude lies in
 * [2^57, 2^58) (rounding right shift, or exact left shift), both then
 * read as Q5.58 values of magnitude below 1; returns the shift: > 0
 * right, < 0 left. |*a|, |*b| < 2^62, not both zero. */
static int scale_legs(int64_t *a, int64_t *b)
{
  uint64_t ma = (uint64_t)ecef_abs64(*a);
  uint64_t mb = (uint64_t)ecef_abs64(*b);
  uint64_t m = (ma > mb) ? ma : mb;
  unsigned n = 0u;

  if (m >= (UINT64_C(1) << 58)) {
    while ((m >> n) >= (UINT64_C(1) << 58)) {
      n++;
    }
    *a = drdc_fx_rshift_round_s64_inline(*a, n);
    *b = drdc_fx_rshift_round_s64_inline(*b, n);
    return (int)n;
  }
  while ((m << n) < (UINT64_C(1) << 57)) {
    n++;
  }
  *a = *a * (int64_t)(UINT64_C(1) << n);
  *b = *b * (int64_t)(UINT64_C(1) << n);
  return -(int)n;
}

/* The state of Bowring's iteration: geo_bowring_t (geo_impl.h), one
 * struct in the frame of the caller of geodetic_direction() (which also
 * fills it with the ECEF point) that the helpers below reach by pointer,
 * so no level keeps copies of it */
typedef geo_bowring_t bowring_t;

/* (b->u, b->v) <- (u, v) / hypot(u, v) (Q5.58, within 3 LSB), and
 * returns hypot(u, v) (relative error within 2^-56: 1e-10 m at the
 * Earth's radius). On the legs scaled to [2^57, 2^58) (a^2 + b^2 in
 * [1/4, 2)): y = 1 / sqrt(a^2 + b^2), the unit vector (a y, b y), the
 * length (a^2 + b^2) y scaled back. (u, v) != (0, 0), |u|, |v| < 2^61.
 * A fifth of the cycles of drdc_fx_hypot_s64()'s exact 128-bit root and
 * two Q5.58 quotients. */
static int64_t normalise(bowring_t *b)
{
  int64_t q;
  int64_t y;
  /* the legs scaled in place: no copy of them in this frame, which is
   * on the deepest chain of the inverse */
  int k = scale_legs(&b->u, &b->v);

  q = drdc__geo_mul(b->u, b->u) + drdc__geo_mul(b->v, b->v);
  y = rsqrt_q58(q, 2u);
  b->u = drdc__geo_mul(b->u, y);
  b->v = drdc__geo_mul(b->v, y);
  q = drdc__geo_mul(q, y);
  /* q < 2^58.5 and the length below 2^61.5: no overflow either way */
  return (k >= 0) ? (q * (int64_t)(UINT64_C(1) << (unsigned)k))
                  : drdc_fx_rshift_round_s64_inline(q, (unsigned)-k);
}

/* One step of Bowring's iteration at distance p from the axis and height
 * z over the equator: the unit vector (b->u, b->v) (cos, sin) of the
 * parametric latitude beta becomes (p - e^2 a cos^3 beta,
 * z + e'^2 b sin^3 beta), the direction of the geodetic latitude. The
 * step converges cubically (measured with mpmath: from beta_0 =
 * atan2(a z, b p) the latitude is within 8e-9 rad after one step,
 * 1.4e-19 after two for heights -10 km .. 10 000 km, 2e-25 after two for
 * any point at least 6 300 km from the centre, 4e-27 after three for
 * every accepted point). */
static void bowring_step(bowring_t *b)
{
  b->u = b->p - drdc__geo_mul(GEO_E2A_Q36,
                              drdc__geo_mul(drdc__geo_mul(b->u, b->u), b->u));
  b->v = b->z + drdc__geo_mul(GEO_EP2B_Q36,
                              drdc__geo_mul(drdc__geo_mul(b->v, b->v), b->v));
}

/* h = p cos phi + z sin phi - a sqrt(1 - e^2 sin^2 phi) (Q27.36) with
 * (b->u, b->v) = (cos phi, sin phi); stationary in phi at the true
 * latitude, so an error d of phi moves h by about N d^2 only. w =
 * sqrt(w^2) as w^2 / sqrt(w^2), w^2 in [1 - e^2, 1]. */
static int64_t height_q36(const bowring_t *b)
{
  int64_t w2 = GEO_ONE - drdc__geo_mul(GEO_E2, drdc__geo_mul(b->v, b->v));

  return (drdc__geo_mul(b->p, b->u) + drdc__geo_mul(b->z, b->v)) -
         drdc__geo_mul(A_Q36, drdc__geo_mul(w2, rsqrt_q58(w2, 2u)));
}

/* Below this height (Q27.36: -50 km) the point is less than 6 300 km
 * from the centre (b - 50 km > 6 300 km), and Bowring's iteration takes a
 * third step. */
#define DEEP_Q36 (INT64_C(-50000) * INT64_C(68719476736))

/* The unit vector (cos phi, sin phi) of the geodetic latitude (Q5.58) and
 * the height (Q47.16) of the ECEF point x = b->u, y = b->v, z = b->z in
 * Q27.36 (|x|, |y|, |z| < 2^61; b is the caller's, its scratch from here
 * on). On DRDC_OK they are left in b: b->u = cos phi, b->v = sin phi and
 * b->p = the height (the distance from the axis is no longer needed), so
 * that no caller holds a point beside b; b->z is then free. */
static drdc_status_t geodetic_direction(bowring_t *b)
{
  int64_t h;

  b->p = 0;
  if ((b->u != 0) || (b->v != 0)) {
    b->p = normalise(b);
  }
  if ((b->p < (ECEF_CORE * Q36_PER_Q16)) &&
      (ecef_abs64(b->z) < (ECEF_CORE * Q36_PER_Q16))) {
    return DRDC_E_HEIGHT;
  }
  /* tan beta_0 = a z / (b p), then tan beta = (b / a) tan phi */
  b->u = drdc__geo_mul(b->p, GEO_B_OVER_A);
  b->v = b->z;
  (void)normalise(b);
  bowring_step(b);
  b->v = drdc__geo_mul(b->v, GEO_B_OVER_A);
  (void)normalise(b);
  bowring_step(b);
  (void)normalise(b);
  h = height_q36(b);
  if (h < DEEP_Q36) {
    b->v = drdc__geo_mul(b->v, GEO_B_OVER_A);
    (void)normalise(b);
    bowring_step(b);
    (void)normalise(b);
    h = height_q36(b);
  }
  h = drdc_fx_rshift_round_s64_inline(h, 20u);
  if ((h > DRDC_GEO_HEIGHT_MAX) || (h < -DRDC_GEO_HEIGHT_MAX)) {
    return DRDC_E_HEIGHT;
  }
  b->p = h;
  return DRDC_OK;
}

/* atan2(y, x) in nas for (y, x) != (0, 0), the radians through *slot (a
 * free slot of the caller's bowring_t, scratch): no result slot in the
 * frames on the inverse's deepest chain. drdc_fx_atan2_q5_58() fails
 * only at (0, 0), which every caller rules out (the longitude's callers
 * test it, the latitude's (sin, cos) is a unit vector), so *slot is
 * always written. */
static inline drdc_nas_t angle_nas(int64_t y, int64_t x, int64_t *slot)
{
  (void)drdc_fx_atan2_q5_58(y, x, slot);
  return drdc__geo_nas_from_rad(*slot);
}

/* The end of drdc__geo_geodetic_q36() once the direction and height are in b:
 * the latitude's atan2 (its radians in b->z, no longer needed) into
 * b->v, the longitude into b->u. A sibling call of its caller, so that
 * no status is kept across the atan2 in the caller's frame; never
 * fails. */
static DRDC_NOINLINE drdc_status_t lat_lon_into(bowring_t *b, drdc_nas_t lon)
{
  b->v = angle_nas(b->v, b->u, &b->z);
  b->u = lon;
  return DRDC_OK;
}

/* geo_impl.h: geodetic of the ECEF point in b (Q27.36, as
 * geodetic_direction() takes it), left in b. The longitude first (atan2
 * is scale-free), then Bowring's iteration for the latitude's direction
 * and the height, then the latitude's atan2: each deep call from a frame
 * that keeps only the longitude and b, whose free slots take the
 * radians. Out of line: not merged into the frame of its caller, which
 * holds the bowring_t. */
DRDC_NOINLINE drdc_status_t drdc__geo_geodetic_q36(bowring_t *b)
{
  drdc_nas_t lon = 0;
  drdc_status_t st;

  if (b->u != 0) {
    /* the longitude's radians in b->p, free until
     * geodetic_direction() */
    lon = angle_nas(b->v, b->u, &b->p);
  } else if (b->v != 0) {
    lon = angle_nas(b->v, b->u, &b->p);
  } else {
    /* on the axis: longitude 0 */
  }
  st = geodetic_direction(b);
  if (st != DRDC_OK) {
    return st;
  }
  return lat_lon_into(b, lon);
}

drdc_status_t drdc_geo_from_ecef(const drdc_vec3_q47_16_t *ecef,
                                 drdc_geo_point_t *p)
{
  bowring_t b;
  drdc_nas_t lon;
  drdc_status_t st;

  if ((ecef == NULL) || (p == NULL)) {
    return DRDC_E_NULL;
  }
  /* each bound on both sides, with no negation of the coordinate
   * (ecef_abs64() of INT64_MIN would overflow) */
  if ((ecef->x >= ECEF_COORD_MAX) || (ecef->x <= -ECEF_COORD_MAX) ||
      (ecef->y >= ECEF_COORD_MAX) || (ecef->y <= -ECEF_COORD_MAX) ||
      (ecef->z >= ECEF_COORD_MAX) || (ecef->z <= -ECEF_COORD_MAX)) {
    return DRDC_E_HEIGHT;
  }
  /* as drdc__geo_geodetic_q36(), reading the coordinates again after each
   * call rather than keeping them: the longitude from the Q47.16 values
   * (the same angle: atan2 scales its arguments exactly) */
  lon = ((ecef->x == 0) && (ecef->y == 0)) ? 0
                                           : angle_nas(ecef->y, ecef->x, &b.p);
  b.u = ecef->x * Q36_PER_Q16;
  b.v = ecef->y * Q36_PER_Q16;
  b.z = ecef->z * Q36_PER_Q16;
  st = geodetic_direction(&b);
  if (st == DRDC_OK) {
    p->lat = angle_nas(b.v, b.u, &b.z);
    p->lon = lon;
    p->height = b.p;
  }
  return st;
}

static bool fits_q15_16(int64_t v)
{
  return (v <= (int64_t)INT32_MAX) && (v >= (int64_t)INT32_MIN);
}

/* The ECEF difference d (Q27.36: d[0] = dx, d[1] = dy, d[2] = dz) turned
 * in place; about the axis by the longitude: (dx, dy) -> (towards the
 * ref's meridian plane t, east); about east by the latitude: (t, dz) ->
 * (up, north). */
drdc_status_t drdc__geo_plane_turn(const drdc_geo_point_t *ref, bool ned,
                                   int64_t d[3], drdc_vec3_q15_16_t *out)
{
  turn(lon_rad(ref->lon), &d[0], &d[1]);
  turn(drdc__geo_rad_from_nas(ref->lat), &d[0], &d[2]);
  /* east, north, up (Q47.16); NED: north, east, down */
  d[0] = drdc_fx_rshift_round_s64_inline(d[0], 20u);
  d[1] = drdc_fx_rshift_round_s64_inline(d[1], 20u);
  d[2] = drdc_fx_rshift_round_s64_inline(d[2], 20u);
  if (ned) {
    d[0] = -d[0];
  }
  if (!fits_q15_16(d[0]) || !fits_q15_16(d[1]) || !fits_q15_16(d[2])) {
    return DRDC_E_OVERFLOW;
  }
  out->x = (drdc_q15_16_t)(ned ? d[2] : d[1]);
  out->y = (drdc_q15_16_t)(ned ? d[1] : d[2]);
  out->z = (drdc_q15_16_t)d[0];
  return DRDC_OK;
}

/* ENU (ned false) or NED (ned true) of p at ref in Q15.16, the pointers
 * checked: the ECEF difference (Q27.36) in one array, then
 * drdc__geo_plane_turn() */
static drdc_status_t plane_of(const drdc_geo_point_t *ref,
                              const drdc_geo_point_t *p, bool ned,
                              drdc_vec3_q15_16_t *out)
{
  drdc_status_t st;
  int64_t d[3] = {0, 0, 0};

  st = drdc__geo_check_point(ref);
  if (st == DRDC_OK) {
    st = drdc__geo_check_point(p);
  }
  if (st != DRDC_OK) {
    return st;
  }
  drdc__geo_ecef_acc_q36(p, false, &d[0], &d[1], &d[2]);
  drdc__geo_ecef_acc_q36(ref, true, &d[0], &d[1], &d[2]);
  return drdc__geo_plane_turn(ref, ned, d, out);
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

/* turn() of b's (north, up) by -latitude (lon false) or of its (east,
 * horizontal) by -longitude (lon true), the slots chosen here: its
 * caller keeps b alone, not the addresses of two of its slots */
static DRDC_NOINLINE void turn_plane(int64_t t, bowring_t *b, bool lon)
{
  int64_t sc[2] = {0, 0};

  geo_sincos(t, &sc[0], &sc[1]);
  turn_apply(sc, lon ? &b->v : &b->z, &b->u);
}

/* acc_body() of the point (ref's latitude and longitude, its height
 * (Q47.16) in b->p) into b's ECEF slots (x in b->u, y in b->v, z in
 * b->z), the same operations in the same order: two arguments, so that
 * drdc__geo_ecef_of_plane() ends with a sibling call on both targets (no stack
 * argument on Cortex-M3), and cos phi then waits in b->p (free until the
 * inverse) rather than in registers across the second sin/cos: a frame
 * that keeps b, p and N + h only. */
static DRDC_NOINLINE drdc_status_t acc_plane(const geo_lat_lon_t *p,
                                             bowring_t *b)
{
  int64_t sc[2] = {0, 0};
  int64_t n;
  int64_t v;

  geo_sincos(drdc__geo_rad_from_nas(p->lat), &sc[0], &sc[1]);
  n = prime_vertical_q36(sc[0]);
  v = drdc__geo_mul(drdc__geo_mul(n, GEO_ONE - GEO_E2) + (b->p * Q36_PER_Q16),
                    sc[0]);
  b->z = b->z + v;
  n = n + (b->p * Q36_PER_Q16);
  b->p = sc[1];
  geo_sincos(lon_rad(p->lon), &sc[0], &sc[1]);
  v = drdc__geo_mul(n, drdc__geo_mul(b->p, sc[1]));
  b->u = b->u + v;
  v = drdc__geo_mul(n, drdc__geo_mul(b->p, sc[0]));
  b->v = b->v + v;
  return DRDC_OK;
}

/* point_status() of drdc__geo_ecef_of_plane()'s point: a leaf, so that its
 * caller keeps only ref and b across it */
static DRDC_NOINLINE drdc_status_t plane_point_status(const geo_lat_lon_t *ref,
                                                      const bowring_t *b)
{
  return point_status(ref->lat, ref->lon, b->p);
}

/* geo_impl.h: the point checked, then b's offset (north b->z, up b->u, east
 * b->v; Q15.16, scaled here) turned to ECEF axes in place (about east by
 * -latitude: (north, up) -> (dz, the horizontal part towards the ref's meridian
 * plane r); about the axis by -longitude: (east, r) -> (dy, dx)), then the
 * point's ECEF added. The check here, and acc_plane()'s DRDC_OK returned by a
 * sibling call: a caller that holds the latitude and longitude alone (16 bytes)
 * saves no register across the check (issue 8's stack). */
DRDC_NOINLINE drdc_status_t drdc__geo_ecef_of_plane(const geo_lat_lon_t *ref,
                                                    bowring_t *b)
{
  drdc_status_t st = plane_point_status(ref, b);

  if (st != DRDC_OK) {
    return st;
  }
  /* the offset Q15.16 -> Q27.36 in place (exact: |part| < 2^32) */
  b->z = b->z * Q36_PER_Q16;
  b->u = b->u * Q36_PER_Q16;
  b->v = b->v * Q36_PER_Q16;
  turn_plane(drdc__geo_rad_from_nas(ref->lat), b, false);
  turn_plane(lon_rad(ref->lon), b, true);
  return acc_plane(ref, b);
}

/* geodetic of ENU (ned false) or NED (ned true) v (Q15.16) at ref: the
 * offset into b's slots (north, up, east), drdc__geo_ecef_of_plane() (ref's
 * check first), then drdc__geo_geodetic_q36(); the one bowring_t of the chain
 * lives here, p written only on DRDC_OK */
static drdc_status_t point_of_plane(const drdc_geo_point_t *ref,
                                    const drdc_vec3_q15_16_t *v, bool ned,
                                    drdc_geo_point_t *p)
{
  bowring_t b;
  geo_lat_lon_t ll;
  drdc_status_t st;

  b.z = ned ? v->x : v->y;
  b.u = ned ? -(int64_t)v->z : (int64_t)v->z;
  b.v = ned ? v->y : v->x;
  b.p = ref->height;
  ll.lat = ref->lat;
  ll.lon = ref->lon;
  st = drdc__geo_ecef_of_plane(&ll, &b);
  if (st == DRDC_OK) {
    st = drdc__geo_geodetic_q36(&b);
  }
  if (st == DRDC_OK) {
    p->lat = b.v;
    p->lon = b.u;
    p->height = b.p;
  }
  return st;
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
