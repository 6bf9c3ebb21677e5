/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Benchmark cases of core/geo: geographic -> UTM (standard zone,
 *        convergence and scale) and geodetic <-> ECEF, against the same
 *        algorithms in double (cases_double.c, "utm_forward",
 *        "ecef_forward", "ecef_reverse"); and the Q5.58 stages they are
 *        made of (fixed_q5_58.h, fixed_hyper.h, drdc_fx_mul_q5_58), to
 *        show where their cycles go.
 */
#include <drdc/fixed.h>
#include <drdc/geo.h>
#include <drdc/geo_ecef.h>

#include "bench.h"

void bench_ecef_point(uint32_t x, int64_t *ex, int64_t *ey, int64_t *ez)
{
  drdc_q1_30_t sp = 0;
  drdc_q1_30_t cp = 0;
  drdc_q1_30_t sl = 0;
  drdc_q1_30_t cl = 0;
  /* radius in metres (< 2^23), latitude half a turn, longitude a turn */
  int64_t r = 6357000 + (int64_t)(x >> 22) * 1000;
  int64_t h;

  drdc_fx_sincos_bam32(
      (drdc_bam32_t)((uint32_t)(int32_t)((int32_t)(x << 21) / 2)), &sp, &cp);
  drdc_fx_sincos_bam32((drdc_bam32_t)((x >> 11) << 21), &sl, &cl);
  /* Q47.16 metres: r cos(lat) < 2^39, times a Q1.22 cosine < 2^61 */
  h = (r * cp) / 16384;
  *ex = (h * (cl / 256)) / 4194304;
  *ey = (h * (sl / 256)) / 4194304;
  *ez = (r * sp) / 16384;
}

/* latitude +-80 and longitude +-180 degrees from the 32-bit input */
static uint32_t utm_case(uint32_t x)
{
  drdc_geo_utm_t u = {0, false, 0, 0};
  drdc_nas_t g = 0;
  drdc_q5_58_t k = 0;

  (void)drdc_geo_to_utm(((int64_t)(x & 0xFFFFu) - 32768) * INT64_C(8800000000),
                        ((int64_t)(x >> 16) - 32768) * INT64_C(19700000000),
                        DRDC_GEO_ZONE_STANDARD, &u, &g, &k);
  return (uint32_t)u.easting ^ (uint32_t)u.northing ^ (uint32_t)g;
}

BENCH_LOOP(run_utm_forward, utm_case(x))

/* UTM -> geographic with convergence and scale: zones 1..60, both
 * hemispheres, eastings 180..820 km, northings 0..8 000 km */
static uint32_t utm_reverse_case(uint32_t x)
{
  drdc_geo_utm_t u;
  drdc_nas_t lat = 0;
  drdc_nas_t lon = 0;
  drdc_nas_t g = 0;
  drdc_q5_58_t k = 0;

  u.zone = (int32_t)(x % 60u) + 1;
  u.north = ((x >> 6) & 1u) != 0u;
  u.easting =
      ((int64_t)180000 + (int64_t)((x >> 7) & 0x3FFu) * 625) * INT64_C(65536);
  u.northing = ((int64_t)((x >> 17) & 0x7FFFu) * 244) * INT64_C(65536);
  (void)drdc_geo_from_utm(&u, &lat, &lon, &g, &k);
  return (uint32_t)lat ^ (uint32_t)lon ^ (uint32_t)g ^ (uint32_t)k;
}

BENCH_LOOP(run_utm_reverse, utm_reverse_case(x))

/* geodetic -> ECEF: latitude +-90, longitude +-180 degrees, heights
 * -10 km .. 1 000 km */
static uint32_t ecef_forward_case(uint32_t x)
{
  drdc_geo_point_t p;
  drdc_vec3_q47_16_t e = {0, 0, 0};

  p.lat = ((int64_t)(x & 0xFFFFu) - 32768) * INT64_C(9880000000);
  p.lon = ((int64_t)((x >> 16) & 0x7FFFu) - 16384) * INT64_C(39500000000);
  p.height = ((int64_t)(x >> 31) * 1000000 - 10000 +
              (int64_t)((x >> 8) & 0xFFu) * 40) *
             INT64_C(65536);
  (void)drdc_geo_to_ecef(&p, &e);
  return (uint32_t)e.x ^ (uint32_t)e.y ^ (uint32_t)e.z;
}

BENCH_LOOP(run_ecef_forward, ecef_forward_case(x))

/* ECEF -> geodetic of points near the surface: a sphere of radius
 * 6 357 .. 7 380 km at latitude +-90 and longitude +-180 degrees, made
 * with the Q1.30 sin/cos of fixed_trig.h (bench_ecef_point(), shared
 * with the double baseline: about 300 of the cycles) */
static uint32_t ecef_reverse_case(uint32_t x)
{
  drdc_vec3_q47_16_t e;
  drdc_geo_point_t p = {0, 0, 0};

  bench_ecef_point(x, &e.x, &e.y, &e.z);
  (void)drdc_geo_from_ecef(&e, &p);
  return (uint32_t)p.lat ^ (uint32_t)p.lon ^ (uint32_t)p.height;
}

BENCH_LOOP(run_ecef_reverse, ecef_reverse_case(x))

/* Q5.58 arguments from the 32-bit input: |a| < 2^(27 + shift - 58) */
#define ARG(v, shift) ((int64_t)(int32_t)(v) * (INT64_C(1) << (shift)))
#define OTHER(v)      ((v)*2654435761u)

static uint32_t q58_mul(uint32_t x)
{
  drdc_q5_58_t r = 0;

  (void)drdc_fx_mul_q5_58(ARG(x, 27), ARG(OTHER(x), 27), &r);
  return (uint32_t)r;
}

static uint32_t q58_div(uint32_t x)
{
  drdc_q5_58_t r = 0;

  (void)drdc_fx_div_q5_58(ARG(x, 25), ARG(OTHER(x) | 1u, 27), &r);
  return (uint32_t)r;
}

static uint32_t q58_sincos(uint32_t x)
{
  drdc_q5_58_t s = 0;
  drdc_q5_58_t c = 0;

  /* |x| < 2 radians */
  (void)drdc_fx_sincos_q5_58(ARG(x, 28), &s, &c);
  return (uint32_t)s ^ (uint32_t)c;
}

static uint32_t q58_atan2(uint32_t x)
{
  drdc_q5_58_t r = 0;

  (void)drdc_fx_atan2_q5_58(ARG(x, 26), ARG(OTHER(x) | 1u, 26), &r);
  return (uint32_t)r;
}

static uint32_t q58_sqrt(uint32_t x)
{
  drdc_q5_58_t r = 0;

  (void)drdc_fx_sqrt_q5_58((int64_t)x * (INT64_C(1) << 27), &r);
  return (uint32_t)r;
}

static uint32_t q58_sinh(uint32_t x)
{
  drdc_q5_58_t r = 0;

  (void)drdc_fx_sinh_q5_58(ARG(x, 28), &r);
  return (uint32_t)r;
}

static uint32_t q58_atanh(uint32_t x)
{
  drdc_q5_58_t r = 0;

  (void)drdc_fx_atanh_q5_58(ARG(x, 26), &r);
  return (uint32_t)r;
}

BENCH_LOOP(run_q58_mul, q58_mul(x))
BENCH_LOOP(run_q58_div, q58_div(x))
BENCH_LOOP(run_q58_sincos, q58_sincos(x))
BENCH_LOOP(run_q58_atan2, q58_atan2(x))
BENCH_LOOP(run_q58_sqrt, q58_sqrt(x))
BENCH_LOOP(run_q58_sinh, q58_sinh(x))
BENCH_LOOP(run_q58_atanh, q58_atanh(x))

const bench_case_t bench_cases_geo[] = {
    {"utm_forward", "drdc", "drdc_geo_to_utm", run_utm_forward},
    {"utm_reverse", "drdc", "drdc_geo_from_utm", run_utm_reverse},
    {"ecef_forward", "drdc", "drdc_geo_to_ecef", run_ecef_forward},
    {"ecef_reverse", "drdc", "drdc_geo_from_ecef", run_ecef_reverse},
    {"q58_mul", "drdc", "drdc_fx_mul_q5_58", run_q58_mul},
    {"q58_div", "drdc", "drdc_fx_div_q5_58", run_q58_div},
    {"q58_sincos", "drdc", "drdc_fx_sincos_q5_58", run_q58_sincos},
    {"q58_atan2", "drdc", "drdc_fx_atan2_q5_58", run_q58_atan2},
    {"q58_sqrt", "drdc", "drdc_fx_sqrt_q5_58", run_q58_sqrt},
    {"q58_sinh", "drdc", "drdc_fx_sinh_q5_58", run_q58_sinh},
    {"q58_atanh", "drdc", "drdc_fx_atanh_q5_58", run_q58_atanh},
    {0, 0, 0, 0},
};
