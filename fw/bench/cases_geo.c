/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Benchmark cases of core/geo: geographic -> UTM (standard zone,
 *        convergence and scale), against the same algorithm in double
 *        (cases_double.c, "utm_forward"); and the Q5.58 stages it is made
 *        of (fixed_q5_58.h, fixed_hyper.h, drdc_fx_mul_q5_58), to show
 *        where its cycles go.
 */
#include <drdc/fixed.h>
#include <drdc/geo.h>

#include "bench.h"

/* latitude +-80 and longitude +-180 degrees from the 32-bit input */
static uint32_t utm_case(uint32_t x)
{
  drdc_geo_utm_t u = { 0, false, 0, 0 };
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
  u.easting = ((int64_t)180000 + (int64_t)((x >> 7) & 0x3FFu) * 625)
              * INT64_C(65536);
  u.northing = ((int64_t)((x >> 17) & 0x7FFFu) * 244) * INT64_C(65536);
  (void)drdc_geo_from_utm(&u, &lat, &lon, &g, &k);
  return (uint32_t)lat ^ (uint32_t)lon ^ (uint32_t)g ^ (uint32_t)k;
}

BENCH_LOOP(run_utm_reverse, utm_reverse_case(x))

/* Q5.58 arguments from the 32-bit input: |a| < 2^(27 + shift - 58) */
#define ARG(v, shift) ((int64_t)(int32_t)(v) * (INT64_C(1) << (shift)))
#define OTHER(v) ((v) * 2654435761u)

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
  { "utm_forward", "drdc", "drdc_geo_to_utm", run_utm_forward },
  { "utm_reverse", "drdc", "drdc_geo_from_utm", run_utm_reverse },
  { "q58_mul", "drdc", "drdc_fx_mul_q5_58", run_q58_mul },
  { "q58_div", "drdc", "drdc_fx_div_q5_58", run_q58_div },
  { "q58_sincos", "drdc", "drdc_fx_sincos_q5_58", run_q58_sincos },
  { "q58_atan2", "drdc", "drdc_fx_atan2_q5_58", run_q58_atan2 },
  { "q58_sqrt", "drdc", "drdc_fx_sqrt_q5_58", run_q58_sqrt },
  { "q58_sinh", "drdc", "drdc_fx_sinh_q5_58", run_q58_sinh },
  { "q58_atanh", "drdc", "drdc_fx_atanh_q5_58", run_q58_atanh },
  { 0, 0, 0, 0 },
};
