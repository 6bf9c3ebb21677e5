/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Digest primitives of the conformance check.
 */
#include <stddef.h>

#include "golden.h"

void golden_start(golden_t *g, uint32_t rng)
{
  unsigned k;

  g->crc = 0xFFFFFFFFu;
  g->rng = rng;
  g->records = 0u;
  g->function = NULL;
  for (k = 0u; k < GOLDEN_INPUTS_MAX; k++) {
    g->inputs[k].name = NULL;
    g->inputs[k].value = 0;
    g->inputs[k].text = NULL;
  }
  g->input_count = 0u;
  g->record = NULL;
  g->context = NULL;
}

uint32_t golden_crc_u32(uint32_t crc, uint32_t value)
{
  int byte;

  for (byte = 0; byte < 4; byte++) {
    int bit;

    crc ^= (value >> (8 * byte)) & 0xFFu;
    for (bit = 0; bit < 8; bit++) {
      /* reflected CRC-32 polynomial 0x04C11DB7 */
      crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
  }
  return crc;
}

/* One record of the trace: one value as the part passed it. */
static void record(golden_t *g, uint64_t value, unsigned bytes)
{
  if (g->record != NULL) {
    g->record(g->context, g, value, bytes);
  }
  g->records++;
}

void golden_u32(golden_t *g, uint32_t value)
{
  g->crc = golden_crc_u32(g->crc, value);
  record(g, value, 4u);
}

void golden_u64(golden_t *g, uint64_t value)
{
  /* the bytes of the two halves, least significant first: the stream
   * two golden_u32 calls would fold */
  g->crc = golden_crc_u32(g->crc, (uint32_t)value);
  g->crc = golden_crc_u32(g->crc, (uint32_t)(value >> 32));
  record(g, value, 8u);
}

void golden_i32(golden_t *g, int32_t value)
{
  golden_u32(g, (uint32_t)value);
}

void golden_i64(golden_t *g, int64_t value)
{
  golden_u64(g, (uint64_t)value);
}

#if GOLDEN_TRACE
void golden_fn(golden_t *g, const char *function)
{
  g->function = function;
  g->input_count = 0u;
}

static void add_input(golden_t *g, const char *name, int64_t value,
                      const char *text)
{
  if (g->input_count < GOLDEN_INPUTS_MAX) {
    g->inputs[g->input_count].name = name;
    g->inputs[g->input_count].value = value;
    g->inputs[g->input_count].text = text;
    g->input_count++;
  }
}

void golden_in(golden_t *g, const char *name, int64_t value)
{
  add_input(g, name, value, NULL);
}

void golden_in_text(golden_t *g, const char *name, const char *text)
{
  add_input(g, name, 0, text);
}
#endif

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
  golden_t g;

  golden_start(&g, GOLDEN_SEED);
  part(&g);
  return ~g.crc;
}
