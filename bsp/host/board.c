/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Host (Linux) board: stdio console, exit status, and a report of
 *        fatal signals in the same form as the bare-metal exception report.
 */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "drdc_board.h"

const char bsp_name[] = "host";

void bsp_putc(int c)
{
  (void)putchar(c);
}

void bsp_exit(int status)
{
  exit(status);
}

static void write_text(const char *s)
{
  /* write() is async-signal-safe; stdio is not. */
  if (write(STDOUT_FILENO, s, strlen(s)) < 0) {
    _exit(BSP_EXIT_EXCEPTION);
  }
}

static void on_fatal_signal(int sig)
{
  write_text("\n" BSP_EXCEPTION_MARKER "signal ");
  write_text(sig == SIGSEGV  ? "SIGSEGV"
             : sig == SIGBUS ? "SIGBUS"
             : sig == SIGILL ? "SIGILL"
             : sig == SIGFPE ? "SIGFPE"
                             : "SIGABRT");
  write_text("\n");
  _exit(BSP_EXIT_EXCEPTION);
}

/* Runs before main() in every host image: line-buffered console so the
 * harness sees each line as it is printed, and fatal signals reported. */
__attribute__((__constructor__)) static void host_board_init(void)
{
  static const int sigs[] = {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT};
  size_t i;

  (void)setvbuf(stdout, NULL, _IOLBF, 0);
#ifndef __SANITIZE_ADDRESS__
  /* Under AddressSanitizer its own handlers give the better report. */
  for (i = 0; i < sizeof sigs / sizeof sigs[0]; i++) {
    (void)signal(sigs[i], on_fatal_signal);
  }
#else
  (void)sigs;
  (void)i;
  (void)on_fatal_signal;
#endif
}

/* The host has no deterministic counter; benchmarks run on the QEMU boards
 * only. These keep the interface complete. */
const uint32_t bsp_spin_insns_per_iteration = 1u;
const uint32_t bsp_ticks_mask = 0xFFFFFFFFu;

void bsp_ticks_start(void)
{
}

uint32_t bsp_ticks(void)
{
  return 0u;
}

void bsp_spin(uint32_t n)
{
  volatile uint32_t i;

  for (i = 0u; i < n; i++) {
  }
}
