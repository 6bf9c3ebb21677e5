/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_units
 * @brief A conversion up to its one rounding: the exact factor, the
 *        offset of an affine (temperature) map in input LSB, powers of two
 *        moved into the factor. In a file of its own, so that these
 *        intermediate rationals are not in drdc_units_convert()'s frame
 *        while it calls the 128-bit division (stack depth, issue 8).
 */
#include "units_impl.h"

/* 2^n as a rational, n = 0..62. */
static units_rat_t pow2_rat(unsigned n)
{
  units_rat_t r;
  uint64_t p = (uint64_t)1u << n;

  r.num = (int64_t)p;
  r.den = 1;
  return r;
}

/*
 * The offset of the affine map in input LSB: H = (o_from - o_to / F) x
 * 2^from_frac with F = factor_from / factor_to, so that
 *   out = (raw + H) x F x 2^(to_frac - from_frac),
 * since v_to + o_to = (v_from + o_from) x F. Zero for linear units.
 */
static drdc_status_t offset_lsb(const drdc_unit_t *from,
                                const drdc_unit_t *to,
                                const units_rat_t *factor,
                                unsigned from_frac, units_rat_t *h)
{
  units_rat_t o_from = units_offset(from);
  units_rat_t o_to = units_offset(to);
  units_rat_t t;
  units_rat_t p = pow2_rat(from_frac);

  if ((units_rat_inv(factor, &t) != DRDC_OK)
      || (units_rat_mul(&o_to, &t, &t) != DRDC_OK)
      || (units_rat_sub(&o_from, &t, &t) != DRDC_OK)
      || (units_rat_mul(&t, &p, h) != DRDC_OK)) {
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
    units_rat_t p;
    unsigned rest;

    k--;
    rest = shift - k;
    p = pow2_rat(k);
    if (units_rat_mul(factor, &p, &f) == DRDC_OK) {
      int64_t shifted = *a;

      if ((rest == 0u) || (units_mul_s64(*a, pow2_rat(rest).num, &shifted)
                           == DRDC_OK)) {
        *factor = f;
        *a = shifted;
        return DRDC_OK;
      }
    }
  }
  return DRDC_E_RANGE;
}

drdc_status_t units_prepare(int64_t raw, unsigned from_frac,
                            const drdc_unit_t *from, unsigned to_frac,
                            const drdc_unit_t *to, int64_t *a,
                            units_rat_t *factor)
{
  units_rat_t f_from;
  units_rat_t f;
  int64_t in = raw;
  drdc_status_t st;

  f_from.num = units_number(from->factor_num);
  f_from.den = units_number(from->factor_den);
  f.num = units_number(to->factor_den);
  f.den = units_number(to->factor_num);
  if (units_rat_mul(&f_from, &f, &f) != DRDC_OK) {
    return DRDC_E_RANGE;
  }
  if ((from->offset != 0u) || (to->offset != 0u)) {
    /* affine: a = raw x Hd + Hn, the factor divided by Hd; both exact */
    int64_t scaled;
    units_rat_t h;
    units_rat_t over_den;

    if (offset_lsb(from, to, &f, from_frac, &h) != DRDC_OK) {
      return DRDC_E_RANGE;
    }
    over_den.num = 1;
    over_den.den = h.den;
    if ((units_mul_s64(raw, h.den, &scaled) != DRDC_OK)
        || (units_rat_mul(&f, &over_den, &f) != DRDC_OK)) {
      return DRDC_E_RANGE;
    }
    if (((h.num > 0) && (scaled > (INT64_MAX - h.num)))
        || ((h.num < 0) && (scaled < (-INT64_MAX - h.num)))) {
      return DRDC_E_RANGE;
    }
    in = scaled + h.num;
  }
  if (to_frac >= from_frac) {
    st = scale_up(&f, &in, to_frac - from_frac);
  } else {
    units_rat_t down;

    down.num = 1;
    down.den = pow2_rat(from_frac - to_frac).num;
    st = units_rat_mul(&f, &down, &f);
  }
  if (st != DRDC_OK) {
    return DRDC_E_RANGE;
  }
  *a = in;
  *factor = f;
  return DRDC_OK;
}
