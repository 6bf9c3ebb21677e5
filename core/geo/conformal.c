/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief The conformal latitude chi of WGS-84: the Fourier series chi <->
 *        phi and the ratio cos chi / cos phi, for the transverse Mercator
 *        (tm.c) and the polar stereographic (ups.c).
 *
 * chi = gd(atanh(sin phi) - e atanh(e sin phi)) (Karney 2011).
 * chi - phi = sum c_j sin(2 j phi) and phi - chi = sum d_j sin(2 j chi),
 * 8 terms each, with the coefficients that tools/tables/geo_consts.py computes
 * from the exact functions (a discrete sine transform at 60 digits):
 * their truncation is far below 2^-58, and the roundings of the
 * recurrence add a few LSB.
 */
#include "geo_projection.h"

/* The product of the sine series' loop, inline: the same bits as
 * drdc__geo_mul(). */
static inline int64_t conf_mul(int64_t a, int64_t b)
{
  return drdc_fx_mul_q5_58_unchecked(a, b);
}

/* sum coef[j] sin(2 (j+1) x), j < terms, from s2 = sin 2x and c2 = cos 2x
 * by Clenshaw's recurrence b_j = coef_j + 2 cos(2x) b_(j+1) - b_(j+2),
 * sum = sin(2x) b_1. The coefficients are below 3.4e-3 and |2 cos 2x| <=
 * 2, so |b_j| < 0.01; each product rounds by 0.5 LSB and the recurrence
 * (Chebyshev polynomials of the second kind, |U_n| <= n + 1) amplifies
 * that to a few LSB at most. Trailing zero coefficients are skipped.
 * The high terms are small: from |c_4| <= 15 529 144, |c_5| <= 50 843,
 * |c_6| <= 174 and |c_7| <= 1 raw (phi from chi; chi from phi's are
 * smaller), |b_7| <= 1, |b_6| <= 176, |b_5| <= 51 196 and |b_4| <=
 * 15 631 712 < 2^24, so the products A b_(n+1) for n >= 3 take the
 * short product (the same bits). */
static int64_t sine_series(const int64_t *coef, unsigned terms, int64_t s2,
                           int64_t c2)
{
  int64_t a = 2 * c2;
  int64_t b1 = 0;
  int64_t b2 = 0;
  unsigned n = terms;

  while ((n > 0u) && (coef[n - 1u] == 0)) {
    n--;
  }
  while (n > 0u) {
    /* b_(n+1) for n >= 3 is below 2^24 raw: its product is short */
    int64_t b0 = (coef[n - 1u] + ((n >= 3u) ? drdc_fx_mul_q5_58_short(a, b1)
                                            : conf_mul(a, b1))) -
                 b2;

    b2 = b1;
    b1 = b0;
    n--;
  }
  return conf_mul(s2, b1);
}

int64_t drdc__geo_lat_series(const int64_t *coef, int64_t s, int64_t c)
{
  return sine_series(coef, GEO_CHI_TERMS, 2 * drdc__geo_mul(s, c),
                     drdc__geo_mul(c, c) - drdc__geo_mul(s, s));
}

int64_t drdc__geo_cos_ratio(int64_t s)
{
  /* |e s| <= 0.082 and |w| <= 0.0068: inside the series' domains */
  int64_t w =
      drdc__geo_mul(GEO_E, drdc__geo_atanh_small(drdc__geo_mul(GEO_E, s)));
  int64_t e = drdc__geo_sinh_small(w) + drdc__geo_cosh_small(w);

  return geo_div(2 * e, (GEO_ONE + s) +
                            drdc__geo_mul(GEO_ONE - s, drdc__geo_mul(e, e)));
}
