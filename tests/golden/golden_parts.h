/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The parts of the conformance digest, their expected digests and
 *        the block digests that find a port's first differing record.
 */
#ifndef DRDC_GOLDEN_PARTS_H
#define DRDC_GOLDEN_PARTS_H

#include <stdint.h>

#include "golden.h"

/** One module's part of the conformance digest. */
typedef struct golden_part {
  const char *name;         /**< as its digest line prints it */
  void (*run)(golden_t *g); /**< golden_time, ... */
  uint32_t digest;          /**< expected (digest.h) */
} golden_part_t;

#define GOLDEN_PARTS 7u

/** Every part, in the order the test runner prints them. */
extern const golden_part_t golden_parts[GOLDEN_PARTS];

/** Records per block: a differing part's trace prints the records of its
 *  first differing block, 57 to 80 bytes each (python/README.md). */
#define GOLDEN_BLOCK_RECORDS 1024u

/** What the host computes for a part's records (golden_expected.c). */
typedef struct golden_expected {
  uint32_t records;       /**< records of the part */
  uint32_t block_count;   /**< ceil(records / GOLDEN_BLOCK_RECORDS) */
  const uint32_t *blocks; /**< digest of each block of records */
} golden_expected_t;

/** Per part, in the order of golden_parts. */
extern const golden_expected_t golden_expected[GOLDEN_PARTS];

/** Called with each block's digest as a part runs. */
typedef void golden_block_fn(void *context, uint32_t block, uint32_t digest);

/** Block digests of a part's records: the CRC-32 of the bytes of each
 *  GOLDEN_BLOCK_RECORDS records (4 or 8 each, least significant first),
 *  independent of the records before the block. */
typedef struct golden_blocks {
  uint32_t crc; /**< of the current block so far, not inverted */
  golden_block_fn *done;
  void *context; /**< passed to done */
} golden_blocks_t;

/** Start block digests; set g's record hook to golden_blocks_record with
 *  context b. */
void golden_blocks_start(golden_blocks_t *b, golden_t *g, golden_block_fn *done,
                         void *context);
/** The record hook of block digests. */
void golden_blocks_record(void *context, const golden_t *g, uint64_t value,
                          unsigned bytes);
/** After the part: the digest of the last, shorter block if any. */
void golden_blocks_end(golden_blocks_t *b, const golden_t *g);

#endif /* DRDC_GOLDEN_PARTS_H */
