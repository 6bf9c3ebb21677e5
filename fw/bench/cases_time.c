/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Benchmark cases of the time module.
 */
#include <drdc/time.h>

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

BENCH_LOOP(run_days_from_civil, days_from_civil(x))
BENCH_LOOP(run_civil_from_days, civil_from_days(x))

const bench_case_t bench_cases_time[] = {
  { "days_from_civil", "drdc", "drdc_time_days_from_civil", run_days_from_civil },
  { "civil_from_days", "drdc", "drdc_time_civil_from_days", run_civil_from_days },
  { 0, 0, 0, 0 },
};
