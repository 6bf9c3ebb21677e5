/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The example on a bare-metal PowerPC e500 (QEMU mpc8544ds): the
 *        console on the 16550 UART, the end through the reset register; the
 *        memory functions are in ../common/freestanding_mem.c.
 */
#include <stdint.h>

#include "example.h"

#define CCSR_BASE        0xE0000000u
#define UART0_THR        (CCSR_BASE + 0x4500u) /* transmit holding register */
#define UART0_LSR        (CCSR_BASE + 0x4505u) /* line status register */
#define UART_LSR_THRE    0x20u /* transmit holding register empty */
#define GUTS_RSTCR       (CCSR_BASE + 0xE00B0u)
#define RSTCR_HRESET_REQ 0x2u /* QEMU: reset; with -no-reboot, exit */

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

/* The board has no way to pass a status out: the console says it. */
void example_stop(int status)
{
  (void)status;
  *(volatile uint32_t *)GUTS_RSTCR = RSTCR_HRESET_REQ;
  for (;;) {
  }
}
