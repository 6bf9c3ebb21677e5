/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_q5_58
 * @brief Q5.58 sin/cos, atan2, sqrt and quotient (see fixed_q5_58.h for
 *        the method and error of each).
 */
#include <drdc/fixed_q5_58.h>

#include <stdbool.h>
#include <stddef.h>

#include <drdc/compiler.h>
#include <drdc/fixed_arith.h>
#include <drdc/fixed_sqrt.h>
#include <drdc/fixed_trig.h>

#include "fixed_impl.h"
#include "trig_impl.h"

/** 1.0 in Q5.58 as a literal (DRDC_Q5_58_ONE shifts a signed value). */
#define Q5_58_ONE INT64_C(288230376151711744)
/** 2 / pi in Q5.58: the quadrant of sin/cos by a product. */
#define Q5_58_TWO_OVER_PI INT64_C(183493156455125077)
/** Binary-angle units (2^-31 half turns) to Q5.58 raw units of a half
 *  turn: 2^27. */
#define BAM_TO_Q58 INT64_C(134217728)
/** Raw values below 2^28 (2^-30) get their square root from a scaled
 *  argument: there the integer root seeds Newton less than 2^-15
 *  relative. */
#define SQRT_SCALE_BELOW INT64_C(268435456)

/* a b / 2^58 rounded to nearest, ties away from zero (the magnitude is
 * rounded): drdc_fx_mul_q5_58() inline, without its status. Every use
 * here keeps |a b| below 21, so the magnitude fits 63 bits. */
static int64_t mul(int64_t a, int64_t b)
{
  uint64_t m = fx_mul_shr_round(fx_abs64(a), fx_abs64(b), 58u);

  return ((a < 0) != (b < 0)) ? -(int64_t)m : (int64_t)m;
}

/* floor or rounded |a| 2^58 / |b| (ties away from zero) from the
 * magnitudes ma = |a|, mb = |b| != 0 and rcp = drdc_fx_reciprocal_3by2()
 * of mb normalised: fx_div_round_u128() of ma 2^58 by mb, bit for bit;
 * UINT64_MAX when the quotient does not fit 64 bits (no quotient of
 * interest is that large: the callers take anything above 2^63 as an
 * overflow). */
static uint64_t quotient_mag(uint64_t ma, uint64_t mb, uint32_t rcp)
{
  unsigned s;
  unsigned back;
  uint64_t v;
  uint64_t un32;
  uint64_t un10;
  uint64_t r = 0;
  uint64_t q;

  if ((ma >> 6) >= mb) {
    return UINT64_MAX; /* quotient >= 2^64 */
  }
  s = (unsigned)__builtin_clzll(mb);
  back = 64u - s;
  v = mb << s;
  if (s == 0u) {
    un32 = ma >> 6;
  } else {
    un32 = ((ma >> 6) << s) | ((ma << 58) >> back);
  }
  un10 = (ma << 58) << s;
  q = (uint64_t)drdc_fx_div_3by2((uint32_t)(un32 >> 32), (uint32_t)un32,
                                 (uint32_t)(un10 >> 32), v, rcp, &r)
      << 32;
  q |= drdc_fx_div_3by2((uint32_t)(r >> 32), (uint32_t)r, (uint32_t)un10, v,
                        rcp, &r);
  r = r >> s;
  if ((r >= (mb - r)) && (q != UINT64_MAX)) {
    q++;
  }
  return q;
}

/* a 2^58 / b, rounded (ties away from zero); 0 when b == 0 or the
 * quotient overflows: the result of drdc_fx_muldiv_s64(a, 2^58, b), bit
 * for bit, without its two call levels. */
static inline int64_t quotient(int64_t a, int64_t b)
{
  uint64_t v;
  uint64_t q;

  if (b == 0) {
    return 0;
  }
  v = fx_abs64(b) << (unsigned)__builtin_clzll(fx_abs64(b));
  q = quotient_mag(fx_abs64(a), fx_abs64(b),
                   drdc_fx_reciprocal_3by2((uint32_t)(v >> 32), (uint32_t)v));
  if ((a != 0) && ((a < 0) != (b < 0))) {
    return (q > (UINT64_C(1) << 63))
               ? 0
               : ((q == (UINT64_C(1) << 63)) ? (-INT64_MAX - 1) : -(int64_t)q);
  }
  return (q > (uint64_t)INT64_MAX) ? 0 : (int64_t)q;
}

/* quotient() for a >= 0 and b > 0 (Newton's steps of the root): no
 * signs to handle */
static inline int64_t quotient_pos(int64_t a, int64_t b)
{
  uint64_t v = (uint64_t)b << (unsigned)__builtin_clzll((uint64_t)b);
  uint64_t q =
      quotient_mag((uint64_t)a, (uint64_t)b,
                   drdc_fx_reciprocal_3by2((uint32_t)(v >> 32), (uint32_t)v));

  return (q > (uint64_t)INT64_MAX) ? 0 : (int64_t)q;
}

drdc_status_t drdc_fx_div_q5_58(drdc_q5_58_t a, drdc_q5_58_t b,
                                drdc_q5_58_t *out)
{
  uint64_t v;
  uint64_t q;
  bool negative;

  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if (b == 0) {
    return DRDC_E_DIVIDE_BY_ZERO;
  }
  /* quotient() without its zero for an overflow: the magnitude tells it
   * (2^63 fits only when negative) */
  negative = ((a < 0) != (b < 0));
  v = fx_abs64(b) << (unsigned)__builtin_clzll(fx_abs64(b));
  q = quotient_mag(fx_abs64(a), fx_abs64(b),
                   drdc_fx_reciprocal_3by2((uint32_t)(v >> 32), (uint32_t)v));
  if (q > (negative ? (UINT64_C(1) << 63) : (uint64_t)INT64_MAX)) {
    return DRDC_E_OVERFLOW;
  }
  if (!negative) {
    *out = (int64_t)q;
  } else if (q == (UINT64_C(1) << 63)) {
    *out = -INT64_MAX - 1;
  } else {
    *out = -(int64_t)q;
  }
  return DRDC_OK;
}

drdc_q5_58_t drdc_fx_div_q5_58_unchecked(drdc_q5_58_t a, drdc_q5_58_t b)
{
  return quotient(a, b);
}

/* sin and cos of x (Q5.58 radians, |x| <= 16): the body of
 * drdc_fx_sincos_q5_58(), also used by atan2 for its correction step.
 * Inlined for the 512-byte stack limit: called from atan2 it adds a frame
 * to the grid poses' chain through the transverse Mercator, which then
 * passes the limit on Cortex-M3. */
static inline DRDC_ALWAYS_INLINE void
sincos_kernel(drdc_q5_58_t x, drdc_q5_58_t *s, drdc_q5_58_t *c)
{
  /* (-1)^i / (2i+1)! and (-1)^i / (2i)! in Q5.58, i = 0..9: on |r| <= pi/4
   * the first omitted terms are below 1e-19. */
  static const int64_t sin_coef[10] = {INT64_C(288230376151711744),
                                       INT64_C(-48038396025285291),
                                       INT64_C(2401919801264265),
                                       INT64_C(-57188566696768),
                                       INT64_C(794285648566),
                                       INT64_C(-7220778623),
                                       INT64_C(46287042),
                                       INT64_C(-220414),
                                       INT64_C(810),
                                       INT64_C(-2)};
  static const int64_t cos_coef[10] = {INT64_C(288230376151711744),
                                       INT64_C(-144115188075855872),
                                       INT64_C(12009599006321323),
                                       INT64_C(-400319966877377),
                                       INT64_C(7148570837096),
                                       INT64_C(-79428564857),
                                       INT64_C(601731552),
                                       INT64_C(-3306217),
                                       INT64_C(13776),
                                       INT64_C(-45)};
  int64_t k;
  int64_t r;
  int64_t r2;
  int64_t ps = sin_coef[9];
  int64_t pc = cos_coef[9];
  int64_t quadrant;
  unsigned i;

  /* x = k pi/2 + r, |r| <= pi/4 (plus a few LSB): k from a product with
   * 2/pi (no division); |k| <= 20, so k pi/2 stays within int64_t */
  k = drdc_fx_rshift_round_s64_inline(mul(x, Q5_58_TWO_OVER_PI), 58u);
  r = x - (k * DRDC_Q5_58_HALF_PI);
  r2 = mul(r, r);
  quadrant = ((k % 4) + 4) % 4;
  /* one polynomial at a time, Horner's rule from the highest
   * coefficient; unrolled for the timed sincos and atan2 (and the
   * geodesy above them) of docs/performance.md. With r2 <= 0.62 the
   * first four partial sums stay near their coefficients, below 2^32
   * raw (sin: 2, 812, 220 917, 46 424 011; cos: 45, 13 804, 3 314 776,
   * 603 786 713, each at most |coefficient| + 0.62 |previous|): their
   * products with r2 are short products, the same bits as full ones
   * (those four as a loop: unrolled they add 0.9 KB to the demo's
   * flash, for 1.5 % of a UTM conversion). */
#pragma GCC unroll 1
  for (i = 9u; i > 5u; i--) {
    ps = sin_coef[i - 1u] + drdc_fx_mul_q5_58_short(r2, ps);
  }
#pragma GCC unroll 5
  for (i = 5u; i > 0u; i--) {
    ps = sin_coef[i - 1u] + mul(ps, r2);
  }
  ps = mul(ps, r);
#pragma GCC unroll 1
  for (i = 9u; i > 5u; i--) {
    pc = cos_coef[i - 1u] + drdc_fx_mul_q5_58_short(r2, pc);
  }
#pragma GCC unroll 5
  for (i = 5u; i > 0u; i--) {
    pc = cos_coef[i - 1u] + mul(pc, r2);
  }
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

drdc_status_t drdc_fx_sincos_q5_58(drdc_q5_58_t x, drdc_q5_58_t *s,
                                   drdc_q5_58_t *c)
{
  if ((s == NULL) || (c == NULL)) {
    return DRDC_E_NULL;
  }
  sincos_kernel(x, s, c);
  return DRDC_OK;
}

/* |v| as uint64_t */
static uint64_t mag64(int64_t v)
{
  return (v < 0) ? (UINT64_C(0) - (uint64_t)v) : (uint64_t)v;
}

/* Bits of v (0 for 0), by halving the search range: 7 steps */
static unsigned bit_length(uint64_t v)
{
  unsigned n = 0u;
  unsigned step = 32u;
  uint64_t t = v;

  while (step > 0u) {
    if ((t >> step) != 0u) {
      t = t >> step;
      n += step;
    }
    step = step >> 1u;
  }
  return (t != 0u) ? (n + 1u) : n;
}

drdc_status_t drdc_fx_atan2_q5_58(int64_t y, int64_t x, drdc_q5_58_t *out)
{
  uint64_t m = (mag64(y) > mag64(x)) ? mag64(y) : mag64(x);
  unsigned bits = bit_length(m);
  int64_t yn = y;
  int64_t xn = x;
  drdc_bam32_t seed = 0u;
  int64_t seed_bam; /* the seed as a signed binary angle */
  int64_t t;        /* the seed in Q5.58 radians */
  int64_t theta;
  int64_t sn = 0;
  int64_t cs = 0;
  int64_t num;
  int64_t den;

  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if (m == 0u) {
    return DRDC_E_DOMAIN;
  }
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
  /* seed: the binary-angle atan2 of the top 31 bits (1 LSB = 1.5e-9),
   * drdc_fx_atan2_bam32()'s body in line (the larger part is at least
   * 2^57, so its top bits are not 0: that function's checks pass) */
  seed = fx_atan2_bam((int32_t)drdc_fx_rshift_round_s64(yn, 28u),
                      (int32_t)drdc_fx_rshift_round_s64(xn, 28u));
  if (seed >= 0x80000000u) {
    seed_bam = (int64_t)seed - INT64_C(4294967296);
  } else {
    seed_bam = (int64_t)seed;
  }
  /* binary angle -> radians: b pi / 2^31 = (b 2^27) pi / 2^58 */
  t = mul(seed_bam * BAM_TO_Q58, DRDC_Q5_58_PI);
  /* the remaining angle d has tan d = (y cos t - x sin t) / (x cos t +
   * y sin t); |d| < 3e-9: the seed's 1 LSB (1.47e-9 rad) plus the
   * turn by rounding y and x to 31 bits, at most 0.5 sqrt(2) / (2^29 -
   * 0.5) = 1.32e-9 rad with the larger part >= 2^29; so atan(q) =
   * q - q^3/3 + ... is q to 1e-26 */
  sincos_kernel(t, &sn, &cs);
  num = mul(yn, cs) - mul(xn, sn);
  den = mul(xn, cs) + mul(yn, sn);
  theta = t + quotient(num, den);
  if (theta > DRDC_Q5_58_PI) {
    theta = theta - DRDC_Q5_58_TWO_PI;
  } else if (theta <= -DRDC_Q5_58_PI) {
    theta = theta + DRDC_Q5_58_TWO_PI;
  } else {
    /* in (-pi, pi] */
  }
  *out = theta;
  return DRDC_OK;
}

drdc_status_t drdc_fx_sqrt_q5_58(drdc_q5_58_t x, drdc_q5_58_t *out)
{
  int64_t v = x;
  int64_t y;
  unsigned k = 0u;

  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if (x < 0) {
    return DRDC_E_DOMAIN;
  }
  if (x == 0) {
    *out = 0;
    return DRDC_OK;
  }
  /* small arguments: sqrt(x) = sqrt(4^k x) / 2^k, with 4^k x >= 2^-30 */
  while (v < SQRT_SCALE_BELOW) {
    v = v * 4;
    k++;
  }
  /* seed: the integer root of v is sqrt of the real value in Q29 */
  y = (int64_t)drdc_fx_sqrt_u64((uint64_t)v) * INT64_C(536870912);
  /* Newton: each step squares the relative error; the rounded integer
   * root is within 2^-15 relative for v >= 2^28, so two steps reach
   * 2^-60 */
  y = drdc_fx_rshift_round_s64_inline(y + quotient_pos(v, y), 1u);
  y = drdc_fx_rshift_round_s64_inline(y + quotient_pos(v, y), 1u);
  *out = (k == 0u) ? y : drdc_fx_rshift_round_s64_inline(y, k);
  return DRDC_OK;
}
