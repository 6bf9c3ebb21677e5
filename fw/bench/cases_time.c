/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Benchmark cases of the time module.
 */
#include <stddef.h>

#include <drdc/time.h>
#include <drdc/time_scales.h>

#include "operands.h"

static uint32_t days_from_civil(uint32_t k)
{
  int32_t days = 0;

  (void)drdc_time_days_from_civil(bench_civil[k].year, bench_civil[k].month,
                                  bench_civil[k].day, &days);
  return (uint32_t)days;
}

static uint32_t civil_from_days(uint32_t k)
{
  int32_t y = 0;
  int32_t m = 0;
  int32_t d = 0;

  (void)drdc_time_civil_from_days(bench_days[k], &y, &m, &d);
  return (uint32_t)(y + m + d);
}

static uint32_t utc_to_gps(uint32_t k)
{
  drdc_time_gps_t gps = {0, 0, 0};

  (void)drdc_time_utc_to_gps(NULL, &bench_instant[k], &gps);
  return (uint32_t)(gps.week + gps.tow);
}

static uint32_t gps_to_utc(uint32_t k)
{
  drdc_time_t t = {0, 0};

  (void)drdc_time_gps_to_utc(NULL, &bench_gps[k], &t);
  return (uint32_t)t.sec;
}

BENCH_LOOP(run_days_from_civil, days_from_civil(k))
BENCH_LOOP(run_utc_to_gps, utc_to_gps(k))
BENCH_LOOP(run_gps_to_utc, gps_to_utc(k))
BENCH_LOOP(run_civil_from_days, civil_from_days(k))

const bench_case_t bench_cases_time[] = {
    {"days_from_civil", "drdc", "drdc_time_days_from_civil",
     run_days_from_civil},
    {"civil_from_days", "drdc", "drdc_time_civil_from_days",
     run_civil_from_days},
    {"utc_to_gps", "drdc", "drdc_time_utc_to_gps", run_utc_to_gps},
    {"gps_to_utc", "drdc", "drdc_time_gps_to_utc", run_gps_to_utc},
    {0, 0, 0, 0},
};
