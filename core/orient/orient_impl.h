/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_orient
 * @brief Internal helpers of core/orient/: exact 64-bit sums of Q60
 *        products, power-of-two prescaling of quaternions, half-angle
 *        sines and atan2 of 64-bit coordinates; powers of two, squares
 *        and limits spelled for MISRA C:2012 (no shift of a signed
 *        value, no cast of a composite expression, no unsigned INT64_MIN).
 *
 * Products of two Q1.30 values are Q60 (2^60 per unit) and are kept exact
 * in int64_t as long as possible; each public result is rounded once, at
 * the end, by drdc_fx_rshift_round_s64() or drdc_fx_muldiv_s64().
 */
#ifndef DRDC_ORIENT_IMPL_H
#define DRDC_ORIENT_IMPL_H

#include <stdint.h>

#include <drdc/fixed_arith.h>
#include <drdc/fixed_trig.h>
#include <drdc/orient.h>

/** The least int64_t, spelled without the unsigned constant of the
 *  <stdint.h> macro (MISRA C:2012 rule 7.2), as fixed/fixed_impl.h does
 *  for FX_INT64_MIN. Same value and type as INT64_MIN. */
#define ORIENT_INT64_MIN (-INT64_MAX - 1)

/** 1.0 in Q1.30, the value and type of DRDC_Q1_30_ONE, written as a
 *  constant instead of a left shift of a signed value (rule 10.1). */
#define ORIENT_Q1_30_ONE ((drdc_q1_30_t)0x40000000)

/** 2^n as int64_t for n <= 62, from an unsigned shift (rule 10.1: no shift
 *  of a signed value), as fx_scale_pow2_64() in fixed/trig_impl.h; equal
 *  to ((int64_t)1 << n). A constant n folds to a constant. */
static inline int64_t orient_pow2_s64(unsigned n)
{
  uint64_t p = UINT64_C(1) << n;

  return (int64_t)p;
}

/** v^2 as uint64_t, exact (<= 2^62), the product computed in int64_t and
 *  then converted (rule 10.8: no cast of a composite expression). */
static inline uint64_t orient_square_u64(int32_t v)
{
  int64_t sq = (int64_t)v * v;

  return (uint64_t)sq;
}

/** Components of a quaternion scaled by 2^k so that the largest magnitude
 *  is in [2^29, 2^30]; the sum of squares n2 (raw units squared) is then
 *  exact and in [2^58, 2^62]. */
typedef struct orient_scaled_quat {
  int32_t c[4]; /**< s, x, y, z times 2^k (rounded when k == -1) */
  int64_t n2;   /**< c[0]^2 + c[1]^2 + c[2]^2 + c[3]^2 */
  int32_t k;    /**< the scale exponent, -1..30 */
} orient_scaled_quat_t;

/**
 * Scale q by a power of two: up (exact) when its largest part is below
 * 0.5, down by 2 (rounded) when it is above 1.0.
 * @return DRDC_OK, or DRDC_E_DOMAIN for the zero quaternion.
 */
drdc_status_t drdc_orient_impl_scale(const drdc_quat_t *q,
                                     orient_scaled_quat_t *out);

/** a + b + c + d without overflow; DRDC_E_OVERFLOW when the exact sum
 *  does not fit int64_t. */
drdc_status_t drdc_orient_impl_sum4(int64_t a, int64_t b, int64_t c,
                                    int64_t d, int64_t *out);

/** Round a Q60 value to Q1.30 (ties away from zero); DRDC_E_OVERFLOW
 *  when the result does not fit int32_t. */
static inline drdc_status_t drdc_orient_impl_q60_to_q30(int64_t v,
                                                        drdc_q1_30_t *out)
{
  /* inline: a quaternion product calls it four times */
  int64_t r = drdc_fx_rshift_round_s64_inline(v, 30u);
  drdc_status_t st = DRDC_E_OVERFLOW;

  if ((r <= INT32_MAX) && (r >= INT32_MIN)) {
    *out = (drdc_q1_30_t)r;
    st = DRDC_OK;
  }
  return st;
}

/**
 * Round a Q60 value to Q1.30 bits (ties away from zero) without a branch,
 * for hot paths whose callers know v cannot reach 2^63: the sign bias
 * 2^29 - [v < 0] turns the floor of the shift into the rounding of
 * drdc_fx_rshift_round_s64() (ceil((v - 2^29) / 2^30) equals
 * floor((v + 2^29 - 1) / 2^30)). The high word of the biased value plus
 * 2^29 is ORed into *ovf: the result fits int32_t exactly when that word
 * is below 2^30, so bits 30..31 of *ovf flag an overflow of any of the
 * parts rounded with the same *ovf.
 * @return the low 32 bits of the rounded value (the Q1.30 part when
 *         *ovf stays below 2^30)
 */
static inline uint32_t orient_q60_round_bits(int64_t v, uint32_t *ovf)
{
  uint64_t u = (uint64_t)v;
  uint32_t neg = (uint32_t)(u >> 63u);
  uint32_t hi;

  u += UINT64_C(0x20000000) - neg;
  hi = (uint32_t)(u >> 32u);
  *ovf |= hi + UINT32_C(0x20000000);
  return (uint32_t)(u >> 30u);
}

/** One 16-bit digit of Knuth's algorithm D (TAOCP vol. 2, 4.3.1): the
 *  quotient digit of (r 2^16 + u) / d for r < d, d >= 2^31 normalised,
 *  with the 32/32 hardware division on the top half dh of d and at most
 *  two corrections; *r becomes the remainder. */
static inline uint32_t orient_div_digit16(uint32_t *r, uint32_t u, uint32_t d)
{
  const uint32_t dh = d >> 16u;
  const uint32_t dl = d & 0xFFFFu;
  uint32_t qh = *r / dh;
  uint32_t rh = *r - (qh * dh);

  while ((qh > 0xFFFFu) || ((qh * dl) > ((rh << 16u) | u))) {
    qh--;
    rh += dh;
    if (rh > 0xFFFFu) {
      break;
    }
  }
  *r = ((*r << 16u) | u) - (qh * d); /* < d: exact modulo 2^32 */
  return qh;
}

/** floor((2^64 - 1) / d) - 2^32 for d >= 2^31 (the 2/1 reciprocal of
 *  Moeller and Granlund), from two 16-bit digits of (~d 2^32 + 2^32 - 1)
 *  / d: 32/32 divisions only, no 64-bit division helper. */
static inline uint32_t orient_reciprocal_word(uint32_t d)
{
  uint32_t r = ~d; /* < d */
  uint32_t q1 = orient_div_digit16(&r, 0xFFFFu, d);
  uint32_t q0 = orient_div_digit16(&r, 0xFFFFu, d);

  return (q1 << 16u) | q0;
}

/**
 * Reciprocal of a normalised two-word divisor d = d1 2^32 + d0 (d1 >=
 * 2^31), after Moeller and Granlund, "Improved division by invariant
 * integers" (IEEE Trans. Computers 60(2), 2011), algorithm 6 with 32-bit
 * words: floor((2^96 - 1) / d) - 2^32. Two 32/32 divisions; every
 * division by d then costs two 32x32->64 products and a few adds
 * (orient_div_3by2()). A fixed-point primitive: it belongs in fixed/.
 */
uint32_t drdc_orient_impl_reciprocal_3by2(uint32_t d1, uint32_t d0);

/**
 * One 32-bit quotient word of u2 2^64 + u1 2^32 + u0 by the normalised
 * d = d1 2^32 + d0 with v = drdc_orient_impl_reciprocal_3by2(d1, d0), for
 * u2 2^32 + u1 < d (Moeller and Granlund, algorithm 5). *r receives the
 * remainder (< d).
 */
static inline uint32_t orient_div_3by2(uint32_t u2, uint32_t u1, uint32_t u0,
                                       uint64_t d, uint32_t v, uint64_t *r)
{
  const uint32_t d1 = (uint32_t)(d >> 32u);
  const uint32_t d0 = (uint32_t)d;
  uint64_t q = ((uint64_t)v * u2) + (((uint64_t)u2 << 32u) | u1);
  uint32_t q1 = (uint32_t)(q >> 32u);
  uint32_t q0 = (uint32_t)q;
  uint32_t r1 = u1 - (q1 * d1);
  uint64_t rr = ((((uint64_t)r1 << 32u) | u0) - ((uint64_t)q1 * d0)) - d;

  q1++;
  if ((uint32_t)(rr >> 32u) >= q0) {
    q1--;
    rr += d;
  }
  if (rr >= d) { /* rare */
    q1++;
    rr -= d;
  }
  *r = rr;
  return q1;
}

/** Row i of the exact Q60 numerators of R(c) (the values of
 * drdc_orient_impl_numerators()), one row at a time so that the whole
 * matrix never sits on the stack. */
void drdc_orient_impl_numerator_row(const int32_t c[4], unsigned i,
                                    int64_t row[3]);

/**
 * round(p 2^t / d) to nearest, ties away from zero (the value of
 * drdc_fx_muldiv_s64(p, 2^t, d)), with dn = d 2^z normalised (bit 63
 * set), rcp = drdc_orient_impl_reciprocal_3by2() of dn, and t including z: for
 * |p| 2^t < dn 2^32 (a quotient below 2^32) and 31 <= t <= 63. The
 * magnitude times 2^t is three words; one orient_div_3by2() step.
 * @return the low 32 bits of the rounded quotient with its sign
 */
static inline uint32_t orient_round_div_shifted(int64_t p, unsigned t,
                                                uint64_t dn, uint32_t rcp)
{
  uint64_t mag = (p < 0) ? (0u - (uint64_t)p) : (uint64_t)p;
  unsigned tr = 64u - t;
  uint64_t lo = mag << t;
  uint64_t r;
  uint32_t quo = orient_div_3by2((uint32_t)(mag >> tr), (uint32_t)(lo >> 32u),
                                 (uint32_t)lo, dn, rcp, &r);

  if (r >= (dn - r)) {
    quo++;
  }
  if (p < 0) {
    quo = 0u - quo;
  }
  return quo;
}

/** x y as 128 bits (*hi, *lo): four 32x32 products */
static inline void orient_mul_u64(uint64_t x, uint64_t y, uint64_t *hi,
                                  uint64_t *lo)
{
  const uint32_t x0 = (uint32_t)x;
  const uint32_t x1 = (uint32_t)(x >> 32u);
  const uint32_t y0 = (uint32_t)y;
  const uint32_t y1 = (uint32_t)(y >> 32u);
  uint64_t ll = (uint64_t)x0 * y0;
  uint64_t lh = (uint64_t)x0 * y1;
  uint64_t hl = (uint64_t)x1 * y0;
  uint64_t hh = (uint64_t)x1 * y1;
  uint64_t mid = (ll >> 32u) + (uint32_t)lh + (uint32_t)hl;

  *lo = (mid << 32u) | (uint32_t)ll;
  *hi = hh + (lh >> 32u) + (hl >> 32u) + (mid >> 32u);
}

/**
 * round(p w / d) to nearest, ties away from zero (the value of
 * drdc_fx_muldiv_s64(p, w, d)) for |p| <= d and |w| < 2^63, with
 * dn = d 2^z normalised (bit 63 set) and rcp its
 * drdc_orient_impl_reciprocal_3by2(): |p w| 2^z < dn 2^63 is four words, the
 * quotient (< 2^63) two orient_div_3by2() steps.
 */
static inline int64_t orient_round_div_128(int64_t p, int64_t w, uint64_t dn,
                                           unsigned z, uint32_t rcp)
{
  uint64_t mp = (p < 0) ? (0u - (uint64_t)p) : (uint64_t)p;
  uint64_t mw = (w < 0) ? (0u - (uint64_t)w) : (uint64_t)w;
  uint64_t hi;
  uint64_t lo;
  uint64_t r;
  uint64_t quo;
  uint32_t q1;
  uint32_t q0;

  orient_mul_u64(mp, mw, &hi, &lo);
  if (z != 0u) {
    unsigned zr = 64u - z;

    hi = (hi << z) | (lo >> zr);
    lo <<= z;
  }
  q1 = orient_div_3by2((uint32_t)(hi >> 32u), (uint32_t)hi,
                       (uint32_t)(lo >> 32u), dn, rcp, &r);
  q0 = orient_div_3by2((uint32_t)(r >> 32u), (uint32_t)r, (uint32_t)lo, dn,
                       rcp, &r);
  quo = ((uint64_t)q1 << 32u) | q0;
  if (r >= (dn - r)) {
    quo++;
  }
  if ((p < 0) != (w < 0)) {
    quo = 0u - quo;
  }
  return (int64_t)quo;
}

/**
 * round(a b / c) to nearest, ties away from zero (the value of
 * drdc_fx_muldiv_s64(a, b, c)) for c > 0 and |a b| < 2^64: the 64-bit
 * product, its quotient and remainder (libgcc's 64-bit division: no
 * 128-bit intermediate and no deep frame).
 */
static inline int64_t orient_muldiv_round64(int64_t a, int32_t b, int32_t c)
{
  uint64_t ma = (a < 0) ? (0u - (uint64_t)a) : (uint64_t)a;
  uint32_t mb = (b < 0) ? (0u - (uint32_t)b) : (uint32_t)b;
  uint64_t d = (uint64_t)(uint32_t)c;
  uint64_t n = ma * mb;
  uint64_t q = n / d;
  uint64_t r = n - (q * d);

  if (r >= (d - r)) {
    q++;
  }
  if ((a < 0) != (b < 0)) {
    q = 0u - q;
  }
  return (int64_t)q;
}

/** The high word (signed) of a 64-bit value. */
static inline int32_t orient_high_word(int64_t v)
{
  uint64_t u = (uint64_t)v;
  uint32_t h = (uint32_t)(u >> 32u);

  return (int32_t)h;
}

/** Q60 -> Q1.30 bits of p = w + x + y + z for any four products of two
 * int32 values (the parts of a quaternion product, the elements of a
 * matrix product), each term (|.| <= 2^62, so also its negation), summed
 * modulo 2^64.
 * With each term = h 2^32 + l (h its signed high word, 0 <= l < 2^32),
 * |p - (sum of h) 2^32| < 2^34: when that sum of high words is within
 * 2^30, |p| < 2^63 and the modular sum is p itself; beyond, |p| > 2^62
 * and the part cannot fit [-2, 2) (bit 31 of *ovf is set). */
static inline uint32_t orient_sum4_round_bits(int64_t w, int64_t x, int64_t y,
                                              int64_t z, uint32_t *ovf)
{
  int64_t hs = (int64_t)orient_high_word(w) + orient_high_word(x)
               + orient_high_word(y) + orient_high_word(z);
  uint64_t sum = (uint64_t)w + (uint64_t)x + (uint64_t)y + (uint64_t)z;

  if ((hs > (INT64_C(1) << 30)) || (hs < -(INT64_C(1) << 30))) {
    *ovf |= (UINT32_C(1) << 31);
    sum = 0u;
  }
  return orient_q60_round_bits((int64_t)sum, ovf);
}

/**
 * round(a b / 2^n) to nearest, ties away from zero (the value of
 * drdc_fx_muldiv_s64(a, b, 2^n)) for 1 <= n <= 63 and |a b| / 2^n < 2^63:
 * the 128-bit product of the magnitudes, half a unit added, shifted; no
 * division and no 128-bit helper frame.
 */
static inline int64_t orient_mul_rshift_round(int64_t a, int64_t b,
                                              unsigned n)
{
  uint64_t ma = (a < 0) ? (0u - (uint64_t)a) : (uint64_t)a;
  uint64_t mb = (b < 0) ? (0u - (uint64_t)b) : (uint64_t)b;
  uint64_t half = UINT64_C(1) << (n - 1u);
  uint64_t hi;
  uint64_t lo;
  uint64_t q;
  unsigned nr = 64u - n;

  orient_mul_u64(ma, mb, &hi, &lo);
  lo += half;
  hi += (lo < half) ? 1u : 0u;
  q = (hi << nr) | (lo >> n);
  if ((a < 0) != (b < 0)) {
    q = 0u - q;
  }
  return (int64_t)q;
}

/**
 * sin and cos of half the signed angle a ([-pi, pi) -> [-pi/2, pi/2)),
 * both doubled: Q1.31 scale (2^31 = 1.0) in int64_t. For an odd a the
 * half angle falls between two binary angles; the mean of the two table
 * values is used (its error is that of drdc_fx_sin_bam32(), the
 * curvature term is below 2^-60).
 */
void drdc_orient_impl_half_sincos(drdc_bam32_t a, int64_t *s2, int64_t *c2);

/** |v| of an int32_t as uint32_t; exact for INT32_MIN. */
static inline uint32_t orient_abs32(int32_t v)
{
  return (v < 0) ? (0u - (uint32_t)v) : (uint32_t)v;
}

/** Doubled half-angle sine and cosine as magnitudes (Q1.31 scale,
 *  <= 2^31) and the sign of the sine; the cosine is never negative. */
typedef struct orient_half {
  uint32_t s;   /**< |2 sin(a / 2)|, Q1.31 scale */
  uint32_t c;   /**< 2 cos(a / 2) >= 0, Q1.31 scale */
  uint32_t neg; /**< 1 when the sine is negative, else 0 */
} orient_half_t;

/** The values of drdc_orient_impl_half_sincos() as magnitudes and a sign
 *  bit (the same bits: s2 = (-1)^neg s, c2 = c), for callers that
 *  multiply them with 32x32->64 products; inline, so that the three
 *  angles of drdc_quat_from_euler() pay no call of their own. */
static inline void orient_half_sincos_mag(drdc_bam32_t a, orient_half_t *out)
{
  drdc_bam32_t h = (a >> 1u) | (a & 0x80000000u); /* floor(a / 2), signed */
  drdc_q1_30_t s0;
  drdc_q1_30_t c0;
  drdc_q1_30_t s1;
  drdc_q1_30_t c1;

  drdc_fx_sincos_bam32(h, &s0, &c0);
  if ((a & 1u) == 0u) {
    s1 = s0;
    c1 = c0;
  } else {
    drdc_fx_sincos_bam32(h + 1u, &s1, &c1);
  }
  /* c0, c1 >= 0 (the half angle is in [-pi/2, pi/2]): the sum <= 2^31
   * fits uint32. s0 and s1 never have opposite signs (h < 0 < h + 1 has
   * no integer h), so the sign is that of either nonzero one and the
   * magnitude the sum of theirs (|s0|, |s1| <= 2^30). */
  out->c = (uint32_t)c0 + (uint32_t)c1;
  out->neg = ((uint32_t)s0 | (uint32_t)s1) >> 31u;
  out->s = orient_abs32(s0) + orient_abs32(s1);
}


/** atan2 of two int64_t coordinates: both are scaled by the same power
 *  of two (rounded) so that the larger fits in 31 bits with the most
 *  precision left, then drdc_fx_atan2_bam32(). DRDC_E_DOMAIN for (0, 0). */
drdc_status_t drdc_orient_impl_atan2_s64(int64_t y, int64_t x,
                                         drdc_bam32_t *out);

/** sqrt(x^2 + y^2) for |x|, |y| <= 2^62, rounded exactly as
 *  drdc_fx_hypot_s64() rounds (the floor root, plus one when the
 *  remainder exceeds it), with two Newton steps on 128 bits from a 16-bit
 *  start instead of 64 bit-by-bit steps. A fixed-point primitive: it
 *  belongs in fixed/. */
uint64_t drdc_orient_impl_hypot62(int64_t x, int64_t y);

/** Exact Q60 numerators p of the rotation matrix of q (prescaled) and
 *  their common denominator n2: R = p / n2, |p| <= n2 <= 2^62.
 *  DRDC_E_DOMAIN for the zero quaternion. */
drdc_status_t drdc_orient_impl_numerators(const drdc_quat_t *q,
                                          int64_t p[3][3], int64_t *n2);

/** Largest shift s <= max such that |v| * 2^s < 2^limit (v any uint64). */
unsigned drdc_orient_impl_headroom(uint64_t v, unsigned limit);

#endif /* DRDC_ORIENT_IMPL_H */
