/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_units
 * @brief A conversion up to its one rounding: the exact factor, the
 *        offset of an affine (temperature) map in input LSB, powers of two
 *        moved into the factor.
 */
#include "units_impl.h"

/* 2^n, n = 0..62. */
static int64_t pow2(unsigned n)
{
  uint64_t p = (uint64_t)1u << n;

  return (int64_t)p;
}

/*
 * The offset of the affine map in input LSB: H = (o_from - o_to / F) x
 * 2^from_frac with F = factor_from / factor_to, so that
 *   out = (raw + H) x F x 2^(to_frac - from_frac),
 * since v_to + o_to = (v_from + o_from) x F. Zero for linear units. With
 * H = Hn / Hd in lowest terms the input becomes raw x Hd + Hn and the
 * factor F / Hd, both exact.
 *
 * Scaling by 2^shift (shift > 0) puts as many of the powers of two into
 * the factor as fit and the rest into the input (an exact left shift);
 * DRDC_E_RANGE when neither can take them.
 */
drdc_status_t drdc__units_prepare(unsigned from_frac,
                                  const units_scale_t *scale, unsigned to_frac,
                                  int64_t *a, units_rat_t *factor)
{
  const int64_t raw = *a;
  units_rat_t f = scale->ratio; /* the input's factor: F, or F / Hd */
  int64_t in = raw; /* the input: raw, or raw x Hd + Hn when affine */
  drdc_status_t st = DRDC_OK;

  if ((scale->from_offset.num != 0) || (scale->to_offset.num != 0)) {
    units_rat_t inv_ratio; /* 1 / F */
    units_rat_t to_off;    /* o_to / F */
    units_rat_t diff;      /* o_from - o_to / F */
    units_rat_t h;         /* H = Hn / Hd */
    int64_t scaled;        /* raw x Hd */

    if ((drdc__units_rat_inv(&scale->ratio, &inv_ratio) != DRDC_OK) ||
        (drdc__units_rat_scale(&inv_ratio, scale->to_offset.num,
                               scale->to_offset.den, &to_off) != DRDC_OK)) {
      return DRDC_E_RANGE;
    }
    if ((drdc__units_rat_sub(scale->from_offset.num, scale->from_offset.den,
                             &to_off, &diff) != DRDC_OK) ||
        (drdc__units_rat_scale(&diff, pow2(from_frac), 1, &h) != DRDC_OK)) {
      return DRDC_E_RANGE;
    }
    if ((drdc__units_mul_s64(raw, h.den, &scaled) != DRDC_OK) ||
        (drdc__units_rat_scale(&scale->ratio, 1, h.den, &f) != DRDC_OK)) {
      return DRDC_E_RANGE;
    }
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
    /* Both parts of a step must fit: 2^(shift - k) into the input and
     * 2^k into the factor, k from shift down; the factor is written
     * only when the step is taken. */
    while ((k > 0u) && (st != DRDC_OK)) {
      unsigned rest;
      int64_t shifted = in; /* in x 2^rest */

      k--;
      rest = shift - k;
      if (((rest == 0u) ||
           (drdc__units_mul_s64(in, pow2(rest), &shifted) == DRDC_OK)) &&
          (drdc__units_rat_scale(&f, pow2(k), 1, factor) == DRDC_OK)) {
        in = shifted;
        st = DRDC_OK;
      }
    }
  } else {
    st = drdc__units_rat_scale(&f, 1, pow2(from_frac - to_frac), factor);
  }
  if (st != DRDC_OK) {
    return DRDC_E_RANGE;
  }
  *a = in;
  return DRDC_OK;
}
