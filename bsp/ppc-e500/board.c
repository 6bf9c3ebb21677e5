/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief QEMU mpc8544ds (e500v2): 16550 UART console, exit via reset
 *        request, exception report.
 */
#include <stdint.h>

#include "drdc_board.h"
#include "console.h"

/* CCSR block, mapped by start.S */
#define CCSR_BASE        0xE0000000u
#define UART0_THR        (CCSR_BASE + 0x4500u) /* transmit holding register */
#define UART0_LSR        (CCSR_BASE + 0x4505u) /* line status register */
#define UART_LSR_THRE    0x20u /* transmit holding register empty */
#define GUTS_RSTCR       (CCSR_BASE + 0xE00B0u)
#define RSTCR_HRESET_REQ 0x2u /* QEMU: reset; with -no-reboot, exit */

const char bsp_name[] = "ppc-e500";

static void uart_write(uint8_t byte)
{
  volatile uint8_t *lsr = (volatile uint8_t *)UART0_LSR;
  volatile uint8_t *thr = (volatile uint8_t *)UART0_THR;

  while ((*lsr & UART_LSR_THRE) == 0u) {
  }
  *thr = byte;
}

void bsp_putc(int c)
{
  if (c == '\n') {
    uart_write((uint8_t)'\r');
  }
  uart_write((uint8_t)c);
}

void bsp_exit(int status)
{
  /* The status cannot leave QEMU here: the console carries the verdict. */
  (void)status;
  *(volatile uint32_t *)GUTS_RSTCR = RSTCR_HRESET_REQ;
  for (;;) {
  }
}

/* Book E interrupt names by IVOR number (32..35 are the e500 SPE ones). */
static const char *interrupt_name(uint32_t ivor)
{
  static const char *const names[16] = {
      "critical input",
      "machine check",
      "data storage",
      "instruction storage",
      "external input",
      "alignment",
      "program",
      "floating-point unavailable",
      "system call",
      "auxiliary processor unavailable",
      "decrementer",
      "fixed-interval timer",
      "watchdog",
      "data TLB error",
      "instruction TLB error",
      "debug",
  };
  static const char *const spe_names[4] = {
      "SPE unavailable",
      "SPE floating-point data",
      "SPE floating-point round",
      "performance monitor",
  };

  if (ivor < 16u) {
    return names[ivor];
  }
  if ((ivor >= 32u) && (ivor < 36u)) {
    return spe_names[ivor - 32u];
  }
  return "unknown";
}

void bsp_exception_report(uint32_t ivor, uint32_t pc, uint32_t esr,
                          uint32_t dear);

/* Called from start.S on its own stack; reports and ends the run. */
void bsp_exception_report(uint32_t ivor, uint32_t pc, uint32_t esr,
                          uint32_t dear)
{
  bsp_puts("\n" BSP_EXCEPTION_MARKER);
  bsp_puts(interrupt_name(ivor));
  bsp_puts(" (IVOR");
  console_put_u64(ivor);
  bsp_puts(") at ");
  console_put_hex32(pc);
  bsp_puts(" ESR=");
  console_put_hex32(esr);
  bsp_puts(" DEAR=");
  console_put_hex32(dear);
  bsp_putc('\n');
  bsp_exit(BSP_EXIT_EXCEPTION);
}

/* Benchmark counter: the Book E time base (SPR 268 lower, 269 upper). */
const uint32_t bsp_spin_insns_per_iteration = 1u;
const uint32_t bsp_ticks_mask = 0xFFFFFFFFu;

void bsp_ticks_start(void)
{
  /* The time base runs from reset. */
}

uint32_t bsp_ticks(void)
{
  uint32_t lower;

  __asm__ volatile("mfspr %0, 268" : "=r"(lower));
  return lower;
}

/* One instruction per iteration: bdnz on the count register. */
void bsp_spin(uint32_t n)
{
  if (n == 0u) {
    return;
  }
  __asm__ volatile("mtctr %0\n"
                   "1: bdnz 1b\n"
                   :
                   : "r"(n)
                   : "ctr");
}
