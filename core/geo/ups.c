/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Universal Polar Stereographic on WGS-84 (k0 = 0.994, false
 *        easting and northing 2 000 000 m), through the conformal
 *        latitude, as GeographicLib's PolarStereographic and UTMUPS.
 *
 * On the north sheet (the south one mirrors phi and lam): the polar
 * distance is rho = (2 k0 a / c) tan(pi/4 - chi/2) with tan(pi/4 - chi/2)
 * = cos chi / (1 + sin chi) and c = sqrt(1 - e^2) ((1 + e) / (1 -
 * e))^(e/2); x = rho sin lam, y = -rho cos lam. The scale is (2 k0 / c)
 * (cos chi / cos phi) sqrt(1 - e^2 sin^2 phi) / (1 + sin chi), k0 at the
 * pole, and the convergence is lam. The inverse takes chi = atan2(1 -
 * t^2, 2 t) from t = rho c / (2 k0 a), then phi from chi by its series.
 */
#include "geo_projection.h"

#include <drdc/fixed_sqrt.h>

/** 2^61: takes (Q5.58 times Q24.39) to Q36. */
#define TWO_POW_61 INT64_C(2305843009213693952)
/** sin chi below which the point is beyond the projection's use (t > 4.4;
 *  the UPS ranges end near chi = 65 degrees). */
#define UPS_MIN_SIN_CHI (-GEO_ONE + (GEO_ONE / 10))

/* k = (2 k0 / c) (cos chi / cos phi) sqrt(1 - e^2 sin^2 phi) / (1 + sin
 * chi) on the north sheet, from sin phi and sin chi */
static int64_t ups_scale(int64_t sphi, int64_t schi)
{
  int64_t k = drdc__geo_mul(GEO_UPS_2K0_OVER_C, drdc__geo_cos_ratio(sphi));

  k = drdc__geo_mul(
      k, geo_sqrt(GEO_ONE - drdc__geo_mul(GEO_E2, drdc__geo_mul(sphi, sphi))));
  return geo_div(k, GEO_ONE + schi);
}

int drdc__geo_ups_forward(bool north, int64_t phi, int64_t lam,
                          geo_projected_t *out)
{
  int64_t p = north ? phi : -phi; /* the latitude on the north sheet */
  int64_t sphi;
  int64_t cphi;
  int64_t chi;
  int64_t schi;
  int64_t cchi;
  int64_t slam;
  int64_t clam;
  int64_t t;

  geo_sincos(p, &sphi, &cphi);
  chi = p + geo_chi_series(sphi, cphi);
  geo_sincos(chi, &schi, &cchi);
  if (schi < UPS_MIN_SIN_CHI) {
    return 0;
  }
  /* t = tan(pi/4 - chi/2), rho / (2 k0 a / c) */
  t = geo_div(cchi, GEO_ONE + schi);
  geo_sincos(lam, &slam, &clam);
  out->x = drdc__geo_mul(t, slam);
  out->y = north ? -drdc__geo_mul(t, clam) : drdc__geo_mul(t, clam);
  out->gamma = north ? lam : -lam;
  out->k = ups_scale(sphi, schi);
  return 1;
}

void drdc__geo_ups_conv_scale(bool north, int64_t phi, int64_t lam,
                              geo_conv_scale_t *cs)
{
  int64_t p = north ? phi : -phi;
  int64_t sphi;
  int64_t cphi;
  int64_t schi;
  int64_t cchi;

  geo_sincos(p, &sphi, &cphi);
  geo_sincos(p + geo_chi_series(sphi, cphi), &schi, &cchi);
  cs->gamma = north ? lam : -lam;
  cs->k = ups_scale(sphi, schi);
}

int64_t drdc__geo_ups_q36(int64_t a)
{
  return drdc__geo_mul_shift(a, GEO_UPS_K_Q39, 61u);
}

void drdc__geo_ups_reverse(bool north, drdc_q47_16_t x, drdc_q47_16_t y,
                           geo_phi_lam_t *out)
{
  int64_t t;
  int64_t chi;
  int64_t schi;
  int64_t cchi;

  if ((x == 0) && (y == 0)) {
    /* GeographicLib's atan2(+0, -0) at the north pole */
    out->lam = north ? GEO_PI : 0;
  } else {
    out->lam = geo_atan2(x, north ? -y : y);
  }
  /* the polar distance (hypot of the metres in Q36) and the longitude
   * straight from the exact metres: next to the pole a Q5.58 angle would
   * keep too few bits, and a Q47.16 hypot would cost 7.6 um */
  t = drdc__geo_muldiv(
      (int64_t)drdc_fx_hypot_s64(x * INT64_C(1048576), y * INT64_C(1048576)),
      TWO_POW_61, GEO_UPS_K_Q39);
  chi = geo_atan2(GEO_ONE - drdc__geo_mul(t, t), 2 * t);
  geo_sincos(chi, &schi, &cchi);
  out->phi = chi + geo_phi_series(schi, cchi);
  if (!north) {
    out->phi = -out->phi;
  }
}
