/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Universal Polar Stereographic on WGS-84 (k0 = 0.994, false
 *        easting and northing 2 000 000 m), through the conformal
 *        latitude of tm.c.
 *
 * The polar distance is rho = (2 k0 a / c) tan(pi/4 - chi/2) with
 * tan(pi/4 - chi/2) = cos chi / (1 + sin chi) and
 * c = sqrt(1 - e^2) ((1 + e) / (1 - e))^(e/2); the scale is
 * (2 k0 / c) (cos chi / cos phi) sqrt(1 - e^2 sin^2 phi) / (1 + sin chi),
 * k0 at the pole. The inverse takes chi = atan2(1 - t^2, 2 t) from
 * t = rho c / (2 k0 a), then phi from chi by its series.
 */
#include "geo_impl.h"

#include <drdc/fixed_sqrt.h>

/** 2^61: takes (Q5.58 times Q24.39) to Q36. */
#define TWO_POW_61 INT64_C(2305843009213693952)
/** sin chi below which the point is beyond the projection's use (t > 4.4;
 *  the UPS ranges end near chi = 65 degrees). */
#define UPS_MIN_SIN_CHI (-GEO_ONE + (GEO_ONE / 10))

int drdc__geo_ups_forward(bool north, geo_tm_t *out)
{
  int64_t p = north ? out->xi : -out->xi;
  int64_t t;

  /* out is the scratch from the start (the callers' own scratch, which
   * they drop on 0): sin phi in out->xi until the scale's root, cos phi
   * and then chi in out->eta, the convergence's lam in out->gamma, the
   * scale's factors in out->k; only p, then t, is live across a call in
   * this frame */
  out->gamma = north ? out->eta : -out->eta;
  geo_sincos(p, &out->xi, &out->eta);
  out->eta = p + geo_chi_series(out->xi, out->eta);
  out->k = drdc__geo_mul(GEO_UPS_2K0_OVER_C, drdc__geo_cos_ratio(out->xi));
  out->k = drdc__geo_mul(
      out->k, geo_sqrt(GEO_ONE -
                       drdc__geo_mul(GEO_E2, drdc__geo_mul(out->xi, out->xi))));
  geo_sincos(out->eta, &out->xi, &out->eta); /* sin chi, cos chi */
  if (out->xi < UPS_MIN_SIN_CHI) {
    return 0;
  }
  out->k = geo_div(out->k, GEO_ONE + out->xi);
  t = geo_div(out->eta, GEO_ONE + out->xi);
  /* sin lam, cos lam */
  geo_sincos(north ? out->gamma : -out->gamma, &out->xi, &out->eta);
  out->xi = drdc__geo_mul(t, out->xi);
  out->eta = north ? -drdc__geo_mul(t, out->eta) : drdc__geo_mul(t, out->eta);
  return 1;
}

int64_t drdc__geo_ups_q36(int64_t a)
{
  return drdc__geo_mul_shift(a, GEO_UPS_K_Q39, 61u);
}

void drdc__geo_ups_reverse(bool north, geo_tm_t *tm)
{
  int64_t t;

  /* the longitude first, the atan2s straight into the slots (0 first, as
   * geo_atan2() gives when both arguments are zero): few values live
   * across the deep calls. x, y wait in tm->xi, tm->eta until the polar
   * distance, lam in tm->k until then */
  if ((tm->xi == 0) && (tm->eta == 0)) {
    /* GeographicLib's atan2(+0, -0) at the north pole */
    tm->k = north ? GEO_PI : 0;
  } else {
    tm->k = 0;
    (void)drdc_fx_atan2_q5_58(tm->xi, north ? -tm->eta : tm->eta, &tm->k);
  }
  /* the polar distance (hypot of the metres in Q36) and the longitude
   * straight from the exact metres: next to the pole a Q5.58 angle would
   * keep too few bits, and a Q47.16 hypot would cost 7.6 um */
  t = drdc__geo_muldiv((int64_t)drdc_fx_hypot_s64(tm->xi * INT64_C(1048576),
                                                  tm->eta * INT64_C(1048576)),
                       TWO_POW_61, GEO_UPS_K_Q39);
  tm->eta = tm->k;
  tm->xi = 0;
  (void)drdc_fx_atan2_q5_58(GEO_ONE - drdc__geo_mul(t, t), 2 * t, &tm->xi);
  geo_sincos(tm->xi, &tm->gamma, &tm->k);
  tm->xi = tm->xi + geo_phi_series(tm->gamma, tm->k);
  if (!north) {
    tm->xi = -tm->xi;
  }
}
