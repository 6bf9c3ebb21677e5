/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Benchmark cases of core/geo: geographic -> UTM (standard zone,
 *        convergence and scale), its reverse and geodetic <-> ECEF,
 *        against the same algorithms in double (cases_double.c); and the
 *        Q5.58 stages they are made of (fixed_q5_58.h, fixed_hyper.h,
 *        drdc_fx_mul_q5_58), to show where their instructions go.
 */
#include <drdc/fixed.h>
#include <drdc/geo.h>
#include <drdc/geo_ecef.h>

#include "operands.h"

static uint32_t utm_forward(uint32_t k)
{
  drdc_geo_utm_t u = {0, false, 0, 0};
  drdc_nas_t g = 0;
  drdc_q5_58_t scale = 0;

  (void)drdc_geo_to_utm(bench_utm_lat[k], bench_utm_lon[k],
                        DRDC_GEO_ZONE_STANDARD, &u, &g, &scale);
  return (uint32_t)u.easting ^ (uint32_t)u.northing ^ (uint32_t)g ^
         (uint32_t)scale;
}

static uint32_t utm_reverse(uint32_t k)
{
  drdc_nas_t lat = 0;
  drdc_nas_t lon = 0;
  drdc_nas_t g = 0;
  drdc_q5_58_t scale = 0;

  (void)drdc_geo_from_utm(&bench_utm[k], &lat, &lon, &g, &scale);
  return (uint32_t)lat ^ (uint32_t)lon ^ (uint32_t)g ^ (uint32_t)scale;
}

static uint32_t ecef_forward(uint32_t k)
{
  drdc_vec3_q47_16_t e = {0, 0, 0};

  (void)drdc_geo_to_ecef(&bench_geodetic[k], &e);
  return (uint32_t)e.x ^ (uint32_t)e.y ^ (uint32_t)e.z;
}

static uint32_t ecef_reverse(uint32_t k)
{
  drdc_geo_point_t p = {0, 0, 0};

  (void)drdc_geo_from_ecef(&bench_ecef[k], &p);
  return (uint32_t)p.lat ^ (uint32_t)p.lon ^ (uint32_t)p.height;
}

BENCH_LOOP(run_utm_forward, utm_forward(k))
BENCH_LOOP(run_utm_reverse, utm_reverse(k))
BENCH_LOOP(run_ecef_forward, ecef_forward(k))
BENCH_LOOP(run_ecef_reverse, ecef_reverse(k))

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
