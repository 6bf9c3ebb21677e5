/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The board interface every bsp/<board>/ folder implements.
 *
 * Firmware images (fw/) use only this header to talk to the board; the
 * library (core/, fixed/) never includes it. Its name is not bsp.h: an
 * RTEMS application's <rtems/confdefs.h> includes the RTEMS BSP's own
 * <bsp.h>, which a bsp.h on the include path would shadow.
 */
#ifndef DRDC_BOARD_H
#define DRDC_BOARD_H

#include <stdint.h>

/** Name of the board, e.g. "ppc-e500". */
extern const char bsp_name[];

/** Write one character to the console (a '\n' may be sent as "\r\n"). */
void bsp_putc(int c);

/** Write a NUL-terminated string to the console. */
void bsp_puts(const char *s);

/** End the program with `status` (0 success). On boards that cannot pass a
 *  status out (ppc-e500), the console carries the verdict. Never returns. */
void bsp_exit(int status) __attribute__((__noreturn__));

/** Start the board's free-running tick counter (benchmarks only). */
void bsp_ticks_start(void);

/** Ticks of the counter, increasing modulo bsp_ticks_mask + 1: the
 *  time base on ppc-e500, SysTick at the core clock on arm-cm3. Under QEMU
 *  -icount shift=0 the count follows executed instructions, so it repeats
 *  exactly from run to run; tools/gates/bench.py converts ticks to instructions
 *  with bsp_spin(). Subtract two readings modulo the mask. */
uint32_t bsp_ticks(void);

/** Width of bsp_ticks(): the largest difference it can measure. */
extern const uint32_t bsp_ticks_mask;

/** Execute exactly bsp_spin_insns_per_iteration * n instructions in a
 *  loop (plus a fixed entry and exit), to calibrate ticks to instructions. */
void bsp_spin(uint32_t n);

/** Instructions per iteration of bsp_spin(). */
extern const uint32_t bsp_spin_insns_per_iteration;

/** Prefix of the line a board prints when the CPU takes an exception; the
 *  QEMU harness judges any image that prints it as crashed. */
#define BSP_EXCEPTION_MARKER "*** EXCEPTION: "

/** Exit status after an exception report. */
#define BSP_EXIT_EXCEPTION 99

#endif /* DRDC_BOARD_H */
