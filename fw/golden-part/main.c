/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief One module's part of the conformance digest alone
 *        (GOLDEN_PART, GOLDEN_NAME): for a part whose memory holds one
 *        module's tables at a time, not the whole test runner (AVR). It
 *        prints the line the test runner prints for that part, so the
 *        two compare as text (tests/integration/test_avr.py).
 */
#include "console.h"
#include "drdc_board.h"
#include "golden.h"

int main(void)
{
  uint32_t digest = golden_part_digest(GOLDEN_PART);

  bsp_puts("golden digest of " GOLDEN_NAME ": ");
  console_put_hex32(digest);
  bsp_putc('\n');
  bsp_exit(0);
  return 0;
}
