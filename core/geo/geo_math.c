/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Q5.58 arithmetic of core/geo: products, sin/cos, atan2, sqrt and
 *        angle conversions (see geo_impl.h for the error of each).
 */
#include "geo_impl.h"

#include <drdc/fixed_arith.h>
#include <drdc/fixed_sqrt.h>
#include <drdc/fixed_trig.h>

int64_t geo_muldiv(int64_t a, int64_t b, int64_t c)
{
  int64_t r = 0;

  /* callers keep the quotient in range and c != 0: never fails */
  (void)drdc_fx_muldiv_s64(a, b, c, &r);
  return r;
}

int64_t geo_mul(int64_t a, int64_t b)
{
  int64_t r = 0;

  /* callers keep |a b| < 32: never fails */
  (void)drdc_fx_mul_q5_58(a, b, &r);
  return r;
}

int64_t geo_div(int64_t a, int64_t b)
{
  return geo_muldiv(a, GEO_ONE, b);
}

int64_t geo_floor_div(int64_t a, int64_t b)
{
  int64_t q = a / b;

  /* C division truncates: step down when a negative quotient was cut */
  if (((a % b) != 0) && (a < 0)) {
    q = q - 1;
  }
  return q;
}

void geo_sincos(int64_t x, int64_t *s, int64_t *c)
{
  /* (-1)^i / (2i+1)! and (-1)^i / (2i)! in Q5.58, i = 0..9: on |r| <= pi/4
   * the first omitted terms are below 1e-19. */
  static const int64_t sin_coef[10] = {
    INT64_C(288230376151711744), INT64_C(-48038396025285291),
    INT64_C(2401919801264265),   INT64_C(-57188566696768),
    INT64_C(794285648566),       INT64_C(-7220778623),
    INT64_C(46287042),           INT64_C(-220414),
    INT64_C(810),                INT64_C(-2)
  };
  static const int64_t cos_coef[10] = {
    INT64_C(288230376151711744), INT64_C(-144115188075855872),
    INT64_C(12009599006321323),  INT64_C(-400319966877377),
    INT64_C(7148570837096),      INT64_C(-79428564857),
    INT64_C(601731552),          INT64_C(-3306217),
    INT64_C(13776),              INT64_C(-45)
  };
  /* x = k pi/2 + r, |r| <= pi/4 (plus a few LSB): k from a product with
   * 2/pi (no division) */
  int64_t k = drdc_fx_rshift_round_s64(geo_mul(x, INT64_C(183493156455125077)),
                                       58u);
  int64_t r = x - (k * GEO_HALF_PI);
  int64_t r2 = geo_mul(r, r);
  int64_t ps = sin_coef[9];
  int64_t pc = cos_coef[9];
  int64_t quadrant = ((k % 4) + 4) % 4;
  unsigned i;

  for (i = 9u; i > 0u; i--) {
    ps = sin_coef[i - 1u] + geo_mul(ps, r2);
    pc = cos_coef[i - 1u] + geo_mul(pc, r2);
  }
  ps = geo_mul(ps, r);
  if (quadrant == 0) {
    *s = ps;
    *c = pc;
  } else if (quadrant == 1) {
    *s = pc;
    *c = -ps;
  } else if (quadrant == 2) {
    *s = -ps;
    *c = -pc;
  } else {
    *s = -pc;
    *c = ps;
  }
}

/* |v| as uint64_t */
static uint64_t mag64(int64_t v)
{
  return (v < 0) ? (UINT64_C(0) - (uint64_t)v) : (uint64_t)v;
}

/* Bits of v (0 for 0). */
static unsigned bit_length(uint64_t v)
{
  unsigned n = 0u;
  uint64_t t = v;

  while (t != 0u) {
    n++;
    t = t >> 1u;
  }
  return n;
}

int64_t geo_atan2(int64_t y, int64_t x)
{
  uint64_t m = (mag64(y) > mag64(x)) ? mag64(y) : mag64(x);
  unsigned bits = bit_length(m);
  int64_t yn = y;
  int64_t xn = x;
  drdc_bam32_t seed = 0u;
  int64_t theta;
  int64_t sn;
  int64_t cs;
  int64_t num;
  int64_t den;

  /* one scale with the larger part in [2^57, 2^58]: shift right when
   * longer (rounding), multiply up (exactly) when shorter */
  if (bits > 58u) {
    yn = drdc_fx_rshift_round_s64(y, bits - 58u);
    xn = drdc_fx_rshift_round_s64(x, bits - 58u);
  } else if (bits < 58u) {
    int64_t up = (int64_t)(UINT64_C(1) << (58u - bits));

    yn = y * up;
    xn = x * up;
  } else {
    /* already on the scale */
  }
  /* seed: the binary-angle atan2 of the top 31 bits (1 LSB = 1.5e-9) */
  (void)drdc_fx_atan2_bam32((int32_t)drdc_fx_rshift_round_s64(yn, 28u),
                            (int32_t)drdc_fx_rshift_round_s64(xn, 28u),
                            &seed);
  if (seed >= 0x80000000u) {
    theta = (int64_t)seed - INT64_C(4294967296);
  } else {
    theta = (int64_t)seed;
  }
  /* binary angle -> radians: theta pi / 2^31 = (theta 2^27) pi / 2^58 */
  theta = geo_mul(theta * INT64_C(134217728), GEO_PI);
  /* the remaining angle d has tan d = (y cos t - x sin t) / (x cos t +
   * y sin t); |d| < 2e-9 so atan(q) = q - q^3/3 is q to 3e-27 */
  geo_sincos(theta, &sn, &cs);
  num = geo_mul(yn, cs) - geo_mul(xn, sn);
  den = geo_mul(xn, cs) + geo_mul(yn, sn);
  theta = theta + geo_div(num, den);
  if (theta > GEO_PI) {
    theta = theta - GEO_TWO_PI;
  } else if (theta <= -GEO_PI) {
    theta = theta + GEO_TWO_PI;
  } else {
    /* in (-pi, pi] */
  }
  return theta;
}

int64_t geo_sqrt(int64_t x)
{
  int64_t y;
  unsigned i;

  if (x <= 0) {
    return 0;
  }
  /* seed: the integer root of x is sqrt of the real value in Q29 */
  y = (int64_t)drdc_fx_sqrt_u64((uint64_t)x) * INT64_C(536870912);
  if (y == 0) {
    y = 1;
  }
  /* Newton: each step squares the relative error; the rounded integer
   * root is within 2^-15 relative for x >= 2^-30 (the geodesy takes
   * x >= 0.003), so two steps reach 2^-60 */
  for (i = 0u; i < 2u; i++) {
    y = drdc_fx_rshift_round_s64(y + geo_div(x, y), 1u);
  }
  return y;
}

int64_t geo_rad_from_nas(drdc_nas_t a)
{
  /* a pi 2^58 / 648e12 = 1397 a + a 0.38029... (the fraction in Q5.58):
   * no division; |a| <= 2^51 keeps 1397 a in range */
  return (a * 1397) + geo_mul(a, INT64_C(109613060018604784));
}

drdc_nas_t geo_nas_from_rad(int64_t r)
{
  return geo_muldiv(r, GEO_NAS_180, GEO_PI);
}
