/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief QEMU virt (RV32): 16550 UART console, exit through the SiFive
 *        test finisher (the status reaches QEMU's exit code), trap report,
 *        cycle counter.
 */
#include <stdint.h>

#include "drdc_board.h"
#include "console.h"

/* QEMU hw/riscv/virt.c memory map */
#define UART0_BASE    0x10000000u
#define UART0_THR     (UART0_BASE + 0u) /* transmit holding register */
#define UART0_LSR     (UART0_BASE + 5u) /* line status register */
#define UART_LSR_THRE 0x20u             /* transmit holding register empty */
#define TEST_FINISHER 0x00100000u
/* sifive_test: 0x5555 ends QEMU with status 0, (status << 16) | 0x3333
 * with `status` */
#define FINISHER_PASS 0x5555u
#define FINISHER_FAIL 0x3333u

const char bsp_name[] = "riscv32";

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
  volatile uint32_t *finisher = (volatile uint32_t *)TEST_FINISHER;

  if (status == 0) {
    *finisher = FINISHER_PASS;
  } else {
    /* the finisher's status field has 16 bits */
    *finisher = (((uint32_t)status & 0xFFFFu) << 16) | FINISHER_FAIL;
  }
  for (;;) {
  }
}

/* Exception causes of the RISC-V privileged specification (mcause with
 * its interrupt bit clear). */
static const char *cause_name(uint32_t mcause)
{
  static const char *const names[16] = {
      "instruction address misaligned",
      "instruction access fault",
      "illegal instruction",
      "breakpoint",
      "load address misaligned",
      "load access fault",
      "store address misaligned",
      "store access fault",
      "environment call from U-mode",
      "environment call from S-mode",
      "reserved",
      "environment call from M-mode",
      "instruction page fault",
      "load page fault",
      "reserved",
      "store page fault",
  };

  if ((mcause & 0x80000000u) != 0u) {
    return "interrupt";
  }
  return (mcause < 16u) ? names[mcause] : "unknown";
}

void bsp_exception_report(uint32_t mcause, uint32_t mepc, uint32_t mtval);

/* Called from start.S on its own stack; reports and ends the run. */
void bsp_exception_report(uint32_t mcause, uint32_t mepc, uint32_t mtval)
{
  bsp_puts("\n" BSP_EXCEPTION_MARKER);
  bsp_puts(cause_name(mcause));
  bsp_puts(" (mcause ");
  console_put_hex32(mcause);
  bsp_puts(") at ");
  console_put_hex32(mepc);
  bsp_puts(" mtval=");
  console_put_hex32(mtval);
  bsp_putc('\n');
  bsp_exit(BSP_EXIT_EXCEPTION);
}

/* Benchmark counter: mcycle, which QEMU -icount advances with the
 * executed instructions. */
const uint32_t bsp_spin_insns_per_iteration = 2u;
const uint32_t bsp_ticks_mask = 0xFFFFFFFFu;

void bsp_ticks_start(void)
{
  /* mcycle runs from reset. */
}

uint32_t bsp_ticks(void)
{
  uint32_t cycles;

  /* Zicsr: outside rv32imac in the ISA specifications from 2019 on */
  __asm__ volatile(".option push\n"
                   ".option arch, +zicsr\n"
                   "csrr %0, mcycle\n"
                   ".option pop\n"
                   : "=r"(cycles));
  return cycles;
}

/* Two instructions per iteration: addi and bnez. */
void bsp_spin(uint32_t n)
{
  if (n == 0u) {
    return;
  }
  __asm__ volatile("1: addi %0, %0, -1\n"
                   "bnez %0, 1b\n"
                   : "+r"(n));
}
