/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_wide
 * @brief Exact wide-integer primitives shared by fixed/ and core/:
 *        64x64->128 products, division by invariant integers
 *        (Moeller-Granlund reciprocals), rounded 128-bit quotients and
 *        shifts, the exact 62-bit hypot and bit lengths.
 */
#ifndef DRDC_FIXED_WIDE_H
#define DRDC_FIXED_WIDE_H

#include <stdint.h>

/**
 * @defgroup drdc_fixed_wide Wide-integer primitives (internal, shared)
 *
 * Building blocks of the library's own exact arithmetic, for fixed/ and
 * core/ modules, so that no module writes its own rounding or overflow
 * arithmetic. They are not part of the data standard's API: they take
 * raw integers, state their preconditions instead of checking them and
 * return no status. Outside its stated domain a primitive's result is
 * unspecified (never undefined behaviour: every operation is on unsigned
 * words).
 *
 * Exactness: every primitive here is exact. Quotients are floors or, where
 * the name says round, rounded to nearest with ties away from zero (of the
 * signed value, as drdc_fx_rshift_round_s64() and drdc_fx_muldiv_s64()
 * round); products are exact to the last bit. Only 32x32->64 multiplies
 * (UMULL on Cortex-M3, mullw/mulhwu on PowerPC) and 32/32 hardware
 * divisions are used: no call to libgcc's 64-bit division, except in
 * drdc_fx_muldiv_round64(), which is one 64/64 division by design.
 * Checked against exact Python integers (tests/ref/gen_fixed_wide.py,
 * tests/fixed/test_wide.c) on every target.
 *
 * Division by invariant integers after N. Moeller and T. Granlund,
 * "Improved division by invariant integers", IEEE Trans. Computers 60(2),
 * 2011 (algorithms 5 and 6 with 32-bit words): a divisor d normalised to
 * bit 63 (dn = d 2^z) gets one reciprocal drdc_fx_reciprocal_3by2(); each
 * 32-bit quotient word by dn then costs two 32x32->64 products and a few
 * adds (drdc_fx_div_3by2()).
 * @{
 */

/**
 * One 16-bit digit of Knuth's algorithm D (TAOCP vol. 2, 4.3.1): the
 * quotient digit floor((r 2^16 + u) / d) for d >= 2^31 (normalised),
 * r < d and u < 2^16, with the 32/32 hardware division on the top half
 * of d and at most two corrections. *r becomes the remainder (< d).
 * Exact.
 */
static inline uint32_t drdc_fx_div_digit16(uint32_t *r, uint32_t u, uint32_t d)
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

/**
 * The 2/1 reciprocal of Moeller and Granlund, floor((2^64 - 1) / d) -
 * 2^32, for d >= 2^31: two 16-bit digits of (~d 2^32 + 2^32 - 1) / d
 * (32/32 divisions only). Exact.
 */
static inline uint32_t drdc_fx_reciprocal_2by1(uint32_t d)
{
  uint32_t r = ~d; /* < d */
  uint32_t q1 = drdc_fx_div_digit16(&r, 0xFFFFu, d);
  uint32_t q0 = drdc_fx_div_digit16(&r, 0xFFFFu, d);

  return (q1 << 16u) | q0;
}

/**
 * Reciprocal of a normalised two-word divisor (Moeller and Granlund,
 * algorithm 6 with 32-bit words): floor((2^96 - 1) / d) - 2^32 for
 * d = d1 2^32 + d0. Exact.
 *
 * @param d1 high word of d, >= 2^31
 * @param d0 low word of d, any
 * @return floor((2^96 - 1) / d) - 2^32, for drdc_fx_div_3by2()
 */
uint32_t drdc_fx_reciprocal_3by2(uint32_t d1, uint32_t d0);

/**
 * One 32-bit quotient word of u2 2^64 + u1 2^32 + u0 by the normalised
 * d (bit 63 set) with v = drdc_fx_reciprocal_3by2() of d, for
 * u2 2^32 + u1 < d (Moeller and Granlund, algorithm 5): the floor of the
 * quotient, *r the remainder (< d). Exact.
 */
static inline uint32_t drdc_fx_div_3by2(uint32_t u2, uint32_t u1, uint32_t u0,
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

/**
 * round(p 2^t / d) to nearest, ties away from zero (the value of
 * drdc_fx_muldiv_s64(p, 2^t, d)), with dn = d 2^z normalised (bit 63
 * set), rcp = drdc_fx_reciprocal_3by2() of dn and t including z: for
 * |p| 2^t < dn 2^32 (a quotient below 2^32) and 31 <= t <= 63. The
 * magnitude times 2^t is three words; one drdc_fx_div_3by2() step.
 * Returns the low 32 bits of the rounded quotient with its sign (two's
 * complement). Exact.
 */
static inline uint32_t drdc_fx_round_div_shifted(int64_t p, unsigned t,
                                                 uint64_t dn, uint32_t rcp)
{
  uint64_t mag = (p < 0) ? (0u - (uint64_t)p) : (uint64_t)p;
  unsigned tr = 64u - t;
  uint64_t lo = mag << t;
  uint64_t r;
  uint32_t quo = drdc_fx_div_3by2((uint32_t)(mag >> tr), (uint32_t)(lo >> 32u),
                                  (uint32_t)lo, dn, rcp, &r);

  if (r >= (dn - r)) {
    quo++;
  }
  if (p < 0) {
    quo = 0u - quo;
  }
  return quo;
}

/** x y as 128 bits (*hi, *lo), exact: four 32x32->64 products. */
static inline void drdc_fx_mul_u64_u128(uint64_t x, uint64_t y, uint64_t *hi,
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
  /* middle column: at most 3 (2^32 - 1) < 2^34, no overflow */
  uint64_t mid = (ll >> 32u) + (uint32_t)lh + (uint32_t)hl;

  *lo = (mid << 32u) | (uint32_t)ll;
  *hi = hh + (lh >> 32u) + (hl >> 32u) + (mid >> 32u);
}

/**
 * round(p w / d) to nearest, ties away from zero (the value of
 * drdc_fx_muldiv_s64(p, w, d)) for |p| <= d and |w| < 2^63, with
 * dn = d 2^z normalised (bit 63 set) and rcp its
 * drdc_fx_reciprocal_3by2(): |p w| 2^z < dn 2^63 is four words, the
 * quotient (< 2^63) two drdc_fx_div_3by2() steps. Exact.
 */
static inline int64_t drdc_fx_round_div_128(int64_t p, int64_t w, uint64_t dn,
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

  drdc_fx_mul_u64_u128(mp, mw, &hi, &lo);
  if (z != 0u) {
    unsigned zr = 64u - z;

    hi = (hi << z) | (lo >> zr);
    lo <<= z;
  }
  q1 = drdc_fx_div_3by2((uint32_t)(hi >> 32u), (uint32_t)hi,
                        (uint32_t)(lo >> 32u), dn, rcp, &r);
  q0 = drdc_fx_div_3by2((uint32_t)(r >> 32u), (uint32_t)r, (uint32_t)lo, dn,
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
 * drdc_fx_muldiv_s64(a, b, c)) for c > 0, |a b| < 2^64 and a quotient
 * within int64_t: the 64-bit
 * product, its quotient and remainder (one libgcc 64-bit division: no
 * 128-bit intermediate and no deep frame). Exact.
 */
static inline int64_t drdc_fx_muldiv_round64(int64_t a, int32_t b, int32_t c)
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

/** The high word of a 64-bit value, as a signed int32 (floor(v / 2^32)).
 *  Exact. */
static inline int32_t drdc_fx_high_word(int64_t v)
{
  uint64_t u = (uint64_t)v;
  uint32_t h = (uint32_t)(u >> 32u);

  return (int32_t)h;
}

/**
 * round(a b / 2^n) to nearest, ties away from zero (the value of
 * drdc_fx_muldiv_s64(a, b, 2^n)) for 1 <= n <= 63 and |a b| / 2^n < 2^63:
 * the 128-bit product of the magnitudes, half a unit added, shifted; no
 * division and no 128-bit helper frame. Exact.
 */
static inline int64_t drdc_fx_mul_rshift_round(int64_t a, int64_t b, unsigned n)
{
  uint64_t ma = (a < 0) ? (0u - (uint64_t)a) : (uint64_t)a;
  uint64_t mb = (b < 0) ? (0u - (uint64_t)b) : (uint64_t)b;
  uint64_t half = UINT64_C(1) << (n - 1u);
  uint64_t hi;
  uint64_t lo;
  uint64_t q;
  unsigned nr = 64u - n;

  drdc_fx_mul_u64_u128(ma, mb, &hi, &lo);
  lo += half;
  hi += (lo < half) ? 1u : 0u;
  q = (hi << nr) | (lo >> n);
  if ((a < 0) != (b < 0)) {
    q = 0u - q;
  }
  return (int64_t)q;
}

/**
 * floor(N / x) for N = nh 2^64 + nl: two quotient words of
 * drdc_fx_div_3by2() with the reciprocal of x normalised. Exact.
 *
 * @param nh high 64 bits of N
 * @param nl low 64 bits of N
 * @param x divisor, with nh < x (so that the quotient fits 64 bits)
 * @return floor(N / x)
 */
uint64_t drdc_fx_div_128_64(uint64_t nh, uint64_t nl, uint64_t x);

/**
 * sqrt(x^2 + y^2) rounded to nearest (the floor root, plus one when the
 * remainder exceeds it; a root is never half-way), exact as
 * drdc_fx_hypot_s64() rounds: two Newton steps on 128 bits from a 16-bit
 * start instead of 64 bit-by-bit steps. Error < 0.5 (correctly rounded).
 *
 * @param x any value with |x| <= 2^62
 * @param y any value with |y| <= 2^62
 * @return round(sqrt(x^2 + y^2)), <= 2^62.5
 */
uint64_t drdc_fx_hypot62(int64_t x, int64_t y);

/**
 * The largest shift s such that v 2^s < 2^limit: limit minus the bit
 * length of v, 0 when v already needs limit bits or more. Exact.
 *
 * @param v any value
 * @param limit 1..64 (0 or more than 64 give 0)
 * @return s, 0..limit - 1; 0 for v == 0
 */
unsigned drdc_fx_headroom(uint64_t v, unsigned limit);

/** @} */

#endif /* DRDC_FIXED_WIDE_H */
