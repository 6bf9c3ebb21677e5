/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Benchmark image: times every case with the board's tick counter
 *        and prints raw counts; tools/gates/bench.py (run under QEMU -icount
 *        shift=0) turns them into instructions per call and the report.
 */
#include "bench.h"
#include "operands.h"
#include "drdc_board.h"
#include "console.h"

uint32_t bench_u32[BENCH_INPUTS];
volatile uint32_t bench_sink;

/* Calls per case: enough that one tick (up to a few hundred instructions
 * on arm-cm3) is well under 0.1 instruction per call. */
#define CALLS 4096u
/* Iterations of the calibration spin. */
#define SPIN 1000000u

void bench_inputs_init(void)
{
  uint32_t x = 2463534242u;
  uint32_t i;

  for (i = 0u; i < BENCH_INPUTS; i++) {
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    bench_u32[i] = x;
  }
}

static uint32_t elapsed(uint32_t start)
{
  return (bsp_ticks() - start) & bsp_ticks_mask;
}

/* The empty loop: measured like a case and subtracted from every case. */
BENCH_LOOP(loop_overhead, k)

static const bench_case_t overhead = {"loop", "overhead", "-", loop_overhead};

static void time_case(const bench_case_t *c)
{
  uint32_t start;
  uint32_t ticks;

  c->run(16u); /* warm-up: nothing cached, but the same path as below */
  start = bsp_ticks();
  c->run(CALLS);
  ticks = elapsed(start);
  bsp_puts("BENCH ");
  bsp_puts(c->impl);
  bsp_putc(' ');
  bsp_puts(c->name);
  bsp_puts(" symbol=");
  bsp_puts(c->symbol);
  bsp_puts(" calls=");
  console_put_u64(CALLS);
  bsp_puts(" ticks=");
  console_put_u64(ticks);
  bsp_putc('\n');
}

static void time_table(const bench_case_t *table)
{
  for (; table->name != 0; table++) {
    time_case(table);
  }
}

int main(void)
{
  uint32_t start;
  uint32_t ticks;

  bench_inputs_init();
  bench_operands_init();
  bench_double_init();
  bsp_ticks_start();
  bsp_puts("BENCH-TARGET ");
  bsp_puts(bsp_name);
  bsp_putc('\n');

  /* ticks per known number of instructions: spin(SPIN) - spin(0) */
  start = bsp_ticks();
  bsp_spin(0u);
  ticks = elapsed(start);
  start = bsp_ticks();
  bsp_spin(SPIN);
  bsp_puts("BENCH-CALIBRATE iterations=");
  console_put_u64(SPIN);
  bsp_puts(" per_iteration=");
  console_put_u64(bsp_spin_insns_per_iteration);
  bsp_puts(" ticks=");
  console_put_u64(elapsed(start) - ticks);
  bsp_putc('\n');

  bench_check_baselines();
  time_case(&overhead);
  time_table(bench_cases_fixed);
  time_table(bench_cases_orient);
  time_table(bench_cases_time);
  time_table(bench_cases_geo);
  time_table(bench_cases_libfixmath);
  time_table(bench_cases_double);
  bsp_puts("BENCH-DONE\n");
  return 0;
}
