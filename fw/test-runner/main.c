/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Test runner: every Unity suite, framed by the RTEMS test markers
 *        so RTEMS's tester and other log parsers read the console. main()
 *        on bare-metal boards and the host; the RTEMS Init task
 *        (fw/test-runner/rtems_init.c) calls test_runner_run() instead.
 */
#include <drdc/version.h>

#include "drdc_board.h"
#include "runner.h"
#include "suites.h"
#include "unity.h"

/* Unity calls these around every test; the suites need no fixtures. */
void setUp(void)
{
}

void tearDown(void)
{
}

int test_runner_run(void)
{
  int failures;

  bsp_puts("\n*** BEGIN OF TEST drdc-");
  bsp_puts(bsp_name);
  bsp_puts(" ***\n*** TEST VERSION: " DRDC_VERSION_STRING "\n");
  bsp_puts("*** TEST STATE: EXPECTED_PASS\n");
  bsp_puts("*** TEST BUILD: drdc " DRDC_VERSION_STRING "\n");
  bsp_puts("*** TEST TOOLS: " __VERSION__ "\n");

  UnityBegin(__FILE__);
#define DRDC_SUITE(name) name();
#include "suites.def"
#if defined(__rtems__)
#include "suites_rtems.def"
#endif
#undef DRDC_SUITE
  failures = UnityEnd();

  /* RTEMS prints the end marker only for a run that met its state. */
  if (failures == 0) {
    bsp_puts("\n*** END OF TEST drdc-");
    bsp_puts(bsp_name);
    bsp_puts(" ***\n");
  }
  return failures;
}

#if !defined(__rtems__)
int main(void)
{
  return test_runner_run();
}
#endif
