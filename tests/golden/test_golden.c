/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Cross-architecture bit-exactness: every target must compute the
 *        committed conformance digest. The harness also checks that all
 *        images of one run print the same digest line.
 */
#include "drdc_board.h"
#include "console.h"
#include "digest.h"
#include "golden.h"
#include "suites.h"
#include "unity.h"

static void golden_part(golden_t *g, const char *name, void (*part)(golden_t *))
{
  part(g);
  bsp_puts("golden digest after ");
  bsp_puts(name);
  bsp_puts(": ");
  console_put_hex32(~g->crc);
  bsp_putc('\n');
}

static void test_golden_digest_is_the_conformance_value(void)
{
  golden_t g = {0xFFFFFFFFu, 2463534242u};
  uint32_t digest;

  /* one line per module, so a port that differs sees where */
  golden_part(&g, "time", golden_time);
  golden_part(&g, "time scales", golden_time_scales);
  golden_part(&g, "fixed", golden_fixed);
  golden_part(&g, "orient", golden_orient);
  golden_part(&g, "interop", golden_interop);
  golden_part(&g, "geo", golden_geo);
  golden_part(&g, "poses and JAUS bodies", golden_poses);
  digest = ~g.crc;
  bsp_puts("*** GOLDEN DIGEST: ");
  console_put_hex32(digest);
  bsp_putc('\n');
  /* A change of any output changes the digest: update digest.h only with
   * a change that is meant to alter results, and say so in the commit. */
  TEST_ASSERT_EQUAL_HEX32(DRDC_GOLDEN_DIGEST, digest);
}

void suite_golden(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_golden_digest_is_the_conformance_value);
}
