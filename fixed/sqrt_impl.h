/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_sqrt
 * @brief Internal part of the square roots: the seed table of the Q15.16
 *        root.
 */
#ifndef DRDC_SQRT_IMPL_H
#define DRDC_SQRT_IMPL_H

#include <stdint.h>

#include <drdc/compiler.h>

/** Seeds for H in [2^24, 2^26), indexed by (H >> 18) - FX_SQRT_SEED_FIRST. */
#define FX_SQRT_SEED_FIRST 64u
#define FX_SQRT_SEED_COUNT 192u

extern const uint16_t drdc__fx_sqrt_seed[FX_SQRT_SEED_COUNT] DRDC_FLASH_TABLE;

#endif /* DRDC_SQRT_IMPL_H */
