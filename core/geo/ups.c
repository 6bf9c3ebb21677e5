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

int geo_ups_forward(int64_t phi, int64_t lam, bool north, int64_t *x,
                    int64_t *y, int64_t *gamma, int64_t *k)
{
  int64_t p = north ? phi : -phi;
  int64_t t;

  /* the outputs are the scratch from the start (the callers' own
   * scratch, which they drop on 0): sin phi in *x until the scale's
   * root, cos phi and then chi in *y, the convergence's lam in *gamma,
   * the scale's factors in *k; only p, then t, is live across a call
   * in this frame */
  *gamma = north ? lam : -lam;
  geo_sincos(p, x, y);
  *y = p + geo_chi_series(*x, *y);
  *k = geo_mul(GEO_UPS_2K0_OVER_C, geo_cos_ratio(*x));
  *k = geo_mul(*k, geo_sqrt(GEO_ONE - geo_mul(GEO_E2, geo_mul(*x, *x))));
  geo_sincos(*y, x, y); /* sin chi, cos chi */
  if (*x < UPS_MIN_SIN_CHI) {
    return 0;
  }
  *k = geo_div(*k, GEO_ONE + *x);
  t = geo_div(*y, GEO_ONE + *x);
  geo_sincos(north ? *gamma : -*gamma, x, y); /* sin lam, cos lam */
  *x = geo_mul(t, *x);
  *y = north ? -geo_mul(t, *y) : geo_mul(t, *y);
  return 1;
}

int64_t geo_ups_q36(int64_t a)
{
  return geo_muldiv(a, GEO_UPS_K_Q39, TWO_POW_61);
}

drdc_q47_16_t geo_ups_metres(int64_t a)
{
  return drdc_fx_rshift_round_s64(geo_ups_q36(a), 20u);
}

int64_t geo_ups_angle(drdc_q47_16_t v)
{
  return geo_muldiv(v * INT64_C(1048576), TWO_POW_61, GEO_UPS_K_Q39);
}

void geo_ups_reverse(drdc_q47_16_t x, drdc_q47_16_t y, bool north,
                     int64_t *phi, int64_t *lam)
{
  int64_t sc = 0;
  int64_t cc = 0;
  int64_t t;

  /* the longitude first (x and y are dead after it), the atan2s straight
   * into the outputs (0 first, as geo_atan2() gives when both arguments
   * are zero): few values live across the deep calls */
  if ((x == 0) && (y == 0)) {
    /* GeographicLib's atan2(+0, -0) at the north pole */
    *lam = north ? GEO_PI : 0;
  } else {
    *lam = 0;
    (void)drdc_fx_atan2_q5_58(x, north ? -y : y, lam);
  }
  /* the polar distance (hypot of the metres in Q36) and the longitude
   * straight from the exact metres: next to the pole a Q5.58 angle would
   * keep too few bits, and a Q47.16 hypot would cost 7.6 um */
  t = geo_muldiv((int64_t)drdc_fx_hypot_s64(x * INT64_C(1048576),
                                            y * INT64_C(1048576)),
                 TWO_POW_61, GEO_UPS_K_Q39);
  *phi = 0;
  (void)drdc_fx_atan2_q5_58(GEO_ONE - geo_mul(t, t), 2 * t, phi);
  geo_sincos(*phi, &sc, &cc);
  *phi = *phi + geo_phi_series(sc, cc);
  if (!north) {
    *phi = -*phi;
  }
}
