/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Cross-architecture bit-exactness: every target must compute the
 *        committed conformance digest. The harness also checks that all
 *        images of one run print the same digest line. A part that
 *        differs prints the records of its first differing block, which
 *        python/drdc/conformance.py compares with the host's.
 */
#include "drdc_board.h"
#include "console.h"
#include "digest.h"
#include "golden.h"
#include "golden_parts.h"
#include "suites.h"
#include "unity.h"

#define NO_BLOCK 0xFFFFFFFFu

/* The block digests of one part against the host's. */
typedef struct block_check {
  const golden_expected_t *expected;
  uint32_t first_differing; /* block index, or NO_BLOCK */
} block_check_t;

static void check_block(void *context, uint32_t block, uint32_t digest)
{
  block_check_t *check = context;
  const golden_expected_t *e = check->expected;

  if ((check->first_differing == NO_BLOCK) &&
      ((block >= e->block_count) || (e->blocks[block] != digest))) {
    check->first_differing = block;
  }
}

/* The records of one block as "golden trace of <part>: <index>
 * <function> <value>" lines. */
typedef struct block_print {
  const char *name;
  uint32_t first;
  uint32_t end;
} block_print_t;

/* value as 0x and `digits` lower-case hex digits: a record's width */
static void put_hex(uint64_t value, unsigned digits)
{
  static const char hex[] = "0123456789abcdef";
  unsigned k;

  bsp_puts("0x");
  for (k = digits; k > 0u; k--) {
    bsp_putc(hex[(value >> (4u * (k - 1u))) & 0xFu]);
  }
}

static void print_record(void *context, const golden_t *g, uint64_t value,
                         unsigned bytes)
{
  const block_print_t *p = context;

  if ((g->records < p->first) || (g->records >= p->end)) {
    return;
  }
  bsp_puts("golden trace of ");
  bsp_puts(p->name);
  bsp_puts(": ");
  console_put_u64(g->records);
  bsp_putc(' ');
  bsp_puts(g->function != NULL ? g->function : "?");
  bsp_putc(' ');
  put_hex(value, 2u * bytes);
  bsp_putc('\n');
}

/* The records of block `block` of a part, framed so that a reader can
 * tell a cut log from a complete trace. */
static void print_block(const golden_part_t *part, uint32_t block,
                        uint32_t records)
{
  block_print_t p;
  golden_t g;

  p.name = part->name;
  p.first = block * GOLDEN_BLOCK_RECORDS;
  p.end = p.first + GOLDEN_BLOCK_RECORDS;
  bsp_puts("golden trace of ");
  bsp_puts(part->name);
  bsp_puts(": block ");
  console_put_u64(block);
  bsp_puts(" differs, records ");
  console_put_u64(p.first);
  bsp_puts(" to ");
  console_put_u64(p.end);
  bsp_puts(" of ");
  console_put_u64(records);
  bsp_putc('\n');
  golden_start(&g, GOLDEN_SEED);
  g.record = print_record;
  g.context = &p;
  part->run(&g);
  bsp_puts("golden trace of ");
  bsp_puts(part->name);
  bsp_puts(": end\n");
}

/* One module's part from the fresh state, its digest printed on its own
 * line and folded into the conformance digest; its trace printed when it
 * differs from the host's. Returns whether it is the expected one. */
static int golden_part(golden_t *all, unsigned k)
{
  const golden_part_t *part = &golden_parts[k];
  block_check_t check;
  golden_blocks_t blocks;
  golden_t g;
  uint32_t digest;

  check.expected = &golden_expected[k];
  check.first_differing = NO_BLOCK;
  golden_start(&g, GOLDEN_SEED);
  golden_blocks_start(&blocks, &g, check_block, &check);
  part->run(&g);
  golden_blocks_end(&blocks, &g);
  digest = ~g.crc;
  if ((check.first_differing == NO_BLOCK) &&
      (g.records < check.expected->records)) {
    /* fewer records than the host's: the trace starts where they end */
    check.first_differing = g.records / GOLDEN_BLOCK_RECORDS;
  }

  bsp_puts("golden digest of ");
  bsp_puts(part->name);
  bsp_puts(": ");
  console_put_hex32(digest);
  bsp_putc('\n');
  golden_u32(all, digest);
  if ((digest != part->digest) || (check.first_differing != NO_BLOCK)) {
    print_block(part,
                check.first_differing == NO_BLOCK ? 0u : check.first_differing,
                g.records);
    return 0;
  }
  return 1;
}

static void test_golden_digest_is_the_conformance_value(void)
{
  golden_t all;
  uint32_t digest;
  unsigned equal = 0u;
  unsigned k;

  golden_start(&all, 0u);
  /* one line per module, so a port that differs sees where */
  for (k = 0u; k < GOLDEN_PARTS; k++) {
    equal += (unsigned)golden_part(&all, k);
  }
  digest = ~all.crc;
  bsp_puts("*** GOLDEN DIGEST: ");
  console_put_hex32(digest);
  bsp_putc('\n');
  /* A change of any output changes the digest: update digest.h only with
   * a change that is meant to alter results, and say so in the commit. */
  TEST_ASSERT_EQUAL_HEX32(DRDC_GOLDEN_DIGEST, digest);
  /* each part and each block of its records as the host computes them
   * (digest.h, golden_expected.c): a stale table would hide a trace */
  TEST_ASSERT_EQUAL_UINT(GOLDEN_PARTS, equal);
}

void suite_golden(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_golden_digest_is_the_conformance_value);
}
