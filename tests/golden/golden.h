/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The conformance digest: a CRC-32 over every output of the library
 *        for a fixed golden input set. A port is conformant when it prints
 *        the same digest as the committed DRDC_GOLDEN_DIGEST.
 */
#ifndef DRDC_GOLDEN_H
#define DRDC_GOLDEN_H

#include <stdint.h>

/* GOLDEN_TRACE 0 compiles the labels and inputs of the trace away, for
 * images whose RAM cannot hold their strings (fw/golden-part on AVR);
 * the digest is the same either way. */
#ifndef GOLDEN_TRACE
#define GOLDEN_TRACE 1
#endif

/** Named inputs a trace shows beside the records of one call. */
#define GOLDEN_INPUTS_MAX 12u

/** One named input of the current function: a number, or a text. */
typedef struct golden_input {
  const char *name;
  int64_t value;
  const char *text; /**< NULL: the input is value */
} golden_input_t;

struct golden;

/** Called for every record (one golden_u32/u64/i32/i64 call) when set:
 *  g->records is its index within the part, bytes 4 or 8. */
typedef void golden_record_fn(void *context, const struct golden *g,
                              uint64_t value, unsigned bytes);

/** Running digest state. */
typedef struct golden {
  uint32_t crc;     /**< CRC-32 (IEEE 802.3, reflected) so far, not inverted */
  uint32_t rng;     /**< xorshift32 state of the golden input generator */
  uint32_t records; /**< records folded so far: the next one's index */
  const char *function; /**< the function whose results follow, or NULL */
  golden_input_t inputs[GOLDEN_INPUTS_MAX]; /**< the inputs of that call */
  unsigned input_count;
  golden_record_fn *record; /**< NULL: digest only */
  void *context;            /**< passed to record */
} golden_t;

/** The state every part starts from, no trace. */
void golden_start(golden_t *g, uint32_t rng);

/** The first state of the golden input generator in every part. */
#define GOLDEN_SEED 2463534242u

/** The CRC-32 state crc (not inverted) continued over the 4 bytes of
 *  value, least significant first. */
uint32_t golden_crc_u32(uint32_t crc, uint32_t value);

/** Fold the bytes of a value into the digest, least significant first, so
 *  the byte order of the target does not matter. */
void golden_u32(golden_t *g, uint32_t value);
void golden_u64(golden_t *g, uint64_t value);
void golden_i32(golden_t *g, int32_t value);
void golden_i64(golden_t *g, int64_t value);

#if GOLDEN_TRACE
/** Name the function whose results the next records are, and forget the
 *  inputs of the one before: a label for the trace, nothing in the
 *  digest. */
void golden_fn(golden_t *g, const char *function);
/** Name an input of the current function (at most GOLDEN_INPUTS_MAX;
 *  more are dropped). Nothing in the digest. */
void golden_in(golden_t *g, const char *name, int64_t value);
/** The same for a text input; it must outlive the function's records. */
void golden_in_text(golden_t *g, const char *name, const char *text);
#else
#define golden_fn(g, function)        ((void)(g))
#define golden_in(g, name, value)     ((void)(g))
#define golden_in_text(g, name, text) ((void)(g))
#endif

/** Next golden input: xorshift32, the same sequence on every target. */
uint32_t golden_next(golden_t *g);

/** The digest of one module's part (golden_time, ...), run from the
 *  fresh state every part starts from: the same on every target, so a
 *  port that differs sees which module, and a part can run alone where
 *  the others do not fit (the AVR images, fw/golden-part). */
uint32_t golden_part_digest(void (*part)(golden_t *));

/** One per module: feed its functions golden inputs, fold their outputs
 *  and statuses into the digest. */
void golden_time(golden_t *g);
void golden_time_scales(golden_t *g);
void golden_fixed(golden_t *g);
void golden_orient(golden_t *g);
void golden_interop(golden_t *g);
void golden_geo(golden_t *g);
void golden_poses(golden_t *g);

#endif /* DRDC_GOLDEN_H */
