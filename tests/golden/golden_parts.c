/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The table of the conformance digest's parts and the block
 *        digests of their records.
 */
#include <stddef.h>

#include "digest.h"
#include "golden_parts.h"

const golden_part_t golden_parts[GOLDEN_PARTS] = {
    {"time", golden_time, DRDC_GOLDEN_DIGEST_TIME},
    {"time scales", golden_time_scales, DRDC_GOLDEN_DIGEST_TIME_SCALES},
    {"fixed", golden_fixed, DRDC_GOLDEN_DIGEST_FIXED},
    {"orient", golden_orient, DRDC_GOLDEN_DIGEST_ORIENT},
    {"interop", golden_interop, DRDC_GOLDEN_DIGEST_INTEROP},
    {"geo", golden_geo, DRDC_GOLDEN_DIGEST_GEO},
    {"poses and JAUS bodies", golden_poses, DRDC_GOLDEN_DIGEST_POSES},
};

void golden_blocks_start(golden_blocks_t *b, golden_t *g, golden_block_fn *done,
                         void *context)
{
  b->crc = 0xFFFFFFFFu;
  b->done = done;
  b->context = context;
  g->record = golden_blocks_record;
  g->context = b;
}

void golden_blocks_record(void *context, const golden_t *g, uint64_t value,
                          unsigned bytes)
{
  golden_blocks_t *b = context;

  b->crc = golden_crc_u32(b->crc, (uint32_t)value);
  if (bytes == 8u) {
    b->crc = golden_crc_u32(b->crc, (uint32_t)(value >> 32));
  }
  /* g->records is this record's index: the block ends with it */
  if (((g->records + 1u) % GOLDEN_BLOCK_RECORDS) == 0u) {
    b->done(b->context, g->records / GOLDEN_BLOCK_RECORDS, ~b->crc);
    b->crc = 0xFFFFFFFFu;
  }
}

void golden_blocks_end(golden_blocks_t *b, const golden_t *g)
{
  if ((g->records % GOLDEN_BLOCK_RECORDS) != 0u) {
    b->done(b->context, g->records / GOLDEN_BLOCK_RECORDS, ~b->crc);
  }
}
