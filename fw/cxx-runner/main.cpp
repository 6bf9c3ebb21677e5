/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Unity test runner of the C++ layer (drdc.hpp), the same markers
 * and summary as fw/test-runner, so that qemu/harness.py judges it.
 */
#include <drdc/version.h>

extern "C" {
#include "drdc_board.h"
}
#include "cxx/test_cxx.h"
#include "unity.h"

/* Unity calls these around every test; the suite needs no fixtures. */
extern "C" void setUp(void)
{
}

extern "C" void tearDown(void)
{
}

int main()
{
  bsp_puts("\n*** BEGIN OF TEST drdc-cxx-");
  bsp_puts(bsp_name);
  bsp_puts(" ***\n*** TEST VERSION: " DRDC_VERSION_STRING "\n");
  bsp_puts("*** TEST STATE: EXPECTED_PASS\n");
  bsp_puts("*** TEST BUILD: drdc.hpp " DRDC_VERSION_STRING "\n");
  bsp_puts("*** TEST TOOLS: " __VERSION__ "\n");

  UnityBegin(__FILE__);
  suite_cxx();
  const int failures = UnityEnd();

  if (failures == 0) {
    bsp_puts("\n*** END OF TEST drdc-cxx-");
    bsp_puts(bsp_name);
    bsp_puts(" ***\n");
  }
  return failures;
}
