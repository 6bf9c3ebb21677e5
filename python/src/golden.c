/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The conformance digest's reference records for
 *        drdc/conformance.py: the parts of tests/golden run in the
 *        package's libdrdc.so, the records of an index range handed to a
 *        callback with their function and inputs.
 *
 * Only python/build_backend.py compiles this file (with tests/golden's
 * parts); drdc/conformance.py declares the prototypes.
 */
#include <stddef.h>
#include <stdint.h>

#include "golden.h"
#include "golden_parts.h"

/** Called for each record in the range: its index within the part, the
 *  function that produced it, its value (bytes 4 or 8) and the inputs. */
typedef void drdc_golden_record_cb(uint32_t index, const char *function,
                                   uint64_t value, unsigned bytes,
                                   const golden_input_t *inputs,
                                   unsigned input_count);

typedef struct range {
  uint32_t first;
  uint32_t end;
  drdc_golden_record_cb *callback;
} range_t;

unsigned drdc_golden_part_count(void)
{
  return GOLDEN_PARTS;
}

const char *drdc_golden_part_name(unsigned part)
{
  return part < GOLDEN_PARTS ? golden_parts[part].name : NULL;
}

/* The conformance digest, as tests/golden/test_golden.c folds it: the
 * CRC of the parts' digests. */
uint32_t drdc_golden_digest(void)
{
  golden_t all;
  unsigned k;

  golden_start(&all, 0u);
  for (k = 0u; k < GOLDEN_PARTS; k++) {
    golden_u32(&all, golden_part_digest(golden_parts[k].run));
  }
  return ~all.crc;
}

static void in_range(void *context, const golden_t *g, uint64_t value,
                     unsigned bytes)
{
  const range_t *r = context;

  if ((g->records >= r->first) && (g->records < r->end)) {
    r->callback(g->records, g->function, value, bytes, g->inputs,
                g->input_count);
  }
}

/* Run a part; the records first..end-1 go to callback (NULL: none).
 * Returns the part's digest; *records its record count. */
uint32_t drdc_golden_trace(unsigned part, uint32_t first, uint32_t end,
                           drdc_golden_record_cb *callback, uint32_t *records)
{
  range_t r;
  golden_t g;

  if (part >= GOLDEN_PARTS) {
    return 0u;
  }
  r.first = first;
  r.end = end;
  r.callback = callback;
  golden_start(&g, GOLDEN_SEED);
  if (callback != NULL) {
    g.record = in_range;
    g.context = &r;
  }
  golden_parts[part].run(&g);
  *records = g.records;
  return ~g.crc;
}
