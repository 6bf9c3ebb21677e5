/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Geodetic <-> ECEF on the WGS-84 ellipsoid.
 *
 * Forward (as GeographicLib's Geocentric::Forward, Karney):
 * N = a / sqrt(1 - e^2 sin^2 phi), X = (N + h) cos phi cos lam,
 * Y = (N + h) cos phi sin lam, Z = (N (1 - e^2) + h) sin phi.
 *
 * Inverse: Bowring's iteration (B. R. Bowring, "Transformation from
 * spatial to geographical coordinates", Survey Review 23 (181), 1976,
 * pp. 323-327) from the parametric latitude beta_0 = atan2(a Z, b p),
 * p = hypot(X, Y): two steps, three for points more than 50 km below the
 * ellipsoid, then h = p cos phi + Z sin phi - a sqrt(1 - e^2 sin^2 phi).
 *
 * WGS-84: a = 6 378 137 m, f = 1 / 298.257223563 (NIMA TR8350.2); the
 * derived constants are in geo_consts.h. Lengths are Q27.36 metres
 * inside (geo_ecef_impl.h), unit vectors and sin/cos Q5.58. Every
 * square root is a reciprocal root by Newton steps from a 32-bit seed
 * (rsqrt_q58()), so neither direction takes a 64-bit division or a
 * Q5.58 square root.
 */
#include <drdc/geo_ecef.h>

#include <stddef.h>
#include <stdint.h>

#include <drdc/fixed_arith.h>
#include <drdc/fixed_sqrt.h>

#include "geo_ecef_impl.h"

/** a = 6 378 137 m in Q27.36. */
#define A_Q36 (INT64_C(6378137) * INT64_C(68719476736))
/** Inputs of the inverse: |X|, |Y|, |Z| below 2^41 Q47.16 (33 554 km),
 *  so that every Q27.36 length stays below 2^61. */
#define ECEF_COORD_MAX INT64_C(2199023255552)
/** Within 1 000 km of the centre (on both p and |Z|) a point has no
 *  useful geodetic position; Q27.36. */
#define ECEF_CORE_Q36 (INT64_C(1000000) * INT64_C(68719476736))
/** Below this height (-50 km, Q27.36) the point is less than 6 300 km
 *  from the centre (b - 50 km > 6 300 km) and Bowring's iteration takes
 *  a third step. */
#define DEEP_Q36 (INT64_C(-50000) * INT64_C(68719476736))
/** Newton steps of rsqrt_q58(): 2^-15 -> 2^-29 -> 2^-57 relative. */
#define RSQRT_STEPS 2u

drdc_status_t drdc__geo_check_point(const drdc_geo_point_t *p)
{
  if ((p->lat > (90 * GEO_NAS_DEG)) || (p->lat < (-90 * GEO_NAS_DEG))) {
    return DRDC_E_LATITUDE;
  }
  if ((p->lon >= (540 * GEO_NAS_DEG)) || (p->lon < (-540 * GEO_NAS_DEG))) {
    return DRDC_E_LONGITUDE;
  }
  if ((p->height > DRDC_GEO_HEIGHT_MAX) || (p->height < -DRDC_GEO_HEIGHT_MAX)) {
    return DRDC_E_HEIGHT;
  }
  return DRDC_OK;
}

/* 1 / sqrt(x) for x in [1/4, 2) (Q5.58; the result is at most 2). The
 * seed 2^16 / s, with s the rounded integer root of x as Q1.30 times
 * 2^30 (drdc_fx_sqrt_q1_30()'s expression) and a 32-bit quotient, is
 * within 2^-15 relative; each Newton step y (3 - x y^2) / 2 squares the
 * relative error (2^-29, then 2^-57 with the roundings) in three
 * products. No 64-bit division: drdc_fx_rsqrt_q1_30() takes a 64-bit
 * quotient and drdc_fx_sqrt_q5_58() two 128-bit ones. */
static int64_t rsqrt_q58(int64_t x)
{
  /* x >> 28 as Q1.30 (x >= 0): floor, so in [2^28, 2^31), and its root
   * in [2^29, 2^30.5) */
  uint32_t s30 = (uint32_t)drdc_fx_sqrt_u64(((uint64_t)x >> 28) << 30);
  /* s 2^16 in [2^15, 2^16.5); (2^32 - 1) / it = 2^16 / s, Q15.16 */
  uint32_t seed_q16 = 0xFFFFFFFFu / (s30 >> 14);
  int64_t y = (int64_t)seed_q16 * INT64_C(4398046511104);
  unsigned i;

  for (i = 0u; i < RSQRT_STEPS; i++) {
    y = drdc_fx_rshift_round_s64_inline(
        drdc__geo_mul(y, (3 * GEO_ONE) - drdc__geo_mul(x, drdc__geo_mul(y, y))),
        1u);
  }
  return y;
}

/* The radius of curvature in the prime vertical N = a / sqrt(w^2)
 * (Q27.36 metres) at sin phi = s, w^2 = 1 - e^2 s^2 in [1 - e^2, 1]. */
static int64_t prime_vertical_q36(int64_t s)
{
  return drdc__geo_mul(
      A_Q36, rsqrt_q58(GEO_ONE - drdc__geo_mul(GEO_E2, drdc__geo_mul(s, s))));
}

void drdc__geo_ecef_q36(const drdc_geo_point_t *p, geo_ecef_q36_t *e)
{
  int64_t sin_phi = 0;
  int64_t cos_phi = 0;
  int64_t sin_lam = 0;
  int64_t cos_lam = 0;
  int64_t n;
  int64_t h = p->height * GEO_Q36_PER_Q16;
  /* N + h, the distance from the polar axis over cos phi */
  int64_t n_plus_h;

  geo_sincos(drdc__geo_rad_from_nas(p->lat), &sin_phi, &cos_phi);
  n = prime_vertical_q36(sin_phi);
  e->z = drdc__geo_mul(drdc__geo_mul(n, GEO_ONE - GEO_E2) + h, sin_phi);
  n_plus_h = n + h;
  geo_sincos(geo_lon_rad(p->lon), &sin_lam, &cos_lam);
  e->x = drdc__geo_mul(n_plus_h, drdc__geo_mul(cos_phi, cos_lam));
  e->y = drdc__geo_mul(n_plus_h, drdc__geo_mul(cos_phi, sin_lam));
}

drdc_status_t drdc_geo_to_ecef(const drdc_geo_point_t *p,
                               drdc_vec3_q47_16_t *ecef)
{
  geo_ecef_q36_t e;
  drdc_status_t st;

  if ((p == NULL) || (ecef == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc__geo_check_point(p);
  if (st != DRDC_OK) {
    return st;
  }
  drdc__geo_ecef_q36(p, &e);
  ecef->x = drdc_fx_rshift_round_s64_inline(e.x, 20u);
  ecef->y = drdc_fx_rshift_round_s64_inline(e.y, 20u);
  ecef->z = drdc_fx_rshift_round_s64_inline(e.z, 20u);
  return DRDC_OK;
}

/* A point in its meridian plane, Q27.36 metres. */
typedef struct meridian_point {
  int64_t p; /* distance from the polar axis, >= 0 */
  int64_t z; /* distance from the equatorial plane */
} meridian_point_t;

/* A direction in the meridian plane: c away from the polar axis, s
 * northwards; the cosine and sine of its angle (Q5.58) once unit. */
typedef struct meridian_dir {
  int64_t c;
  int64_t s;
} meridian_dir_t;

/* |v| for |v| < 2^62 (Q27.36 lengths; drdc_geo_from_ecef() checks its
 * input without it) */
static int64_t abs_q36(int64_t v)
{
  return (v < 0) ? -v : v;
}

/* (*a, *b) scaled by one power of two so that the larger magnitude lies
 * in [2^57, 2^58) (a rounding right shift, or an exact left shift): both
 * then read as Q5.58 values below 1, and a vector keeps its direction.
 * Returns the shift: > 0 right, <= 0 left. |*a|, |*b| < 2^62, not both
 * zero. */
static int scale_to_q58(int64_t *a, int64_t *b)
{
  uint64_t ma = (uint64_t)abs_q36(*a);
  uint64_t mb = (uint64_t)abs_q36(*b);
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

/* hypot(x, y) (Q27.36) for (x, y) != (0, 0), |x|, |y| < 2^61: on the
 * scaled legs (a^2 + b^2 in [1/4, 2)) the length (a^2 + b^2) / sqrt(a^2
 * + b^2), scaled back. Relative error within 2^-56 (1e-10 m at the
 * Earth's radius), at a fifth of the cycles of drdc_fx_hypot_s64()'s
 * exact 128-bit root. The scaled length is below 2^58.5 and the result
 * below 2^61.5: no overflow either way. */
static int64_t hypot_q36(int64_t x, int64_t y)
{
  int64_t a = x;
  int64_t b = y;
  int shift = scale_to_q58(&a, &b);
  int64_t sum_sq = drdc__geo_mul(a, a) + drdc__geo_mul(b, b);
  int64_t len = drdc__geo_mul(sum_sq, rsqrt_q58(sum_sq));

  return (shift >= 0) ? (len * (int64_t)(UINT64_C(1) << (unsigned)shift))
                      : drdc_fx_rshift_round_s64_inline(len, (unsigned)-shift);
}

/* d scaled to unit length (Q5.58, each part within 3 LSB); d != (0, 0),
 * |d.c|, |d.s| < 2^61 */
static void unit(meridian_dir_t *d)
{
  int64_t inv_len;

  (void)scale_to_q58(&d->c, &d->s);
  inv_len = rsqrt_q58(drdc__geo_mul(d->c, d->c) + drdc__geo_mul(d->s, d->s));
  d->c = drdc__geo_mul(d->c, inv_len);
  d->s = drdc__geo_mul(d->s, inv_len);
}

/* The unit direction of the parametric latitude beta of the geodetic
 * direction phi: tan beta = (b / a) tan phi. */
static void parametric(const meridian_dir_t *phi, meridian_dir_t *beta)
{
  beta->c = phi->c;
  beta->s = drdc__geo_mul(phi->s, GEO_B_OVER_A);
  unit(beta);
}

/* Bowring's step: from the unit direction of the parametric latitude
 * beta, the direction of the geodetic latitude of m, (p - e^2 a cos^3
 * beta, z + e'^2 b sin^3 beta) (Q27.36, not unit). It converges
 * cubically; measured with mpmath from beta_0 = atan2(a z, b p): within
 * 8e-9 rad after one step, 1.4e-19 after two for heights -10 km .. 10 000
 * km, 2e-25 after two for any point at least 6 300 km from the centre,
 * 4e-27 after three for every accepted point. */
static void bowring_step(const meridian_point_t *m, const meridian_dir_t *beta,
                         meridian_dir_t *phi)
{
  phi->c = m->p - drdc__geo_mul(
                      GEO_E2A_Q36,
                      drdc__geo_mul(drdc__geo_mul(beta->c, beta->c), beta->c));
  phi->s = m->z + drdc__geo_mul(
                      GEO_EP2B_Q36,
                      drdc__geo_mul(drdc__geo_mul(beta->s, beta->s), beta->s));
}

/* h = p cos phi + z sin phi - a sqrt(1 - e^2 sin^2 phi) (Q27.36) at the
 * unit direction phi; stationary in phi at the true latitude, so an
 * error d of phi moves h by about N d^2 only. sqrt(w^2) = w^2 /
 * sqrt(w^2), w^2 in [1 - e^2, 1]. */
static int64_t height_q36(const meridian_point_t *m, const meridian_dir_t *phi)
{
  int64_t w2 = GEO_ONE - drdc__geo_mul(GEO_E2, drdc__geo_mul(phi->s, phi->s));

  return (drdc__geo_mul(m->p, phi->c) + drdc__geo_mul(m->z, phi->s)) -
         drdc__geo_mul(A_Q36, drdc__geo_mul(w2, rsqrt_q58(w2)));
}

/* The unit direction of the geodetic latitude of e into *phi and its
 * height (Q47.16) into *height, or DRDC_E_HEIGHT (see
 * drdc__geo_geodetic_q36()) */
static drdc_status_t latitude_and_height(const geo_ecef_q36_t *e,
                                         meridian_dir_t *phi,
                                         drdc_q47_16_t *height)
{
  meridian_point_t m;
  meridian_dir_t beta;
  int64_t h;

  m.p = 0;
  if ((e->x != 0) || (e->y != 0)) {
    m.p = hypot_q36(e->x, e->y);
  }
  m.z = e->z;
  if ((m.p < ECEF_CORE_Q36) && (abs_q36(m.z) < ECEF_CORE_Q36)) {
    return DRDC_E_HEIGHT;
  }
  /* tan beta_0 = a z / (b p) */
  beta.c = drdc__geo_mul(m.p, GEO_B_OVER_A);
  beta.s = m.z;
  unit(&beta);
  bowring_step(&m, &beta, phi);
  parametric(phi, &beta);
  bowring_step(&m, &beta, phi);
  unit(phi);
  h = height_q36(&m, phi);
  if (h < DEEP_Q36) {
    parametric(phi, &beta);
    bowring_step(&m, &beta, phi);
    unit(phi);
    h = height_q36(&m, phi);
  }
  h = drdc_fx_rshift_round_s64_inline(h, 20u);
  if ((h > DRDC_GEO_HEIGHT_MAX) || (h < -DRDC_GEO_HEIGHT_MAX)) {
    return DRDC_E_HEIGHT;
  }
  *height = h;
  return DRDC_OK;
}

/* The latitude's direction and the height, then the latitude from its
 * unit direction (never (0, 0), so atan2 always succeeds) and the
 * longitude (0 on the polar axis). drdc_fx_atan2_q5_58() scales its
 * arguments to [2^57, 2^58] itself, so the longitude is the same from
 * Q47.16 or Q27.36 coordinates. */
drdc_status_t drdc__geo_geodetic_q36(const geo_ecef_q36_t *e,
                                     drdc_geo_point_t *p)
{
  meridian_dir_t phi;
  drdc_q47_16_t height = 0;
  drdc_status_t st = latitude_and_height(e, &phi, &height);

  if (st != DRDC_OK) {
    return st;
  }
  p->lat = drdc__geo_nas_from_rad(geo_atan2(phi.s, phi.c));
  p->lon = 0;
  if ((e->x != 0) || (e->y != 0)) {
    p->lon = drdc__geo_nas_from_rad(geo_atan2(e->y, e->x));
  }
  p->height = height;
  return DRDC_OK;
}

drdc_status_t drdc_geo_from_ecef(const drdc_vec3_q47_16_t *ecef,
                                 drdc_geo_point_t *p)
{
  geo_ecef_q36_t e;

  if ((ecef == NULL) || (p == NULL)) {
    return DRDC_E_NULL;
  }
  /* each bound on both sides, with no negation of the coordinate
   * (-INT64_MIN overflows) */
  if ((ecef->x >= ECEF_COORD_MAX) || (ecef->x <= -ECEF_COORD_MAX) ||
      (ecef->y >= ECEF_COORD_MAX) || (ecef->y <= -ECEF_COORD_MAX) ||
      (ecef->z >= ECEF_COORD_MAX) || (ecef->z <= -ECEF_COORD_MAX)) {
    return DRDC_E_HEIGHT;
  }
  e.x = ecef->x * GEO_Q36_PER_Q16;
  e.y = ecef->y * GEO_Q36_PER_Q16;
  e.z = ecef->z * GEO_Q36_PER_Q16;
  return drdc__geo_geodetic_q36(&e, p);
}
