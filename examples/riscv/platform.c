/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The example on a bare-metal RISC-V rv32imac (QEMU virt): the
 *        console on the 16550 UART, the end through the SiFive test
 *        finisher (QEMU exits with the status), and the four memory
 *        functions a freestanding program must give GCC (there is no C
 *        library).
 */
#include <stddef.h>
#include <stdint.h>

#include "example.h"

#define UART0_THR     0x10000000u /* transmit holding register */
#define UART0_LSR     0x10000005u /* line status register */
#define UART_LSR_THRE 0x20u       /* transmit holding register empty */
#define TEST_FINISHER 0x00100000u /* 0x5555: pass; status << 16 | 0x3333 */

void example_stop(int status);
void *memcpy(void *dst, const void *src, size_t n);
void *memmove(void *dst, const void *src, size_t n);
void *memset(void *dst, int c, size_t n);
int memcmp(const void *a, const void *b, size_t n);

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

void *memcpy(void *dst, const void *src, size_t n)
{
  return memmove(dst, src, n);
}

void *memmove(void *dst, const void *src, size_t n)
{
  unsigned char *d = dst;
  const unsigned char *s = src;
  size_t i;

  if (d < s) {
    for (i = 0; i < n; i++) {
      d[i] = s[i];
    }
  } else {
    for (i = n; i > 0; i--) {
      d[i - 1] = s[i - 1];
    }
  }
  return dst;
}

void *memset(void *dst, int c, size_t n)
{
  unsigned char *d = dst;
  size_t i;

  for (i = 0; i < n; i++) {
    d[i] = (unsigned char)c;
  }
  return dst;
}

int memcmp(const void *a, const void *b, size_t n)
{
  const unsigned char *x = a;
  const unsigned char *y = b;
  size_t i;

  for (i = 0; i < n; i++) {
    if (x[i] != y[i]) {
      return (x[i] < y[i]) ? -1 : 1;
    }
  }
  return 0;
}
