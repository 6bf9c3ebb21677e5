/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Test-runner image: every Unity suite, framed by the RTEMS test
 *        markers so RTEMS's tester and other log parsers read the console.
 */
#include <drdc/version.h>

#include "bsp.h"
#include "suites.h"
#include "unity.h"

/* Unity calls these around every test; the suites need no fixtures. */
void setUp(void)
{
}

void tearDown(void)
{
}

int main(void)
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
