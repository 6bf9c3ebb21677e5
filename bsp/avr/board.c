/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief AVR ATmega2560 under simavr: console on USART0 (simavr prints
 *        what it sends), the end by sleeping with interrupts off, which
 *        ends simavr. No exception report: the AVR has no traps.
 */
#include <stdint.h>

#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>

#include "drdc_board.h"

const char bsp_name[] = "avr";

void bsp_putc(int c)
{
  if ((UCSR0B & (uint8_t)(1u << TXEN0)) == 0u) {
    UCSR0B = (uint8_t)(1u << TXEN0);
  }
  while ((UCSR0A & (uint8_t)(1u << UDRE0)) == 0u) {
  }
  UDR0 = (uint8_t)c;
}

void bsp_exit(int status)
{
  /* simavr cannot pass a status out: the console carries the verdict */
  (void)status;
  cli();
  for (;;) {
    sleep_mode();
  }
}

/* No benchmark runs on this board: a counter that never moves. */
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
  (void)n;
}
