/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Baselines in double precision: the same algorithms as the library,
 *        as an engineer would write them, compiled with soft-float and
 *        newlib's libm (arm-cm3 only: Debian's PowerPC libgcc has no
 *        soft-float routines). Never linked into the library.
 */
#include "bench.h"

#if BENCH_DOUBLE
#include <math.h>

/* Results land here: a double sink, since converting an out-of-range
 * double to an integer would be undefined behaviour. */
static volatile double sink;

#define BENCH_LOOP_DOUBLE(fn, expr)                                            \
  static void fn(uint32_t calls)                                               \
  {                                                                            \
    uint32_t i;                                                                \
    double acc = 0.0;                                                          \
    for (i = 0u; i < calls; i++) {                                             \
      uint32_t x = bench_u32[i % BENCH_INPUTS];                                \
      acc += (expr);                                                           \
    }                                                                          \
    sink = acc;                                                                \
  }

/* The calendar algorithm of core/time/civil.c with doubles and floor(). */
static double days_from_civil(double year, double month, double day)
{
  double y = (month <= 2.0) ? (year - 1.0) : year;
  double era = floor(y / 400.0);
  double yoe = y - (era * 400.0);
  double mp = (month > 2.0) ? (month - 3.0) : (month + 9.0);
  double doy = floor(((153.0 * mp) + 2.0) / 5.0) + day - 1.0;
  double doe = (yoe * 365.0) + floor(yoe / 4.0) - floor(yoe / 100.0) + doy;

  return (era * 146097.0) + doe - 719468.0;
}

static double civil_from_days(double days)
{
  double z = days + 719468.0;
  double era = floor(z / 146097.0);
  double doe = z - (era * 146097.0);
  double yoe = floor((doe - floor(doe / 1460.0) + floor(doe / 36524.0) -
                      floor(doe / 146096.0)) /
                     365.0);
  double doy = doe - ((365.0 * yoe) + floor(yoe / 4.0) - floor(yoe / 100.0));
  double mp = floor(((5.0 * doy) + 2.0) / 153.0);
  double d = doy - floor(((153.0 * mp) + 2.0) / 5.0) + 1.0;
  double m = (mp < 10.0) ? (mp + 3.0) : (mp - 9.0);

  return (yoe + (era * 400.0) + ((m <= 2.0) ? 1.0 : 0.0)) + m + d;
}

/* UTC -> GPS as it is often written: Unix seconds as a double, a table of
 * leap-second instants, floor and fmod. Leap seconds after 1980 (Unix
 * seconds of the first second with the new TAI - UTC). */
static const double leaps[] = {
    362793600.0,  394329600.0,  425865600.0,  489024000.0,  567993600.0,
    631152000.0,  662688000.0,  709948800.0,  741484800.0,  773020800.0,
    820454400.0,  867715200.0,  915148800.0,  1136073600.0, 1230768000.0,
    1341100800.0, 1435708800.0, 1483228800.0,
};

static double gps_seconds(double unix_seconds)
{
  double leap = 0.0;
  unsigned i;

  for (i = 0; i < sizeof leaps / sizeof leaps[0]; i++) {
    if (unix_seconds >= leaps[i]) {
      leap += 1.0;
    }
  }
  return unix_seconds - 315964800.0 + leap;
}

static double utc_to_gps(double unix_seconds)
{
  double s = gps_seconds(unix_seconds);
  double week = floor(s / 604800.0);

  return week + fmod(s, 604800.0);
}

static double gps_to_utc(double week, double tow)
{
  double s = (week * 604800.0) + tow;
  double u = s + 315964800.0;
  unsigned i;

  for (i = 0; i < sizeof leaps / sizeof leaps[0]; i++) {
    if (u - (double)(i + 1u) >= leaps[i]) {
      u -= 1.0;
    }
  }
  return u;
}

/* Quaternions and Euler angles as an engineer writes them in double. */
typedef struct {
  double s, x, y, z;
} dquat;

static dquat dquat_of(uint32_t x)
{
  dquat q;

  q.s = (double)(x >> 3) / 1073741824.0;
  q.x = (double)(int32_t)(((x << 7) >> 3) - (1u << 28)) / 1073741824.0;
  q.y = (double)(int32_t)(((x << 13) >> 3) - (1u << 28)) / 1073741824.0;
  q.z = (double)(int32_t)(((x << 21) >> 3) - (1u << 28)) / 1073741824.0;
  return q;
}

static double quat_mul(uint32_t x)
{
  dquat a = dquat_of(x);
  dquat b = dquat_of(x * 2654435761u);
  dquat r;

  r.s = a.s * b.s - a.x * b.x - a.y * b.y - a.z * b.z;
  r.x = a.s * b.x + a.x * b.s + a.y * b.z - a.z * b.y;
  r.y = a.s * b.y - a.x * b.z + a.y * b.s + a.z * b.x;
  r.z = a.s * b.z + a.x * b.y - a.y * b.x + a.z * b.s;
  return r.s + r.x + r.y + r.z;
}

static double quat_rotate(uint32_t x)
{
  dquat q = dquat_of(x);
  double n = sqrt(q.s * q.s + q.x * q.x + q.y * q.y + q.z * q.z);
  double s = q.s / n, a = q.x / n, b = q.y / n, c = q.z / n;
  double vx = (double)(x & 0xFFFFFu) / 65536.0;
  double vy = (double)(x >> 12) / 65536.0;
  double vz = -(double)(x & 0xFFFFu) / 65536.0;
  double rx = (1 - 2 * (b * b + c * c)) * vx + 2 * (a * b - s * c) * vy +
              2 * (a * c + s * b) * vz;
  double ry = 2 * (a * b + s * c) * vx + (1 - 2 * (a * a + c * c)) * vy +
              2 * (b * c - s * a) * vz;
  double rz = 2 * (a * c - s * b) * vx + 2 * (b * c + s * a) * vy +
              (1 - 2 * (a * a + b * b)) * vz;

  return rx + ry + rz;
}

static double euler_to_quat(uint32_t x)
{
  double yaw = (double)(int32_t)x * 1.4629180792671596e-9;
  double pitch =
      (double)(int32_t)((x * 2654435761u) >> 2) * 1.4629180792671596e-9;
  double roll = (double)(int32_t)(x * 40503u) * 1.4629180792671596e-9;
  double cy = cos(yaw / 2), sy = sin(yaw / 2);
  double cp = cos(pitch / 2), sp = sin(pitch / 2);
  double cr = cos(roll / 2), sr = sin(roll / 2);

  return (cr * cp * cy + sr * sp * sy) + (cr * cp * sy - sr * sp * cy);
}

static double quat_to_euler(uint32_t x)
{
  dquat q = dquat_of(x);
  double n = sqrt(q.s * q.s + q.x * q.x + q.y * q.y + q.z * q.z);
  double s = q.s / n, a = q.x / n, b = q.y / n, c = q.z / n;
  double yaw = atan2(2 * (s * c + a * b), 1 - 2 * (b * b + c * c));
  double sp = 2 * (s * b - c * a);
  double pitch = asin(sp > 1 ? 1 : (sp < -1 ? -1 : sp));
  double roll = atan2(2 * (s * a + b * c), 1 - 2 * (a * a + b * b));

  return yaw + pitch + roll;
}

static double angle(uint32_t x)
{
  return ((double)(x % 1000000u) / 1000000.0 - 0.5) * 6.283185307179586;
}

/* The transverse Mercator of core/geo/tm.c in double: conformal latitude
 * series, spherical TM, Krueger's 6 terms with their derivative for the
 * convergence and scale (WGS-84, k0 = 0.9996, standard 6-degree zone). */
static double utm_forward(double lat, double lon)
{
  static const double alpha[6] = {8.3773182062446983e-04,
                                  7.608527773572307e-07,
                                  1.197645503242e-09,
                                  2.4291706e-12,
                                  5.711e-15,
                                  1.5e-17};
  static const double chic[6] = {-3.3565514856e-03, 4.69462275e-06, -8.1946e-09,
                                 1.558e-11,         -3.1e-14,       6.0e-17};
  const double deg = 0.017453292519943295;
  const double e2 = 6.69437999014e-3, e = 0.0818191908426215;
  const double k0a = 6364902.166165086;
  double zone = floor((lon + 180.0) / 6.0);
  double lam = (lon - ((6.0 * zone) - 177.0)) * deg;
  double phi = lat * deg;
  double chi = phi, xip, etap, xi, eta, p = 1.0, q = 0.0, gamma, k;
  int j;

  for (j = 0; j < 6; j++) {
    chi += chic[j] * sin(2.0 * (j + 1) * phi);
  }
  xip = atan2(sin(chi), cos(chi) * cos(lam));
  etap = atanh(cos(chi) * sin(lam));
  xi = xip;
  eta = etap;
  for (j = 0; j < 6; j++) {
    double m = 2.0 * (j + 1);

    xi += alpha[j] * sin(m * xip) * cosh(m * etap);
    eta += alpha[j] * cos(m * xip) * sinh(m * etap);
    p += m * alpha[j] * cos(m * xip) * cosh(m * etap);
    q += m * alpha[j] * sin(m * xip) * sinh(m * etap);
  }
  gamma = atan2(sin(chi) * sin(lam), cos(lam)) + atan2(q, p);
  k = 0.99852 * sqrt(1.0 - (e2 * sin(phi) * sin(phi))) * cos(chi) / cos(phi) *
      cosh(etap) * hypot(p, q);
  (void)e;
  return (k0a * eta) + (k0a * xi) + gamma + k;
}

/* geodetic -> ECEF and Bowring's two steps back, as core/geo/ecef.c
 * does them, in double (WGS-84) */
static double ecef_forward(double lat, double lon, double h)
{
  const double a = 6378137.0, e2 = 6.69437999014e-3;
  const double deg = 0.017453292519943295;
  double sp = sin(lat * deg), cp = cos(lat * deg);
  double n = a / sqrt(1.0 - (e2 * sp * sp));

  return ((n + h) * cp * cos(lon * deg)) + ((n + h) * cp * sin(lon * deg)) +
         (((n * (1.0 - e2)) + h) * sp);
}

static double ecef_reverse(uint32_t x)
{
  const double a = 6378137.0, e2 = 6.69437999014e-3;
  const double bova = 0.99664718933525254, e2a = e2 * a;
  const double ep2b = e2 * a / 0.99664718933525254;
  int64_t ex, ey, ez;
  double x0, y0, z, p, u, v, r, c, s, h;
  int i;

  bench_ecef_point(x, &ex, &ey, &ez);
  x0 = (double)ex / 65536.0;
  y0 = (double)ey / 65536.0;
  z = (double)ez / 65536.0;
  p = hypot(x0, y0);
  u = p * bova;
  v = z;
  for (i = 0; i < 2; i++) {
    r = hypot(u, v);
    c = u / r;
    s = v / r;
    u = p - (e2a * c * c * c);
    v = z + (ep2b * s * s * s);
    if (i == 0) {
      v = v * bova;
    }
  }
  r = hypot(u, v);
  h = (p * u / r) + (z * v / r) - (a * sqrt(1.0 - (e2 * v * v / (r * r))));
  return atan2(v, u) + atan2(y0, x0) + h;
}

BENCH_LOOP_DOUBLE(run_days_from_civil,
                  days_from_civil(1900.0 + (double)(x % 200u),
                                  1.0 + (double)((x >> 8) % 12u),
                                  1.0 + (double)((x >> 16) % 28u)))
BENCH_LOOP_DOUBLE(run_civil_from_days,
                  civil_from_days((double)(x % 73000u) - 25000.0))
BENCH_LOOP_DOUBLE(run_utc_to_gps,
                  utc_to_gps(631152000.0 + (double)(x % 1136073600u) +
                             (double)((x >> 3) % 1000000000u) * 1e-9))
BENCH_LOOP_DOUBLE(run_gps_to_utc, gps_to_utc(522.0 + (double)(x % 1900u),
                                             (double)((x >> 11) % 604800u)))
BENCH_LOOP_DOUBLE(run_quat_mul, quat_mul(x))
BENCH_LOOP_DOUBLE(run_quat_rotate, quat_rotate(x))
BENCH_LOOP_DOUBLE(run_euler_to_quat, euler_to_quat(x))
BENCH_LOOP_DOUBLE(run_quat_to_euler, quat_to_euler(x))
BENCH_LOOP_DOUBLE(run_sin, sin(angle(x)))
BENCH_LOOP_DOUBLE(run_cos, cos(angle(x)))
BENCH_LOOP_DOUBLE(run_atan2, atan2((double)(x & 0xFFFFu) - 32768.0,
                                   (double)(x >> 16) - 32768.0))
BENCH_LOOP_DOUBLE(run_sqrt, sqrt((double)(x >> 1)))
BENCH_LOOP_DOUBLE(run_mul,
                  (double)(int32_t)x *(double)(int32_t)(x >> 7) / 65536.0)
BENCH_LOOP_DOUBLE(
    run_utm_forward,
    utm_forward(((double)(x & 0xFFFFu) - 32768.0) * (8.8e9 / 3.6e12),
                ((double)(x >> 16) - 32768.0) * (19.7e9 / 3.6e12)))
BENCH_LOOP_DOUBLE(
    run_ecef_forward,
    ecef_forward(((double)(x & 0xFFFFu) - 32768.0) * (9.88e9 / 3.6e12),
                 ((double)((x >> 16) & 0x7FFFu) - 16384.0) * (39.5e9 / 3.6e12),
                 (double)(x >> 31) * 1e6 - 1e4 +
                     (double)((x >> 8) & 0xFFu) * 40.0))
BENCH_LOOP_DOUBLE(run_ecef_reverse, ecef_reverse(x))

const bench_case_t bench_cases_double[] = {
    {"days_from_civil", "double", "run_days_from_civil", run_days_from_civil},
    {"civil_from_days", "double", "run_civil_from_days", run_civil_from_days},
    {"utc_to_gps", "double", "run_utc_to_gps", run_utc_to_gps},
    {"gps_to_utc", "double", "run_gps_to_utc", run_gps_to_utc},
    {"quat_mul", "double", "run_quat_mul", run_quat_mul},
    {"quat_rotate", "double", "run_quat_rotate", run_quat_rotate},
    {"euler_to_quat", "double", "run_euler_to_quat", run_euler_to_quat},
    {"quat_to_euler", "double", "run_quat_to_euler", run_quat_to_euler},
    {"sin", "double", "run_sin", run_sin},
    {"cos", "double", "run_cos", run_cos},
    {"atan2", "double", "run_atan2", run_atan2},
    {"sqrt", "double", "run_sqrt", run_sqrt},
    {"mul_q15_16", "double", "run_mul", run_mul},
    {"utm_forward", "double", "run_utm_forward", run_utm_forward},
    {"ecef_forward", "double", "run_ecef_forward", run_ecef_forward},
    {"ecef_reverse", "double", "run_ecef_reverse", run_ecef_reverse},
    {0, 0, 0, 0},
};
#else
const bench_case_t bench_cases_double[] = {
    {0, 0, 0, 0},
};
#endif
