/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Benchmark cases: a function timed over a fixed set of inputs,
 *        next to the baselines it is compared with.
 */
#ifndef DRDC_BENCH_H
#define DRDC_BENCH_H

#include <stdint.h>

/** One timed case. `run` calls the measured function `calls` times over
 *  the golden inputs and folds every result into bench_sink, so nothing
 *  can be optimised away. */
typedef struct bench_case {
  const char
      *name; /**< operation, shared by an implementation and its baselines */
  const char *impl;   /**< "drdc", "double" (soft-float + newlib libm),
                           "libfixmath" or "hand" (a by-hand floor) */
  const char *symbol; /**< the function measured, for its code size */
  void (*run)(uint32_t calls);
} bench_case_t;

/** Inputs every case draws from (bench_inputs_init() fills them the same
 *  way on every target), indexed by call number modulo BENCH_INPUTS. */
#define BENCH_INPUTS 256u
extern uint32_t bench_u32[BENCH_INPUTS];

/** Results land here. */
extern volatile uint32_t bench_sink;

void bench_inputs_init(void);

/** The double baselines' operands, converted from those of operands.h
 *  (cases_double.c; empty where there is no soft-float libm). */
void bench_double_init(void);
/** Each double baseline against the library on every input: prints one
 *  "BENCH-CHECK name worst=W limit=L unit=U ok|FAIL" line per output. */
void bench_check_baselines(void);

/** Case tables, one per module and baseline family; each ends with a
 *  case whose name is NULL. */
extern const bench_case_t bench_cases_time[];
extern const bench_case_t bench_cases_fixed[];
extern const bench_case_t bench_cases_orient[];
/** core/geo cases (cases_geo.c). */
extern const bench_case_t bench_cases_geo[];
extern const bench_case_t bench_cases_libfixmath[];
extern const bench_case_t bench_cases_double[];

/** Define `static void fn(uint32_t calls)` that evaluates `expr` (which may
 *  use `k`, the index of the call's operands in the tables of operands.h,
 *  and `x`, its 32-bit input word) `calls` times, folding each result
 *  into a word. The empty loop (main.c), subtracted from every case, has
 *  the same index; a case that reads `x` pays its load. */
#define BENCH_LOOP(fn, expr)                                                   \
  static void fn(uint32_t calls)                                               \
  {                                                                            \
    uint32_t i;                                                                \
    uint32_t acc = 0u;                                                         \
    for (i = 0u; i < calls; i++) {                                             \
      uint32_t k = i % BENCH_INPUTS;                                           \
      uint32_t x = bench_u32[k];                                               \
      (void)k;                                                                 \
      (void)x;                                                                 \
      acc ^= (uint32_t)(expr);                                                 \
    }                                                                          \
    bench_sink = acc;                                                          \
  }

#endif /* DRDC_BENCH_H */
