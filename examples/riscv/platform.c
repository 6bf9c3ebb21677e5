/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The example on a bare-metal RISC-V rv32imac (QEMU virt): the
 *        console on the 16550 UART, the end through the SiFive test
 *        finisher (QEMU exits with the status); the memory functions
 *        are in ../common/freestanding_mem.c.
 */
#include <stdint.h>

#include "example.h"

#define UART0_THR     0x10000000u /* transmit holding register */
#define UART0_LSR     0x10000005u /* line status register */
#define UART_LSR_THRE 0x20u       /* transmit holding register empty */
#define TEST_FINISHER 0x00100000u /* 0x5555: pass; status << 16 | 0x3333 */

void example_stop(int status);

static void put(char c)
{
  while ((*(volatile uint8_t *)UART0_LSR & UART_LSR_THRE) == 0u) {
  }
  *(volatile uint8_t *)UART0_THR = (uint8_t)c;
}

void example_write(const char *text)
{
  for (; *text != '\0'; text++) {
    if (*text == '\n') {
      put('\r');
    }
    put(*text);
  }
}

void example_stop(int status)
{
  *(volatile uint32_t *)TEST_FINISHER =
      (status == 0) ? 0x5555u
                    : ((((uint32_t)status & 0xFFFFu) << 16) | 0x3333u);
  for (;;) {
  }
}
