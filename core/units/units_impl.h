/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_units
 * @brief Internal: the compact table row and its readers, and exact
 *        rationals of int64_t with overflow reported, for combining unit
 *        factors before the one rounding.
 */
#ifndef DRDC_UNITS_IMPL_H
#define DRDC_UNITS_IMPL_H

#include <stdint.h>

#include <drdc/status.h>
#include <drdc/units.h>

/** An exact rational num / den, den > 0, lowest terms after every
 *  operation. */
typedef struct units_rat {
  int64_t num;
  int64_t den;
} units_rat_t;

/* The rationals are passed by pointer; `out` may be `a` or `b`: every
 * part is read before `out` is written. */

/** a x num / den (den > 0), exact: cross-cancels before multiplying,
 *  so the result is in lowest terms when a and num / den are; the same
 *  as a product of two rationals, with the second one passed as its two
 *  parts. DRDC_E_RANGE when a part
 *  does not fit int64_t (outputs unchanged). */
drdc_status_t drdc__units_rat_scale(const units_rat_t *a, int64_t num,
                                    int64_t den, units_rat_t *out);

/** 1 / a for a != 0 (sign moved to the numerator); DRDC_E_RANGE for
 *  a == 0 or a numerator of INT64_MIN. */
drdc_status_t drdc__units_rat_inv(const units_rat_t *a, units_rat_t *out);

/** a_num / a_den - b (a_den > 0), exact; DRDC_E_RANGE when a part does
 *  not fit int64_t. */
drdc_status_t drdc__units_rat_sub(int64_t a_num, int64_t a_den,
                                  const units_rat_t *b, units_rat_t *out);

/** x * y when it fits int64_t; DRDC_E_RANGE otherwise. */
drdc_status_t drdc__units_mul_s64(int64_t x, int64_t y, int64_t *out);

/** Steps of UNITS_SCALE_BITS bits in which a product's binary scale is
 *  counted: 2^32 fits int64_t, so a step is one exact product. */
#define UNITS_SCALE_BITS 32u

/** Largest |scale| in steps (an int8_t): 2^+-4064. */
#define UNITS_SCALE_MAX 127

/** a x num / den (den > 0, parts nonzero) as drdc__units_rat_scale()
 *  when the exact result fits; otherwise rounded: the exact 128-bit
 *  quotient as Q / 2^e (or 2^e / Q below 1) with Q of 61 to 62 bits, a
 *  relative error below 2^-61, and `*rounded` set to 1 (never cleared).
 *  A value beyond about 2^+-61 has no such form: with `scale` NULL it is
 *  refused (DRDC_E_OVERFLOW, outputs unchanged); otherwise `*out` is
 *  that value divided by 2^(UNITS_SCALE_BITS s), rounded the same way,
 *  and s is added to `*scale` (DRDC_E_OVERFLOW beyond
 *  +-UNITS_SCALE_MAX). */
drdc_status_t drdc__units_rat_mul(const units_rat_t *a, int64_t num,
                                  int64_t den, units_rat_t *out, int8_t *scale,
                                  uint8_t *rounded);

/** The scale of a conversion: the ratio F = factor_from / factor_to and
 *  the two offsets (zero of each scale in its own unit). */
typedef struct units_scale {
  units_rat_t ratio;
  units_rat_t from_offset;
  units_rat_t to_offset;
} units_scale_t;

/** Everything of a conversion before its one rounding, for validated
 *  arguments: from the raw input in `*a`, the exact input `*a` and factor
 *  A / B such that the result is round(a x A / B) (core/units/scale.c).
 *  DRDC_E_RANGE when they do not fit 63-bit integers; `*a` and `*factor`
 *  are then undefined. */
drdc_status_t drdc__units_prepare(unsigned from_frac,
                                  const units_scale_t *scale, unsigned to_frac,
                                  int64_t *a, units_rat_t *factor);

/** One unit: indices into the tables of core/units/table.c (generated
 *  by tools/tables/units_table.py); its name is the row's string in the
 *  names, in row order. Four bytes a unit instead of a pointer and four
 *  int64_t. */
struct drdc_unit {
  uint8_t factor_num; /**< factor numerator: drdc__units_number() index */
  uint8_t factor_den; /**< factor denominator: drdc__units_number() index */
  uint8_t dimension;  /**< row of the dimension table */
  uint8_t flags;      /**< UNITS_FLAGS(offset row, takes SI prefixes) */
};

/** The flags byte of an offset row (below 16) and a prefix flag (0, 1). */
#define UNITS_FLAGS(offset, prefix) ((offset) | ((prefix) << 4u))

/** Row of the unit's offset in the offset table, 0: linear. */
static inline unsigned units_offset_row(const drdc_unit_t *unit)
{
  return (unsigned)unit->flags & 0x0Fu;
}

/** Whether the unit takes SI prefixes in an expression (SI and
 *  SI-accepted units). */
static inline int units_takes_prefix(const drdc_unit_t *unit)
{
  return (((unsigned)unit->flags >> 4u) & 1u) != 0u;
}

/** The first name; the names follow each other, NUL-terminated, in the
 *  order of the rows. */
const char *drdc__units_names_first(void);

/** Row number of a unit of the table; drdc_units_count() for a pointer
 *  that is no row of the table. */
size_t drdc__units_index(const drdc_unit_t *unit);

/** Exponent `i` (DRDC_UNITS_DIM_*) of the unit's dimension. */
int8_t drdc__units_dimension(const drdc_unit_t *unit, size_t i);

/** Factor number `index` (a drdc_unit field), 1..2^63 - 1. */
int64_t drdc__units_number(uint8_t index);

/** The unit's offset num / den (0 / 1 for linear units). */
units_rat_t drdc__units_offset(const drdc_unit_t *unit);

/** The numerator (`part` 0) or denominator (`part` 1) of the unit's
 *  offset, as a value. */
int64_t drdc__units_offset_part(const drdc_unit_t *unit, unsigned part);

#endif /* DRDC_UNITS_IMPL_H */
