/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The board interface every bsp/<board>/ folder implements.
 *
 * Firmware images (fw/) use only this header to talk to the board; the
 * library (core/, fixed/) never includes it.
 */
#ifndef DRDC_BSP_H
#define DRDC_BSP_H

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

/** Prefix of the line a board prints when the CPU takes an exception; the
 *  QEMU harness judges any image that prints it as crashed. */
#define BSP_EXCEPTION_MARKER "*** EXCEPTION: "

/** Exit status after an exception report. */
#define BSP_EXIT_EXCEPTION 99

#endif /* DRDC_BSP_H */
