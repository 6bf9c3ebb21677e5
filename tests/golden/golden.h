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

/** Running digest state. */
typedef struct golden {
  uint32_t crc; /**< CRC-32 (IEEE 802.3, reflected) so far, not inverted */
  uint32_t rng; /**< xorshift32 state of the golden input generator */
} golden_t;

/** Fold the bytes of a value into the digest, least significant first, so
 *  the byte order of the target does not matter. */
void golden_u32(golden_t *g, uint32_t value);
void golden_u64(golden_t *g, uint64_t value);
void golden_i32(golden_t *g, int32_t value);
void golden_i64(golden_t *g, int64_t value);

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
