/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Baselines in double precision: each computation of a timed
 *        library function as a competent engineer writes it in double,
 *        compiled with soft-float and newlib's libm (arm-cm3 only:
 *        Debian's PowerPC libgcc has no soft-float routines). Never
 *        linked into the library.
 *
 * Fairness rules, the same for every baseline:
 * - the operands are converted to double before any timing (the tables
 *   below, from those of operands.h): the timed loop holds the call;
 * - the function is called, not inlined into the loop, with operands and
 *   results through pointers, like the library's;
 * - as few libm calls, divisions and square roots as the computation
 *   allows: angle sums and double angles from products, hyperbolic
 *   functions from one tanh or exp, one square root where two roots
 *   multiply, Clenshaw summation for the Krueger and conformal-latitude
 *   series as GeographicLib does, multiplications by constants rather
 *   than divisions;
 * - results folded into the loop's word by their bits, not by a
 *   soft-float addition;
 * - bench_check_baselines() compares every baseline's outputs with the
 *   library's on all the inputs before timing and prints the worst
 *   difference against the library's documented accuracy; tools/gates/bench.py
 *   fails when one is beyond it.
 */
#include "operands.h"

#if BENCH_DOUBLE
#include <math.h>
#include <string.h>

#include "console.h"
#include "drdc_board.h"

/* called, never inlined, cloned or specialised to its call site */
#define NOINLINE __attribute__((noipa))

typedef struct dquat {
  double s, x, y, z;
} dquat_t;

typedef struct dvec3 {
  double x, y, z;
} dvec3_t;

typedef struct deuler {
  double yaw, pitch, roll; /* radians */
} deuler_t;

typedef struct dgrid {
  int zone;
  int north;
  double easting, northing; /* metres */
  double convergence;       /* degrees */
  double scale;
} dgrid_t;

typedef struct dgeodetic {
  double lat, lon; /* degrees */
  double height;   /* metres */
} dgeodetic_t;

typedef struct dgps {
  double week, tow;
} dgps_t;

/* the operands of operands.h in double, made before timing */
static dquat_t dqa[BENCH_INPUTS];
static dquat_t dqb[BENCH_INPUTS];
static dvec3_t dvec[BENCH_INPUTS];
static deuler_t deuler[BENCH_INPUTS];
static double dutm_lat[BENCH_INPUTS]; /* degrees */
static double dutm_lon[BENCH_INPUTS];
static dgrid_t dutm[BENCH_INPUTS];
static dgeodetic_t dgeodetic[BENCH_INPUTS];
static dvec3_t decef[BENCH_INPUTS];
static double dinstant[BENCH_INPUTS]; /* Unix seconds */
static dgps_t dgps[BENCH_INPUTS];

#define TWO_POW_16     65536.0
#define TWO_POW_30     1073741824.0
#define TWO_POW_32     4294967296.0
#define TWO_POW_58     288230376151711744.0
#define NAS_PER_DEGREE 3.6e12
#define PI             3.14159265358979323846
#define DEG            (PI / 180.0)
#define DEG_PER_RAD    (180.0 / PI)

static uint32_t fold(double v)
{
  uint64_t bits;

  memcpy(&bits, &v, sizeof bits);
  return (uint32_t)bits ^ (uint32_t)(bits >> 32);
}

/* ---- time: Unix seconds with fraction in one double ---- */

/* Unix seconds of the first second with each new TAI - UTC after 1980 */
static const double leaps[] = {
    362793600.0,  394329600.0,  425865600.0,  489024000.0,  567993600.0,
    631152000.0,  662688000.0,  709948800.0,  741484800.0,  773020800.0,
    820454400.0,  867715200.0,  915148800.0,  1136073600.0, 1230768000.0,
    1341100800.0, 1435708800.0, 1483228800.0,
};
#define LEAPS          (sizeof leaps / sizeof leaps[0])
#define GPS_EPOCH_UNIX 315964800.0
#define WEEK           604800.0

/* UTC (Unix seconds with fraction) -> GPS week and seconds of week: the
 * leap seconds counted by a binary search of the table */
static NOINLINE void utc_to_gps_d(double unix_seconds, dgps_t *out)
{
  unsigned lo = 0u;
  unsigned hi = LEAPS;
  double s;

  while (lo < hi) {
    unsigned mid = (lo + hi) / 2u;

    if (unix_seconds >= leaps[mid]) {
      lo = mid + 1u;
    } else {
      hi = mid;
    }
  }
  s = unix_seconds - GPS_EPOCH_UNIX + (double)lo;
  out->week = floor(s / WEEK);
  out->tow = s - (out->week * WEEK);
}

/* GPS seconds of the first second after each leap: leaps[i] plus the
 * i + 1 leap seconds GPS has counted by then */
static double gps_leaps[LEAPS];

static NOINLINE double gps_to_utc_d(const dgps_t *gps)
{
  double g = (gps->week * WEEK) + gps->tow;
  unsigned lo = 0u;
  unsigned hi = LEAPS;

  while (lo < hi) {
    unsigned mid = (lo + hi) / 2u;

    if (g >= gps_leaps[mid]) {
      lo = mid + 1u;
    } else {
      hi = mid;
    }
  }
  return g + GPS_EPOCH_UNIX - (double)lo;
}

/* ---- orientation ---- */

static NOINLINE void quat_mul_d(const dquat_t *a, const dquat_t *b, dquat_t *r)
{
  r->s = a->s * b->s - a->x * b->x - a->y * b->y - a->z * b->z;
  r->x = a->s * b->x + a->x * b->s + a->y * b->z - a->z * b->y;
  r->y = a->s * b->y - a->x * b->z + a->y * b->s + a->z * b->x;
  r->z = a->s * b->z + a->x * b->y - a->y * b->x + a->z * b->s;
}

/* R(q / |q|) v = v + s t + u x t with t = (2 / |q|^2) u x v: one
 * division, no square root */
static NOINLINE void quat_rotate_d(const dquat_t *q, const dvec3_t *v,
                                   dvec3_t *r)
{
  double k = 2.0 / (q->s * q->s + q->x * q->x + q->y * q->y + q->z * q->z);
  double tx = k * (q->y * v->z - q->z * v->y);
  double ty = k * (q->z * v->x - q->x * v->z);
  double tz = k * (q->x * v->y - q->y * v->x);

  r->x = v->x + q->s * tx + (q->y * tz - q->z * ty);
  r->y = v->y + q->s * ty + (q->z * tx - q->x * tz);
  r->z = v->z + q->s * tz + (q->x * ty - q->y * tx);
}

/* yaw-pitch-roll (z-y-x) to the quaternion q_yaw q_pitch q_roll */
static NOINLINE void euler_to_quat_d(const deuler_t *e, dquat_t *q)
{
  double cy = cos(0.5 * e->yaw), sy = sin(0.5 * e->yaw);
  double cp = cos(0.5 * e->pitch), sp = sin(0.5 * e->pitch);
  double cr = cos(0.5 * e->roll), sr = sin(0.5 * e->roll);

  double cc = cp * cy, ss = sp * sy, cs = cp * sy, sc = sp * cy;

  q->s = cr * cc + sr * ss;
  q->x = sr * cc - cr * ss;
  q->y = cr * sc + sr * cs;
  q->z = cr * cs - sr * sc;
}

/* the angles of q / |q|: the squared norm only where the formula needs
 * a unit quaternion (the pitch's sine) */
static NOINLINE void quat_to_euler_d(const dquat_t *q, deuler_t *e)
{
  double ss = q->s * q->s, xx = q->x * q->x, yy = q->y * q->y, zz = q->z * q->z;
  double sp = 2.0 * (q->s * q->y - q->z * q->x) / (ss + xx + yy + zz);

  e->yaw = atan2(2.0 * (q->s * q->z + q->x * q->y), ss + xx - yy - zz);
  e->pitch = asin((sp > 1.0) ? 1.0 : ((sp < -1.0) ? -1.0 : sp));
  e->roll = atan2(2.0 * (q->s * q->x + q->y * q->z), ss - xx - yy + zz);
}

/* ---- geodesy: WGS-84 ---- */

#define WGS84_A  6378137.0
#define WGS84_F  (1.0 / 298.257223563)
#define WGS84_E2 (WGS84_F * (2.0 - WGS84_F))
#define WGS84_N  (WGS84_F / (2.0 - WGS84_F))
#define UTM_K0   0.9996
/* rectifying radius A = a / (1 + n) (1 + n^2/4 + n^4/64 + n^6/256) */
#define WGS84_RECT                                                             \
  (WGS84_A / (1.0 + WGS84_N) *                                                 \
   (1.0 + WGS84_N * WGS84_N / 4.0 +                                            \
    WGS84_N * WGS84_N * WGS84_N * WGS84_N / 64.0 +                             \
    WGS84_N * WGS84_N * WGS84_N * WGS84_N * WGS84_N * WGS84_N / 256.0))

/* Krueger's series to 6th order in n for WGS-84 (Karney 2011, "Transverse
 * Mercator with an accuracy of a few nanometers", eqs. 35-36) and the
 * conformal latitude's (chi - phi, phi - chi), sin(2 j x) coefficients */
static const double alpha[6] = {8.3773182062446896e-04, 7.6085277735810086e-07,
                                1.1976455036033506e-09, 2.4291714473267945e-12,
                                5.7107096829156490e-15, 1.3877787807814457e-17};
static const double beta[6] = {8.3773216405794854e-04, 5.9058701522979318e-08,
                               1.6734826718822760e-10, 2.1647961201409771e-13,
                               3.7816971776294395e-16, 0.0};
static const double chi_from_phi[6] = {
    -3.3565546197974264e-03, 4.6945730271634456e-06,  -8.1944975457992619e-09,
    1.5579967871381939e-11,  -3.1034202985225079e-14, 6.2450045135165055e-17};
static const double phi_from_chi[7] = {
    3.3565514691328326e-03, 6.5718731986283419e-06, 1.7646404112253711e-08,
    5.3877541317248756e-11, 1.7639709137817761e-13, 6.0368376963992887e-16,
    3.4694469519536142e-18};

/* sum c[j] sin(2 (j+1) x) from sin 2x, cos 2x by Clenshaw's recurrence */
static double sine_series(const double *c, int terms, double s2, double c2)
{
  double b1 = 0.0, b2 = 0.0;
  int j;

  for (j = terms - 1; j >= 0; j--) {
    double b0 = c[j] + 2.0 * c2 * b1 - b2;

    b2 = b1;
    b1 = b0;
  }
  return s2 * b1;
}

/* Krueger's sum over zeta = xi + i eta by Clenshaw's recurrence in
 * complex arithmetic, from sin and cos of 2 xi and sinh and cosh of
 * 2 eta: sum c_j sin(2 j zeta) into (*dxi, *deta) and its derivative
 * 1 + sum 2 j sign c_j cos(2 j zeta) into (*p, *q) = p - i q; sign is +1
 * forward (alpha), -1 reverse (beta) */
typedef struct twice {
  double s2, c2;   /* sin 2 xi, cos 2 xi */
  double sh2, ch2; /* sinh 2 eta, cosh 2 eta */
} twice_t;

static void krueger(const double *c, double sign, const twice_t *w, double *dxi,
                    double *deta, double *p, double *q)
{
  double ar = 2.0 * w->c2 * w->ch2,
         ai = -2.0 * w->s2 * w->sh2; /* 2 cos 2 zeta */
  double yr0 = 0.0, yi0 = 0.0, yr1 = 0.0, yi1 = 0.0;
  double zr0 = 0.0, zi0 = 0.0, zr1 = 0.0, zi1 = 0.0;
  double sr = w->s2 * w->ch2, si = w->c2 * w->sh2; /* sin 2 zeta */
  int j;

  for (j = 6; j >= 1; j--) {
    double cj = sign * c[j - 1];
    double yr = ar * yr0 - ai * yi0 - yr1 + cj;
    double yi = ar * yi0 + ai * yr0 - yi1;
    double zr = ar * zr0 - ai * zi0 - zr1 + 2.0 * j * cj;
    double zi = ar * zi0 + ai * zr0 - zi1;

    yr1 = yr0;
    yi1 = yi0;
    yr0 = yr;
    yi0 = yi;
    zr1 = zr0;
    zi1 = zi0;
    zr0 = zr;
    zi0 = zi;
  }
  *dxi = sr * yr0 - si * yi0;
  *deta = sr * yi0 + si * yr0;
  /* 1 + cos(2 zeta) b'_1 - b'_2 */
  *p = 1.0 + 0.5 * (ar * zr0 - ai * zi0) - zr1;
  *q = -(0.5 * (ar * zi0 + ai * zr0) - zi1);
}

/* sin and cos of x + d from those of x for |d| < 0.004 (the conformal
 * latitude's correction): Taylor to d^6, then the addition theorems */
static void rotate_small(double s, double c, double d, double *s_out,
                         double *c_out)
{
  double d2 = d * d;
  double sd = d * (1.0 - d2 * (1.0 / 6.0 - d2 * (1.0 / 120.0)));
  double cd = 1.0 - d2 * (0.5 - d2 * (1.0 / 24.0 - d2 * (1.0 / 720.0)));

  *s_out = s * cd + c * sd;
  *c_out = c * cd - s * sd;
}

/* UTM zone of a point, with the Norway and Svalbard exceptions */
static int utm_zone_d(double lat, double lon)
{
  int zone = (int)floor((lon + 180.0) / 6.0) + 1;

  if (zone > 60) {
    zone = 1;
  }
  if ((lat >= 56.0) && (lat < 64.0) && (lon >= 3.0) && (lon < 12.0)) {
    zone = 32;
  }
  if ((lat >= 72.0) && (lon >= 0.0) && (lon < 42.0)) {
    zone = (lon < 9.0) ? 31 : (lon < 21.0) ? 33 : (lon < 33.0) ? 35 : 37;
  }
  return zone;
}

#define K0A (UTM_K0 * WGS84_RECT)

/* geographic (degrees) -> UTM in its standard zone, with convergence
 * (degrees) and scale: the computation of drdc_geo_to_utm(). libm: sin
 * and cos of phi and of lambda, atan2 for xi', log for eta' = atanh,
 * atan2 for the convergence, one square root for the scale (7 calls);
 * chi's sine and cosine by a small rotation from phi's, the double
 * angles of xi' and eta' from products of tanh eta' = cos chi sin lam */
static NOINLINE void utm_forward_d(double lat, double lon, dgrid_t *out)
{
  int zone = utm_zone_d(lat, lon);
  double lam = (lon - (6.0 * zone - 183.0)) * DEG;
  double phi = lat * DEG;
  double sphi = sin(phi), cphi = cos(phi);
  double dchi = sine_series(chi_from_phi, 6, 2.0 * sphi * cphi,
                            cphi * cphi - sphi * sphi);
  double schi, cchi, slam = sin(lam), clam = cos(lam);
  double t, u, xip, etap, dxi, deta, p, q;
  twice_t w;

  rotate_small(sphi, cphi, dchi, &schi, &cchi);
  t = cchi * slam;         /* tanh eta' */
  u = 1.0 / (1.0 - t * t); /* cosh^2 eta' */
  xip = atan2(schi, cchi * clam);
  etap = 0.5 * log((1.0 + t) / (1.0 - t));
  /* sin xi' = sin chi cosh eta', cos xi' = cos chi cos lam cosh eta' */
  w.s2 = 2.0 * schi * cchi * clam * u;
  w.c2 = (cchi * cchi * clam * clam - schi * schi) * u;
  w.sh2 = 2.0 * t * u;
  w.ch2 = (1.0 + t * t) * u;
  krueger(alpha, 1.0, &w, &dxi, &deta, &p, &q);
  out->zone = zone;
  out->north = lat >= 0.0;
  out->easting = 500000.0 + K0A * (etap + deta);
  out->northing = K0A * (xip + dxi) + (lat < 0.0 ? 1e7 : 0.0);
  /* arg((cos lam + i sin chi sin lam) (p + i q)) */
  out->convergence =
      atan2(schi * slam * p + clam * q, clam * p - schi * slam * q) *
      DEG_PER_RAD;
  /* k0 A / a sqrt(1 - e^2 sin^2 phi) (cos chi / cos phi) cosh eta' |p + i q|,
   * the roots as one */
  out->scale = (K0A / WGS84_A) * (cchi / cphi) *
               sqrt((1.0 - WGS84_E2 * sphi * sphi) * (p * p + q * q) * u);
}

/* UTM -> geographic (degrees) with convergence and scale: the
 * computation of drdc_geo_from_utm(). libm: sin and cos of 2 xi, exp of
 * 2 eta and of eta', sin and cos of xi', atan2 for chi and lambda, one
 * square root for cos chi and one for the scale, atan2 for the
 * convergence (10 calls); phi's sine and cosine by a small rotation from
 * chi's */
static NOINLINE void utm_reverse_d(const dgrid_t *in, dgeodetic_t *out,
                                   double *convergence, double *scale)
{
  double xi = (in->northing - (in->north ? 0.0 : 1e7)) * (1.0 / K0A);
  double eta = (in->easting - 500000.0) * (1.0 / K0A);
  double e2 = exp(2.0 * eta), ie2 = 1.0 / e2;
  double dxi, deta, p, q, ep, iep, shp, chp, sxip, cxip, r, chi, dphi;
  double schi, cchi, sphi, cphi;
  twice_t w;

  w.s2 = sin(2.0 * xi);
  w.c2 = cos(2.0 * xi);
  w.sh2 = 0.5 * (e2 - ie2);
  w.ch2 = 0.5 * (e2 + ie2);
  krueger(beta, -1.0, &w, &dxi, &deta, &p, &q);
  ep = exp(eta + deta);
  iep = 1.0 / ep;
  shp = 0.5 * (ep - iep);
  chp = 0.5 * (ep + iep);
  sxip = sin(xi + dxi);
  cxip = cos(xi + dxi);
  /* sin chi = sin xi' / cosh eta', cos chi = hypot(sinh eta', cos xi') /
   * cosh eta' */
  r = sqrt(shp * shp + cxip * cxip);
  chi = atan2(sxip, r);
  schi = sxip / chp;
  cchi = r / chp;
  dphi = sine_series(phi_from_chi, 7, 2.0 * schi * cchi,
                     cchi * cchi - schi * schi);
  rotate_small(schi, cchi, dphi, &sphi, &cphi);
  out->lat = (chi + dphi) * DEG_PER_RAD;
  out->lon = (6.0 * in->zone - 183.0) + atan2(shp, cxip) * DEG_PER_RAD;
  out->height = 0.0;
  /* arg((cos xi' cosh eta' + i sin xi' sinh eta') (p - i q)): the
   * sphere's convergence less the series' */
  *convergence =
      atan2(sxip * shp * p - cxip * chp * q, cxip * chp * p + sxip * shp * q) *
      DEG_PER_RAD;
  *scale = (K0A / WGS84_A) * (cchi / cphi) * chp *
           sqrt((1.0 - WGS84_E2 * sphi * sphi) / (p * p + q * q));
}

static NOINLINE void ecef_forward_d(const dgeodetic_t *g, dvec3_t *out)
{
  double sp = sin(g->lat * DEG), cp = cos(g->lat * DEG);
  double sl = sin(g->lon * DEG), cl = cos(g->lon * DEG);
  double n = WGS84_A / sqrt(1.0 - WGS84_E2 * sp * sp);

  out->x = (n + g->height) * cp * cl;
  out->y = (n + g->height) * cp * sl;
  out->z = (n * (1.0 - WGS84_E2) + g->height) * sp;
}

/* ECEF -> geodetic by Bowring's iteration, two steps, as
 * drdc_geo_from_ecef() */
static NOINLINE void ecef_reverse_d(const dvec3_t *e, dgeodetic_t *out)
{
  const double bova = 1.0 - WGS84_F;
  const double e2a = WGS84_E2 * WGS84_A;
  const double ep2b = WGS84_E2 * WGS84_A / bova;
  double p = sqrt(e->x * e->x + e->y * e->y);
  double u = p * bova, v = e->z, ir, c, s;
  int i;

  for (i = 0; i < 2; i++) {
    ir = 1.0 / sqrt(u * u + v * v);
    c = u * ir;
    s = v * ir;
    u = p - (e2a * c * c * c);
    v = e->z + (ep2b * s * s * s);
    if (i == 0) {
      v = v * bova;
    }
  }
  ir = 1.0 / sqrt(u * u + v * v);
  c = u * ir;
  s = v * ir;
  out->lat = atan2(v, u) * DEG_PER_RAD;
  out->lon = atan2(e->y, e->x) * DEG_PER_RAD;
  out->height = (p * c) + (e->z * s) - WGS84_A * sqrt(1.0 - WGS84_E2 * s * s);
}

/* ---- the timed calls ---- */

static uint32_t utc_to_gps_case(uint32_t k)
{
  dgps_t g;

  utc_to_gps_d(dinstant[k], &g);
  return fold(g.week) ^ fold(g.tow);
}

static uint32_t gps_to_utc_case(uint32_t k)
{
  return fold(gps_to_utc_d(&dgps[k]));
}

static uint32_t quat_mul_case(uint32_t k)
{
  dquat_t r;

  quat_mul_d(&dqa[k], &dqb[k], &r);
  return fold(r.s) ^ fold(r.x) ^ fold(r.y) ^ fold(r.z);
}

static uint32_t quat_rotate_case(uint32_t k)
{
  dvec3_t r;

  quat_rotate_d(&dqa[k], &dvec[k], &r);
  return fold(r.x) ^ fold(r.y) ^ fold(r.z);
}

static uint32_t euler_to_quat_case(uint32_t k)
{
  dquat_t q;

  euler_to_quat_d(&deuler[k], &q);
  return fold(q.s) ^ fold(q.x) ^ fold(q.y) ^ fold(q.z);
}

static uint32_t quat_to_euler_case(uint32_t k)
{
  deuler_t e;

  quat_to_euler_d(&dqa[k], &e);
  return fold(e.yaw) ^ fold(e.pitch) ^ fold(e.roll);
}

static uint32_t utm_forward_case(uint32_t k)
{
  dgrid_t g;

  utm_forward_d(dutm_lat[k], dutm_lon[k], &g);
  return fold(g.easting) ^ fold(g.northing) ^ fold(g.convergence) ^
         fold(g.scale);
}

static uint32_t utm_reverse_case(uint32_t k)
{
  dgeodetic_t g;
  double convergence, scale;

  utm_reverse_d(&dutm[k], &g, &convergence, &scale);
  return fold(g.lat) ^ fold(g.lon) ^ fold(convergence) ^ fold(scale);
}

static uint32_t ecef_forward_case(uint32_t k)
{
  dvec3_t e;

  ecef_forward_d(&dgeodetic[k], &e);
  return fold(e.x) ^ fold(e.y) ^ fold(e.z);
}

static uint32_t ecef_reverse_case(uint32_t k)
{
  dgeodetic_t g;

  ecef_reverse_d(&decef[k], &g);
  return fold(g.lat) ^ fold(g.lon) ^ fold(g.height);
}

BENCH_LOOP(run_utc_to_gps, utc_to_gps_case(k))
BENCH_LOOP(run_gps_to_utc, gps_to_utc_case(k))
BENCH_LOOP(run_quat_mul, quat_mul_case(k))
BENCH_LOOP(run_quat_rotate, quat_rotate_case(k))
BENCH_LOOP(run_euler_to_quat, euler_to_quat_case(k))
BENCH_LOOP(run_quat_to_euler, quat_to_euler_case(k))
BENCH_LOOP(run_utm_forward, utm_forward_case(k))
BENCH_LOOP(run_utm_reverse, utm_reverse_case(k))
BENCH_LOOP(run_ecef_forward, ecef_forward_case(k))
BENCH_LOOP(run_ecef_reverse, ecef_reverse_case(k))

const bench_case_t bench_cases_double[] = {
    {"utc_to_gps", "double", "utc_to_gps_d", run_utc_to_gps},
    {"gps_to_utc", "double", "gps_to_utc_d", run_gps_to_utc},
    {"quat_mul", "double", "quat_mul_d", run_quat_mul},
    {"quat_rotate", "double", "quat_rotate_d", run_quat_rotate},
    {"euler_to_quat", "double", "euler_to_quat_d", run_euler_to_quat},
    {"quat_to_euler", "double", "quat_to_euler_d", run_quat_to_euler},
    {"utm_forward", "double", "utm_forward_d", run_utm_forward},
    {"utm_reverse", "double", "utm_reverse_d", run_utm_reverse},
    {"ecef_forward", "double", "ecef_forward_d", run_ecef_forward},
    {"ecef_reverse", "double", "ecef_reverse_d", run_ecef_reverse},
    {0, 0, 0, 0},
};

static dquat_t dquat_of(const drdc_quat_t *q)
{
  dquat_t d;

  d.s = q->s / TWO_POW_30;
  d.x = q->x / TWO_POW_30;
  d.y = q->y / TWO_POW_30;
  d.z = q->z / TWO_POW_30;
  return d;
}

/* a binary angle as radians in [-pi, pi) */
static double radians_of(drdc_bam32_t a)
{
  return (double)(int32_t)a * (2.0 * PI / TWO_POW_32);
}

void bench_double_init(void)
{
  uint32_t k;

  for (k = 0u; k < LEAPS; k++) {
    gps_leaps[k] = leaps[k] - GPS_EPOCH_UNIX + (double)(k + 1u);
  }
  for (k = 0u; k < BENCH_INPUTS; k++) {
    dqa[k] = dquat_of(&bench_qa[k]);
    dqb[k] = dquat_of(&bench_qb[k]);
    dvec[k].x = bench_vec[k].x / TWO_POW_16;
    dvec[k].y = bench_vec[k].y / TWO_POW_16;
    dvec[k].z = bench_vec[k].z / TWO_POW_16;
    deuler[k].yaw = radians_of(bench_euler[k].yaw);
    deuler[k].pitch = radians_of(bench_euler[k].pitch);
    deuler[k].roll = radians_of(bench_euler[k].roll);
    dutm_lat[k] = (double)bench_utm_lat[k] / NAS_PER_DEGREE;
    dutm_lon[k] = (double)bench_utm_lon[k] / NAS_PER_DEGREE;
    dutm[k].zone = bench_utm[k].zone;
    dutm[k].north = bench_utm[k].north ? 1 : 0;
    dutm[k].easting = (double)bench_utm[k].easting / TWO_POW_16;
    dutm[k].northing = (double)bench_utm[k].northing / TWO_POW_16;
    dgeodetic[k].lat = (double)bench_geodetic[k].lat / NAS_PER_DEGREE;
    dgeodetic[k].lon = (double)bench_geodetic[k].lon / NAS_PER_DEGREE;
    dgeodetic[k].height = (double)bench_geodetic[k].height / TWO_POW_16;
    decef[k].x = (double)bench_ecef[k].x / TWO_POW_16;
    decef[k].y = (double)bench_ecef[k].y / TWO_POW_16;
    decef[k].z = (double)bench_ecef[k].z / TWO_POW_16;
    dinstant[k] = (double)bench_instant[k].sec + bench_instant[k].nsec * 1e-9;
    dgps[k].week = bench_gps[k].week;
    dgps[k].tow = bench_gps[k].tow;
  }
}

/* ---- the check of every baseline against the library ---- */

/* The worst |library - baseline| of one output over the inputs, in
 * `unit` (an integer scale: thousandths of an LSB, nanometres, ...),
 * against the library's documented accuracy plus the baseline's own
 * rounding, in the same unit. */
typedef struct check {
  const char *name;
  const char *unit;
  double limit;
  double worst;
} check_t;

static void note(check_t *c, double diff)
{
  double d = fabs(diff);

  if (!(d <= c->worst)) { /* NaN counts as the worst */
    c->worst = isnan(d) ? 1e300 : d;
  }
}

static void report(const check_t *c)
{
  int ok = c->worst <= c->limit;

  bsp_puts("BENCH-CHECK ");
  bsp_puts(c->name);
  bsp_puts(" worst=");
  console_put_u64((uint64_t)(c->worst < 1e18 ? c->worst + 0.5 : 1e18));
  bsp_puts(" limit=");
  console_put_u64((uint64_t)(c->limit + 0.5));
  bsp_puts(" unit=");
  bsp_puts(c->unit);
  bsp_puts(ok ? " ok\n" : " FAIL\n");
}

/* difference of two angles in binary-angle units, wrapped to a turn */
static double bam_diff(drdc_bam32_t lib, double radians)
{
  double d = (double)lib - radians * (TWO_POW_32 / (2.0 * PI));

  d = fmod(d, TWO_POW_32);
  if (d > TWO_POW_32 / 2.0) {
    d -= TWO_POW_32;
  } else if (d < -TWO_POW_32 / 2.0) {
    d += TWO_POW_32;
  }
  return d;
}

static double quat_diff(const drdc_quat_t *lib, const dquat_t *d)
{
  double plus = 0.0, minus = 0.0;
  double l[4] = {lib->s, lib->x, lib->y, lib->z};
  double b[4] = {d->s * TWO_POW_30, d->x * TWO_POW_30, d->y * TWO_POW_30,
                 d->z * TWO_POW_30};
  int i;

  /* q and -q are the same rotation */
  for (i = 0; i < 4; i++) {
    plus = fmax(plus, fabs(l[i] - b[i]));
    minus = fmax(minus, fabs(l[i] + b[i]));
  }
  return fmin(plus, minus);
}

void bench_check_baselines(void)
{
  /* limits: the header's accuracy of each function plus a margin for the
   * baseline's own rounding, stated beside each */
  check_t mul = {"quat_mul", "milli-LSB(Q1.30)", 500.0 + 1.0, 0.0};
  check_t rot = {"quat_rotate", "milli-LSB(Q15.16)", 500.0 + 1.0, 0.0};
  check_t e2q = {"euler_to_quat", "milli-LSB(Q1.30)", 2000.0 + 1.0, 0.0};
  check_t q2e = {"quat_to_euler", "milli-BAM", 1125.0 + 1.0, 0.0};
  check_t utm_en = {"utm_forward.xy", "nm", 15259.0 + 10.0, 0.0};
  check_t utm_g = {"utm_forward.convergence", "milli-nas", 1000.0 + 10.0, 0.0};
  check_t utm_k = {"utm_forward.scale", "1e-18", 1100.0 + 100.0, 0.0};
  check_t rev_ll = {"utm_reverse.latlon", "milli-nas", 1000.0 + 10.0, 0.0};
  check_t rev_g = {"utm_reverse.convergence", "milli-nas", 1000.0 + 10.0, 0.0};
  check_t rev_k = {"utm_reverse.scale", "1e-18", 1100.0 + 100.0, 0.0};
  check_t ecef_f = {"ecef_forward", "nm", 15259.0 + 10.0, 0.0};
  check_t ecef_ll = {"ecef_reverse.latlon", "milli-nas", 1000.0 + 10.0, 0.0};
  check_t ecef_h = {"ecef_reverse.height", "nm", 15259.0 + 10.0, 0.0};
  /* a double holds a 2026 instant to 0.24 us */
  check_t time = {"time", "us", 1.0, 0.0};
  uint32_t k;

  for (k = 0u; k < BENCH_INPUTS; k++) {
    drdc_quat_t q = {0, 0, 0, 0};
    drdc_vec3_q15_16_t v = {0, 0, 0};
    drdc_euler_t e = {0u, 0u, 0u};
    drdc_geo_utm_t u = {0, false, 0, 0};
    drdc_nas_t g = 0, lat = 0, lon = 0;
    drdc_q5_58_t scale = 0;
    drdc_vec3_q47_16_t x = {0, 0, 0};
    drdc_geo_point_t p = {0, 0, 0};
    drdc_time_gps_t gps = {0, 0, 0};
    drdc_time_t t = {0, 0};
    dquat_t dq;
    dvec3_t dv;
    deuler_t de;
    dgrid_t dg;
    dgeodetic_t dgeo;
    dgps_t dgp;
    double dconv, dscale;
    drdc_status_t status;

    (void)drdc_quat_mul(&bench_qa[k], &bench_qb[k], &q);
    quat_mul_d(&dqa[k], &dqb[k], &dq);
    note(&mul, 1000.0 * quat_diff(&q, &dq));

    (void)drdc_quat_rotate_q15_16(&bench_qa[k], &bench_vec[k], &v);
    quat_rotate_d(&dqa[k], &dvec[k], &dv);
    note(&rot, 1000.0 * (v.x - dv.x * TWO_POW_16));
    note(&rot, 1000.0 * (v.y - dv.y * TWO_POW_16));
    note(&rot, 1000.0 * (v.z - dv.z * TWO_POW_16));

    (void)drdc_quat_from_euler(&bench_euler[k], &q);
    euler_to_quat_d(&deuler[k], &dq);
    note(&e2q, 1000.0 * quat_diff(&q, &dq));

    (void)drdc_euler_from_quat(&bench_qa[k], &e);
    quat_to_euler_d(&dqa[k], &de);
    /* beyond 0.001 degree of gimbal lock, where the header excludes yaw
     * and roll (ill-conditioned) */
    if (cos(de.pitch) > 1.7453292e-5) {
      note(&q2e, 1000.0 * bam_diff(e.yaw, de.yaw));
      note(&q2e, 1000.0 * bam_diff(e.roll, de.roll));
    }
    note(&q2e, 1000.0 * bam_diff(e.pitch, de.pitch));

    status = drdc_geo_to_utm(bench_utm_lat[k], bench_utm_lon[k],
                             DRDC_GEO_ZONE_STANDARD, &u, &g, &scale);
    utm_forward_d(dutm_lat[k], dutm_lon[k], &dg);
    if ((status != DRDC_OK) || (u.zone != dg.zone) ||
        ((u.north ? 1 : 0) != dg.north)) {
      note(&utm_en, 1e300);
    }
    note(&utm_en, 1e9 * ((double)u.easting / TWO_POW_16 - dg.easting));
    note(&utm_en, 1e9 * ((double)u.northing / TWO_POW_16 - dg.northing));
    note(&utm_g, 1000.0 * ((double)g - dg.convergence * NAS_PER_DEGREE));
    note(&utm_k, 1e18 * ((double)scale / TWO_POW_58 - dg.scale));

    if (drdc_geo_from_utm(&bench_utm[k], &lat, &lon, &g, &scale) != DRDC_OK) {
      note(&rev_ll, 1e300);
    }
    utm_reverse_d(&dutm[k], &dgeo, &dconv, &dscale);
    note(&rev_ll, 1000.0 * ((double)lat - dgeo.lat * NAS_PER_DEGREE));
    /* the same meridian: 360 degrees apart at zone 1's west edge */
    note(&rev_ll, 1000.0 * remainder((double)lon - dgeo.lon * NAS_PER_DEGREE,
                                     360.0 * NAS_PER_DEGREE));
    note(&rev_g, 1000.0 * ((double)g - dconv * NAS_PER_DEGREE));
    note(&rev_k, 1e18 * ((double)scale / TWO_POW_58 - dscale));

    if (drdc_geo_to_ecef(&bench_geodetic[k], &x) != DRDC_OK) {
      note(&ecef_f, 1e300);
    }
    ecef_forward_d(&dgeodetic[k], &dv);
    note(&ecef_f, 1e9 * ((double)x.x / TWO_POW_16 - dv.x));
    note(&ecef_f, 1e9 * ((double)x.y / TWO_POW_16 - dv.y));
    note(&ecef_f, 1e9 * ((double)x.z / TWO_POW_16 - dv.z));

    if (drdc_geo_from_ecef(&bench_ecef[k], &p) != DRDC_OK) {
      note(&ecef_ll, 1e300);
    }
    ecef_reverse_d(&decef[k], &dgeo);
    note(&ecef_ll, 1000.0 * ((double)p.lat - dgeo.lat * NAS_PER_DEGREE));
    note(&ecef_ll, 1000.0 * ((double)p.lon - dgeo.lon * NAS_PER_DEGREE));
    note(&ecef_h, 1e9 * ((double)p.height / TWO_POW_16 - dgeo.height));

    /* time: whole numbers, equal or not */
    (void)drdc_time_utc_to_gps(NULL, &bench_instant[k], &gps);
    utc_to_gps_d(dinstant[k], &dgp);
    note(&time, 1e6 * ((gps.week - dgp.week) * WEEK + gps.tow +
                       gps.nsec * 1e-9 - dgp.tow));
    (void)drdc_time_gps_to_utc(NULL, &bench_gps[k], &t);
    note(&time, 1e6 * ((double)t.sec + t.nsec * 1e-9 - gps_to_utc_d(&dgps[k])));
  }
  report(&mul);
  report(&rot);
  report(&e2q);
  report(&q2e);
  report(&utm_en);
  report(&utm_g);
  report(&utm_k);
  report(&rev_ll);
  report(&rev_g);
  report(&rev_k);
  report(&ecef_f);
  report(&ecef_ll);
  report(&ecef_h);
  report(&time);
}
#else
const bench_case_t bench_cases_double[] = {
    {0, 0, 0, 0},
};

void bench_double_init(void)
{
}

void bench_check_baselines(void)
{
}
#endif
