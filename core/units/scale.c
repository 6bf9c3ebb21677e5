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
 * Everything below works in two scratch rationals `x`, `y` besides the
 * factor `f` and the offset `h`, reused from step to step: each 16-byte
 * rational in this frame adds to the stack of drdc_units_convert().
 *
 * The offset of the affine map in input LSB: H = (o_from - o_to / F) x
 * 2^from_frac with F = factor_from / factor_to, so that
 *   out = (raw + H) x F x 2^(to_frac - from_frac),
 * since v_to + o_to = (v_from + o_from) x F. Zero for linear units.
 *
 * Scaling by 2^shift (shift > 0) puts as many of the powers of two into
 * the factor as fit and the rest into the input (an exact left shift);
 * DRDC_E_RANGE when neither can take them.
 */
drdc_status_t units_prepare(int64_t raw, unsigned from_frac,
                            const drdc_unit_t *from, unsigned to_frac,
                            const drdc_unit_t *to, int64_t *a,
                            units_rat_t *factor)
{
  units_rat_t f;
  units_rat_t x;
  units_rat_t y;
  int64_t in = raw;
  drdc_status_t st = DRDC_OK;

  x.num = units_number(from->factor_num);
  x.den = units_number(from->factor_den);
  f.num = units_number(to->factor_den);
  f.den = units_number(to->factor_num);
  if (units_rat_mul(&x, &f, &f) != DRDC_OK) {
    return DRDC_E_RANGE;
  }
  if ((from->offset != 0u) || (to->offset != 0u)) {
    /* affine: a = raw x Hd + Hn, the factor divided by Hd; both exact */
    int64_t scaled;
    units_rat_t h;

    x = units_offset(from);
    y = units_offset(to);
    if ((units_rat_inv(&f, &h) != DRDC_OK)
        || (units_rat_mul(&y, &h, &h) != DRDC_OK)
        || (units_rat_sub(&x, &h, &h) != DRDC_OK)) {
      return DRDC_E_RANGE;
    }
    x = pow2_rat(from_frac);
    if (units_rat_mul(&h, &x, &h) != DRDC_OK) {
      return DRDC_E_RANGE;
    }
    x.num = 1;
    x.den = h.den;
    if ((units_mul_s64(raw, h.den, &scaled) != DRDC_OK)
        || (units_rat_mul(&f, &x, &f) != DRDC_OK)) {
      return DRDC_E_RANGE;
    }
    if (((h.num > 0) && (scaled > (INT64_MAX - h.num)))
        || ((h.num < 0) && (scaled < (-INT64_MAX - h.num)))) {
      return DRDC_E_RANGE;
    }
    in = scaled + h.num;
  }
  if (to_frac >= from_frac) {
    unsigned shift = to_frac - from_frac;
    unsigned k = shift + 1u;

    st = DRDC_E_RANGE;
    while ((k > 0u) && (st != DRDC_OK)) {
      unsigned rest;

      k--;
      rest = shift - k;
      x = pow2_rat(k);
      if (units_rat_mul(&f, &x, &y) == DRDC_OK) {
        int64_t shifted = in;

        if ((rest == 0u)
            || (units_mul_s64(in, pow2_rat(rest).num, &shifted) == DRDC_OK)) {
          f = y;
          in = shifted;
          st = DRDC_OK;
        }
      }
    }
  } else {
    x.num = 1;
    x.den = pow2_rat(from_frac - to_frac).num;
    st = units_rat_mul(&f, &x, &f);
  }
  if (st != DRDC_OK) {
    return DRDC_E_RANGE;
  }
  *a = in;
  *factor = f;
  return DRDC_OK;
}
