/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Windows board (win64, run by Wine in ./waf check): stdio console,
 *        exit status, and a report of CPU exceptions and abort() in the same
 *        form as the bare-metal exception report.
 */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>

#include <fcntl.h>
#include <io.h>
#include <windows.h>

#include "drdc_board.h"

const char bsp_name[] = "win64";

/* Each line flushed as it ends: the C library of Windows has no line
 * buffering (_IOLBF means full buffering there), and the harness must see
 * each line as it is printed. */
void bsp_putc(int c)
{
  (void)putchar(c);
  if (c == '\n') {
    (void)fflush(stdout);
  }
}

void bsp_exit(int status)
{
  exit(status);
}

static void write_text(const char *s)
{
  DWORD written;

  (void)WriteFile(GetStdHandle(STD_OUTPUT_HANDLE), s, (DWORD)lstrlenA(s),
                  &written, NULL);
}

/* The first exception handler that sees an access violation, an illegal
 * instruction or a division by zero: instead of Windows's error dialog
 * (or Wine's crash dialog and backtrace), one line the harness knows. */
static LONG WINAPI on_exception(EXCEPTION_POINTERS *info)
{
  char line[80];
  DWORD code = info->ExceptionRecord->ExceptionCode;

  (void)fflush(stdout);
  (void)snprintf(line, sizeof line, "\n%sexception 0x%08lx\n",
                 BSP_EXCEPTION_MARKER, (unsigned long)code);
  write_text(line);
  ExitProcess(BSP_EXIT_EXCEPTION);
  return EXCEPTION_EXECUTE_HANDLER;
}

static void on_abort(int sig)
{
  (void)sig;
  (void)fflush(stdout);
  write_text("\n" BSP_EXCEPTION_MARKER "abort\n");
  ExitProcess(BSP_EXIT_EXCEPTION);
}

/* Runs before main() in every win64 image: the console in binary mode, so
 * that the harness sees the same bytes as from every other board (no CR
 * before each LF); no error dialog that would wait for a click. */
__attribute__((__constructor__)) static void win64_board_init(void)
{
  (void)_setmode(_fileno(stdout), _O_BINARY);
  (void)SetErrorMode(SEM_FAILCRITICALERRORS | SEM_NOGPFAULTERRORBOX);
  (void)SetUnhandledExceptionFilter(on_exception);
  (void)signal(SIGABRT, on_abort);
}

/* Windows has no deterministic counter; benchmarks run on the QEMU boards
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
