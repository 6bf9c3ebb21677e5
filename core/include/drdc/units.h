/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_units
 * @brief Units of measure: a const table of named units with their
 *        dimension and exact SI factor, and conversion of fixed-point
 *        values between any two units of one dimension.
 */
#ifndef DRDC_UNITS_H
#define DRDC_UNITS_H

#include <stddef.h>
#include <stdint.h>

#include <drdc/status.h>

/**
 * @defgroup drdc_units Units of measure
 *
 * The library works in SI (libdrdc's data standard); other units are
 * converted at the edge with this module.
 *
 * **Names** are spelled as GNU units 2.22 spells them (`ft`, `nmi`,
 * `lbf`, `psi`, `knot`, `degree`, `rpm`, `kWh`, `Mbps`, ...), including
 * compound spellings GNU units accepts as one word (`m/s`, `km/hr`,
 * `ft^2`, `radian/s`, `btu/hr`). Names are case-sensitive, as in GNU
 * units (`Pa` is pascal, `mbar` millibar).
 *
 * **Dimension**: exponents of metre, kilogram, second, kelvin and bit (GNU
 * units' base units; `bit` is a base unit there too). The radian is
 * dimensionless, as in GNU units, so `rpm` converts to `Hz` and a
 * `radian` to the number 1.
 *
 * **Factor**: every unit has its SI value as an exact rational
 * `factor_num / factor_den` (lowest terms, both positive), with the
 * definition it comes from cited in the table (core/units/units.txt). It is
 * exact wherever the definition is (ft = 0.3048 m, lb = 0.45359237 kg,
 * nmi = 1852 m, lbf = lb x 9.80665 m/s^2 = 4.4482216152605 N, cal =
 * 4.184 J, the thermochemical calorie that GNU units' `cal` means, ...).
 * Units involving pi (degree, arcmin, arcsec, gon, turn, rpm, ...) use the
 * continued-fraction convergent pi ~ 245850922 / 78256779, whose relative
 * error is 2.5e-17: those factors are accurate to 1e-16, not exact.
 * Every numerator and denominator is below 2^56 (checked by the suite),
 * so a conversion to or from the unit's SI unit has a combined factor
 * that always fits with room for 7 bits of format change.
 *
 * **Temperature** is affine. `K`, `degC`, `degF` and `degR` here are
 * temperatures (points on a scale): 0 degC converts to 273.15 K and
 * 32 degF to 0 degC. The unit's `offset_num / offset_den` is its zero in
 * its own unit: SI = (value + offset) x factor (degC: offset 273.15,
 * degF: 459.67 with factor 5/9, K and degR: 0). GNU units' names
 * `tempC`, `tempF`, `tempR` and `tempK` are accepted with the same
 * meaning. Note that GNU units' own `degC` and `degF` are temperature
 * *differences* (1 degC = 1 K, 1 degF = 5/9 K, no offset); for a
 * difference use `K` or `degR` (a Rankine or Kelvin degree is both a
 * point and a difference), or convert both ends.
 *
 * **Fixed-point values**: a value is an int64_t `raw` with `frac` fraction
 * bits (real value = raw / 2^frac), frac 0..62, chosen per call for the
 * input and the output independently: Q47.16 metres is frac 16, Q15.16
 * values widened to int64_t likewise, nano-units are not needed because
 * the unit itself can be `ns` or `nm`.
 *
 * **Rounding**: one rounding per conversion. The exact rational result
 * raw_out = (raw_in / 2^from_frac + offset_from) x factor_from /
 * factor_to - offset_to, times 2^to_frac, is rounded once to nearest,
 * ties away from zero, with drdc_fx_muldiv_s64() (exact 128-bit
 * intermediate). Error <= 0.5 LSB of the output (plus, for units
 * involving pi, the 2.5e-17 relative error of the pi convergent).
 * @{
 */

/** Number of base dimensions: m, kg, s, K, bit. */
#define DRDC_UNITS_DIMENSIONS 5

/** Index of the metre in drdc_unit_t::dimension. */
#define DRDC_UNITS_DIM_METRE 0
/** Index of the kilogram in drdc_unit_t::dimension. */
#define DRDC_UNITS_DIM_KILOGRAM 1
/** Index of the second in drdc_unit_t::dimension. */
#define DRDC_UNITS_DIM_SECOND 2
/** Index of the kelvin in drdc_unit_t::dimension. */
#define DRDC_UNITS_DIM_KELVIN 3
/** Index of the bit (data) in drdc_unit_t::dimension. */
#define DRDC_UNITS_DIM_BIT 4

/** Largest fraction-bit count of a fixed-point value (int64_t raw). */
#define DRDC_UNITS_FRAC_MAX 62u

/** A unit of measure: a row of the const unit table, obtained from
 *  drdc_units_find() or drdc_units_at(). The table is stored compactly
 *  (about 4 bytes a unit plus its name), so the type is opaque: read a
 *  unit's name, dimension, factor and offset with drdc_units_describe(). */
typedef struct drdc_unit drdc_unit_t;

/** What a unit is: its row of the table, decoded by drdc_units_describe(). */
typedef struct drdc_unit_info {
  const char *name; /**< GNU units spelling, NUL-terminated (in the table) */
  /** exponents of m, kg, s, K, bit (DRDC_UNITS_DIM_*) */
  int8_t dimension[DRDC_UNITS_DIMENSIONS];
  int64_t factor_num; /**< SI value of one unit: factor_num / factor_den */
  int64_t factor_den; /**< > 0 */
  /** zero of the unit's scale in its own unit (temperatures), 0 for
   *  linear units: SI = (value + offset_num / offset_den) x factor */
  int64_t offset_num;
  int64_t offset_den; /**< > 0 */
} drdc_unit_info_t;

/**
 * Number of units in the table.
 *
 * @return the count, at least 80; drdc_units_at() takes 0..count - 1.
 */
size_t drdc_units_count(void);

/**
 * Unit number `index` of the table, for listing every unit.
 *
 * @param index 0..drdc_units_count() - 1
 * @return the unit, or NULL when `index` is out of range
 */
const drdc_unit_t *drdc_units_at(size_t index);

/**
 * Name, dimension, SI factor and offset of a unit.
 *
 * @param unit a unit of the table (from drdc_units_find() or
 *             drdc_units_at())
 * @param[out] info the unit decoded; `info->name` points into the const
 *             table; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `unit` or `info` is NULL
 * @retval DRDC_E_UNKNOWN_UNIT `unit` is not a row of the table
 *
 * Cost: a walk over the names before the unit's (at most about 1 KiB of
 * characters); the other fields are table reads.
 *
 * @code
 * const drdc_unit_t *ft;
 * drdc_unit_info_t info;
 * drdc_units_find("ft", 2, &ft);
 * drdc_units_describe(ft, &info);  // info.factor_num / info.factor_den
 *                                  //   = 381 / 1250 (0.3048 m)
 * @endcode
 */
drdc_status_t drdc_units_describe(const drdc_unit_t *unit,
                                  drdc_unit_info_t *info);

/**
 * Find a unit by its name.
 *
 * @param name   the name's characters, not necessarily NUL-terminated;
 *               exactly `length` of them are read, never more
 * @param length number of characters of `name`
 * @param[out] unit the table row; unchanged on error
 * @retval DRDC_OK found, `*unit` written
 * @retval DRDC_E_NULL `name` or `unit` is NULL
 * @retval DRDC_E_UNKNOWN_UNIT no unit has this name (also for length 0 or
 *         a name longer than any unit's)
 *
 * @code
 * const drdc_unit_t *ft;
 * drdc_units_find("ft", 2, &ft);   // drdc_units_describe(ft, ...) gives
 *                                  //   381 / 1250 (0.3048 m)
 * @endcode
 */
drdc_status_t drdc_units_find(const char *name, size_t length,
                              const drdc_unit_t **unit);

/**
 * Convert a fixed-point value from one unit to another of the same
 * dimension.
 *
 * @param raw       input value, real value raw / 2^from_frac in unit `from`
 * @param from_frac fraction bits of the input, 0..62
 * @param from      unit of the input (a table row)
 * @param to_frac   fraction bits of the output, 0..62
 * @param to        unit of the output (a table row)
 * @param[out] out  result, real value *out / 2^to_frac in unit `to`,
 *                  rounded once to nearest, ties away from zero;
 *                  unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `from`, `to` or `out` is NULL
 * @retval DRDC_E_DIMENSION `from` and `to` have different dimensions
 * @retval DRDC_E_RANGE from_frac or to_frac above 62, or the exact
 *         combined factor factor_from x factor_to^-1 x 2^(to_frac -
 *         from_frac) (and for temperatures the offset in input LSB) does
 *         not fit 63-bit integers even after shifting powers of two into
 *         the input (only for far-apart unit pairs combined with a large
 *         change of format; never for a linear unit to or from its SI
 *         unit with |to_frac - from_frac| <= 7; for a temperature to or
 *         from K only when from_frac > 48 or |raw| > 2^53)
 * @retval DRDC_E_OVERFLOW the rounded result does not fit int64_t
 *
 * Scaling and overflow: the factor is reduced to lowest terms A / B
 * (cross-cancelling numerators and denominators, and powers of two), the
 * input gets the temperature offset as raw x q + p (exact), and the
 * result is drdc_fx_muldiv_s64(raw', A, B x q): a 128-bit product and one
 * rounding.
 *
 * Accuracy: correctly rounded (<= 0.5 LSB; units with pi add 2.5e-17
 * relative). Checked for every unit against GNU units 2.22 (`units -t
 * -d 15`): 1 unit to SI and 1 SI unit to the unit at formats where the
 * result has about 2^39 LSB, and random values both ways: 1852 vectors,
 * 1851 equal to GNU units' value rounded, one 1 LSB away (GNU units
 * prints 15 significant digits); largest relative error 2.4e-12, below
 * 1e-9 on every vector (tests/units/test_units.c).
 *
 * @code
 * const drdc_unit_t *ft, *m;
 * int64_t q;
 * drdc_units_find("ft", 2, &ft);
 * drdc_units_find("m", 1, &m);
 * drdc_units_convert(INT64_C(10) << 16, 16, ft, 16, m, &q);
 * // q = round(3.048 x 2^16) = 199754 (Q47.16 metres)
 * @endcode
 */
drdc_status_t drdc_units_convert(int64_t raw, unsigned from_frac,
                                 const drdc_unit_t *from, unsigned to_frac,
                                 const drdc_unit_t *to, int64_t *out);

/**
 * Whether two units measure the same quantity (same dimension).
 *
 * @param a, b units (table rows)
 * @retval DRDC_OK same dimension
 * @retval DRDC_E_NULL `a` or `b` is NULL
 * @retval DRDC_E_DIMENSION different dimensions
 */
drdc_status_t drdc_units_compatible(const drdc_unit_t *a, const drdc_unit_t *b);

/** @} */

#endif /* DRDC_UNITS_H */
