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
  /* the exact input and factor (scale.c) */
  if (drdc__units_prepare(from_frac, from, to_frac, to, &a, &factor) !=
      DRDC_OK) {
    return DRDC_E_RANGE;
  }
  /* the one rounding: 128-bit product, nearest, ties away from zero */
  return drdc_fx_muldiv_s64(a, factor.num, factor.den, out);
}
