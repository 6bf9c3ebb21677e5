/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_hyper
 * @brief sinh, cosh, atanh, asinh in Q5.58 from an exp and an atanh
 *        series in Q62 with rounded 128-bit products.
 *
 * exp: x = k ln 2 + r with k = round(x / ln 2), |r| <= ln 2 / 2 (Q63, the
 * product k ln 2 from ln 2 in Q64, so r is good to 2^-64); e^r by Taylor
 * to the last term that is not 0 (<= 22 terms), e^r in (0.70, 1.42), Q63.
 * Then sinh, cosh = (e^r 2^(2k) -+ e^-r) / 2^(k+1), rounded once from a
 * 128-bit numerator.
 *
 * log: y = m 2^e with m in [1/sqrt 2, sqrt 2), s = (m - 1) / (m + 1),
 * |s| <= 3 - 2 sqrt 2 = 0.1716, ln y = e ln 2 + 2 atanh(s), atanh(s) by
 * its series s + s^3/3 + ... (s^2 <= 0.0295: <= 13 terms to 2^-62).
 */
#include <drdc/fixed_hyper.h>

#include <stddef.h>

#include <drdc/fixed_sqrt.h>

#include "fixed_impl.h"

/* ln 2 in Q64 and Q58, rounded. */
#define LN2_Q64 ((uint64_t)0xB17217F7D1CF79ACu) /* 12786308645202655660 */
#define LN2_Q58 INT64_C(199786072581291495)
/* 1.0 in Q62. */
#define ONE_Q62 (UINT64_C(1) << 62)
/* sqrt(2) and sqrt(1/2) in Q62: the mantissa interval of the logarithm. */
#define SQRT2_Q62 UINT64_C(6521908912666391106)
#define SQRTH_Q62 UINT64_C(3260954456333195553)
/* 3 - 2 sqrt 2 in Q58 (floor): below it atanh(x) is its series directly. */
#define ATANH_SERIES_MAX INT64_C(49452514371836343)
/* Largest |x| for sinh/cosh before the final range check: ln(64) < 4.5. */
#define EXP_ARG_MAX (INT64_C(9) << 57)

/* 1.0 in Q63: e^r < 1.42 fits Q63 in a uint64_t. */
#define ONE_Q63 (UINT64_C(1) << 63)

/* e^r in Q63 for |r| <= ln 2 / 2 + 2^-63 (r Q63, sign separate). Each
 * term is rounded (product and division), so the errors do not pile up
 * in one direction: about 2^-62 in all. */
static uint64_t exp_small_q63(uint64_t mag, int neg)
{
  uint64_t sum = ONE_Q63;
  uint64_t term = ONE_Q63;
  uint64_t n;

  for (n = 1u; n < 32u; n++) {
    term = fx_mul_shr_round(term, mag, 63u);
    term = fx_div_u64_small(term + (n >> 1), (uint32_t)n);
    if (term == 0u) {
      break;
    }
    sum = (neg && ((n & 1u) != 0u)) ? (sum - term) : (sum + term);
  }
  return sum;
}

/* Internal marker of a sinh/cosh result beyond INT64_MAX. */
#define SINH_COSH_OVERFLOW UINT64_MAX

/* sinh (plus == 0) or cosh (plus == 1) of |x| <= EXP_ARG_MAX in Q58, or
 * SINH_COSH_OVERFLOW when it does not fit int64_t. */
static uint64_t sinh_cosh_mag(uint64_t x, int plus)
{
  uint64_t k = (x + (uint64_t)(LN2_Q58 / 2)) / (uint64_t)LN2_Q58; /* <= 6 */
  fx_u128_t kln2 = fx_shr_u128(fx_add_u128(fx_mul_u64(k, LN2_Q64), 1u), 1u);
  uint64_t d = (x << 5) - kln2.lo; /* r in Q63 modulo 2^64: |r| < 2^62 */
  int neg = 0;
  uint64_t mag = d;
  uint64_t ep;
  uint64_t em;
  fx_u128_t n;
  unsigned shift = (unsigned)k + 6u; /* 2^(k+1), and Q63 -> Q58 */

  if (d >= (UINT64_C(1) << 63)) {
    neg = 1;
    mag = 0u - d;
  }
  ep = exp_small_q63(mag, neg);     /* e^r  */
  em = exp_small_q63(mag, 1 - neg); /* e^-r */
  n.hi = 0u;
  n.lo = ep;
  if (k != 0u) {
    n = fx_shl_u128(n, 2u * (unsigned)k);
  }
  if (plus != 0) {
    n = fx_add_u128(n, em);
  } else {
    /* e^r 2^(2k) >= e^-r: for k = 0, r = x >= 0 */
    n.hi -= (n.lo < em) ? 1u : 0u;
    n.lo -= em;
  }
  n = fx_shr_u128(fx_add_u128(n, UINT64_C(1) << (shift - 1u)), shift);
  if ((n.hi != 0u) || (n.lo > (uint64_t)INT64_MAX)) {
    return SINH_COSH_OVERFLOW;
  }
  return n.lo;
}

/* *out = sinh(x) (plus == 0) or cosh(x) (plus == 1): one body for the
 * two public entries, which call it as their last step. */
static drdc_status_t sinh_cosh(drdc_q5_58_t x, int plus, drdc_q5_58_t *out)
{
  uint64_t r;

  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if ((x > EXP_ARG_MAX) || (x < -EXP_ARG_MAX)) {
    return DRDC_E_OVERFLOW;
  }
  r = sinh_cosh_mag(fx_abs64(x), plus);
  if (r == SINH_COSH_OVERFLOW) {
    return DRDC_E_OVERFLOW;
  }
  /* sinh is odd, cosh even */
  *out = ((plus == 0) && (x < 0)) ? -(int64_t)r : (int64_t)r;
  return DRDC_OK;
}

drdc_status_t drdc_fx_sinh_q5_58(drdc_q5_58_t x, drdc_q5_58_t *out)
{
  return sinh_cosh(x, 0, out);
}

drdc_status_t drdc_fx_cosh_q5_58(drdc_q5_58_t x, drdc_q5_58_t *out)
{
  return sinh_cosh(x, 1, out);
}

/* atanh(s) in Q62 for |s| <= 0.1716 (magnitude; the sign is the caller's):
 * s + s^3/3 + s^5/5 + ... */
static uint64_t atanh_series_q62(uint64_t s)
{
  uint64_t s2 = fx_mul_shr_round(s, s, 62u);
  uint64_t power = s;
  uint64_t sum = s;
  uint64_t n;

  for (n = 3u; n < 64u; n += 2u) {
    power = fx_mul_shr_round(power, s2, 62u);
    if (power == 0u) {
      break;
    }
    sum += fx_div_u64_small(power + (n >> 1), (uint32_t)n);
  }
  return sum;
}

/* Bit length minus one of v > 0. */
static unsigned top_bit(uint64_t v)
{
  uint64_t rest = v;
  unsigned p = 0;

  while ((rest >> 1) != 0u) {
    rest >>= 1;
    p++;
  }
  return p;
}

/* x 2^62 / d rounded to nearest (ties up), 0 when the quotient does
 * not fit 64 bits, given rcp = drdc_fx_reciprocal_3by2() of d normalised:
 * fx_div_round_u128() of (x 2^62, d) bit for bit. */
static uint64_t div_q62_rcp(uint64_t x, uint64_t d, uint32_t rcp)
{
  unsigned s;
  uint64_t v;
  uint64_t un32;
  uint64_t un10;
  uint64_t r = 0;
  uint64_t quo;

  if ((x >> 2) >= d) {
    return 0; /* quotient >= 2^64 */
  }
  s = (unsigned)__builtin_clzll(d); /* d > x / 4 >= 0 */
  v = d << s;
  if (s == 0u) {
    un32 = x >> 2;
  } else {
    unsigned back = 64u - s;

    un32 = ((x >> 2) << s) | ((x << 62) >> back);
  }
  un10 = (x << 62) << s;
  quo = (uint64_t)drdc_fx_div_3by2((uint32_t)(un32 >> 32), (uint32_t)un32,
                                   (uint32_t)(un10 >> 32), v, rcp, &r)
        << 32;
  quo |= drdc_fx_div_3by2((uint32_t)(r >> 32), (uint32_t)r, (uint32_t)un10, v,
                          rcp, &r);
  r = r >> s;
  if (r >= (d - r)) {
    if (quo == UINT64_MAX) {
      return 0;
    }
    quo++;
  }
  return quo;
}

/* x 2^62 / d as div_q62_rcp(), d > 0, with the reciprocal of d
 * normalised */
static inline uint64_t div_q62(uint64_t x, uint64_t d)
{
  uint64_t v = d << (unsigned)__builtin_clzll(d);

  return div_q62_rcp(x, d,
                     drdc_fx_reciprocal_3by2((uint32_t)(v >> 32), (uint32_t)v));
}

/* ln(num / den) = e ln 2 + 2 atanh(s), for num, den > 0: writes e and
 * s (Q62 magnitude, sign in *s_neg). */
static inline void log_parts(uint64_t num, uint64_t den, int32_t *e,
                             uint64_t *s, int *s_neg)
{
  unsigned pn = top_bit(num);
  unsigned pd = top_bit(den);
  unsigned num_shift = 63u - pn;
  unsigned den_shift = 63u - pd;
  uint64_t m;
  uint64_t diff;

  *e = (int32_t)pn - (int32_t)pd;
  /* m = nn / dn in Q62, in (1/2, 2), both normalised to [2^63, 2^64) */
  m = div_q62(num << num_shift, den << den_shift);
  if (m < SQRTH_Q62) {
    m <<= 1;
    *e -= 1;
  } else if (m >= SQRT2_Q62) {
    m = (m + 1u) >> 1;
    *e += 1;
  } else {
    /* already in [sqrt(1/2), sqrt(2)) */
  }
  *s_neg = m < ONE_Q62;
  diff = *s_neg ? (ONE_Q62 - m) : (m - ONE_Q62);
  *s = div_q62(diff, m + ONE_Q62);
}

/* (e ln 2 + 2 atanh(s)) / 2^half rounded to Q58, given at = atanh(s) in
 * Q62 (half = 1 gives ln(y) / 2, half = 0 gives ln(y)); e >= 0 here. */
static uint64_t log_q58(int32_t e, uint64_t at, int s_neg, unsigned half)
{
  /* e ln 2 in Q64 (128 bits), then Q62: e <= 64 keeps it < 2^68 */
  fx_u128_t acc = fx_mul_u64((uint64_t)e, LN2_Q64);
  uint64_t a = at << 1; /* 2 atanh(s), Q62, < 2^62 */

  acc = fx_shr_u128(acc, 2u); /* Q62 (drops 2^-63 at most) */
  if (s_neg != 0) {
    acc.hi -= (acc.lo < a) ? 1u : 0u;
    acc.lo -= a;
  } else {
    acc = fx_add_u128(acc, a);
  }
  /* to Q58 and halve when asked, rounded once */
  acc = fx_shr_u128(fx_add_u128(acc, UINT64_C(1) << (3u + half)), 4u + half);
  return acc.lo;
}

/* *out = atanh(s) / 16 rounded (Q62 -> Q58), negated when neg != 0:
 * |s| <= 0.1716 in Q62 */
static drdc_status_t series_out(uint64_t s, int neg, drdc_q5_58_t *out)
{
  uint64_t r = (atanh_series_q62(s) + 8u) >> 4;

  *out = (neg != 0) ? -(int64_t)r : (int64_t)r;
  return DRDC_OK;
}

/* *out = atanh(x) (asinh == 0, |x| < 1) or asinh(x) (asinh != 0) by the
 * logarithm: the large-argument branch of each */
static inline drdc_status_t log_out(drdc_q5_58_t x, int asinh,
                                    drdc_q5_58_t *out)
{
  uint64_t ax = fx_abs64(x);
  int32_t e = 0;
  uint64_t s = 0;
  int s_neg = 0;
  uint64_t num;
  uint64_t den;
  unsigned half;
  uint64_t r;

  if (asinh != 0) {
    /* y = |x| + sqrt(x^2 + 1) in Q58, halved so it fits 64 bits */
    uint64_t h = drdc_fx_hypot_s64(x, INT64_C(1) << 58);

    num = (ax >> 1) + (h >> 1) + (ax & h & 1u);
    den = UINT64_C(1) << 57;
    half = 0u;
  } else {
    /* atanh(x) = ln((1 + x) / (1 - x)) / 2, both exact in Q58 */
    num = (UINT64_C(1) << 58) + ax;
    den = (UINT64_C(1) << 58) - ax;
    half = 1u;
  }
  log_parts(num, den, &e, &s, &s_neg);
  r = log_q58(e, atanh_series_q62(s), s_neg, half);
  *out = (x < 0) ? -(int64_t)r : (int64_t)r;
  return DRDC_OK;
}

/* x / sqrt(1 + x^2) in Q62 (magnitude): the atanh argument of asinh(x)
 * for |x| <= 3 - 2 sqrt 2 */
static uint64_t asinh_series_arg(drdc_q5_58_t x)
{
  uint64_t h = drdc_fx_hypot_s64(x, INT64_C(1) << 58); /* Q58 */

  return div_q62(fx_abs64(x), h);
}

drdc_status_t drdc_fx_atanh_q5_58(drdc_q5_58_t x, drdc_q5_58_t *out)
{
  uint64_t ax = fx_abs64(x);

  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if (ax >= (UINT64_C(1) << 58)) {
    return DRDC_E_DOMAIN;
  }
  if (ax <= (uint64_t)ATANH_SERIES_MAX) {
    return series_out(ax << 4, x < 0, out);
  }
  return log_out(x, 0, out);
}

drdc_status_t drdc_fx_asinh_q5_58(drdc_q5_58_t x, drdc_q5_58_t *out)
{
  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if (fx_abs64(x) <= (uint64_t)ATANH_SERIES_MAX) {
    return series_out(asinh_series_arg(x), x < 0, out);
  }
  return log_out(x, 1, out);
}
