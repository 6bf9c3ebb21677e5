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

/* One module's part from the fresh state, its digest printed on its own
 * line and folded into the conformance digest. */
static void golden_part(golden_t *all, const char *name,
                        void (*part)(golden_t *))
{
  uint32_t digest = golden_part_digest(part);

  bsp_puts("golden digest of ");
  bsp_puts(name);
  bsp_puts(": ");
  console_put_hex32(digest);
  bsp_putc('\n');
  golden_u32(all, digest);
}

static void test_golden_digest_is_the_conformance_value(void)
{
  golden_t all = {0xFFFFFFFFu, 0u};
  uint32_t digest;

  /* one line per module, so a port that differs sees where */
  golden_part(&all, "time", golden_time);
  golden_part(&all, "time scales", golden_time_scales);
  golden_part(&all, "fixed", golden_fixed);
  golden_part(&all, "orient", golden_orient);
  golden_part(&all, "interop", golden_interop);
  golden_part(&all, "geo", golden_geo);
  golden_part(&all, "poses and JAUS bodies", golden_poses);
  digest = ~all.crc;
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
