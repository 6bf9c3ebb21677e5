/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Transverse Mercator on WGS-84 by Krueger's series to 6th order in
 *        the third flattening n, with meridian convergence and point
 *        scale.
 *
 * Krueger (1912), in the form of Karney, "Transverse Mercator with an
 * accuracy of a few nanometers", J. Geodesy 85 (2011), as GeographicLib's
 * TransverseMercator implements it:
 *
 * Forward: the conformal latitude chi from phi (conformal.c), the
 * spherical transverse Mercator xi' = atan2(tan chi, cos lam), eta' =
 * atanh(cos chi sin lam), then zeta = zeta' + sum alpha_j sin(2 j zeta')
 * with zeta = xi + i eta, summed by Clenshaw's recurrence in complex
 * arithmetic; its derivative gives the convergence and the scale.
 * Reverse: zeta' = zeta - sum beta_j sin(2 j zeta), then chi and lam from
 * xi', eta', then phi from chi.
 *
 * Every value is Q5.58. The series' truncation (terms of order n^7,
 * about 4e-20) is far below the 2^-58 = 3.5e-18 resolution; what remains
 * is the rounding of the arithmetic, a few LSB on xi and eta (15 um at
 * most on the ground: see docs/accuracy.md).
 */
#include <drdc/compiler.h>
#include <drdc/fixed_sqrt.h>
#include <drdc/geo.h>

#include "geo_projection.h"

/* A complex number re + i im. */
typedef struct tm_complex {
  int64_t re;
  int64_t im;
} tm_complex_t;

/* zeta = xi + i eta by the sine and cosine of 2 xi and the hyperbolic
 * sine and cosine of 2 eta. */
typedef struct tm_zeta {
  int64_t s2xi;
  int64_t c2xi;
  int64_t sh2eta;
  int64_t ch2eta;
} tm_zeta_t;

/* Krueger's series at zeta by Clenshaw's recurrence in complex arithmetic
 * (as GeographicLib does): with A = 2 cos 2 zeta (2 a below), b_j = c_j + A
 * b_(j+1) - b_(j+2) from b_7 = b_8 = 0, and then
 *  - the sum: sum c_j sin(2 j zeta) = sin(2 zeta) b_1;
 *  - with c_j replaced by d_j = 2 j c_j (deriv), the derivative
 *    d zeta / d zeta' = 1 + sum d_j cos(2 j zeta) = 1 + cos(2 zeta) b_1 -
 *    b_2 = p - i q, returned as p + i q.
 * |A| <= 2 cosh 0.68 < 2.5 and |b_j| < 2e-3: every product stays far
 * inside Q5.58, and the roundings add up to a few LSB.
 *
 * The terms b_3 .. b_6 are small: with the largest coefficients (alpha's
 * derivative, 2 j alpha_j raw 52, 16 462, 5.6e6 and 2.07e9 for j = 6 ..
 * 3; beta's and the sums' are smaller), |b_6| <= 52, |b_5| <= 16 462 +
 * 2.5 52 < 16 600, |b_4| <= 5.61e6 + 2.5 16 600 + 52 < 5.66e6 and |b_3|
 * <= 2.071e9 + 2.5 5.66e6 + 16 600 < 2.09e9, each part below 2^32 raw:
 * their products with A are short products (drdc__geo_mul_short()), the
 * same bits as the full ones: the steps to b_5 .. b_2 take them, the
 * step to b_1 full ones (a loop per kind of product: one loop choosing
 * between them deepens krueger()'s frame past the 512-byte stack limit
 * of the grid poses). b_7 = b_8 = 0: the recurrence starts at b_6 = c_6
 * (the full recurrence's products by 0 are 0). */
static tm_complex_t krueger(const int64_t *coef, bool deriv, const tm_zeta_t *z)
{
  tm_complex_t a; /* cos 2 zeta = cos 2xi cosh 2eta - i sin 2xi sinh 2eta */
  tm_complex_t b0;
  tm_complex_t b1;
  tm_complex_t b2;
  tm_complex_t r;
  unsigned j;

  a.re = drdc__geo_mul(z->c2xi, z->ch2eta);
  a.im = -drdc__geo_mul(z->s2xi, z->sh2eta);
  /* b_7 = 0, b_6 = c_6 */
  b2.re = 0;
  b2.im = 0;
  b1.re = deriv ? (coef[5] * 12) : coef[5];
  b1.im = 0;
  for (j = GEO_KRUEGER_TERMS - 1u; j > 1u; j--) {
    int64_t c = deriv ? (coef[j - 1u] * (2 * (int64_t)j)) : coef[j - 1u];

    b0.re = ((c - b2.re) + drdc__geo_mul_short(2 * a.re, b1.re)) -
            drdc__geo_mul_short(2 * a.im, b1.im);
    b0.im = (drdc__geo_mul_short(2 * a.re, b1.im) - b2.im) +
            drdc__geo_mul_short(2 * a.im, b1.re);
    b2 = b1;
    b1 = b0;
  }
  /* b_1, from the full b_2 */
  b0.re = (((deriv ? (coef[0] * 2) : coef[0]) - b2.re) +
           drdc__geo_mul(2 * a.re, b1.re)) -
          drdc__geo_mul(2 * a.im, b1.im);
  b0.im =
      (drdc__geo_mul(2 * a.re, b1.im) - b2.im) + drdc__geo_mul(2 * a.im, b1.re);
  b2 = b1;
  b1 = b0;
  if (deriv) {
    r.re =
        (GEO_ONE + (drdc__geo_mul(a.re, b1.re) - drdc__geo_mul(a.im, b1.im))) -
        b2.re;
    r.im = -((drdc__geo_mul(a.re, b1.im) + drdc__geo_mul(a.im, b1.re)) - b2.im);
  } else {
    /* sin 2 zeta = sin 2xi cosh 2eta + i cos 2xi sinh 2eta */
    tm_complex_t sin2;

    sin2.re = drdc__geo_mul(z->s2xi, z->ch2eta);
    sin2.im = drdc__geo_mul(z->c2xi, z->sh2eta);
    r.re = drdc__geo_mul(sin2.re, b1.re) - drdc__geo_mul(sin2.im, b1.im);
    r.im = drdc__geo_mul(sin2.re, b1.im) + drdc__geo_mul(sin2.im, b1.re);
  }
  return r;
}

/* Krueger's sum at z added to *re + i *im (the forward's xi', eta',
 * which become xi, eta). */
static void krueger_add(const int64_t *coef, const tm_zeta_t *z, int64_t *re,
                        int64_t *im)
{
  tm_complex_t sum = krueger(coef, false, z);

  *re = *re + sum.re;
  *im = *im + sum.im;
}

/* sin and cos of x + d from s = sin x, c = cos x and a small d (|d| <=
 * 0.004, the conformal latitude's correction): sin d = d (1 - d^2/6 +
 * d^4/120), cos d = 1 - d^2/2 + d^4/24 - d^6/720 (first omitted terms
 * d^7/5040 and d^8/40320, below 1e-20), then the addition theorems: 11
 * products instead of a full sin/cos. */
static void rotate_small(int64_t s, int64_t c, int64_t d, int64_t *s_out,
                         int64_t *c_out)
{
  int64_t d2 = drdc__geo_mul(d, d);
  int64_t sd = drdc__geo_mul(
      d,
      GEO_ONE - drdc__geo_mul(d2, GEO_Q58_RECIP(6) -
                                      drdc__geo_mul(d2, GEO_Q58_RECIP(120))));
  int64_t cd =
      GEO_ONE -
      drdc__geo_mul(
          d2, GEO_Q58_RECIP(2) -
                  drdc__geo_mul(d2, GEO_Q58_RECIP(24) -
                                        drdc__geo_mul(d2, GEO_Q58_RECIP(720))));

  *s_out = drdc__geo_mul(s, cd) + drdc__geo_mul(c, sd);
  *c_out = drdc__geo_mul(c, cd) - drdc__geo_mul(s, sd);
}

/* atan2(y, x) for a direction near the positive x axis: where |y| <= x
 * / 4 (the test comes before the division, which then cannot overflow)
 * the atan series of the quotient, else the general atan2. Always
 * inline: a frame of its own between the projections and the general
 * atan2 passes the 512-byte stack limit of the grid poses. */
static inline DRDC_ALWAYS_INLINE int64_t atan2_near_axis(int64_t y, int64_t x)
{
  if ((x > 0) && (y <= (x / 4)) && (y >= -(x / 4))) {
    return drdc__geo_atan_small(geo_div(y, x));
  }
  return geo_atan2(y, x);
}

/* The forward projection on the conformal sphere: what the series, the
 * convergence and the scale take from phi and lam. */
typedef struct tm_sphere {
  int64_t chi;  /* conformal latitude */
  int64_t schi; /* sin chi, cos chi */
  int64_t cchi;
  int64_t slam; /* sin lam, cos lam */
  int64_t clam;
  int64_t cphi;   /* cos phi */
  int64_t kfac;   /* 1 - e^2 sin^2 phi */
  int64_t eta;    /* eta' = atanh(cos chi sin lam) */
  int64_t sh_eta; /* sinh eta', cosh eta' */
  int64_t ch_eta;
} tm_sphere_t;

/* chi, eta' and the sines and cosines of phi, lam into *s; 0 beyond the
 * series' domain. chi comes from phi by its series, its sine and cosine
 * by rotating those of phi by chi - phi. sinh eta' = tanh eta' cosh
 * eta', cosh eta' by its series (|eta'| <= 0.34). */
static int tm_sphere(int64_t phi, int64_t lam, tm_sphere_t *s)
{
  int64_t sphi;
  int64_t dchi;
  int64_t tanh_eta;

  geo_sincos(lam, &s->slam, &s->clam);
  geo_sincos(phi, &sphi, &s->cphi);
  dchi = geo_chi_series(sphi, s->cphi);
  s->chi = phi + dchi;
  rotate_small(sphi, s->cphi, dchi, &s->schi, &s->cchi);
  s->kfac = GEO_ONE - drdc__geo_mul(GEO_E2, drdc__geo_mul(sphi, sphi));
  tanh_eta = drdc__geo_mul(s->cchi, s->slam);
  if ((tanh_eta > GEO_TM_MAX_TANH_ETA) || (tanh_eta < -GEO_TM_MAX_TANH_ETA)) {
    return 0;
  }
  s->eta = drdc__geo_atanh_small(tanh_eta);
  s->ch_eta = drdc__geo_cosh_small(s->eta);
  s->sh_eta = drdc__geo_mul(tanh_eta, s->ch_eta);
  return 1;
}

/* xi' = chi + atan(q) with q = tan(xi' - chi) = sin chi cos chi (1 - cos
 * lam) / (1 - cos^2 chi (1 - cos lam)) (the denominator >= 0.89 in the
 * domain), which avoids an atan2 near the meridian; far from it near the
 * poles |q| exceeds the atan series' 0.25, and the full atan2(sin chi,
 * cos chi cos lam) is taken. */
static int64_t tm_sphere_xi(const tm_sphere_t *s)
{
  int64_t v = GEO_ONE - s->clam;
  int64_t q =
      geo_div(drdc__geo_mul(drdc__geo_mul(s->schi, s->cchi), v),
              GEO_ONE - drdc__geo_mul(drdc__geo_mul(s->cchi, s->cchi), v));

  if ((q <= GEO_ATAN_SMALL_MAX) && (q >= -GEO_ATAN_SMALL_MAX)) {
    return s->chi + drdc__geo_atan_small(q);
  }
  return geo_atan2(s->schi, drdc__geo_mul(s->cchi, s->clam));
}

/* Convergence: gamma' = arg(cos lam + i sin chi sin lam) of the sphere
 * plus arg(p + i q) of the series' derivative, as the argument of the
 * product (|gamma| < pi/2 + 0.01: no wrap). Within 14 degrees of the
 * meridian (every standard zone, Svalbard's included) |y| <= x / 4, and
 * the atan series of the quotient replaces the atan2 (the test comes
 * before the division, which then cannot overflow). */
static int64_t tm_convergence(const tm_sphere_t *s, const tm_complex_t *pq)
{
  int64_t t = drdc__geo_mul(s->schi, s->slam);
  int64_t y = drdc__geo_mul(s->clam, pq->im) + drdc__geo_mul(t, pq->re);
  int64_t x = drdc__geo_mul(s->clam, pq->re) - drdc__geo_mul(t, pq->im);

  return atan2_near_axis(y, x);
}

/* Point scale: k0 (A/a) sqrt(1 - e^2 sin^2 phi) (cos chi / cos phi) cosh
 * eta' |p + i q|, the two roots taken as one. Its argument lies within
 * 1 - 0.0113 .. 1 + 0.0046 in the whole domain, where the binomial series
 * of sqrt(1 + u) is good to about 1 LSB; the general root stays for any
 * argument beyond. */
static int64_t tm_scale(const tm_sphere_t *s, int64_t ratio,
                        const tm_complex_t *pq)
{
  int64_t u = drdc__geo_mul(s->kfac, drdc__geo_mul(pq->re, pq->re) +
                                         drdc__geo_mul(pq->im, pq->im)) -
              GEO_ONE;
  int64_t root;

  if ((u <= GEO_SQRT1P_SMALL_MAX) && (u >= -GEO_SQRT1P_SMALL_MAX)) {
    root = drdc__geo_sqrt1p_small(u);
  } else {
    root = geo_sqrt(GEO_ONE + u);
  }
  return drdc__geo_mul(GEO_K0A_OVER_A,
                       drdc__geo_mul(drdc__geo_mul(root, ratio), s->ch_eta));
}

int drdc__geo_tm_forward(int64_t phi, int64_t lam, geo_projected_t *out)
{
  tm_sphere_t s;
  tm_zeta_t z;
  tm_complex_t pq;
  int64_t ratio;
  int64_t xi;
  int64_t sxi;
  int64_t cxi;

  if (tm_sphere(phi, lam, &s) == 0) {
    return 0;
  }
  /* cos chi / cos phi, and its limit at the poles */
  ratio = (s.cphi > 0) ? geo_div(s.cchi, s.cphi) : GEO_POLE_RATIO;
  xi = tm_sphere_xi(&s);
  /* sin^2 chi + cos^2 chi cos^2 lam = 1 - tanh^2 eta' = 1 / cosh^2
   * eta', so sin xi' = sin chi cosh eta' and cos xi' = cos chi cos lam
   * cosh eta': no sin/cos of xi' and no exponential */
  sxi = drdc__geo_mul(s.schi, s.ch_eta);
  cxi = drdc__geo_mul(drdc__geo_mul(s.cchi, s.clam), s.ch_eta);
  z.s2xi = 2 * drdc__geo_mul(sxi, cxi);
  z.c2xi = drdc__geo_mul(cxi, cxi) - drdc__geo_mul(sxi, sxi);
  z.sh2eta = 2 * drdc__geo_mul(s.sh_eta, s.ch_eta);
  z.ch2eta =
      drdc__geo_mul(s.ch_eta, s.ch_eta) + drdc__geo_mul(s.sh_eta, s.sh_eta);
  out->y = xi;
  out->x = s.eta;
  krueger_add(drdc__geo_alpha, &z, &out->y, &out->x);
  pq = krueger(drdc__geo_alpha, true, &z);
  out->gamma = tm_convergence(&s, &pq);
  out->k = tm_scale(&s, ratio, &pq);
  return 1;
}

/* A TM angle (radius k0 A) -> metres, Q47.16: the Q28.36 metres rounded
 * again (the angles of the projection keep them within int64_t). */
static drdc_q47_16_t metres_from_angle(int64_t a)
{
  return drdc_fx_rshift_round_s64_inline(
      drdc__geo_mul_shift(a, GEO_K0A_Q40, 62u), 20u);
}

drdc_status_t drdc_geo_tm_forward(drdc_nas_t lat, drdc_nas_t dlon,
                                  drdc_q47_16_t *x, drdc_q47_16_t *y,
                                  drdc_nas_t *convergence, drdc_q5_58_t *scale)
{
  geo_projected_t p;

  if ((x == NULL) || (y == NULL)) {
    return DRDC_E_NULL;
  }
  if ((lat > (90 * GEO_NAS_DEG)) || (lat < (-90 * GEO_NAS_DEG))) {
    return DRDC_E_LATITUDE;
  }
  if ((dlon > (90 * GEO_NAS_DEG)) || (dlon < (-90 * GEO_NAS_DEG))) {
    return DRDC_E_LONGITUDE;
  }
  if (drdc__geo_tm_forward(drdc__geo_rad_from_nas(lat),
                           drdc__geo_rad_from_nas(dlon), &p) == 0) {
    return DRDC_E_RANGE;
  }
  *x = metres_from_angle(p.x);
  *y = metres_from_angle(p.y);
  if (convergence != NULL) {
    *convergence = drdc__geo_nas_from_rad(p.gamma);
  }
  if (scale != NULL) {
    *scale = p.k;
  }
  return DRDC_OK;
}

/* Convergence and scale of the reverse at zeta' = xi' + i eta', from the
 * derivative of zeta = zeta' + ..., d zeta / d zeta' = 1 / D with D =
 * d zeta' / d zeta = 1 - sum 2 j beta_j cos(2 j zeta). krueger() over
 * beta gives 1 + sum 2 j beta_j cos(2 j zeta) = p - i q, so D = (2 - p)
 * + i q. The convergence is that of the sphere, arg(cos xi' cosh eta' +
 * i sin xi' sinh eta'), plus arg D, taken as one argument of the
 * product; the scale k0 (A/a) sqrt(1 - e^2 sin^2 phi) (cos chi / cos
 * phi) cosh eta' / |D|, its two roots as one. |D|^2 stays within 0.3 %
 * of 1 and 1 - e^2 sin^2 phi within 0.7 %: the binomial series of
 * sqrt(1 + u) covers the quotient. */
typedef struct tm_reverse_point {
  int64_t sxi; /* sin xi', cos xi' */
  int64_t cxi;
  int64_t sh_eta; /* sinh eta', cosh eta' */
  int64_t ch_eta;
  int64_t schi; /* sin chi, cos chi */
  int64_t cchi;
  int64_t dphi; /* phi - chi */
} tm_reverse_point_t;

static void tm_reverse_conv_scale(const tm_reverse_point_t *r,
                                  const tm_complex_t *pq, geo_conv_scale_t *cs)
{
  int64_t a = drdc__geo_mul(r->cxi, r->ch_eta);
  int64_t b = drdc__geo_mul(r->sxi, r->sh_eta);
  int64_t dre = (2 * GEO_ONE) - pq->re;
  int64_t dim = pq->im;
  int64_t sphi;
  int64_t cphi;
  int64_t kfac;
  int64_t u;
  int64_t root;
  int64_t ratio;

  cs->gamma = atan2_near_axis(drdc__geo_mul(a, dim) + drdc__geo_mul(b, dre),
                              drdc__geo_mul(a, dre) - drdc__geo_mul(b, dim));
  rotate_small(r->schi, r->cchi, r->dphi, &sphi, &cphi);
  kfac = GEO_ONE - drdc__geo_mul(GEO_E2, drdc__geo_mul(sphi, sphi));
  u = geo_div(kfac, drdc__geo_mul(dre, dre) + drdc__geo_mul(dim, dim)) -
      GEO_ONE;
  if ((u <= GEO_SQRT1P_SMALL_MAX) && (u >= -GEO_SQRT1P_SMALL_MAX)) {
    root = drdc__geo_sqrt1p_small(u);
  } else {
    root = geo_sqrt(GEO_ONE + u);
  }
  ratio = (cphi > 0) ? geo_div(r->cchi, cphi) : GEO_POLE_RATIO;
  cs->k = drdc__geo_mul(GEO_K0A_OVER_A,
                        drdc__geo_mul(drdc__geo_mul(root, ratio), r->ch_eta));
}

/* sqrt(x) for 0 <= x < 4 (Q5.58): x' = x 4^k in [1, 4), the seed
 * 2^16 / sqrt(x') from the rounded integer root of x' 2^30 (16 bits,
 * drdc_fx_sqrt_u32()) and a 32-bit quotient, within 2^-14.5 relative;
 * three Newton steps y (3 - x' y^2) / 2 of the reciprocal root, each
 * squaring the relative error (1.5 e^2: 2^-28.4, 2^-56, then the
 * roundings), and sqrt(x') = x' y, shifted back by k: at most 3.3 LSB
 * for x <= 2 and 5.7 LSB below 4 (2 million random arguments against
 * the exact root). No 128-bit quotient, where drdc_fx_sqrt_q5_58()
 * takes two. Not inline: its locals in the reverse's frame pass the
 * 512-byte stack limit of the grid poses. */
static DRDC_NOINLINE int64_t tm_sqrt(int64_t x)
{
  unsigned k;
  int64_t xs;
  uint64_t top;
  uint32_t seed;
  int64_t y;
  unsigned i;

  if (x <= 0) {
    return 0;
  }
  k = ((unsigned)__builtin_clzll((uint64_t)x) - 4u) >> 1;
  xs = x * (INT64_C(1) << (2u * k));
  /* xs in [2^58, 2^60): xs / 2^28 is x' 2^30, in [2^30, 2^32), and its
   * rounded root sqrt(x') 2^15 in [2^15, 2^16]; 2^32 - 1 over it is
   * 2^17 / sqrt(x'), in [2^16, 2^17): Q17 -> Q58 */
  top = (uint64_t)xs >> 28u;
  seed = 0xFFFFFFFFu / drdc_fx_sqrt_u32((uint32_t)top);
  y = (int64_t)seed * (INT64_C(1) << 41);
  for (i = 0u; i < 3u; i++) {
    y = drdc_fx_rshift_round_s64_inline(
        drdc__geo_mul(y,
                      (3 * GEO_ONE) - drdc__geo_mul(xs, drdc__geo_mul(y, y))),
        1u);
  }
  y = drdc__geo_mul(xs, y);
  return (k == 0u) ? y : drdc_fx_rshift_round_s64_inline(y, k);
}

/* q = tan(xi' - chi) at a point r of the reverse (sin xi', cos xi' and
 * sinh eta' set, cos chi holding r = sqrt(sinh^2 eta' + cos^2 xi')),
 * or 1 where the atan series does not serve. tan chi = sin xi' / r, so
 * tan(chi - xi') = sin xi' (cos xi' - r) / (r cos xi' + sin^2 xi'), and
 * cos xi' - r = -sinh^2 eta' / (cos xi' + r): q = sin xi' sinh^2 eta' /
 * ((cos xi' + r)(r cos xi' + sin^2 xi')), free of cancellation; |q| <=
 * |sinh eta'| (0.08 in the UTM zones), and where cos xi' >= 1/16 (every
 * UTM northing: xi' <= 1.47) the quotient's rounding is amplified at
 * most 16 times. Not inline: its locals in the reverse's frame pass the
 * 512-byte stack limit of the grid poses. */
static DRDC_NOINLINE int64_t tm_reverse_tan(const tm_reverse_point_t *r)
{
  int64_t q = GEO_ONE;

  if (r->cxi >= (GEO_ONE / 16)) {
    int64_t num = drdc__geo_mul(r->sxi, drdc__geo_mul(r->sh_eta, r->sh_eta));
    int64_t den =
        drdc__geo_mul(r->cxi + r->cchi, drdc__geo_mul(r->cchi, r->cxi) +
                                            drdc__geo_mul(r->sxi, r->sxi));

    if ((num <= (den / 4)) && (num >= -(den / 4))) {
      q = geo_div(num, den);
    }
  }
  return q;
}

void drdc__geo_tm_reverse(int64_t xi, int64_t eta, geo_phi_lam_t *out,
                          geo_conv_scale_t *cs)
{
  tm_zeta_t z;
  tm_complex_t sum;
  tm_reverse_point_t r = {0, 0, 0, 0, 0, 0, 0};
  int64_t q;
  int64_t sech;

  /* sin and cos of 2 xi from those of xi, sinh and cosh of 2 eta from
   * the series of sinh and cosh of eta (|eta| <= 0.08 for eastings
   * 0 .. 1 000 km): one sin/cos and no exponential (sinh and cosh of eta
   * held in r until then) */
  geo_sincos(xi, &r.sxi, &r.cxi);
  z.s2xi = 2 * drdc__geo_mul(r.sxi, r.cxi);
  z.c2xi = drdc__geo_mul(r.cxi, r.cxi) - drdc__geo_mul(r.sxi, r.sxi);
  r.sh_eta = drdc__geo_sinh_small(eta);
  r.ch_eta = drdc__geo_cosh_small(eta);
  z.sh2eta = 2 * drdc__geo_mul(r.sh_eta, r.ch_eta);
  z.ch2eta =
      drdc__geo_mul(r.ch_eta, r.ch_eta) + drdc__geo_mul(r.sh_eta, r.sh_eta);
  sum = krueger(drdc__geo_beta, false, &z);
  /* zeta' = xi' + i eta' on the sphere; sin and cos of xi' by rotating
   * those of xi through -sum.re (|sum| <= beta_1 cosh 0.68 < 0.0011) */
  rotate_small(r.sxi, r.cxi, -sum.re, &r.sxi, &r.cxi);
  r.sh_eta = drdc__geo_sinh_small(eta - sum.im);
  r.ch_eta = drdc__geo_cosh_small(eta - sum.im);
  /* lam = atan2(sinh eta', cos xi'); with r = sqrt(sinh^2 eta' + cos^2
   * xi') = sqrt(cosh^2 eta' - sin^2 xi'), tan chi = sin xi' / r, so sin
   * chi = sin xi' / cosh eta' and cos chi = r / cosh eta' (no sin/cos of
   * chi); r held in cchi until then */
  out->lam = atan2_near_axis(r.sh_eta, r.cxi);
  r.cchi =
      tm_sqrt(drdc__geo_mul(r.sh_eta, r.sh_eta) + drdc__geo_mul(r.cxi, r.cxi));
  /* chi = xi' - atan q, or the general atan2 where q does not serve */
  q = tm_reverse_tan(&r);
  if (q < GEO_ONE) {
    out->phi = (xi - sum.re) - drdc__geo_atan_small(q);
  } else {
    out->phi = geo_atan2(r.sxi, r.cchi);
  }
  sech = geo_div(GEO_ONE, r.ch_eta);
  r.schi = drdc__geo_mul(r.sxi, sech);
  r.cchi = drdc__geo_mul(r.cchi, sech);
  r.dphi = geo_phi_series(r.schi, r.cchi);
  out->phi = out->phi + r.dphi;
  if (cs != NULL) {
    tm_complex_t pq = krueger(drdc__geo_beta, true, &z);

    tm_reverse_conv_scale(&r, &pq, cs);
  }
}
