/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Transverse Mercator on WGS-84 by Krueger's series to 6th order in
 *        the third flattening n, with convergence and point scale.
 *
 * Forward: the conformal latitude chi from phi by its Fourier series,
 * then the spherical transverse Mercator xi' = atan2(tan chi, cos lam),
 * eta' = atanh(cos chi sin lam), then zeta = zeta' + sum alpha_j
 * sin(2 j zeta') with zeta = xi + i eta, summed by Clenshaw's recurrence
 * in complex arithmetic. The sin, cos, sinh and cosh of 2 xi' and 2 eta'
 * come from products (cosh eta' = 1 / sqrt(1 - tanh^2 eta') makes sin xi'
 * = sin chi cosh eta'), the small-argument functions (atanh, sinh, cosh,
 * atan, sqrt(1 + u)) from their Taylor series in Q5.58 on the domains the
 * projection needs, each truncated below 0.001 LSB. Inverse: the beta
 * series, then chi and lam from xi', eta', then phi from chi by its
 * series. Every term is Q5.58; the series' own truncation (n^7 = 4e-20)
 * is far below the 2^-58 resolution of the arithmetic.
 */
#include <drdc/compiler.h>
#include "geo_impl.h"

/* the product of the series' Horner and sine loops, inlined (one copy
 * per loop); the rest, the complex recurrence included, call drdc__geo_mul(),
 * the same bits */
static inline int64_t tm_mul(int64_t a, int64_t b)
{
  return drdc_fx_mul_q5_58_unchecked(a, b);
}

/* sum coef[j] sin(2 (j+1) x) from s2 = sin 2x, c2 = cos 2x by Clenshaw's
 * recurrence b_j = coef_j + 2 cos(2x) b_(j+1) - b_(j+2), sum = sin(2x) b_1:
 * one product per term. The coefficients are below 3.4e-3 and |2 cos 2x|
 * <= 2, so |b_j| < 0.01: every rounding adds at most 0.5 LSB, and the
 * recurrence (the Chebyshev polynomials of the second kind, |U_n| <= n+1)
 * amplifies them to a few LSB at most. Trailing zero coefficients are
 * skipped (exact zeros). */
static inline DRDC_ALWAYS_INLINE int64_t sine_series(const int64_t *coef,
                                                     unsigned terms, int64_t s2,
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
    int64_t b0 = (coef[n - 1u] + tm_mul(a, b1)) - b2;

    b2 = b1;
    b1 = b0;
    n--;
  }
  return tm_mul(s2, b1);
}

/* Krueger's series at zeta = xi + i eta by Clenshaw's recurrence in
 * complex arithmetic (as GeographicLib does): with A = 2 cos 2 zeta,
 * b_j = c_j + A b_(j+1) - b_(j+2), sum c_j sin(2 j zeta) = sin(2 zeta) b_1
 * = dxi + i deta; with d_j = 2 j c_j the same recurrence gives the
 * derivative 1 + sum d_j cos(2 j zeta) = 1 + cos(2 zeta) b_1 - b_2
 * = p - i q (only when deriv). |A| <= 2 cosh(0.68) < 2.5 and |b_j| <
 * 2e-3, so every product stays far inside Q5.58 and the roundings add up
 * to a few LSB.
 *
 * Stack: on a 32-bit core each int64_t takes two registers, so the
 * series' state lives in one struct owned by the caller (tm_zeta_t) and
 * the recurrence runs in a small out-of-line helper that reaches it by
 * pointer: no frame on the chain holds a second copy of it. sin 2 zeta,
 * idle during the recurrence, waits in two slots the caller names (the
 * forward projection's output slots that are free then). */
typedef struct tm_zeta {
  int64_t c2[2]; /* cos 2 zeta = c2[0] + i c2[1] */
  int64_t r1;    /* b_(j+1), b_(j+2): real and imaginary parts */
  int64_t i1;
  int64_t r2;
  int64_t i2;
} tm_zeta_t;

/* cos 2 zeta into z and sin 2 zeta = *sr + i *si from sin, cos of 2 xi
 * and sinh, cosh of 2 eta, which the caller leaves in z->r1, i1, r2, i2
 * (the recurrence's slots, free until it starts): cos 2 zeta = c2 ch2 -
 * i s2 sh2, sin 2 zeta = s2 ch2 + i c2 sh2 */
static inline DRDC_ALWAYS_INLINE void zeta_set(tm_zeta_t *z, int64_t *sr,
                                               int64_t *si)
{
  z->c2[0] = drdc__geo_mul(z->i1, z->i2);
  z->c2[1] = -drdc__geo_mul(z->r1, z->r2);
  *sr = drdc__geo_mul(z->r1, z->i2);
  *si = drdc__geo_mul(z->i1, z->r2);
}

/* the recurrence over coef[0..5] (times 2 j when deriv), from b = 0:
 * b_1, b_2 left in z->r1, i1, r2, i2 (out of line: its few registers are
 * the deepest frame of the chain). cos 2 zeta comes as c2 = z->c2 by a
 * pointer of its own: the compiler cannot tell that the stores to z's
 * slots leave it unchanged, so it reads A = 2 cos 2 zeta at each product
 * instead of holding it in four registers across the loop (which a
 * 32-bit core spills: 16 bytes more frame on either target). Its
 * products call drdc__geo_mul(): four inline 64 x 64-bit products per step
 * held 80 bytes of frame on Cortex-M3, the calls 40 + 12 (2 %
 * of drdc_geo_to_utm()'s cycles on PowerPC, the library 1 KB smaller:
 * the loops of horner() are no longer inlined into each series). */
static DRDC_NOINLINE void clenshaw(const int64_t *coef, bool deriv,
                                   tm_zeta_t *z, const int64_t c2[2])
{
  unsigned j;

  z->r1 = 0;
  z->i1 = 0;
  z->r2 = 0;
  z->i2 = 0;
  for (j = GEO_KRUEGER_TERMS; j > 0u; j--) {
    int64_t c = deriv ? (coef[j - 1u] * (2 * (int64_t)j)) : coef[j - 1u];
    int64_t t;

    /* the new b_j into the b_(j+2) slots one product at a time, then
     * the slots swapped */
    z->r2 = (c - z->r2) + drdc__geo_mul(2 * c2[0], z->r1);
    z->r2 = z->r2 - drdc__geo_mul(2 * c2[1], z->i1);
    z->i2 = drdc__geo_mul(2 * c2[0], z->i1) - z->i2;
    z->i2 = z->i2 + drdc__geo_mul(2 * c2[1], z->r1);
    t = z->r1;
    z->r1 = z->r2;
    z->r2 = t;
    t = z->i1;
    z->i1 = z->i2;
    z->i2 = t;
  }
}

/* After clenshaw() over the coefficients: the sum sin(2 zeta) b_1 =
 * dxi + i deta into *sr, *si, which held sin 2 zeta (zeta_set()): no
 * second copy is on the stack. */
static DRDC_NOINLINE void krueger_sum(const tm_zeta_t *z, int64_t *sr,
                                      int64_t *si)
{
  int64_t d = drdc__geo_mul(*sr, z->r1) - drdc__geo_mul(*si, z->i1);

  *si = drdc__geo_mul(*sr, z->i1) + drdc__geo_mul(*si, z->r1);
  *sr = d;
}

/* After clenshaw() over 2 j times the coefficients: the derivative
 * 1 + cos(2 zeta) b_1 - b_2 = p - i q, p into z->c2[0] and q into
 * z->c2[1]. The series' stages call clenshaw() and these directly (one
 * frame fewer on the chain than a wrapper would add). */
static DRDC_NOINLINE void krueger_deriv(tm_zeta_t *z)
{
  int64_t d = (GEO_ONE + (drdc__geo_mul(z->c2[0], z->r1) -
                          drdc__geo_mul(z->c2[1], z->i1))) -
              z->r2;

  z->c2[1] =
      -((drdc__geo_mul(z->c2[0], z->i1) + drdc__geo_mul(z->c2[1], z->r1)) -
        z->i2);
  z->c2[0] = d;
}

/* coef[0] + x (coef[1] + x (... + x coef[n-1])) by Horner, n >= 1: the
 * one loop of the series below (one inlined product) */
static int64_t horner(const int64_t *coef, unsigned n, int64_t x)
{
  int64_t acc = coef[n - 1u];
  unsigned k;

  for (k = n - 1u; k > 0u; k--) {
    acc = coef[k - 1u] + tm_mul(acc, x);
  }
  return acc;
}

/* 2^58 / n rounded (n odd or a factorial: no ties in these uses) */
#define Q58_RECIP(n) ((GEO_ONE + ((n) / 2)) / (n))

/* atanh(t) for |t| <= tanh(0.34) = 0.3275 (GEO_TM_MAX_TANH_ETA): its
 * Taylor series t sum t^(2k) / (2k+1) to k = 18, by Horner in t^2. The
 * first omitted term is t^39 / 39 < 3e-21 (0.001 LSB); each of the 20
 * rounded products adds 0.5 LSB damped by t^2 < 0.108, the coefficients
 * 0.5 LSB each: about 1.5 LSB in all, against the 1 LSB of the general
 * drdc_fx_atanh_q5_58() for one third of its cycles. */
static int64_t tm_atanh(int64_t t)
{
  static const int64_t coef[19] = {
      Q58_RECIP(1),  Q58_RECIP(3),  Q58_RECIP(5),  Q58_RECIP(7),  Q58_RECIP(9),
      Q58_RECIP(11), Q58_RECIP(13), Q58_RECIP(15), Q58_RECIP(17), Q58_RECIP(19),
      Q58_RECIP(21), Q58_RECIP(23), Q58_RECIP(25), Q58_RECIP(27), Q58_RECIP(29),
      Q58_RECIP(31), Q58_RECIP(33), Q58_RECIP(35), Q58_RECIP(37)};
  return drdc__geo_mul(horner(coef, 19u, drdc__geo_mul(t, t)), t);
}

/* cosh(x) for |x| <= 0.34: sum x^(2k) / (2k)! to k = 8 by Horner in x^2
 * (first omitted term x^18 / 18! < 1e-23); about 1 LSB. */
static int64_t tm_cosh(int64_t x)
{
  static const int64_t coef[9] = {Q58_RECIP(INT64_C(1)),
                                  Q58_RECIP(INT64_C(2)),
                                  Q58_RECIP(INT64_C(24)),
                                  Q58_RECIP(INT64_C(720)),
                                  Q58_RECIP(INT64_C(40320)),
                                  Q58_RECIP(INT64_C(3628800)),
                                  Q58_RECIP(INT64_C(479001600)),
                                  Q58_RECIP(INT64_C(87178291200)),
                                  Q58_RECIP(INT64_C(20922789888000))};
  return horner(coef, 9u, drdc__geo_mul(x, x));
}

/* sinh(x) for |x| <= 0.35: x sum x^(2k) / (2k+1)! to k = 8 by Horner in
 * x^2 (first omitted term x^19 / 19! < 1e-25); about 1 LSB. The reverse
 * projection needs it for |eta| <= 0.08 (eastings 0 .. 1 000 km). */
static int64_t tm_sinh(int64_t x)
{
  static const int64_t coef[9] = {Q58_RECIP(INT64_C(1)),
                                  Q58_RECIP(INT64_C(6)),
                                  Q58_RECIP(INT64_C(120)),
                                  Q58_RECIP(INT64_C(5040)),
                                  Q58_RECIP(INT64_C(362880)),
                                  Q58_RECIP(INT64_C(39916800)),
                                  Q58_RECIP(INT64_C(6227020800)),
                                  Q58_RECIP(INT64_C(1307674368000)),
                                  Q58_RECIP(INT64_C(355687428096000))};

  return drdc__geo_mul(horner(coef, 9u, drdc__geo_mul(x, x)), x);
}

/* Largest |tan(xi' - chi)| for tm_atan(): 0.25. */
#define TM_ATAN_MAX (GEO_ONE / 4)

/* atan(q) for |q| <= 0.25: q sum (-1)^k q^(2k) / (2k+1) to k = 14 by
 * Horner in q^2; the first omitted term is q^31 / 31 < 2e-21 (0.0005
 * LSB), the 16 rounded products and the coefficients about 1 LSB. */
static int64_t tm_atan(int64_t q)
{
  static const int64_t coef[15] = {
      Q58_RECIP(1),  -Q58_RECIP(3),  Q58_RECIP(5),  -Q58_RECIP(7),
      Q58_RECIP(9),  -Q58_RECIP(11), Q58_RECIP(13), -Q58_RECIP(15),
      Q58_RECIP(17), -Q58_RECIP(19), Q58_RECIP(21), -Q58_RECIP(23),
      Q58_RECIP(25), -Q58_RECIP(27), Q58_RECIP(29)};
  return drdc__geo_mul(horner(coef, 15u, drdc__geo_mul(q, q)), q);
}

/* sin and cos of x + d from s = sin x, c = cos x and a small d
 * (|d| <= 0.004, the conformal latitude's correction): sin d = d (1 -
 * d^2/6 + d^4/120) and cos d = 1 - d^2/2 + d^4/24 - d^6/720 (first omitted
 * terms d^7/5040 and d^8/40320 below 1e-20), then the addition theorems:
 * 11 products instead of a full sin/cos. */
static DRDC_NOINLINE void rotate_small(int64_t s, int64_t c, int64_t d,
                                       int64_t *s_out, int64_t *c_out)
{
  int64_t d2 = drdc__geo_mul(d, d);
  int64_t sd = drdc__geo_mul(
      d, GEO_ONE - drdc__geo_mul(d2, Q58_RECIP(6) -
                                         drdc__geo_mul(d2, Q58_RECIP(120))));
  int64_t cd =
      GEO_ONE -
      drdc__geo_mul(
          d2, Q58_RECIP(2) -
                  drdc__geo_mul(d2, Q58_RECIP(24) -
                                        drdc__geo_mul(d2, Q58_RECIP(720))));

  *s_out = drdc__geo_mul(s, cd) + drdc__geo_mul(c, sd);
  *c_out = drdc__geo_mul(c, cd) - drdc__geo_mul(s, sd);
}

/* Largest |u| for tm_sqrt1p(): 1/80 = 0.0125. */
#define TM_SQRT_MAX (GEO_ONE / 80)

/* sqrt(1 + u) for |u| <= 0.0125 by its binomial series to u^9 (the
 * coefficients C(1/2, n) are dyadic: exact in Q5.58); the first omitted
 * term is below 2e-21 and the 10 rounded products add about 1 LSB. The
 * point scale needs sqrt((1 - e^2 sin^2 phi) (p^2 + q^2)), whose argument
 * lies within 1 - 0.0113 .. 1 + 0.0046 in the whole domain. */
static DRDC_NOINLINE int64_t tm_sqrt1p(int64_t u)
{
  static const int64_t coef[10] = {INT64_C(1) << 58,      INT64_C(1) << 57,
                                   -(INT64_C(1) << 55),   INT64_C(1) << 54,
                                   -(INT64_C(5) << 51),   INT64_C(7) << 50,
                                   -(INT64_C(21) << 48),  INT64_C(33) << 47,
                                   -(INT64_C(429) << 43), INT64_C(715) << 42};
  return horner(coef, 10u, u);
}

int64_t drdc__geo_cos_ratio(int64_t s)
{
  /* |e s| <= 0.082 and |w| <= 0.0068: inside the series' domains */
  int64_t w = drdc__geo_mul(GEO_E, tm_atanh(drdc__geo_mul(GEO_E, s)));
  int64_t e = tm_sinh(w) + tm_cosh(w);

  return geo_div(2 * e, (GEO_ONE + s) +
                            drdc__geo_mul(GEO_ONE - s, drdc__geo_mul(e, e)));
}

int64_t drdc__geo_lat_series(const int64_t *coef, int64_t s, int64_t c)
{
  /* the recurrence inline: one frame under the projections' stages */
  return sine_series(coef, GEO_CHI_TERMS, 2 * drdc__geo_mul(s, c),
                     drdc__geo_mul(c, c) - drdc__geo_mul(s, s));
}

/* What the forward projection keeps between its stages (in the frame of
 * drdc__geo_tm_forward() or drdc_geo_tm_forward(), which run the stages by
 * tm_forward_stages(); each stage a small out-of-line function that
 * reaches it by pointer, so that the frames under the two atan2 calls
 * and under the Krueger series stay small). cos chi and sinh eta' are
 * needed only up to the series: they wait in out->k and out->gamma,
 * which the series' derivative overwrites. */
typedef struct tm_fwd {
  int64_t schi; /* sin chi, chi the conformal latitude */
  int64_t slam; /* sin and cos of the longitude from the meridian */
  int64_t clam;
  int64_t kfac;  /* 1 - e^2 sin^2 phi */
  int64_t ratio; /* cos chi / cos phi (cos phi until fwd_ratio()) */
  int64_t ch;    /* cosh eta' */
} tm_fwd_t;

/* chi and the sphere's eta' from phi, lam in out->xi, out->eta: out->xi
 * = chi (xi' - chi is added by fwd_xi()), out->eta = eta', out->k = cos
 * chi, out->gamma = sinh eta', st->ratio = cos phi (fwd_ratio()
 * divides); 0 beyond the series' domain */
static DRDC_NOINLINE int fwd_sphere(tm_fwd_t *st, geo_tm_t *out)
{
  int64_t chi;
  int64_t tanh_eta;

  /* sin phi and cos phi wait in out->eta and out->gamma (free until
   * eta' and sinh eta' are known), phi in out->xi: only chi, then
   * tanh eta', is live in this frame across a call */
  geo_sincos(out->eta, &st->slam, &st->clam);
  geo_sincos(out->xi, &out->eta, &out->gamma);
  chi = geo_chi_series(out->eta, out->gamma);
  out->xi = out->xi + chi;
  rotate_small(out->eta, out->gamma, chi, &st->schi, &out->k);
  st->kfac = GEO_ONE - drdc__geo_mul(GEO_E2, drdc__geo_mul(out->eta, out->eta));
  /* cos phi waits in st->ratio for fwd_ratio() */
  st->ratio = out->gamma;
  tanh_eta = drdc__geo_mul(out->k, st->slam);
  if ((tanh_eta > GEO_TM_MAX_TANH_ETA) || (tanh_eta < -GEO_TM_MAX_TANH_ETA)) {
    return 0;
  }
  out->eta = tm_atanh(tanh_eta);
  /* sinh eta' = tanh eta' cosh eta' (see fwd_series()) */
  st->ch = tm_cosh(out->eta);
  out->gamma = drdc__geo_mul(tanh_eta, st->ch);
  return 1;
}

/* the scale's cos chi / cos phi (cos chi in out->k, cos phi in
 * st->ratio, from fwd_sphere()) into st->ratio, its limit at the poles:
 * the division's chain from a frame of its own */
static DRDC_NOINLINE void fwd_ratio(tm_fwd_t *st, const geo_tm_t *out)
{
  st->ratio = (st->ratio > 0) ? geo_div(out->k, st->ratio) : GEO_POLE_RATIO;
}

/* xi' = chi + atan(q), q = tan(xi' - chi) = sin chi cos chi (1 - cos
 * lam) / (1 - cos^2 chi (1 - cos lam)) (the denominator >= 0.89 in the
 * domain); far from the central meridian near the poles |q| exceeds
 * tm_atan()'s 0.25: then 0, and the caller takes the full atan2 (from
 * its own small frame). out->xi holds chi, out->k cos chi. */
static DRDC_NOINLINE int fwd_xi(const tm_fwd_t *st, geo_tm_t *out)
{
  int64_t q = GEO_ONE - st->clam;

  q = geo_div(drdc__geo_mul(drdc__geo_mul(st->schi, out->k), q),
              GEO_ONE - drdc__geo_mul(drdc__geo_mul(out->k, out->k), q));
  if ((q <= TM_ATAN_MAX) && (q >= -TM_ATAN_MAX)) {
    out->xi = out->xi + tm_atan(q);
    return 1;
  }
  return 0;
}

/* cos 2 zeta at xi' + i eta' into z, sin 2 zeta into out->gamma and
 * out->k (see fwd_series()); out of line: its products' temporaries are
 * not in the frame that holds z under the recurrence */
static DRDC_NOINLINE void fwd_zeta(const tm_fwd_t *st, geo_tm_t *out,
                                   tm_zeta_t *z)
{
  z->c2[0] = drdc__geo_mul(st->schi, st->ch); /* sin xi' */
  z->c2[1] =
      drdc__geo_mul(drdc__geo_mul(out->k, st->clam), st->ch); /* cos xi' */
  z->r1 = 2 * drdc__geo_mul(z->c2[0], z->c2[1]);
  z->i1 = drdc__geo_mul(z->c2[1], z->c2[1]) - drdc__geo_mul(z->c2[0], z->c2[0]);
  z->r2 = 2 * drdc__geo_mul(out->gamma, st->ch);
  z->i2 = drdc__geo_mul(st->ch, st->ch) + drdc__geo_mul(out->gamma, out->gamma);
  /* sinh eta' and cos chi are used up: sin 2 zeta into their slots */
  zeta_set(z, &out->gamma, &out->k);
}

/* Krueger's series at xi' + i eta': sin^2 chi + cos^2 chi cos^2 lam =
 * 1 - tanh^2 eta' = 1 / cosh^2 eta', so sin xi' = sin chi cosh eta' and
 * cos xi' = cos chi cos lam cosh eta': no exponential and no sin/cos of
 * xi'. Adds the sum to out->xi, out->eta; p and q to out->gamma, out->k
 * (which held sinh eta' and cos chi). */
static DRDC_NOINLINE void fwd_series(const tm_fwd_t *st, geo_tm_t *out)
{
  tm_zeta_t z;

  fwd_zeta(st, out, &z);
  /* the sine series, then the derivative's: one series at a time keeps
   * half the state live */
  clenshaw(drdc__geo_alpha, false, &z, z.c2);
  krueger_sum(&z, &out->gamma, &out->k);
  out->xi = out->xi + out->gamma;
  out->eta = out->eta + out->k;
  clenshaw(drdc__geo_alpha, true, &z, z.c2);
  krueger_deriv(&z);
  out->gamma = z.c2[0];
  out->k = z.c2[1];
}

/* the scale from the series' derivative p - i q (in out->gamma,
 * out->k) into out->k: k0 A/a sqrt(1 - e^2 sin^2 phi) (cos chi / cos
 * phi) cosh eta' times |p + i q|, the two roots as one. Out of line, so
 * that the root's chain starts from a frame that keeps one value. */
static DRDC_NOINLINE void fwd_scale(const tm_fwd_t *st, geo_tm_t *out)
{
  int64_t p = drdc__geo_mul(st->kfac, drdc__geo_mul(out->gamma, out->gamma) +
                                          drdc__geo_mul(out->k, out->k)) -
              GEO_ONE;

  /* the root into out->k (0 first, as geo_sqrt() gives on failure): no
   * result slot in this frame */
  if ((p <= TM_SQRT_MAX) && (p >= -TM_SQRT_MAX)) {
    out->k = tm_sqrt1p(p);
  } else {
    out->k = 0;
    (void)drdc_fx_sqrt_q5_58(GEO_ONE + p, &out->k);
  }
  out->k = drdc__geo_mul(
      GEO_K0A_OVER_A, drdc__geo_mul(drdc__geo_mul(out->k, st->ratio), st->ch));
}

/* the convergence's atan2(y, x) arguments into st->slam, st->clam (no
 * longer needed there) from p, q in out->gamma, out->k, before
 * fwd_scale() overwrites q */
static DRDC_NOINLINE void fwd_conv_args(tm_fwd_t *st, const geo_tm_t *out)
{
  int64_t y = drdc__geo_mul(st->schi, st->slam);

  st->slam = drdc__geo_mul(st->clam, out->k) + drdc__geo_mul(y, out->gamma);
  st->clam = drdc__geo_mul(st->clam, out->gamma) - drdc__geo_mul(y, out->k);
}

/* convergence: gamma' = arg(cos lam + i sin chi sin lam) of the sphere
 * plus arg(p + i q) of the series' derivative, as the argument of the
 * product (|gamma| < pi/2 + 0.01: no wrap), into out->gamma. Within 14
 * degrees (every standard zone, Svalbard's included) the series of atan
 * of the quotient, |y| <= x / 4 tested before dividing (so the quotient
 * cannot overflow and is at most 0.25): 1; beyond, 0, and the caller
 * takes the full atan2 from its own small frame. */
static DRDC_NOINLINE int fwd_gamma(const tm_fwd_t *st, geo_tm_t *out)
{
  if ((st->clam > 0) && (st->slam <= (st->clam / 4)) &&
      (st->slam >= -(st->clam / 4))) {
    out->gamma = tm_atan(geo_div(st->slam, st->clam));
    return 1;
  }
  return 0;
}

/* the forward projection's stages in the caller's frame, on its state
 * (inline, so that no frame of its own lies between the caller and the
 * stages) */
static inline DRDC_ALWAYS_INLINE int tm_forward_stages(tm_fwd_t *st,
                                                       geo_tm_t *out)
{
  if (fwd_sphere(st, out) == 0) {
    return 0;
  }
  fwd_ratio(st, out);
  /* the full atan2s write straight into out (0 where both arguments
   * are zero, as geo_atan2() gives): no result slot in this frame. x
   * waits in out->xi, where the result goes (the atan2 takes it by value
   * and leaves it, 0, when both are zero), not in registers across the
   * product */
  if (fwd_xi(st, out) == 0) {
    out->xi = drdc__geo_mul(out->k, st->clam);
    (void)drdc_fx_atan2_q5_58(st->schi, out->xi, &out->xi);
  }
  fwd_series(st, out);
  /* the stages one after the other from this frame, each with few
   * values live: no stage's frame is on top of another's */
  fwd_conv_args(st, out);
  fwd_scale(st, out);
  if (fwd_gamma(st, out) == 0) {
    out->gamma = 0;
    (void)drdc_fx_atan2_q5_58(st->slam, st->clam, &out->gamma);
  }
  return 1;
}

int drdc__geo_tm_forward(geo_tm_t *out)
{
  tm_fwd_t st;

  return tm_forward_stages(&st, out);
}

/* Here rather than in utm_forward.c: the stages run from this frame,
 * which holds the stages' state and the result, with no drdc__geo_tm_forward()
 * frame between (issue 8's stack goal). The checks and statuses are those
 * of the range checks of utm_forward.c. */
drdc_status_t drdc_geo_tm_forward(drdc_nas_t lat, drdc_nas_t dlon,
                                  drdc_q47_16_t *x, drdc_q47_16_t *y,
                                  drdc_nas_t *convergence, drdc_q5_58_t *scale)
{
  geo_tm_t tm;
  tm_fwd_t st;

  if ((x == NULL) || (y == NULL)) {
    return DRDC_E_NULL;
  }
  if ((lat > (90 * GEO_NAS_DEG)) || (lat < (-90 * GEO_NAS_DEG))) {
    return DRDC_E_LATITUDE;
  }
  if ((dlon > (90 * GEO_NAS_DEG)) || (dlon < (-90 * GEO_NAS_DEG))) {
    return DRDC_E_LONGITUDE;
  }
  tm.xi = drdc__geo_rad_from_nas(lat);
  tm.eta = drdc__geo_rad_from_nas(dlon);
  if (tm_forward_stages(&st, &tm) == 0) {
    return DRDC_E_RANGE;
  }
  *x = drdc__geo_metres_from_angle(tm.eta);
  *y = drdc__geo_metres_from_angle(tm.xi);
  if (convergence != NULL) {
    *convergence = drdc__geo_nas_from_rad(tm.gamma);
  }
  if (scale != NULL) {
    *scale = tm.k;
  }
  return DRDC_OK;
}

/* xi' + i eta' = zeta - Krueger's beta series at zeta = xi + i eta
 * (in tm->xi, tm->eta), into tm->xi, tm->eta (the caller's outputs, its
 * scratch until the end); sin 2 zeta and then the sum wait in tm->gamma,
 * tm->k, free until the caller's forward: no slot of this frame has its
 * address taken but the recurrence's */
static DRDC_NOINLINE void rev_series(geo_tm_t *tm)
{
  tm_zeta_t z;

  geo_sincos(2 * tm->xi, &z.r1, &z.i1);
  /* sinh and cosh of 2 eta from the series of sinh and cosh of eta
   * (|eta| <= 0.08 from the eastings' range): no exponential */
  z.r2 = tm_sinh(tm->eta);
  z.i2 = tm_cosh(tm->eta);
  z.c2[0] = 2 * drdc__geo_mul(z.r2, z.i2);
  z.i2 = drdc__geo_mul(z.i2, z.i2) + drdc__geo_mul(z.r2, z.r2);
  z.r2 = z.c2[0];
  zeta_set(&z, &tm->gamma, &tm->k);
  clenshaw(drdc__geo_beta, false, &z, z.c2);
  krueger_sum(&z, &tm->gamma, &tm->k);
  tm->xi = tm->xi - tm->gamma;
  tm->eta = tm->eta - tm->k;
}

/* xi', eta' wait in tm->xi, tm->eta, sin xi' and cos xi' in tm->gamma,
 * tm->k; chi = atan2(sin xi', sqrt(sinh^2 eta' + cos^2 xi')) in tm->xi
 * too, before phi = chi + its series */
void drdc__geo_tm_reverse(geo_tm_t *tm)
{
  rev_series(tm);
  geo_sincos(tm->xi, &tm->gamma, &tm->k);
  /* xi' is used up: sinh eta', then its root with cos xi', wait in
   * tm->xi (no value of this frame across the calls) */
  tm->xi = tm_sinh(tm->eta);
  /* the atan2s write straight into the outputs (0 where both arguments
   * are zero, as geo_atan2() gives: first, or the x they take by value
   * and leave) */
  tm->eta = 0;
  (void)drdc_fx_atan2_q5_58(tm->xi, tm->k, &tm->eta);
  /* a sum of squares: the root never fails (0 for 0, as geo_sqrt()) */
  tm->xi = drdc__geo_mul(tm->xi, tm->xi) + drdc__geo_mul(tm->k, tm->k);
  (void)drdc_fx_sqrt_q5_58(tm->xi, &tm->xi);
  (void)drdc_fx_atan2_q5_58(tm->gamma, tm->xi, &tm->xi);
  geo_sincos(tm->xi, &tm->gamma, &tm->k);
  tm->xi = tm->xi + geo_phi_series(tm->gamma, tm->k);
}
