/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Digest primitives of the conformance check.
 */
#include "golden.h"

void golden_u32(golden_t *g, uint32_t value)
{
  int byte;

  for (byte = 0; byte < 4; byte++) {
    int bit;

    g->crc ^= (value >> (8 * byte)) & 0xFFu;
    for (bit = 0; bit < 8; bit++) {
      /* reflected CRC-32 polynomial 0x04C11DB7 */
      g->crc = (g->crc >> 1) ^ (0xEDB88320u & (0u - (g->crc & 1u)));
    }
  }
}

void golden_u64(golden_t *g, uint64_t value)
{
  golden_u32(g, (uint32_t)value);
  golden_u32(g, (uint32_t)(value >> 32));
}

void golden_i32(golden_t *g, int32_t value)
{
  golden_u32(g, (uint32_t)value);
}

void golden_i64(golden_t *g, int64_t value)
{
  golden_u64(g, (uint64_t)value);
}

uint32_t golden_next(golden_t *g)
{
  uint32_t x = g->rng;

  x ^= x << 13;
  x ^= x >> 17;
  x ^= x << 5;
  g->rng = x;
  return x;
}

uint32_t golden_part_digest(void (*part)(golden_t *))
{
  golden_t g = {0xFFFFFFFFu, 2463534242u};

  part(&g);
  return ~g.crc;
}
