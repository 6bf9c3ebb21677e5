/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Internal helpers of core/geo: shorthands for the Q5.58
 *        arithmetic of fixed/ (fixed_q5_58.h), WGS-84 constants.
 *
 * Every value here is Q5.58 (drdc_q5_58_t, real value raw / 2^58) unless
 * its name says otherwise; angles are radians. The arithmetic itself
 * (products, quotients, sin/cos, atan2, sqrt, with their error bounds)
 * lives in fixed/; these shorthands return the value and drop the status
 * where the geodesy keeps every argument inside the function's domain,
 * so no wide arithmetic lives in core/.
 */
#ifndef DRDC_GEO_IMPL_H
#define DRDC_GEO_IMPL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include <drdc/fixed_arith.h>
#include <drdc/fixed_q5_58.h>
#include <drdc/fixed_types.h>
#include <drdc/geo.h>
#include <drdc/types.h>

/** 1.0 in Q5.58. */
#define GEO_ONE INT64_C(288230376151711744)
/** pi in Q5.58. */
#define GEO_PI DRDC_Q5_58_PI
/** pi / 2 in Q5.58. */
#define GEO_HALF_PI DRDC_Q5_58_HALF_PI
/** 2 pi in Q5.58. */
#define GEO_TWO_PI DRDC_Q5_58_TWO_PI
/** Nano-arcseconds in 180 degrees (pi radians). */
#define GEO_NAS_180 INT64_C(648000000000000)
/** Nano-arcseconds in one degree. */
#define GEO_NAS_DEG INT64_C(3600000000000)
/** WGS-84 first eccentricity squared e^2 = f (2 - f), f = 1/298.257223563. */
#define GEO_E2 INT64_C(1929523662660924)
/** WGS-84 first eccentricity e. */
#define GEO_E INT64_C(23582776152997482)
/** k0 A in metres, Q23.40: k0 = 0.9996 times the rectifying radius
 *  A = a / (1 + n) (1 + n^2/4 + n^4/64 + n^6/256), a = 6 378 137 m. */
#define GEO_K0A_Q40 INT64_C(6998283941355162077)
/** k0 A / a. */
#define GEO_K0A_OVER_A INT64_C(287632289103010426)
/** lim cos(chi) / cos(phi) at the poles: ((1 + e) / (1 - e))^(e/2). */
#define GEO_POLE_RATIO INT64_C(290170724834618951)
/** Terms of the series of the conformal latitude (8) and of Krueger's
 *  series (6). */
#define GEO_CHI_TERMS 8u
/** Number of Krueger coefficients (6th order in n). */
#define GEO_KRUEGER_TERMS 6u

/** chi - phi = sum GEO_CHI_FROM_PHI[j] sin(2 (j+1) phi). */
extern const int64_t geo_chi_from_phi[GEO_CHI_TERMS];
/** phi - chi = sum GEO_PHI_FROM_CHI[j] sin(2 (j+1) chi). */
extern const int64_t geo_phi_from_chi[GEO_CHI_TERMS];
/** Krueger alpha_1..6 (geographic -> transverse Mercator). */
extern const int64_t geo_alpha[GEO_KRUEGER_TERMS];
/** Krueger beta_1..6 (transverse Mercator -> geographic). */
extern const int64_t geo_beta[GEO_KRUEGER_TERMS];

/** a b / 2^58, rounded to nearest (ties away from zero); the caller keeps
 *  |a b| / 2^58 within int64_t. */
int64_t geo_mul(int64_t a, int64_t b);

/** a 2^58 / b, rounded; b != 0 and the quotient within int64_t. */
int64_t geo_div(int64_t a, int64_t b);

/** a b / c, rounded; c != 0 and the quotient within int64_t. */
int64_t geo_muldiv(int64_t a, int64_t b, int64_t c);

/** sin and cos of x radians: drdc_fx_sincos_q5_58() (s, c not NULL). */
static inline void geo_sincos(int64_t x, int64_t *s, int64_t *c)
{
  (void)drdc_fx_sincos_q5_58(x, s, c);
}

/** atan2(y, x) in radians, in (-pi, pi]: drdc_fx_atan2_q5_58(); 0 when
 *  both are zero. */
static inline int64_t geo_atan2(int64_t y, int64_t x)
{
  int64_t r = 0;

  (void)drdc_fx_atan2_q5_58(y, x, &r);
  return r;
}

/** sqrt(x): drdc_fx_sqrt_q5_58(); 0 for x <= 0. */
static inline int64_t geo_sqrt(int64_t x)
{
  int64_t r = 0;

  (void)drdc_fx_sqrt_q5_58(x, &r);
  return r;
}

/** Nano-arcseconds -> radians (Q5.58), |a| <= 2^49 nas. */
int64_t geo_rad_from_nas(drdc_nas_t a);

/** Radians (Q5.58) -> nano-arcseconds, rounded. */
drdc_nas_t geo_nas_from_rad(int64_t r);

/** floor(a / b) for b > 0 (integer division rounding towards -inf). */
int64_t geo_floor_div(int64_t a, int64_t b);

/** Transverse Mercator result on the unit sphere of radius k0 A:
 *  xi and eta (Q5.58), convergence gamma (rad, Q5.58), point scale k. */
typedef struct geo_tm {
  int64_t xi;    /**< northing / (k0 A) */
  int64_t eta;   /**< easting offset / (k0 A) */
  int64_t gamma; /**< meridian convergence, radians */
  int64_t k;     /**< point scale factor (including k0) */
} geo_tm_t;

/** Largest cos(chi) |sin(lambda)| the series accept: tanh(0.34), so that
 *  cosh(12 eta') stays below 32 (the Q5.58 range). */
#define GEO_TM_MAX_TANH_ETA INT64_C(94388932686895755)

/** Largest |eta| of the inverse series (same reason): 0.34. */
#define GEO_TM_MAX_ETA INT64_C(97998327891581993)

/**
 * Transverse Mercator (Krueger series, 6th order) of latitude phi and
 * longitude from the central meridian lam (radians, |phi| <= pi/2,
 * |lam| <= pi/2). Returns 0 when the point is beyond the series' domain
 * (cos(chi) |sin(lam)| > tanh(0.34)), else 1 with *out written.
 */
int geo_tm_forward(int64_t phi, int64_t lam, geo_tm_t *out);

/** Inverse of geo_tm_forward(): xi, eta (|eta| <= 0.34) -> phi, lam. */
void geo_tm_reverse(int64_t xi, int64_t eta, int64_t *phi, int64_t *lam);

/** cos(chi) / cos(phi) from s = sin(phi), well conditioned up to the
 *  poles: 2 E / ((1 + s) + (1 - s) E^2) with E = exp(e atanh(e s)). */
int64_t geo_cos_ratio(int64_t s);

/** chi - phi of the conformal latitude from sin phi, cos phi. */
int64_t geo_chi_series(int64_t sphi, int64_t cphi);

/** phi - chi from sin chi, cos chi. */
int64_t geo_phi_series(int64_t schi, int64_t cchi);

/**
 * Polar stereographic (UPS, k0 = 0.994) of phi, lam (radians) on the
 * north or south sheet: x, y as angles of the sphere of radius
 * 2 k0 a / c (geo_ups_metres() makes metres), convergence gamma
 * (radians) and scale k. Returns 0 (outputs unchanged) when the point is
 * too far on the other hemisphere (sin chi < -0.9), else 1.
 */
int geo_ups_forward(int64_t phi, int64_t lam, bool north, int64_t *x,
                    int64_t *y, int64_t *gamma, int64_t *k);

/** Inverse of geo_ups_forward(): x, y from the pole in metres (Q47.16,
 *  |x|, |y| < 2 000 km) -> phi, lam (radians). */
void geo_ups_reverse(drdc_q47_16_t x, drdc_q47_16_t y, bool north,
                     int64_t *phi, int64_t *lam);

/** UPS angle -> metres (Q47.16). */
drdc_q47_16_t geo_ups_metres(int64_t a);

/** Metres (Q47.16, |v| < 2^43) -> UPS angle. */
int64_t geo_ups_angle(drdc_q47_16_t v);

/**
 * MGRS text of a UTM/UPS position already validated by drdc_geo_to_utm()
 * or drdc_geo_from_utm(); lat (nas) picks the UTM latitude band. Returns
 * DRDC_E_RANGE (prec outside -1..11), DRDC_E_EASTING or DRDC_E_NORTHING
 * (outside the MGRS limits), DRDC_E_BUFFER (size too small); the text is
 * written only on DRDC_OK.
 */
drdc_status_t geo_mgrs_format(const drdc_geo_utm_t *u, drdc_nas_t lat,
                              int32_t prec, char *text, size_t size);

#endif /* DRDC_GEO_IMPL_H */
