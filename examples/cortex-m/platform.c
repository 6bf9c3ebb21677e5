/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The example on a Cortex-M (M0/M0+, M3, M4F) of QEMU's MPS2
 *        boards: vector table, reset, and a console and an exit through
 *        Arm semihosting, with no C library I/O at all.
 *
 * On a real board, replace all three, not only the text: semihosting's
 * BKPT 0xAB without a debugger attached is a HardFault (the core then
 * locks up), so write example_write() for the board's UART and stop()
 * for what the board does at the end; and give link.ld the MCU's own
 * flash and RAM (the MPS2 boards have 4 MiB of SRAM at 0x20000000, so
 * the initial stack pointer here is 0x20400000).
 */
#include <stdint.h>

#include "example.h"

/* Arm semihosting: operation in r0, argument in r1, then BKPT 0xAB. */
#define SEMIHOSTING_SYS_WRITE0       0x04u
#define SEMIHOSTING_SYS_EXIT         0x18u
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u
#define ADP_STOPPED_RUNTIME_ERROR    0x20023u

extern uint32_t __data_load, __data_start, __data_end;
extern uint32_t __bss_start, __bss_end, __stack_top;

static void semihosting(uint32_t operation, uint32_t argument)
{
  register uint32_t r0 __asm__("r0") = operation;
  register uint32_t r1 __asm__("r1") = argument;

  __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
}

void example_write(const char *text)
{
  semihosting(SEMIHOSTING_SYS_WRITE0, (uint32_t)(uintptr_t)text);
}

static void stop(int status)
{
  for (;;) {
    semihosting(SEMIHOSTING_SYS_EXIT, (status == 0)
                                          ? ADP_STOPPED_APPLICATION_EXIT
                                          : ADP_STOPPED_RUNTIME_ERROR);
  }
}

/* A fault ends the run: semihosting first says so under QEMU or a
 * debugger (a fault inside this handler locks the core up, which stops it
 * all the same on a board without one). */
static void fault(void)
{
  stop(1);
}

void reset(void);

void reset(void)
{
  const uint32_t *src = &__data_load;
  uint32_t *dst;

#if defined(__ARM_FP)
  /* hard-float ABI (Cortex-M4F): CP10 and CP11 full access first (the
   * loops below may become calls of memcpy and memset) */
  *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
  __asm__ volatile("dsb\n"
                   "isb\n" ::
                       : "memory");
#endif
  for (dst = &__data_start; dst < &__data_end; dst++) {
    *dst = *src;
    src++;
  }
  for (dst = &__bss_start; dst < &__bss_end; dst++) {
    *dst = 0u;
  }
  stop(example_run());
}

typedef void (*vector_t)(void);

__attribute__((section(".vectors"), used)) static const vector_t vectors[16] = {
    (vector_t)(uintptr_t)&__stack_top,
    reset,
    fault,
    fault,
    fault,
    fault,
    fault,
    0,
    0,
    0,
    0,
    fault,
    fault,
    0,
    fault,
    fault,
};
