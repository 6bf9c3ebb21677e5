/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_units
 * @brief Internal: exact rationals of int64_t with overflow reported, for
 *        combining unit factors before the one rounding.
 */
#ifndef DRDC_UNITS_IMPL_H
#define DRDC_UNITS_IMPL_H

#include <stdint.h>

#include <drdc/status.h>

/** An exact rational num / den, den > 0, lowest terms after every
 *  operation. */
typedef struct units_rat {
  int64_t num;
  int64_t den;
} units_rat_t;

/** a x b, exact: cross-cancels before multiplying, so the result is in
 *  lowest terms. DRDC_E_RANGE when a part does not fit int64_t (outputs
 *  unchanged). */
drdc_status_t units_rat_mul(units_rat_t a, units_rat_t b, units_rat_t *out);

/** 1 / a for a != 0 (sign moved to the numerator); DRDC_E_RANGE for
 *  a == 0 or a numerator of INT64_MIN. */
drdc_status_t units_rat_inv(units_rat_t a, units_rat_t *out);

/** a - b, exact; DRDC_E_RANGE when a part does not fit int64_t. */
drdc_status_t units_rat_sub(units_rat_t a, units_rat_t b, units_rat_t *out);

/** x * y when it fits int64_t; DRDC_E_RANGE otherwise. */
drdc_status_t units_mul_s64(int64_t x, int64_t y, int64_t *out);

#endif /* DRDC_UNITS_IMPL_H */
