/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Benchmark cases of fixed/, named like their libfixmath and double
 *        baselines (cases_libfixmath.c, cases_double.c) over the same
 *        spread of inputs.
 */
#include <drdc/fixed.h>

#include "bench.h"

static uint32_t atan2_case(uint32_t x)
{
  drdc_bam32_t a = 0u;

  (void)drdc_fx_atan2_bam32((int32_t)(x & 0xFFFFu) - 32768,
                            (int32_t)(x >> 16) - 32768, &a);
  return a;
}

static uint32_t sqrt_case(uint32_t x)
{
  drdc_q15_16_t r = 0;

  (void)drdc_fx_sqrt_q15_16((drdc_q15_16_t)(x >> 1), &r);
  return (uint32_t)r;
}

static uint32_t mul_case(uint32_t x)
{
  drdc_q15_16_t r = 0;

  (void)drdc_fx_mul_q15_16_sat((drdc_q15_16_t)x, (drdc_q15_16_t)(x >> 7), &r);
  return (uint32_t)r;
}

BENCH_LOOP(run_sin, drdc_fx_sin_bam32(x))
BENCH_LOOP(run_cos, drdc_fx_cos_bam32(x))
BENCH_LOOP(run_atan2, atan2_case(x))
BENCH_LOOP(run_sqrt, sqrt_case(x))
BENCH_LOOP(run_mul, mul_case(x))

const bench_case_t bench_cases_fixed[] = {
    {"sin", "drdc", "drdc_fx_sin_bam32", run_sin},
    {"cos", "drdc", "drdc_fx_cos_bam32", run_cos},
    {"atan2", "drdc", "drdc_fx_atan2_bam32", run_atan2},
    {"sqrt", "drdc", "drdc_fx_sqrt_q15_16", run_sqrt},
    {"mul_q15_16", "drdc", "drdc_fx_mul_q15_16_sat", run_mul},
    {0, 0, 0, 0},
};
