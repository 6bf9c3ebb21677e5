/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Internal interface of the map projections of core/geo: the
 *        transverse Mercator (tm.c), the polar stereographic (ups.c), the
 *        conformal latitude (conformal.c) and the small-argument series
 *        they share (series.c).
 *
 * Angles are radians and every value is Q5.58 unless its name says
 * otherwise.
 */
#ifndef DRDC_GEO_PROJECTION_H
#define DRDC_GEO_PROJECTION_H

#include <stdbool.h>
#include <stdint.h>

#include <drdc/types.h>

#include "geo_impl.h"

/** A point of a forward projection: x east and y north in units of the
 *  projection's length (TM: the angles eta and xi of the sphere of radius
 *  k0 A, from the central meridian's point on the equator; UPS: in units
 *  of 2 k0 a / c, from the pole), with the meridian convergence gamma
 *  (radians) and the point scale k (k0 included). */
typedef struct geo_projected {
  int64_t x;     /**< easting / the projection's length */
  int64_t y;     /**< northing / the projection's length */
  int64_t gamma; /**< meridian convergence, radians */
  int64_t k;     /**< point scale factor */
} geo_projected_t;

/** Geodetic latitude phi and longitude lam (radians), the result of a
 *  reverse projection; lam from the central meridian (TM) or from
 *  Greenwich (UPS). */
typedef struct geo_phi_lam {
  int64_t phi; /**< latitude, radians */
  int64_t lam; /**< longitude, radians */
} geo_phi_lam_t;

/**
 * Transverse Mercator (Krueger's series to 6th order in n, as in Karney
 * 2011) of latitude phi and longitude lam from the central meridian
 * (|phi| <= pi/2, |lam| <= pi/2) into *out (x = eta, y = xi). Returns 0
 * when the point is beyond the series' domain (cos chi |sin lam| >
 * tanh 0.34, about 2 100 km from the meridian; *out undefined), else 1.
 */
int drdc__geo_tm_forward(int64_t phi, int64_t lam, geo_projected_t *out);

/** The meridian convergence (radians) and the point scale (k0
 *  included) at a point of a projection. */
typedef struct geo_conv_scale {
  int64_t gamma; /**< meridian convergence, radians */
  int64_t k;     /**< point scale factor */
} geo_conv_scale_t;

/** The inverse of drdc__geo_tm_forward(): xi and eta (|eta| <= 0.34) ->
 *  phi and lam (from the central meridian) into *out and, unless cs is
 *  NULL, the convergence and scale there into *cs, from the derivative
 *  of the inverse series itself (as GeographicLib's reverse does). */
void drdc__geo_tm_reverse(int64_t xi, int64_t eta, geo_phi_lam_t *out,
                          geo_conv_scale_t *cs);

/**
 * Universal Polar Stereographic (k0 = 0.994) of phi and lam (radians,
 * lam from Greenwich) on the north or south sheet into *out: x, y from
 * the pole in units of 2 k0 a / c (drdc__geo_ups_q36() makes metres), the
 * convergence and the scale. Returns 0 when the point is
 * too far into the other hemisphere (sin chi < -0.9; *out undefined),
 * else 1.
 */
int drdc__geo_ups_forward(bool north, int64_t phi, int64_t lam,
                          geo_projected_t *out);

/** The convergence and scale of drdc__geo_ups_forward() at phi, lam (the
 *  same bits), without the position: for a point the reverse found. */
void drdc__geo_ups_conv_scale(bool north, int64_t phi, int64_t lam,
                              geo_conv_scale_t *cs);

/** The inverse of drdc__geo_ups_forward(): x, y from the pole in metres
 *  (Q47.16, |x|, |y| < 2 000 km) -> phi and lam. */
void drdc__geo_ups_reverse(bool north, drdc_q47_16_t x, drdc_q47_16_t y,
                           geo_phi_lam_t *out);

/** A UPS x or y (units of 2 k0 a / c) -> metres in Q28.36, rounded. */
int64_t drdc__geo_ups_q36(int64_t a);

/** Terms of the series of the conformal latitude. */
#define GEO_CHI_TERMS 8u
/** Number of Krueger coefficients (6th order in n). */
#define GEO_KRUEGER_TERMS 6u

/** chi - phi = sum drdc__geo_chi_from_phi[j] sin(2 (j+1) phi). */
extern const int64_t drdc__geo_chi_from_phi[GEO_CHI_TERMS];
/** phi - chi = sum drdc__geo_phi_from_chi[j] sin(2 (j+1) chi). */
extern const int64_t drdc__geo_phi_from_chi[GEO_CHI_TERMS];
/** Krueger's alpha_1..6 (geographic -> transverse Mercator). */
extern const int64_t drdc__geo_alpha[GEO_KRUEGER_TERMS];
/** Krueger's beta_1..6 (transverse Mercator -> geographic). */
extern const int64_t drdc__geo_beta[GEO_KRUEGER_TERMS];

/** sum coef[j] sin(2 (j+1) x), j < GEO_CHI_TERMS, from s = sin x and
 *  c = cos x: the series between the geodetic and the conformal
 *  latitude, in either direction. */
int64_t drdc__geo_lat_series(const int64_t *coef, int64_t s, int64_t c);

/** chi - phi of the conformal latitude from sin phi, cos phi. */
static inline int64_t geo_chi_series(int64_t sphi, int64_t cphi)
{
  return drdc__geo_lat_series(drdc__geo_chi_from_phi, sphi, cphi);
}

/** phi - chi from sin chi, cos chi. */
static inline int64_t geo_phi_series(int64_t schi, int64_t cchi)
{
  return drdc__geo_lat_series(drdc__geo_phi_from_chi, schi, cchi);
}

/** cos(chi) / cos(phi) from s = sin(phi), well conditioned up to the
 *  poles: 2 E / ((1 + s) + (1 - s) E^2) with E = exp(e atanh(e s)). */
int64_t drdc__geo_cos_ratio(int64_t s);

/** 2^58 / n rounded (n odd or a factorial: no ties in these uses). */
#define GEO_Q58_RECIP(n) ((GEO_ONE + ((n) / 2)) / (n))

/* The small-argument Taylor series (series.c), each on the stated
 * domain, truncated below 0.001 LSB of Q5.58; their rounding errors are
 * stated with each. */

/** atanh(t), |t| <= tanh(0.34) = 0.3275; about 1.5 LSB. */
int64_t drdc__geo_atanh_small(int64_t t);
/** sinh(x), |x| <= 0.35; about 1 LSB. */
int64_t drdc__geo_sinh_small(int64_t x);
/** cosh(x), |x| <= 0.34; about 1 LSB. */
int64_t drdc__geo_cosh_small(int64_t x);
/** Largest |q| of drdc__geo_atan_small(): 0.25. */
#define GEO_ATAN_SMALL_MAX (GEO_ONE / 4)
/** atan(q), |q| <= 0.25; about 1 LSB. */
int64_t drdc__geo_atan_small(int64_t q);
/** Largest |u| of drdc__geo_sqrt1p_small(): 1/80 = 0.0125. */
#define GEO_SQRT1P_SMALL_MAX (GEO_ONE / 80)
/** sqrt(1 + u), |u| <= 0.0125; about 1 LSB. */
int64_t drdc__geo_sqrt1p_small(int64_t u);

#endif /* DRDC_GEO_PROJECTION_H */
