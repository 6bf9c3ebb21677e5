/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Internal helpers of core/geo: shorthands for the Q5.58
 *        arithmetic of fixed/ (fixed_q5_58.h); the WGS-84 constants are
 *        in geo_consts.h and geo_consts.c (tools/tables/geo_consts.py).
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
#include <drdc/types.h>

#include "geo_consts.h"

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

/** a b / 2^58, rounded to nearest (ties away from zero): the caller keeps
 *  |a b| / 2^58 within Q5.58. drdc_fx_mul_q5_58_unchecked() (the bits of
 *  drdc_fx_mul_q5_58() without its checks), one copy out of line; the
 *  innermost loops of the series inline it. */
int64_t drdc__geo_mul(int64_t a, int64_t b);

/** drdc__geo_mul(a, b) when the raw |b| is below 2^32, bit for bit, from
 *  two 32 x 32 -> 64 products instead of four:
 *  drdc_fx_mul_q5_58_short(), one copy out of line. */
int64_t drdc__geo_mul_short(int64_t a, int64_t b);

/** a 2^58 / b, rounded; b != 0 and the quotient within int64_t (the
 *  callers keep it so): drdc_fx_div_q5_58_unchecked(). */
static inline int64_t geo_div(int64_t a, int64_t b)
{
  return drdc_fx_div_q5_58_unchecked(a, b);
}

/** a b / c, rounded; c != 0 and the quotient within int64_t. */
int64_t drdc__geo_muldiv(int64_t a, int64_t b, int64_t c);

/** a b / 2^n rounded to nearest, ties away from zero: the bits of
 *  drdc__geo_muldiv(a, b, 2^n) for b > 0, 0 < n < 64, the quotient within
 *  int64_t, by a 128-bit product and a shift instead of a division. */
int64_t drdc__geo_mul_shift(int64_t a, int64_t b, unsigned n);

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
int64_t drdc__geo_rad_from_nas(drdc_nas_t a);

/** Radians (Q5.58) -> nano-arcseconds, rounded. */
drdc_nas_t drdc__geo_nas_from_rad(int64_t r);

/** floor(a / b) for b > 0 (integer division rounding towards -inf). */
int64_t drdc__geo_floor_div(int64_t a, int64_t b);

#endif /* DRDC_GEO_IMPL_H */
