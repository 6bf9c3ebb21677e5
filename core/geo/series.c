/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Small-argument Taylor series in Q5.58 for the projections
 *        (atanh, sinh, cosh, atan, sqrt(1 + u)), on the domains the
 *        transverse Mercator and the conformal latitude need.
 *
 * Each is a polynomial by Horner's rule, truncated where the first
 * omitted term is below 0.001 LSB, so that only the roundings of the
 * products remain (1 to 1.5 LSB); on these domains they are several
 * times faster than the general functions of fixed/. The callers keep
 * the arguments inside the stated domains.
 */
#include "geo_projection.h"

/* The product of Horner's loop, inline: the same bits as
 * drdc__geo_mul(). */
static inline int64_t series_mul(int64_t a, int64_t b)
{
  return drdc_fx_mul_q5_58_unchecked(a, b);
}

/* Where a shorter series is enough: the first n terms serve |x| up to
 * the bound whose square is x2_max, the first omitted term there below
 * 2^-68 (0.001 LSB), as at the end of each function's domain. Rows by
 * rising bound; the last one is the whole domain. Dropping a term that
 * small leaves the same error bound: the products' roundings dominate. */
typedef struct series_cut {
  int64_t x2_max; /* bound^2, Q5.58 */
  unsigned terms;
} series_cut_t;

/* bound^2 in Q5.58 for the bounds 0.04, 0.08, 0.16 and 0.25 */
#define X2_004 INT64_C(461168601842739)
#define X2_008 INT64_C(1844674407370955)
#define X2_016 INT64_C(7378697629483821)
#define X2_025 INT64_C(18014398509481984)

static unsigned terms_for(const series_cut_t *cuts, int64_t x2)
{
  unsigned row = 0u;

  while (x2 > cuts[row].x2_max) {
    row++;
  }
  return cuts[row].terms;
}

/* horner(coef, n, x) = coef[0] + x (coef[1] + x (... + x coef[n-1])),
 * n >= 1: the one loop of the Taylor series below. */
static int64_t horner(const int64_t *coef, unsigned n, int64_t x)
{
  int64_t acc = coef[n - 1u];
  unsigned k;

  for (k = n - 1u; k > 0u; k--) {
    acc = coef[k - 1u] + series_mul(acc, x);
  }
  return acc;
}

/* atanh(t) = t sum t^(2k) / (2k+1), k <= 18, by Horner in t^2, for |t| <=
 * tanh 0.34 = 0.3275. The first omitted term is t^39 / 39 < 3e-21 (0.001
 * LSB); each of the 20 rounded products adds 0.5 LSB damped by t^2 <
 * 0.108, the coefficients 0.5 LSB each: about 1.5 LSB in all, against the
 * 1 LSB of the general drdc_fx_atanh_q5_58() for a third of its cycles. */
int64_t drdc__geo_atanh_small(int64_t t)
{
  static const int64_t coef[19] = {
      GEO_Q58_RECIP(1),  GEO_Q58_RECIP(3),  GEO_Q58_RECIP(5),
      GEO_Q58_RECIP(7),  GEO_Q58_RECIP(9),  GEO_Q58_RECIP(11),
      GEO_Q58_RECIP(13), GEO_Q58_RECIP(15), GEO_Q58_RECIP(17),
      GEO_Q58_RECIP(19), GEO_Q58_RECIP(21), GEO_Q58_RECIP(23),
      GEO_Q58_RECIP(25), GEO_Q58_RECIP(27), GEO_Q58_RECIP(29),
      GEO_Q58_RECIP(31), GEO_Q58_RECIP(33), GEO_Q58_RECIP(35),
      GEO_Q58_RECIP(37)};
  /* t^(2n+1) / (2n+1) < 2^-68 */
  static const series_cut_t cut[] = {{X2_004, 7u},
                                     {X2_008, 9u},
                                     {X2_016, 12u},
                                     {X2_025, 16u},
                                     {INT64_MAX, 19u}};
  int64_t t2 = drdc__geo_mul(t, t);

  return drdc__geo_mul(horner(coef, terms_for(cut, t2), t2), t);
}

/* cosh(x) = sum x^(2k) / (2k)!, k <= 8, by Horner in x^2, for |x| <=
 * 0.34 (first omitted term x^18 / 18! < 1e-23); about 1 LSB. */
int64_t drdc__geo_cosh_small(int64_t x)
{
  static const int64_t coef[9] = {GEO_Q58_RECIP(INT64_C(1)),
                                  GEO_Q58_RECIP(INT64_C(2)),
                                  GEO_Q58_RECIP(INT64_C(24)),
                                  GEO_Q58_RECIP(INT64_C(720)),
                                  GEO_Q58_RECIP(INT64_C(40320)),
                                  GEO_Q58_RECIP(INT64_C(3628800)),
                                  GEO_Q58_RECIP(INT64_C(479001600)),
                                  GEO_Q58_RECIP(INT64_C(87178291200)),
                                  GEO_Q58_RECIP(INT64_C(20922789888000))};
  /* x^(2n) / (2n)! < 2^-68 */
  static const series_cut_t cut[] = {
      {X2_004, 5u}, {X2_008, 6u}, {X2_016, 7u}, {INT64_MAX, 9u}};
  int64_t x2 = drdc__geo_mul(x, x);

  return horner(coef, terms_for(cut, x2), x2);
}

/* sinh(x) = x sum x^(2k) / (2k+1)!, k <= 8, by Horner in x^2, for |x| <=
 * 0.35 (first omitted term x^19 / 19! < 1e-25); about 1 LSB. */
int64_t drdc__geo_sinh_small(int64_t x)
{
  static const int64_t coef[9] = {GEO_Q58_RECIP(INT64_C(1)),
                                  GEO_Q58_RECIP(INT64_C(6)),
                                  GEO_Q58_RECIP(INT64_C(120)),
                                  GEO_Q58_RECIP(INT64_C(5040)),
                                  GEO_Q58_RECIP(INT64_C(362880)),
                                  GEO_Q58_RECIP(INT64_C(39916800)),
                                  GEO_Q58_RECIP(INT64_C(6227020800)),
                                  GEO_Q58_RECIP(INT64_C(1307674368000)),
                                  GEO_Q58_RECIP(INT64_C(355687428096000))};
  /* x^(2n+1) / (2n+1)! < 2^-68 */
  static const series_cut_t cut[] = {
      {X2_004, 5u}, {X2_008, 6u}, {X2_016, 7u}, {INT64_MAX, 9u}};
  int64_t x2 = drdc__geo_mul(x, x);

  return drdc__geo_mul(horner(coef, terms_for(cut, x2), x2), x);
}

/* atan(q) = q sum (-1)^k q^(2k) / (2k+1), k <= 14, by Horner in q^2, for
 * |q| <= 0.25; the first omitted term is q^31 / 31 < 2e-21 (0.0005 LSB),
 * the 16 rounded products and the coefficients about 1 LSB. */
int64_t drdc__geo_atan_small(int64_t q)
{
  static const int64_t coef[15] = {
      GEO_Q58_RECIP(1),   -GEO_Q58_RECIP(3),  GEO_Q58_RECIP(5),
      -GEO_Q58_RECIP(7),  GEO_Q58_RECIP(9),   -GEO_Q58_RECIP(11),
      GEO_Q58_RECIP(13),  -GEO_Q58_RECIP(15), GEO_Q58_RECIP(17),
      -GEO_Q58_RECIP(19), GEO_Q58_RECIP(21),  -GEO_Q58_RECIP(23),
      GEO_Q58_RECIP(25),  -GEO_Q58_RECIP(27), GEO_Q58_RECIP(29)};
  /* q^(2n+1) / (2n+1) < 2^-68 */
  static const series_cut_t cut[] = {
      {X2_004, 7u}, {X2_008, 9u}, {X2_016, 12u}, {INT64_MAX, 15u}};
  int64_t q2 = drdc__geo_mul(q, q);

  return drdc__geo_mul(horner(coef, terms_for(cut, q2), q2), q);
}

/* sqrt(1 + u) by its binomial series to u^9 for |u| <= 0.0125: the
 * coefficients C(1/2, n) are dyadic, exact in Q5.58; the first omitted
 * term is below 2e-21 and the 10 rounded products add about 1 LSB. */
int64_t drdc__geo_sqrt1p_small(int64_t u)
{
  static const int64_t coef[10] = {INT64_C(1) << 58,      INT64_C(1) << 57,
                                   -(INT64_C(1) << 55),   INT64_C(1) << 54,
                                   -(INT64_C(5) << 51),   INT64_C(7) << 50,
                                   -(INT64_C(21) << 48),  INT64_C(33) << 47,
                                   -(INT64_C(429) << 43), INT64_C(715) << 42};
  return horner(coef, 10u, u);
}
