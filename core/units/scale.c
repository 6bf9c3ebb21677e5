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

/* 2^n, n = 0..62. */
static int64_t pow2(unsigned n)
{
  uint64_t p = (uint64_t)1u << n;

  return (int64_t)p;
}

/*
 * The factor is worked on in place, in the caller's `*factor`; the
 * second operand of each product and the offsets are passed as their
 * two parts; the products of the input go to the caller's `*a`. So this
 * frame holds one rational, the offset `h` of an affine map (each
 * 16-byte rational here adds to the stack of drdc_units_convert()). The
 * operations and their order are those of before, so every rational and
 * the result are the same.
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
drdc_status_t drdc__units_prepare(unsigned from_frac, const drdc_unit_t *from,
                                  unsigned to_frac, const drdc_unit_t *to,
                                  int64_t *a, units_rat_t *factor)
{
  units_rat_t *f = factor;
  int64_t raw = *a;
  int64_t in = raw;
  drdc_status_t st = DRDC_OK;

  f->num = drdc__units_number(to->factor_den);
  f->den = drdc__units_number(to->factor_num);
  if (drdc__units_rat_scale(f, drdc__units_number(from->factor_num),
                            drdc__units_number(from->factor_den),
                            f) != DRDC_OK) {
    return DRDC_E_RANGE;
  }
  if ((units_offset_row(from) != 0u) || (units_offset_row(to) != 0u)) {
    /* affine: a = raw x Hd + Hn, the factor divided by Hd; both exact */
    int64_t scaled;
    units_rat_t h;

    if ((drdc__units_rat_inv(f, &h) != DRDC_OK) ||
        (drdc__units_rat_scale(&h, drdc__units_offset_part(to, 0u),
                               drdc__units_offset_part(to, 1u),
                               &h) != DRDC_OK)) {
      return DRDC_E_RANGE;
    }
    if ((drdc__units_rat_sub(drdc__units_offset_part(from, 0u),
                             drdc__units_offset_part(from, 1u), &h,
                             &h) != DRDC_OK) ||
        (drdc__units_rat_scale(&h, pow2(from_frac), 1, &h) != DRDC_OK)) {
      return DRDC_E_RANGE;
    }
    /* raw x Hd goes to *a (no local whose address is taken) */
    if ((drdc__units_mul_s64(raw, h.den, a) != DRDC_OK) ||
        (drdc__units_rat_scale(f, 1, h.den, f) != DRDC_OK)) {
      return DRDC_E_RANGE;
    }
    scaled = *a;
    if (((h.num > 0) && (scaled > (INT64_MAX - h.num))) ||
        ((h.num < 0) && (scaled < (-INT64_MAX - h.num)))) {
      return DRDC_E_RANGE;
    }
    in = scaled + h.num;
  }
  if (to_frac >= from_frac) {
    unsigned shift = to_frac - from_frac;
    unsigned k = shift + 1u;

    st = DRDC_E_RANGE;
    /* Both parts of a step must fit; each writes its output only when
     * it does, the input's shift (into *a) first, so the factor changes
     * only when the step is taken. */
    while ((k > 0u) && (st != DRDC_OK)) {
      unsigned rest;

      k--;
      rest = shift - k;
      *a = in;
      if (((rest == 0u) ||
           (drdc__units_mul_s64(in, pow2(rest), a) == DRDC_OK)) &&
          (drdc__units_rat_scale(f, pow2(k), 1, f) == DRDC_OK)) {
        in = *a;
        st = DRDC_OK;
      }
    }
  } else {
    st = drdc__units_rat_scale(f, 1, pow2(from_frac - to_frac), f);
  }
  if (st != DRDC_OK) {
    return DRDC_E_RANGE;
  }
  *a = in;
  return DRDC_OK;
}
