/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_units
 * @brief Conversion of a fixed-point value between two units of one
 *        dimension with a single rounding.
 */
#include <drdc/fixed_arith.h>

#include "units_impl.h"

/* 2^n as a rational, n = 0..62. */
static units_rat_t pow2(unsigned n)
{
  units_rat_t r;
  uint64_t p = (uint64_t)1u << n;

  r.num = (int64_t)p;
  r.den = 1;
  return r;
}

drdc_status_t drdc_units_compatible(const drdc_unit_t *a,
                                    const drdc_unit_t *b)
{
  size_t i;

  if ((a == NULL) || (b == NULL)) {
    return DRDC_E_NULL;
  }
  for (i = 0u; i < (size_t)DRDC_UNITS_DIMENSIONS; i++) {
    if (units_dimension(a, i) != units_dimension(b, i)) {
      return DRDC_E_DIMENSION;
    }
  }
  return DRDC_OK;
}

/*
 * The offset of the affine map in input LSB: H = (o_from - o_to / F) x
 * 2^from_frac with F = factor_from / factor_to, so that
 *   out = (raw + H) x F x 2^(to_frac - from_frac),
 * since v_to + o_to = (v_from + o_from) x F. Zero for linear units.
 */
static drdc_status_t offset_lsb(const drdc_unit_t *from, const drdc_unit_t *to,
                                units_rat_t factor, unsigned from_frac,
                                units_rat_t *h)
{
  units_rat_t o_from = units_offset(from);
  units_rat_t o_to = units_offset(to);
  units_rat_t inverse;
  units_rat_t t;

  if ((units_rat_inv(factor, &inverse) != DRDC_OK)
      || (units_rat_mul(o_to, inverse, &t) != DRDC_OK)
      || (units_rat_sub(o_from, t, &t) != DRDC_OK)
      || (units_rat_mul(t, pow2(from_frac), h) != DRDC_OK)) {
    return DRDC_E_RANGE;
  }
  return DRDC_OK;
}

/*
 * Scale `factor` by 2^shift (shift > 0), putting as many of the powers of
 * two into the factor as fit and the rest into the input `*a` (an exact
 * left shift). DRDC_E_RANGE when neither can take them.
 */
static drdc_status_t scale_up(units_rat_t *factor, int64_t *a,
                              unsigned shift)
{
  unsigned k = shift + 1u;

  while (k > 0u) {
    units_rat_t f;
    unsigned rest;

    k--;
    rest = shift - k;
    if (units_rat_mul(*factor, pow2(k), &f) == DRDC_OK) {
      int64_t shifted = *a;

      if ((rest == 0u) || (units_mul_s64(*a, pow2(rest).num, &shifted)
                           == DRDC_OK)) {
        *factor = f;
        *a = shifted;
        return DRDC_OK;
      }
    }
  }
  return DRDC_E_RANGE;
}

drdc_status_t drdc_units_convert(int64_t raw, unsigned from_frac,
                                 const drdc_unit_t *from, unsigned to_frac,
                                 const drdc_unit_t *to, int64_t *out)
{
  units_rat_t factor;
  units_rat_t f_from;
  units_rat_t f_to_inverse;
  units_rat_t h;
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
  f_from.num = units_number(from->factor_num);
  f_from.den = units_number(from->factor_den);
  f_to_inverse.num = units_number(to->factor_den);
  f_to_inverse.den = units_number(to->factor_num);
  if (units_rat_mul(f_from, f_to_inverse, &factor) != DRDC_OK) {
    return DRDC_E_RANGE;
  }
  if ((from->offset != 0u) || (to->offset != 0u)) {
    /* affine: a = raw x Hd + Hn, the factor divided by Hd; both exact */
    int64_t scaled;
    units_rat_t over_den;

    if (offset_lsb(from, to, factor, from_frac, &h) != DRDC_OK) {
      return DRDC_E_RANGE;
    }
    over_den.num = 1;
    over_den.den = h.den;
    if ((units_mul_s64(raw, h.den, &scaled) != DRDC_OK)
        || (units_rat_mul(factor, over_den, &factor) != DRDC_OK)) {
      return DRDC_E_RANGE;
    }
    if (((h.num > 0) && (scaled > (INT64_MAX - h.num)))
        || ((h.num < 0) && (scaled < (-INT64_MAX - h.num)))) {
      return DRDC_E_RANGE;
    }
    a = scaled + h.num;
  }
  if (to_frac >= from_frac) {
    st = scale_up(&factor, &a, to_frac - from_frac);
  } else {
    units_rat_t down;

    down.num = 1;
    down.den = pow2(from_frac - to_frac).num;
    st = units_rat_mul(factor, down, &factor);
  }
  if (st != DRDC_OK) {
    return DRDC_E_RANGE;
  }
  /* the one rounding: 128-bit product, nearest, ties away from zero */
  return drdc_fx_muldiv_s64(a, factor.num, factor.den, out);
}
