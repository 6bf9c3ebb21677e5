/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Benchmark cases of the time module.
 */
#include <stddef.h>

#include <drdc/time.h>
#include <drdc/time_scales.h>

#include "bench.h"

static uint32_t days_from_civil(uint32_t x)
{
  int32_t days = 0;

  (void)drdc_time_days_from_civil(1900 + (int32_t)(x % 200u),
                                  1 + (int32_t)((x >> 8) % 12u),
                                  1 + (int32_t)((x >> 16) % 28u), &days);
  return (uint32_t)days;
}

static uint32_t civil_from_days(uint32_t x)
{
  int32_t y = 0;
  int32_t m = 0;
  int32_t d = 0;

  (void)drdc_time_civil_from_days((int32_t)(x % 73000u) - 25000, &y, &m, &d);
  return (uint32_t)(y + m + d);
}

/* instants 1990..2026 with nanoseconds */
static drdc_time_t instant(uint32_t x)
{
  drdc_time_t t;

  t.sec = INT64_C(631152000) + (int64_t)(x % 1136073600u);
  t.nsec = (int32_t)((x >> 3) % 1000000000u);
  return t;
}

static uint32_t utc_to_gps(uint32_t x)
{
  drdc_time_t t = instant(x);
  drdc_time_gps_t gps = {0, 0, 0};

  (void)drdc_time_utc_to_gps(NULL, &t, &gps);
  return (uint32_t)(gps.week + gps.tow);
}

static uint32_t gps_to_utc(uint32_t x)
{
  drdc_time_gps_t gps;
  drdc_time_t t = {0, 0};

  gps.week = 522 + (int32_t)(x % 1900u);
  gps.tow = (int32_t)((x >> 11) % 604800u);
  gps.nsec = 0;
  (void)drdc_time_gps_to_utc(NULL, &gps, &t);
  return (uint32_t)t.sec;
}

BENCH_LOOP(run_days_from_civil, days_from_civil(x))
BENCH_LOOP(run_utc_to_gps, utc_to_gps(x))
BENCH_LOOP(run_gps_to_utc, gps_to_utc(x))
BENCH_LOOP(run_civil_from_days, civil_from_days(x))

const bench_case_t bench_cases_time[] = {
    {"days_from_civil", "drdc", "drdc_time_days_from_civil",
     run_days_from_civil},
    {"civil_from_days", "drdc", "drdc_time_civil_from_days",
     run_civil_from_days},
    {"utc_to_gps", "drdc", "drdc_time_utc_to_gps", run_utc_to_gps},
    {"gps_to_utc", "drdc", "drdc_time_gps_to_utc", run_gps_to_utc},
    {0, 0, 0, 0},
};
