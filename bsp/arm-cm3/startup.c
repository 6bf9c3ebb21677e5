/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief QEMU mps2-an385 (Cortex-M3): vector table, reset, fault reports,
 *        console and exit through newlib and ARM semihosting.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "drdc_board.h"
#include "console.h"

/* Provided by link.ld */
extern uint32_t __stack_top;
extern uint32_t __data_load, __data_start, __data_end;
extern uint32_t __bss_start, __bss_end;

/* Provided by newlib's rdimon (semihosting) library */
extern void initialise_monitor_handles(void);

int main(void);

/* System control block fault status registers (ARMv7-M) */
#define SCB_CFSR  (*(volatile uint32_t *)0xE000ED28u)
#define SCB_HFSR  (*(volatile uint32_t *)0xE000ED2Cu)
#define SCB_MMFAR (*(volatile uint32_t *)0xE000ED34u)
#define SCB_BFAR  (*(volatile uint32_t *)0xE000ED38u)
/* CCR.DIV_0_TRP: make integer division by zero fault instead of giving 0 */
#define SCB_CCR                  (*(volatile uint32_t *)0xE000ED14u)
#define SCB_CCR_DIV_0_TRP        (1u << 4)
#define SCB_CPACR                (*(volatile uint32_t *)0xE000ED88u)
#define SCB_CPACR_CP10_CP11_FULL (0xFu << 20)

const char bsp_name[] = "arm-cm3";

void bsp_putc(int c)
{
  (void)putchar(c);
}

void bsp_exit(int status)
{
  /* exit() flushes stdout; rdimon's _exit ends QEMU with `status`. */
  exit(status);
}

static const char *exception_name(uint32_t number)
{
  static const char *const names[16] = {
      "thread",       "reset",    "NMI",        "HardFault",
      "MemManage",    "BusFault", "UsageFault", "reserved",
      "reserved",     "reserved", "reserved",   "SVCall",
      "DebugMonitor", "reserved", "PendSV",     "SysTick",
  };

  return (number < 16u) ? names[number] : "IRQ";
}

void bsp_fault_report(const uint32_t *frame, uint32_t ipsr);

/* Called by fault_entry with the stacked exception frame
 * (r0-r3, r12, lr, pc, xpsr): reports and ends the run. */
void bsp_fault_report(const uint32_t *frame, uint32_t ipsr)
{
  uint32_t number = ipsr & 0x1FFu;

  (void)fflush(stdout);
  bsp_puts("\n" BSP_EXCEPTION_MARKER);
  bsp_puts(exception_name(number));
  bsp_puts(" (exception ");
  console_put_u64(number);
  bsp_puts(") at ");
  console_put_hex32(frame[6]);
  bsp_puts(" CFSR=");
  console_put_hex32(SCB_CFSR);
  bsp_puts(" HFSR=");
  console_put_hex32(SCB_HFSR);
  bsp_puts(" MMFAR=");
  console_put_hex32(SCB_MMFAR);
  bsp_puts(" BFAR=");
  console_put_hex32(SCB_BFAR);
  bsp_putc('\n');
  bsp_exit(BSP_EXIT_EXCEPTION);
}

/* Every fault and unexpected interrupt: find the frame on the stack that
 * was in use (EXC_RETURN bit 2) and report it. Thumb-1 instructions only,
 * so that the Cortex-M0 build (armv6-m) assembles the same code. */
__attribute__((__naked__)) static void fault_entry(void)
{
  __asm__ volatile("movs r0, #4\n"
                   "mov r1, lr\n"
                   "tst r1, r0\n"
                   "bne 1f\n"
                   "mrs r0, msp\n"
                   "b 2f\n"
                   "1: mrs r0, psp\n"
                   "2: mrs r1, ipsr\n"
                   "ldr r2, =bsp_fault_report\n"
                   "bx r2\n"
                   ".ltorg\n");
}

void bsp_reset(void) __attribute__((__noreturn__));

void bsp_reset(void)
{
  const uint32_t *src = &__data_load;
  uint32_t *dst;

#if defined(__ARM_FP)
  /* A hard-float build (Cortex-M4F): CP10 and CP11 full access first,
   * before any code of the image's ABI may touch the FPU (the copy loops
   * below may become newlib's memcpy and memset; the library never does). */
  SCB_CPACR |= SCB_CPACR_CP10_CP11_FULL;
  __asm__ volatile("dsb\n"
                   "isb\n"
                   :
                   :
                   : "memory");
#endif
  for (dst = &__data_start; dst < &__data_end; dst++) {
    *dst = *src;
    src++;
  }
  for (dst = &__bss_start; dst < &__bss_end; dst++) {
    *dst = 0u;
  }
  SCB_CCR |= SCB_CCR_DIV_0_TRP;
  initialise_monitor_handles();
  /* Line-buffered: the harness sees each line as it is printed. */
  (void)setvbuf(stdout, NULL, _IOLBF, 64);
  bsp_exit(main());
}

typedef void (*vector_t)(void);

/* Cortex-M vector table: initial stack pointer, then the handlers. */
__attribute__((__section__(".isr_vector"),
               __used__)) static const vector_t vectors[16 + 48] = {
    [0] = (vector_t)(uintptr_t)&__stack_top,
    [1] = bsp_reset,
    [2] = fault_entry,  /* NMI */
    [3] = fault_entry,  /* HardFault */
    [4] = fault_entry,  /* MemManage */
    [5] = fault_entry,  /* BusFault */
    [6] = fault_entry,  /* UsageFault */
    [11] = fault_entry, /* SVCall */
    [12] = fault_entry, /* DebugMonitor */
    [14] = fault_entry, /* PendSV */
    [15] = fault_entry, /* SysTick */
    [16 ... 63] = fault_entry,
};

/* Benchmark counter: SysTick, a 24-bit down-counter at the core clock. */
#define SYST_CSR                   (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR                   (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR                   (*(volatile uint32_t *)0xE000E018u)
#define SYST_CSR_ENABLE_CORE_CLOCK 5u /* ENABLE | CLKSOURCE, no interrupt */

const uint32_t bsp_spin_insns_per_iteration = 2u;
const uint32_t bsp_ticks_mask = 0xFFFFFFu;

void bsp_ticks_start(void)
{
  SYST_RVR = bsp_ticks_mask;
  SYST_CVR = 0u;
  SYST_CSR = SYST_CSR_ENABLE_CORE_CLOCK;
}

uint32_t bsp_ticks(void)
{
  /* counts down: invert so that the count increases */
  return bsp_ticks_mask - SYST_CVR;
}

/* Two instructions per iteration: subs and bne. */
void bsp_spin(uint32_t n)
{
  if (n == 0u) {
    return;
  }
  __asm__ volatile("1: subs %0, %0, #1\n"
                   "bne 1b\n"
                   : "+r"(n)
                   :
                   : "cc");
}
