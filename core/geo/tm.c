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
 * sin(2 j zeta') with zeta = xi + i eta. The multiples 2 j zeta' come from
 * one sin/cos and one sinh/cosh by the addition theorems. Inverse: the
 * beta series, then chi and lam from xi', eta', then phi from chi by its
 * series. Every term is Q5.58; the series' own truncation (n^7 = 4e-20)
 * is far below the 2^-58 resolution of the arithmetic.
 */
#include "geo_impl.h"

#include <drdc/fixed_hyper.h>

/* sum coef[j] sin(2 (j+1) x) from s2 = sin 2x, c2 = cos 2x. Trailing zero
 * coefficients add exact zeros and are skipped, and so is the recurrence
 * after the last term: the same sum with fewer products. */
static int64_t sine_series(const int64_t *coef, unsigned terms, int64_t s2,
                           int64_t c2)
{
  int64_t sn = s2;
  int64_t cn = c2;
  int64_t acc = 0;
  unsigned n = terms;
  unsigned j;

  while ((n > 0u) && (coef[n - 1u] == 0)) {
    n--;
  }
  for (j = 0u; j < n; j++) {
    acc = acc + geo_mul(coef[j], sn);
    if ((j + 1u) < n) {
      int64_t next_s = geo_mul(sn, c2) + geo_mul(cn, s2);
      int64_t next_c = geo_mul(cn, c2) - geo_mul(sn, s2);

      sn = next_s;
      cn = next_c;
    }
  }
  return acc;
}

/* Krueger's series at zeta = xi + i eta: dxi = sum c_j sin 2j xi cosh 2j eta,
 * deta = sum c_j cos 2j xi sinh 2j eta; and the derivative
 * 1 + sum 2j c_j cos(2 j zeta) = p - i q. */
typedef struct krueger {
  int64_t dxi;
  int64_t deta;
  int64_t p;
  int64_t q;
} krueger_t;

static void krueger(const int64_t *coef, int64_t xi, int64_t eta,
                    krueger_t *out)
{
  int64_t s1 = 0;
  int64_t c1 = 0;
  int64_t sh1 = 0;
  int64_t ch1 = 0;
  int64_t sn;
  int64_t cn;
  int64_t shn;
  int64_t chn;
  unsigned j;

  geo_sincos(2 * xi, &s1, &c1);
  (void)drdc_fx_sinh_q5_58(2 * eta, &sh1);
  (void)drdc_fx_cosh_q5_58(2 * eta, &ch1);
  sn = s1;
  cn = c1;
  shn = sh1;
  chn = ch1;
  out->dxi = 0;
  out->deta = 0;
  out->p = GEO_ONE;
  out->q = 0;
  for (j = 0u; j < GEO_KRUEGER_TERMS; j++) {
    int64_t c = coef[j];
    int64_t twojc = c * (2 * ((int64_t)j + 1));

    out->dxi = out->dxi + geo_mul(c, geo_mul(sn, chn));
    out->deta = out->deta + geo_mul(c, geo_mul(cn, shn));
    out->p = out->p + geo_mul(twojc, geo_mul(cn, chn));
    out->q = out->q + geo_mul(twojc, geo_mul(sn, shn));
    /* the multiples 2 (j+2) zeta by the addition theorems, not after the
     * last term */
    if ((j + 1u) < GEO_KRUEGER_TERMS) {
      int64_t next_s = geo_mul(sn, c1) + geo_mul(cn, s1);
      int64_t next_c = geo_mul(cn, c1) - geo_mul(sn, s1);
      int64_t next_sh = geo_mul(shn, ch1) + geo_mul(chn, sh1);
      int64_t next_ch = geo_mul(chn, ch1) + geo_mul(shn, sh1);

      sn = next_s;
      cn = next_c;
      shn = next_sh;
      chn = next_ch;
    }
  }
}

int64_t geo_cos_ratio(int64_t s)
{
  int64_t w = 0;
  int64_t sh = 0;
  int64_t ch = 0;
  int64_t e;

  (void)drdc_fx_atanh_q5_58(geo_mul(GEO_E, s), &w);
  w = geo_mul(GEO_E, w);
  (void)drdc_fx_sinh_q5_58(w, &sh);
  (void)drdc_fx_cosh_q5_58(w, &ch);
  e = sh + ch;
  return geo_div(2 * e, (GEO_ONE + s) + geo_mul(GEO_ONE - s, geo_mul(e, e)));
}

int64_t geo_chi_series(int64_t sphi, int64_t cphi)
{
  return sine_series(geo_chi_from_phi, GEO_CHI_TERMS,
                     2 * geo_mul(sphi, cphi),
                     geo_mul(cphi, cphi) - geo_mul(sphi, sphi));
}

int64_t geo_phi_series(int64_t schi, int64_t cchi)
{
  return sine_series(geo_phi_from_chi, GEO_CHI_TERMS,
                     2 * geo_mul(schi, cchi),
                     geo_mul(cchi, cchi) - geo_mul(schi, schi));
}

int geo_tm_forward(int64_t phi, int64_t lam, geo_tm_t *out)
{
  int64_t sphi = 0;
  int64_t cphi = 0;
  int64_t slam = 0;
  int64_t clam = 0;
  int64_t schi = 0;
  int64_t cchi = 0;
  int64_t chi;
  int64_t tanh_eta;
  int64_t xip;
  int64_t etap = 0;
  int64_t cosh_etap = 0;
  int64_t ratio;
  int64_t kp;
  krueger_t kr;

  geo_sincos(phi, &sphi, &cphi);
  geo_sincos(lam, &slam, &clam);
  chi = phi + geo_chi_series(sphi, cphi);
  geo_sincos(chi, &schi, &cchi);
  tanh_eta = geo_mul(cchi, slam);
  if ((tanh_eta > GEO_TM_MAX_TANH_ETA) || (tanh_eta < -GEO_TM_MAX_TANH_ETA)) {
    return 0;
  }
  xip = geo_atan2(schi, geo_mul(cchi, clam));
  (void)drdc_fx_atanh_q5_58(tanh_eta, &etap);
  krueger(geo_alpha, xip, etap, &kr);
  out->xi = xip + kr.dxi;
  out->eta = etap + kr.deta;
  /* convergence: gamma' = atan2(sin chi sin lam, cos lam) of the sphere,
   * plus the argument of the series' derivative */
  out->gamma = geo_atan2(geo_mul(schi, slam), clam) + geo_atan2(kr.q, kr.p);
  /* scale: k0 A/a sqrt(1 - e^2 sin^2 phi) (cos chi / cos phi) cosh eta'
   * times |derivative| */
  (void)drdc_fx_cosh_q5_58(etap, &cosh_etap);
  if (cphi > 0) {
    ratio = geo_div(cchi, cphi);
  } else {
    ratio = GEO_POLE_RATIO;
  }
  kp = geo_sqrt(GEO_ONE - geo_mul(GEO_E2, geo_mul(sphi, sphi)));
  kp = geo_mul(geo_mul(kp, ratio), cosh_etap);
  kp = geo_mul(kp, geo_sqrt(geo_mul(kr.p, kr.p) + geo_mul(kr.q, kr.q)));
  out->k = geo_mul(GEO_K0A_OVER_A, kp);
  return 1;
}

void geo_tm_reverse(int64_t xi, int64_t eta, int64_t *phi, int64_t *lam)
{
  krueger_t kr;
  int64_t xip;
  int64_t etap;
  int64_t sxip = 0;
  int64_t cxip = 0;
  int64_t shetap = 0;
  int64_t schi = 0;
  int64_t cchi = 0;
  int64_t chi;

  krueger(geo_beta, xi, eta, &kr);
  xip = xi - kr.dxi;
  etap = eta - kr.deta;
  geo_sincos(xip, &sxip, &cxip);
  (void)drdc_fx_sinh_q5_58(etap, &shetap);
  *lam = geo_atan2(shetap, cxip);
  chi = geo_atan2(sxip, geo_sqrt(geo_mul(shetap, shetap)
                                 + geo_mul(cxip, cxip)));
  geo_sincos(chi, &schi, &cchi);
  *phi = chi + geo_phi_series(schi, cchi);
}
