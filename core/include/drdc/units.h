/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_units
 * @brief Units of measure: a const table of named units with their
 *        dimension and exact SI factor, unit expressions (products,
 *        quotients, powers, SI prefixes), and conversion of fixed-point
 *        values between any two units or expressions of one dimension.
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
 * `ft^2`, `radian/s`, `btu/hr`) and GNU units' abbreviations of the
 * table's units (`mi`, `ly`, `ch`, `cc`, `qt`, `pt`, `tbsp`, `tsp`,
 * `gm`, `gr`, `lbm`, `ozt`, `ct`, `d`, `wk`, `yr`, `rev`, `dyn`, `pdl`,
 * `psia`, `degK`, `B`, `lfm`, and the Unix spellings `nmile`, `hz`, `pa`,
 * `ev`, `coul`, ...). Names are case-sensitive, as in GNU units (`Pa` is
 * pascal, `mbar` millibar).
 *
 * **Symbols that differ from GNU units**: where GNU units 2.22 reads a
 * symbol otherwise than the SI (and pint and udunits), the SI wins:
 *
 * - `h`: the hour, 3600 s (an SI-accepted symbol); GNU units: Planck's
 *   constant (use `hr` there).
 * - `rad`: the radian; GNU units: rad, the absorbed dose 0.01 Gy.
 * - `kt`: the knot, 1852 m / hr (as pint); GNU units: the kilotonne.
 * - `BTU`: GNU's `btu`, 1055.05585262 J; GNU units: unknown (pint's
 *   `BTU` is the ISO 1055.056 J).
 * - `degC`, `degF`: temperatures (points), see below; GNU units:
 *   temperature differences.
 * - `Gs`, `nt`: the gigasecond and the nanotonne (an SI prefix on s and
 *   t, as pint reads them); GNU units: the gauss and the newton (use
 *   `gauss` and `N`).
 * - `G`, `dB`: not units here; GNU units: the gravitational constant,
 *   a function. `B` is the byte, as in GNU units, but takes no prefix,
 *   so that `dB` stays no unit.
 * - `b`, `a`, `smi`: not units here; GNU units: the bar, the are, the
 *   international mile; the SI's `b` is the barn, ISO 80000-3's and
 *   pint's `a` the year, pint's `smi` the US survey mile.
 *
 * The decibel (`dB`, `dBm`) is deliberately absent: it is a logarithmic
 * ratio, 10 log10(p1 / p2), not a factor times a unit, so it fits no row
 * of this table and no product of units.
 *
 * **Dimension**: exponents of metre, kilogram, second, kelvin, bit and
 * ampere (GNU units' base units; `bit` is a base unit there too). The
 * radian and the steradian are dimensionless, as in GNU units, so `rpm`
 * converts to `Hz` and a `radian` to the number 1.
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
 * that always fits with room for 7 bits of format change; the one
 * exception is `eV` (and GNU units' `ev`), 1.602176634e-19 J exactly,
 * whose exact fraction (1602176634 / 10^28) has no 63-bit form: it is
 * stored as 1 / 6241509074460762608, relative error 4e-20.
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

/** Number of base dimensions: m, kg, s, K, bit, A. */
#define DRDC_UNITS_DIMENSIONS 6

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
/** Index of the ampere in drdc_unit_t::dimension. */
#define DRDC_UNITS_DIM_AMPERE 5

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
  /** exponents of m, kg, s, K, bit, A (DRDC_UNITS_DIM_*) */
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
 *         change of format; never for a linear unit other than eV (ev)
 *         to or from its SI unit with |to_frac - from_frac| <= 7; for a
 *         temperature to or from K only when from_frac > 48 or |raw| >
 *         2^53)
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
 * result has about 2^39 LSB, and random values both ways: 2576 vectors,
 * every one equal to GNU units' value rounded (tests/units/test_units.c;
 * the test allows 1 LSB, as GNU units prints 15 significant digits).
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

/** Longest unit expression drdc_units_parse() reads, in characters. */
#define DRDC_UNITS_EXPR_LENGTH_MAX 255u
/** Deepest nesting of parentheses in a unit expression. */
#define DRDC_UNITS_EXPR_DEPTH_MAX 4u
/** Largest |exponent| of a power in a unit expression (`^-9` .. `^9`). */
#define DRDC_UNITS_EXPR_POWER_MAX 9
/** Largest integer factor in a unit expression (`1/s`, `3600 s`). */
#define DRDC_UNITS_EXPR_NUMBER_MAX 1000000000

/** A unit expression parsed by drdc_units_parse(): what it measures and
 *  its SI value, the same parts as drdc_unit_info_t without a name. A
 *  plain value type: copy it, keep it, no pointer into the text. */
typedef struct drdc_units_expr {
  /** exponents of m, kg, s, K, bit, A (DRDC_UNITS_DIM_*) */
  int8_t dimension[DRDC_UNITS_DIMENSIONS];
  int64_t factor_num; /**< SI value: factor_num / factor_den, lowest terms */
  int64_t factor_den; /**< > 0 */
  /** zero of the scale in its own unit: only a lone temperature unit
   *  (`degC`, `degF`, ...) has one, 0 otherwise */
  int64_t offset_num;
  int64_t offset_den; /**< > 0 */
  /** 0: the factor is the exact product of the table's fractions; 1: a
   *  product did not fit 63 bits and was rounded (see drdc_units_parse()) */
  uint8_t rounded;
} drdc_units_expr_t;

/**
 * Parse a unit expression: products, quotients, integer powers,
 * parentheses and SI prefixes over the unit table.
 *
 * Grammar (blanks are spaces and tabs; every name is case-sensitive):
 *
 *     expression := blank* term (blank* ('*' | '/') blank* term)* blank*
 *     term       := factor (blank+ factor)*        juxtaposition
 *     factor     := (name | number | '(' expression ')') power?
 *     power      := '^' ('+' | '-')? digit+  |  digit+  (right after a name
 *                   or ')': `s2` is s^2, `(m/s)2` is (m/s)^2)
 *     number     := digit+                          (1 .. 10^9; `1/s`)
 *     name       := a table name  |  prefix table-name-that-takes-prefixes
 *
 * Precedence, as GNU units: a power binds tightest, then juxtaposition
 * (a blank), then `*` and `/` (equal, left to right). So `kg m/s^2` is
 * kg m s^-2, `m/s s` is m / (s s) (as GNU units; pint would read (m/s)
 * s), `m/s*s` is m. A quotient of juxtaposed factors is `kg/(m s)` or
 * `kg/m s` alike.
 *
 * Names: a name is a run of letters, `_` and bytes of 0x80 and above
 * (for `µ`). It is first looked up whole (drdc_units_find()); only if
 * that fails is it read as an SI prefix followed by a table unit that
 * takes prefixes. So an exact name always wins: `min` is the minute, not
 * milli-inch; `h` the hour, not hecto; `Pa` the pascal, `nm` the
 * nanometre, `kt` the knot, `mAh` milliampere-hours, `Gal` the galileo,
 * `cd` nothing. Prefixes, tried in this order, first match wins: the
 * words `yotta` .. `yocto` (`kilo`, `milli`, `micro`, ...), `da`, `µ`
 * (U+00B5 and U+03BC), then the letters `Y Z E P T G M k h d c m u n p f
 * a z y`. Units that take prefixes (`prefix` in core/units/units.txt):
 * the SI units and their spelled names (m, g, s, A, K, N, Pa, J, W, Hz,
 * C, V, ohm, F, H, Wb, T, S, rad, sr), the SI-accepted l, L, liter,
 * litre, t, tonne, eV, the customary bar, Wh, Ah, gauss, bit, byte.
 * Others take none: `kft` and `mdegC` are unknown.
 *
 * Temperatures: a unit with an offset (degC, degF, tempC, tempF) is
 * accepted only as the whole expression (blanks around it allowed), as
 * a point on its scale; inside a product, quotient or power it has no
 * meaning (use K or degR, which have no offset).
 *
 * Factor: the product of the table's exact fractions, 10^k of the
 * prefixes, the numbers and their powers, in lowest terms, exact
 * whenever every intermediate fits int64_t (`expr->rounded` 0). When a
 * product does not fit, its exact 128-bit quotient is rounded to Q / 2^e
 * (or 2^e / Q) with Q of 61 to 62 bits: a relative error below 2^-61
 * (4.4e-19) per product, and `rounded` is 1. A running product may go
 * beyond 2^+-61 on the way (`parsec^2/lightyear^2` passes 9.5e32): its
 * magnitude is then carried as a power of 2^32 beside the fraction, up
 * to 2^+-4064, and only the final factor must fit (folding the power
 * back is at most 3 more exact-or-rounded products). An expression of at most
 * DRDC_UNITS_EXPR_LENGTH_MAX characters makes fewer than 1200 products
 * (rounding: below 6e-16 in all) and uses fewer than 600 units whose
 * factor holds the pi convergent (2.5e-17 each: below 1.5e-14), so the
 * factor is within 2e-14 relative of the exact value, well within the
 * 1e-12 the library promises. Checked against GNU units 2.22 and pint
 * 0.25.3 on random expressions (tests/units/vectors_units_expr.h).
 *
 * @param text   the expression's characters, not necessarily
 *               NUL-terminated; exactly `length` of them are read
 * @param length number of characters, 1..DRDC_UNITS_EXPR_LENGTH_MAX
 * @param[out] expr the dimension, factor and offset; unchanged on error
 * @retval DRDC_OK parsed, `*expr` written
 * @retval DRDC_E_NULL `text` or `expr` is NULL
 * @retval DRDC_E_OVERLONG `length` is above DRDC_UNITS_EXPR_LENGTH_MAX
 * @retval DRDC_E_SYNTAX malformed: empty or blank text, a character
 *         outside the grammar (`+`, `.`, `,`, a control character), an
 *         operator without a factor on either side, unbalanced
 *         parentheses, `^` without digits, a number of 0 or above 10^9
 * @retval DRDC_E_UNKNOWN_UNIT a name is neither a table name nor a prefix
 *         and a unit that takes prefixes
 * @retval DRDC_E_RANGE parentheses nested deeper than
 *         DRDC_UNITS_EXPR_DEPTH_MAX, an exponent beyond
 *         +-DRDC_UNITS_EXPR_POWER_MAX, or a dimension exponent beyond
 *         +-127
 * @retval DRDC_E_DOMAIN a temperature with an offset (degC, degF, tempC,
 *         tempF) in a product, quotient, power or parentheses
 * @retval DRDC_E_OVERFLOW the factor does not fit 63-bit integers even
 *         rounded: beyond about 2^61 (2.3e18) or below 2^-61 with no
 *         exact 63-bit fraction, e.g. `lightyear^3/nm^3` (8.5e74), `Ym`
 *         (10^24), `uN^3 gon^2`; or a running product beyond 2^+-4064
 *         (`(Ym^9/ym^9)^3`)
 *
 * Cost: one table walk (about 2 KiB of names) for each name, and one for
 * each prefix that matches the name's start when the whole name is not
 * a unit; no heap, a fixed stack (DRDC_UNITS_EXPR_DEPTH_MAX + 1 levels).
 *
 * @code
 * drdc_units_expr_t torque;
 * drdc_units_parse("ft*lbf", 6, &torque);
 * // torque.factor_num / torque.factor_den
 * //   = 3389544870828501 / 2500000000000000 (1.3558179483314003 N m),
 * // dimension { 2, 1, -2, 0, 0, 0 }, rounded 0
 * @endcode
 */
drdc_status_t drdc_units_parse(const char *text, size_t length,
                               drdc_units_expr_t *expr);

/**
 * Convert a fixed-point value between two unit expressions of the same
 * dimension: drdc_units_convert() for parsed expressions.
 *
 * @param raw       input value, real value raw / 2^from_frac in `from`
 * @param from_frac fraction bits of the input, 0..62
 * @param from      expression of the input (drdc_units_parse())
 * @param to_frac   fraction bits of the output, 0..62
 * @param to        expression of the output
 * @param[out] out  result, real value *out / 2^to_frac in `to`, rounded
 *                  once to nearest, ties away from zero; unchanged on
 *                  error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `from`, `to` or `out` is NULL
 * @retval DRDC_E_DIMENSION `from` and `to` have different dimensions
 * @retval DRDC_E_RANGE from_frac or to_frac above 62, a factor or offset
 *         part that is not positive where it must be, or the combined
 *         factor (and temperature offset in input LSB) does not fit
 *         63-bit integers, as for drdc_units_convert()
 * @retval DRDC_E_OVERFLOW the rounded result does not fit int64_t
 *
 * The combined factor factor_from / factor_to is exact when it fits
 * 63 bits and otherwise rounded as in drdc_units_parse() (2^-61
 * relative). Accuracy: correctly rounded (<= 0.5 LSB) for exact factors;
 * otherwise within 0.5 LSB plus the factors' relative error (below 1e-12
 * in all, see drdc_units_parse()).
 *
 * @code
 * drdc_units_expr_t kmh, ms;
 * int64_t v;
 * drdc_units_parse("km/h", 4, &kmh);
 * drdc_units_parse("m/s", 3, &ms);
 * drdc_units_convert_expr(INT64_C(100) << 16, 16, &kmh, 16, &ms, &v);
 * // v = round(27.777... x 2^16) = 1820444
 * @endcode
 */
drdc_status_t drdc_units_convert_expr(int64_t raw, unsigned from_frac,
                                      const drdc_units_expr_t *from,
                                      unsigned to_frac,
                                      const drdc_units_expr_t *to,
                                      int64_t *out);

/** @} */

#endif /* DRDC_UNITS_H */
