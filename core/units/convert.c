/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_units
 * @brief Conversion of a fixed-point value between two units of one
 *        dimension with a single rounding.
 */
#include <drdc/fixed_arith.h>

#include "units_impl.h"

drdc_status_t drdc_units_compatible(const drdc_unit_t *a, const drdc_unit_t *b)
{
  size_t i;

  if ((a == NULL) || (b == NULL)) {
    return DRDC_E_NULL;
  }
  for (i = 0u; i < (size_t)DRDC_UNITS_DIMENSIONS; i++) {
    if (drdc__units_dimension(a, i) != drdc__units_dimension(b, i)) {
      return DRDC_E_DIMENSION;
    }
  }
  return DRDC_OK;
}

drdc_status_t drdc_units_convert(int64_t raw, unsigned from_frac,
                                 const drdc_unit_t *from, unsigned to_frac,
                                 const drdc_unit_t *to, int64_t *out)
{
  units_scale_t scale;
  units_rat_t to_inv; /* 1 / factor_to */
  units_rat_t factor;
  int64_t a = raw;
  drdc_status_t st;

  if ((from == NULL) || (to == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc_units_compatible(from, to);
  if (st != DRDC_OK) {
    return st;
  }
  if ((from_frac > DRDC_UNITS_FRAC_MAX) || (to_frac > DRDC_UNITS_FRAC_MAX)) {
    return DRDC_E_RANGE;
  }
  /* F = factor_from / factor_to, exact, and the offsets */
  to_inv.num = drdc__units_number(to->factor_den);
  to_inv.den = drdc__units_number(to->factor_num);
  if (drdc__units_rat_scale(&to_inv, drdc__units_number(from->factor_num),
                            drdc__units_number(from->factor_den),
                            &scale.ratio) != DRDC_OK) {
    return DRDC_E_RANGE;
  }
  scale.from_offset = drdc__units_offset(from);
  scale.to_offset = drdc__units_offset(to);
  /* the exact input and factor (scale.c) */
  if (drdc__units_prepare(from_frac, &scale, to_frac, &a, &factor) != DRDC_OK) {
    return DRDC_E_RANGE;
  }
  /* the one rounding: 128-bit product, nearest, ties away from zero */
  return drdc_fx_muldiv_s64(a, factor.num, factor.den, out);
}

/* round(raw x factor_from x 2^(to_frac - from_frac) / factor_to) for a
 * linear expression, the power of two applied before 1 / factor_to
 * (`to_inv`); DRDC_E_RANGE when that factor does not fit either. */
static drdc_status_t convert_wide(int64_t raw, unsigned from_frac,
                                  const drdc_units_expr_t *from,
                                  unsigned to_frac, const units_rat_t *to_inv,
                                  int64_t *out)
{
  units_rat_t f;
  uint8_t rounded = 0u;
  uint64_t p2;

  if ((from->offset_num != 0) || (to_inv->num <= 0)) {
    return DRDC_E_RANGE;
  }
  f.num = from->factor_num;
  f.den = from->factor_den;
  p2 = (uint64_t)1u << ((to_frac >= from_frac) ? (to_frac - from_frac)
                                               : (from_frac - to_frac));
  if ((drdc__units_rat_mul(&f, (to_frac >= from_frac) ? (int64_t)p2 : 1,
                           (to_frac >= from_frac) ? 1 : (int64_t)p2, &f, NULL,
                           &rounded) != DRDC_OK) ||
      (drdc__units_rat_mul(&f, to_inv->num, to_inv->den, &f, NULL, &rounded) !=
       DRDC_OK)) {
    return DRDC_E_RANGE;
  }
  return drdc_fx_muldiv_s64(raw, f.num, f.den, out);
}

drdc_status_t drdc_units_convert_expr(int64_t raw, unsigned from_frac,
                                      const drdc_units_expr_t *from,
                                      unsigned to_frac,
                                      const drdc_units_expr_t *to, int64_t *out)
{
  units_scale_t scale;
  units_rat_t to_inv; /* 1 / factor_to */
  units_rat_t factor;
  uint8_t rounded = 0u;
  int64_t a = raw;
  size_t i;

  if ((from == NULL) || (to == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  for (i = 0u; i < (size_t)DRDC_UNITS_DIMENSIONS; i++) {
    if (from->dimension[i] != to->dimension[i]) {
      return DRDC_E_DIMENSION;
    }
  }
  if ((from_frac > DRDC_UNITS_FRAC_MAX) || (to_frac > DRDC_UNITS_FRAC_MAX) ||
      (from->factor_num <= 0) || (from->factor_den <= 0) ||
      (to->factor_num <= 0) || (to->factor_den <= 0) ||
      (from->offset_den <= 0) || (to->offset_den <= 0)) {
    return DRDC_E_RANGE;
  }
  /* F = factor_from / factor_to: exact, or rounded to 63 bits */
  to_inv.num = to->factor_den;
  to_inv.den = to->factor_num;
  if (drdc__units_rat_mul(&to_inv, from->factor_num, from->factor_den,
                          &scale.ratio, NULL, &rounded) != DRDC_OK) {
    /* F beyond about 2^+-61: a linear map may still have a factor F x
     * 2^(to_frac - from_frac) in range, formed with the change of format
     * first and applied in one rounding */
    return convert_wide(raw, from_frac, from, to_frac, &to_inv, out);
  }
  scale.from_offset.num = from->offset_num;
  scale.from_offset.den = from->offset_den;
  scale.to_offset.num = to->offset_num;
  scale.to_offset.den = to->offset_den;
  if (drdc__units_prepare(from_frac, &scale, to_frac, &a, &factor) != DRDC_OK) {
    return DRDC_E_RANGE;
  }
  return drdc_fx_muldiv_s64(a, factor.num, factor.den, out);
}
