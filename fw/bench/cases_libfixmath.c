/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Baselines from libfixmath (Q16.16, built with FIXMATH_NO_CACHE so
 *        that it has no global state, like our library).
 */
#include <fix16.h>

#include "bench.h"

/* Inputs mapped to each function's domain: angles in [-pi, pi), values
 * in [0, 32768) for sqrt. */
static fix16_t angle(uint32_t x)
{
  return (fix16_t)((int32_t)(x % 411775u) - 205887);
}

BENCH_LOOP(run_sin, fix16_sin(angle(x)))
BENCH_LOOP(run_cos, fix16_cos(angle(x)))
BENCH_LOOP(run_atan2, fix16_atan2((fix16_t)(x & 0xFFFFu) - 32768,
                                  (fix16_t)(x >> 16) - 32768))
BENCH_LOOP(run_sqrt, fix16_sqrt((fix16_t)(x >> 1)))
BENCH_LOOP(run_mul, fix16_mul((fix16_t)x, (fix16_t)(x >> 7)))

const bench_case_t bench_cases_libfixmath[] = {
    {"sin", "libfixmath", "fix16_sin", run_sin},
    {"cos", "libfixmath", "fix16_cos", run_cos},
    {"atan2", "libfixmath", "fix16_atan2", run_atan2},
    {"sqrt", "libfixmath", "fix16_sqrt", run_sqrt},
    {"mul_q15_16", "libfixmath", "fix16_mul", run_mul},
    {0, 0, 0, 0},
};
