/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The board interface (bsp/drdc_board.h) on RTEMS: the RTEMS console and
 *        exit(). Any RTEMS BSP, so no board code of ours is involved.
 */
#include <stdio.h>
#include <stdlib.h>

#include "drdc_board.h"

const char bsp_name[] = "rtems";

void bsp_putc(int c)
{
  (void)putchar(c);
}

void bsp_exit(int status)
{
  exit(status);
}

/* Benchmarks run on the QEMU boards; RTEMS keeps the interface only. */
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
