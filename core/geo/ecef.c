/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Geodetic <-> ECEF on WGS-84 and the ENU / NED tangent planes.
 *
 * Forward: N = a / sqrt(1 - e^2 sin^2 phi), X = (N + h) cos phi cos lam,
 * Y = (N + h) cos phi sin lam, Z = (N (1 - e^2) + h) sin phi. Inverse:
 * phi = atan2(Z + e^2 N sin phi, p) iterated 8 times from
 * atan2(Z, p (1 - e^2)) (the error shrinks by e^2 N / (N + h) <= 0.0067 a
 * step), h = p cos phi + Z sin phi - a sqrt(1 - e^2 sin^2 phi). Lengths
 * are carried in Q27.36 inside (20 more bits than Q47.16), so p = hypot(X,
 * Y) and the local rotations lose nothing to the output rounding.
 */
#include <drdc/geo_ecef.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>
#include <drdc/fixed_sqrt.h>

#include "geo_impl.h"

/** a = 6 378 137 m in Q27.36. */
#define A_Q36 (INT64_C(6378137) * INT64_C(68719476736))
/** 2^20: Q47.16 -> Q27.36. */
#define Q36_PER_Q16 INT64_C(1048576)
/** Inputs of the inverse: |X|, |Y|, |Z| below 2^41 Q47.16 (33 554 km). */
#define ECEF_COORD_MAX INT64_C(2199023255552)
/** Within this of the centre (on both p and |Z|) there is no useful
 *  geodetic position: 1 000 km. */
#define ECEF_CORE (INT64_C(1000000) * INT64_C(65536))

static drdc_status_t check_point(const drdc_geo_point_t *p)
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

/* sin/cos of latitude and longitude of a checked point */
typedef struct trig4 {
  int64_t sphi;
  int64_t cphi;
  int64_t slam;
  int64_t clam;
} trig4_t;

static void point_trig(const drdc_geo_point_t *p, trig4_t *t)
{
  /* |lon| < 540 degrees: reduce by whole turns to +-180 first */
  drdc_nas_t lon = p->lon;

  if (lon >= (180 * GEO_NAS_DEG)) {
    lon = lon - (360 * GEO_NAS_DEG);
  } else if (lon < (-180 * GEO_NAS_DEG)) {
    lon = lon + (360 * GEO_NAS_DEG);
  } else {
    /* in range */
  }
  geo_sincos(geo_rad_from_nas(p->lat), &t->sphi, &t->cphi);
  geo_sincos(geo_rad_from_nas(lon), &t->slam, &t->clam);
}

/* ECEF of a checked point in Q27.36 */
static void ecef_q36(const drdc_geo_point_t *p, int64_t *x, int64_t *y,
                     int64_t *z)
{
  trig4_t t;
  int64_t w;
  int64_t n;
  int64_t h = p->height * Q36_PER_Q16;

  point_trig(p, &t);
  w = geo_sqrt(GEO_ONE - geo_mul(GEO_E2, geo_mul(t.sphi, t.sphi)));
  n = geo_div(A_Q36, w);
  *x = geo_mul(n + h, geo_mul(t.cphi, t.clam));
  *y = geo_mul(n + h, geo_mul(t.cphi, t.slam));
  *z = geo_mul(geo_mul(n, GEO_ONE - GEO_E2) + h, t.sphi);
}

drdc_status_t drdc_geo_to_ecef(const drdc_geo_point_t *p,
                               drdc_vec3_q47_16_t *ecef)
{
  drdc_status_t st;
  int64_t x = 0;
  int64_t y = 0;
  int64_t z = 0;

  if ((p == NULL) || (ecef == NULL)) {
    return DRDC_E_NULL;
  }
  st = check_point(p);
  if (st != DRDC_OK) {
    return st;
  }
  ecef_q36(p, &x, &y, &z);
  ecef->x = drdc_fx_rshift_round_s64(x, 20u);
  ecef->y = drdc_fx_rshift_round_s64(y, 20u);
  ecef->z = drdc_fx_rshift_round_s64(z, 20u);
  return DRDC_OK;
}

static int64_t ecef_abs64(int64_t v)
{
  return (v < 0) ? -v : v;
}

/* geodetic of ECEF in Q27.36 (|x|, |y|, |z| < 2^61) */
static drdc_status_t geodetic_q36(int64_t x, int64_t y, int64_t z,
                                  drdc_geo_point_t *out)
{
  int64_t p = (int64_t)drdc_fx_hypot_s64(x, y);
  int64_t phi;
  int64_t sphi = 0;
  int64_t cphi = 0;
  int64_t w;
  int64_t h;
  unsigned i;

  if ((p < (ECEF_CORE * Q36_PER_Q16)) && (ecef_abs64(z) < (ECEF_CORE * Q36_PER_Q16))) {
    return DRDC_E_HEIGHT;
  }
  phi = geo_atan2(z, geo_mul(p, GEO_ONE - GEO_E2));
  for (i = 0u; i < 8u; i++) {
    geo_sincos(phi, &sphi, &cphi);
    w = geo_sqrt(GEO_ONE - geo_mul(GEO_E2, geo_mul(sphi, sphi)));
    phi = geo_atan2(z + geo_mul(geo_div(A_Q36, w), geo_mul(GEO_E2, sphi)),
                    p);
  }
  geo_sincos(phi, &sphi, &cphi);
  w = geo_sqrt(GEO_ONE - geo_mul(GEO_E2, geo_mul(sphi, sphi)));
  h = (geo_mul(p, cphi) + geo_mul(z, sphi)) - geo_mul(A_Q36, w);
  h = drdc_fx_rshift_round_s64(h, 20u);
  if ((h > DRDC_GEO_HEIGHT_MAX) || (h < -DRDC_GEO_HEIGHT_MAX)) {
    return DRDC_E_HEIGHT;
  }
  out->lat = geo_nas_from_rad(phi);
  out->lon = ((x == 0) && (y == 0)) ? 0 : geo_nas_from_rad(geo_atan2(y, x));
  out->height = h;
  return DRDC_OK;
}

drdc_status_t drdc_geo_from_ecef(const drdc_vec3_q47_16_t *ecef,
                                 drdc_geo_point_t *p)
{
  if ((ecef == NULL) || (p == NULL)) {
    return DRDC_E_NULL;
  }
  if ((ecef_abs64(ecef->x) >= ECEF_COORD_MAX) || (ecef_abs64(ecef->y) >= ECEF_COORD_MAX)
      || (ecef_abs64(ecef->z) >= ECEF_COORD_MAX)) {
    return DRDC_E_HEIGHT;
  }
  return geodetic_q36(ecef->x * Q36_PER_Q16, ecef->y * Q36_PER_Q16,
                      ecef->z * Q36_PER_Q16, p);
}

/* ENU of p at ref, Q47.16 */
static drdc_status_t enu_q16(const drdc_geo_point_t *ref,
                             const drdc_geo_point_t *p, int64_t *e,
                             int64_t *n, int64_t *u)
{
  drdc_status_t st;
  trig4_t t;
  int64_t x0 = 0;
  int64_t y0 = 0;
  int64_t z0 = 0;
  int64_t x1 = 0;
  int64_t y1 = 0;
  int64_t z1 = 0;
  int64_t dx;
  int64_t dy;
  int64_t dz;

  st = check_point(ref);
  if (st == DRDC_OK) {
    st = check_point(p);
  }
  if (st != DRDC_OK) {
    return st;
  }
  ecef_q36(ref, &x0, &y0, &z0);
  ecef_q36(p, &x1, &y1, &z1);
  dx = x1 - x0;
  dy = y1 - y0;
  dz = z1 - z0;
  point_trig(ref, &t);
  *e = drdc_fx_rshift_round_s64(geo_mul(dy, t.clam) - geo_mul(dx, t.slam),
                                20u);
  *n = drdc_fx_rshift_round_s64(
    (geo_mul(dz, t.cphi)
     - geo_mul(geo_mul(dx, t.clam) + geo_mul(dy, t.slam), t.sphi)),
    20u);
  *u = drdc_fx_rshift_round_s64(
    (geo_mul(dz, t.sphi)
     + geo_mul(geo_mul(dx, t.clam) + geo_mul(dy, t.slam), t.cphi)),
    20u);
  return DRDC_OK;
}

static bool fits_q15_16(int64_t v)
{
  return (v <= (int64_t)INT32_MAX) && (v >= (int64_t)INT32_MIN);
}

drdc_status_t drdc_geo_to_enu(const drdc_geo_point_t *ref,
                              const drdc_geo_point_t *p,
                              drdc_vec3_q15_16_t *enu)
{
  drdc_status_t st;
  int64_t e = 0;
  int64_t n = 0;
  int64_t u = 0;

  if ((ref == NULL) || (p == NULL) || (enu == NULL)) {
    return DRDC_E_NULL;
  }
  st = enu_q16(ref, p, &e, &n, &u);
  if (st != DRDC_OK) {
    return st;
  }
  if (!fits_q15_16(e) || !fits_q15_16(n) || !fits_q15_16(u)) {
    return DRDC_E_OVERFLOW;
  }
  enu->x = (drdc_q15_16_t)e;
  enu->y = (drdc_q15_16_t)n;
  enu->z = (drdc_q15_16_t)u;
  return DRDC_OK;
}

drdc_status_t drdc_geo_to_ned(const drdc_geo_point_t *ref,
                              const drdc_geo_point_t *p,
                              drdc_vec3_q15_16_t *ned)
{
  drdc_status_t st;
  int64_t e = 0;
  int64_t n = 0;
  int64_t u = 0;

  if ((ref == NULL) || (p == NULL) || (ned == NULL)) {
    return DRDC_E_NULL;
  }
  st = enu_q16(ref, p, &e, &n, &u);
  if (st != DRDC_OK) {
    return st;
  }
  if (!fits_q15_16(e) || !fits_q15_16(n) || !fits_q15_16(-u)) {
    return DRDC_E_OVERFLOW;
  }
  ned->x = (drdc_q15_16_t)n;
  ned->y = (drdc_q15_16_t)e;
  ned->z = (drdc_q15_16_t)(-u);
  return DRDC_OK;
}

/* geodetic of ENU (e, n, u in Q15.16 as int64) at a checked ref */
static drdc_status_t from_enu_q16(const drdc_geo_point_t *ref, int64_t e,
                                  int64_t n, int64_t u, drdc_geo_point_t *p)
{
  trig4_t t;
  int64_t x0 = 0;
  int64_t y0 = 0;
  int64_t z0 = 0;
  int64_t e36 = e * Q36_PER_Q16;
  int64_t n36 = n * Q36_PER_Q16;
  int64_t u36 = u * Q36_PER_Q16;
  /* the horizontal part towards the ref's meridian plane */
  int64_t r;

  ecef_q36(ref, &x0, &y0, &z0);
  point_trig(ref, &t);
  r = geo_mul(u36, t.cphi) - geo_mul(n36, t.sphi);
  return geodetic_q36(x0 + (geo_mul(r, t.clam) - geo_mul(e36, t.slam)),
                      y0 + (geo_mul(r, t.slam) + geo_mul(e36, t.clam)),
                      z0 + (geo_mul(n36, t.cphi) + geo_mul(u36, t.sphi)), p);
}

drdc_status_t drdc_geo_from_enu(const drdc_geo_point_t *ref,
                                const drdc_vec3_q15_16_t *enu,
                                drdc_geo_point_t *p)
{
  drdc_status_t st;

  if ((ref == NULL) || (enu == NULL) || (p == NULL)) {
    return DRDC_E_NULL;
  }
  st = check_point(ref);
  if (st != DRDC_OK) {
    return st;
  }
  return from_enu_q16(ref, enu->x, enu->y, enu->z, p);
}

drdc_status_t drdc_geo_from_ned(const drdc_geo_point_t *ref,
                                const drdc_vec3_q15_16_t *ned,
                                drdc_geo_point_t *p)
{
  drdc_status_t st;

  if ((ref == NULL) || (ned == NULL) || (p == NULL)) {
    return DRDC_E_NULL;
  }
  st = check_point(ref);
  if (st != DRDC_OK) {
    return st;
  }
  return from_enu_q16(ref, ned->y, ned->x, -(int64_t)ned->z, p);
}
