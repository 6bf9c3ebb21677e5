/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_arith
 * @brief Internal helpers of fixed/: magnitudes, rounded division, the
 *        final range check of a signed result, 128-bit unsigned integers.
 *
 * Every routine works on magnitudes (unsigned) and a separate sign, so no
 * signed overflow and no shift of a negative value can happen; rounding to
 * nearest with ties away from zero is then "add half, truncate" on the
 * magnitude.
 */
#ifndef DRDC_FIXED_IMPL_H
#define DRDC_FIXED_IMPL_H

#include <stdint.h>

#include <drdc/fixed_wide.h>
#include <drdc/status.h>

/** 1 when the quotient a * b / c is negative: an odd count of negative
 *  operands (muldiv.c, muldiv_s32.c). */
static inline int fx_quotient_negative(int a_negative, int b_negative,
                                       int c_negative)
{
  return (a_negative + b_negative + c_negative) & 1;
}

/** |x| of an int32_t as uint32_t; exact for INT32_MIN (2^31). */
static inline uint32_t fx_abs32(int32_t x)
{
  return (x < 0) ? (0u - (uint32_t)x) : (uint32_t)x;
}

/** |x| of an int64_t as uint64_t; exact for INT64_MIN (2^63). */
static inline uint64_t fx_abs64(int64_t x)
{
  return (x < 0) ? (UINT64_C(0) - (uint64_t)x) : (uint64_t)x;
}

/** The int32_t whose two's complement bits are v: v itself below 2^31,
 *  v - 2^32 above, computed without an out-of-range conversion (which
 *  C99 leaves implementation-defined); it reduces to a plain move. */
static inline int32_t fx_s32_from_bits(uint32_t v)
{
  uint32_t complement = ~v; /* < 2^31 when v >= 2^31 */

  return (v < (UINT32_C(1) << 31)) ? (int32_t)v : (-(int32_t)complement - 1);
}

/** n / d rounded to nearest, ties away from zero, for d != 0 and
 *  n <= 2^63 (so n + d / 2 cannot overflow). One division: n / d is a tie
 *  k + 1/2 only for an even d, and then n + d / 2 = (k + 1) d; otherwise
 *  adding floor(d / 2) reaches the next multiple of d exactly when the
 *  remainder is at least half of d. (Computing the remainder as well would
 *  cost a second libgcc call on 32-bit targets.) */
static inline uint64_t fx_div_round_u64(uint64_t n, uint64_t d)
{
  return (n + (d >> 1)) / d;
}

/**
 * Signed int32 result of sign `neg` and magnitude `mag`: writes it and
 * returns DRDC_OK when it fits; otherwise DRDC_E_OVERFLOW with `*out`
 * unchanged, or, when `sat`, the clamped limit and DRDC_W_SATURATED.
 */
static inline drdc_status_t fx_finish_s32(int neg, uint64_t mag, int sat,
                                          int32_t *out)
{
  uint64_t limit = neg ? (UINT64_C(1) << 31) : (uint64_t)INT32_MAX;

  if (mag > limit) {
    if (!sat) {
      return DRDC_E_OVERFLOW;
    }
    *out = neg ? INT32_MIN : INT32_MAX;
    return DRDC_W_SATURATED;
  }
  /* negate in range: 2^31 is INT32_MIN, smaller magnitudes negate as
   * int32_t (no out-of-range conversion anywhere) */
  if (neg && (mag == (UINT64_C(1) << 31))) {
    *out = INT32_MIN;
  } else {
    *out = neg ? -(int32_t)mag : (int32_t)mag;
  }
  return DRDC_OK;
}

/* INT64_MIN spelled as <stdint.h> spells it: the plain constant
 * 9223372036854775808 has no signed type, and MISRA rule 7.2 checkers
 * (cppcheck) read INT64_MIN as that constant. */
#define FX_INT64_MIN (-INT64_MAX - 1)

/** As fx_finish_s32() for int64; `too_big` flags a magnitude >= 2^64. */
static inline drdc_status_t fx_finish_s64(int neg, int too_big, uint64_t mag,
                                          int sat, int64_t *out)
{
  uint64_t limit = neg ? (UINT64_C(1) << 63) : (uint64_t)INT64_MAX;

  if (too_big || (mag > limit)) {
    if (!sat) {
      return DRDC_E_OVERFLOW;
    }
    *out = neg ? FX_INT64_MIN : INT64_MAX;
    return DRDC_W_SATURATED;
  }
  /* Two's complement negation in uint64_t, then the conversion of a value
   * in int64_t range (2^63 maps to INT64_MIN through the explicit case). */
  if (neg && (mag == (UINT64_C(1) << 63))) {
    *out = FX_INT64_MIN;
  } else {
    *out = neg ? -(int64_t)mag : (int64_t)mag;
  }
  return DRDC_OK;
}

/** x / n (truncated) for a small divisor 0 < n < 2^16, by four 32-bit
 *  divisions of 16-bit digits (each partial dividend is below n 2^16):
 *  no call to libgcc's 64-bit division, which is slower and needs stack. */
static inline uint64_t fx_div_u64_small(uint64_t x, uint32_t n)
{
  uint64_t q = 0;
  uint32_t r = 0;
  unsigned digit_index;

  /* four 16-bit digits, most significant first */
  for (digit_index = 0u; digit_index < 4u; digit_index++) {
    unsigned shift = 48u - (16u * digit_index);
    uint32_t cur = (r << 16u) | (uint32_t)((x >> shift) & 0xFFFFu);
    uint32_t digit = cur / n;

    r = cur - (digit * n);
    q = (q << 16u) | digit;
  }
  return q;
}

/** Unsigned 128-bit integer as two 64-bit halves. */
typedef struct fx_u128 {
  uint64_t hi;
  uint64_t lo;
} fx_u128_t;

/** a * b exactly, from four 32 x 32 -> 64 products
 *  (drdc_fx_mul_u64_u128(), as a struct). */
static inline fx_u128_t fx_mul_u64(uint64_t a, uint64_t b)
{
  fx_u128_t r;

  drdc_fx_mul_u64_u128(a, b, &r.hi, &r.lo);
  return r;
}

/** a + b (mod 2^128). */
static inline fx_u128_t fx_add_u128(fx_u128_t a, uint64_t b)
{
  a.lo += b;
  if (a.lo < b) {
    a.hi++;
  }
  return a;
}

/** a >> n for 0 < n < 64. */
static inline fx_u128_t fx_shr_u128(fx_u128_t a, unsigned n)
{
  a.lo = (a.lo >> n) | (a.hi << (64u - n));
  a.hi >>= n;
  return a;
}

/** round(a b / 2^n) for 0 < n < 64 when the result fits 64 bits (the
 *  caller's bounds guarantee it; the high part is dropped). */
static inline uint64_t fx_mul_shr_round(uint64_t a, uint64_t b, unsigned n)
{
  fx_u128_t p = fx_add_u128(fx_mul_u64(a, b), UINT64_C(1) << (n - 1u));

  return fx_shr_u128(p, n).lo;
}

/** a << n for 0 < n < 64. */
static inline fx_u128_t fx_shl_u128(fx_u128_t a, unsigned n)
{
  a.hi = (a.hi << n) | (a.lo >> (64u - n));
  a.lo <<= n;
  return a;
}

/** a <= b. */
static inline int fx_le_u128(fx_u128_t a, fx_u128_t b)
{
  return (a.hi < b.hi) || ((a.hi == b.hi) && (a.lo <= b.lo));
}

/**
 * n / d rounded to nearest, ties away from zero, for a 128-bit n and
 * 64-bit d != 0. Returns 0 and writes `*q` when the quotient fits 64 bits,
 * 1 when it does not. Division by the invariant d (fixed_wide.h): d is
 * normalised so its top bit is set, one 3/2 reciprocal of Moeller and
 * Granlund is formed from 32/32 hardware divisions, and each of the two
 * 32-bit quotient words costs two 32x32->64 products
 * (drdc_fx_div_3by2()); no call to libgcc's 64-bit division. The floor
 * quotient and remainder are exact, so the rounding is decided exactly.
 */
static inline int fx_div_round_u128(fx_u128_t n, uint64_t d, uint64_t *q)
{
  unsigned s;
  uint64_t v;
  uint64_t un32;
  uint64_t un10;
  uint64_t r;
  uint32_t rcp;
  uint32_t q1;
  uint32_t q0;
  uint64_t rem;
  uint64_t quo;

  if (n.hi >= d) {
    return 1; /* quotient >= 2^64 */
  }
  s = (unsigned)__builtin_clzll(d); /* d != 0 */
  v = d << s;
  if (s == 0u) {
    un32 = n.hi;
  } else {
    un32 = (n.hi << s) | (n.lo >> (64u - s));
  }
  un10 = n.lo << s;
  rcp = drdc_fx_reciprocal_3by2((uint32_t)(v >> 32), (uint32_t)v);
  /* un32 < v and then r < v: each step's precondition */
  q1 = drdc_fx_div_3by2((uint32_t)(un32 >> 32), (uint32_t)un32,
                        (uint32_t)(un10 >> 32), v, rcp, &r);
  q0 = drdc_fx_div_3by2((uint32_t)(r >> 32), (uint32_t)r, (uint32_t)un10, v,
                        rcp, &r);
  rem = r >> s;
  quo = ((uint64_t)q1 << 32) | q0;

  if (rem >= (d - rem)) {
    if (quo == UINT64_MAX) {
      return 1;
    }
    quo++;
  }
  *q = quo;
  return 0;
}

#endif /* DRDC_FIXED_IMPL_H */
