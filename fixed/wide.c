/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_wide
 * @brief Out-of-line wide-integer primitives (fixed_wide.h): the 3/2
 *        reciprocal, the 128/64 division, the exact 62-bit hypot and the
 *        headroom of a 64-bit value.
 */
#include <drdc/fixed_wide.h>

#include <drdc/fixed_sqrt.h>

#include "fixed_impl.h"

uint32_t drdc_fx_reciprocal_3by2(uint32_t d1, uint32_t d0)
{
  uint32_t v = drdc_fx_reciprocal_2by1(d1);
  uint32_t p = d1 * v;
  uint64_t t;
  uint32_t t1;
  uint32_t t0;

  p += d0;
  if (p < d0) {
    v--;
    if (p >= d1) {
      v--;
      p -= d1;
    }
    p -= d1;
  }
  t = (uint64_t)v * d0;
  t1 = (uint32_t)(t >> 32u);
  t0 = (uint32_t)t;
  p += t1;
  if (p < t1) {
    v--;
    if ((p > d1) || ((p == d1) && (t0 >= d0))) {
      v--;
    }
  }
  return v;
}

/* the body of drdc_fx_div_128_64(), inline in drdc_fx_hypot62()'s
 * Newton steps (no call per step) */
static inline uint64_t div_128_64(uint64_t nh, uint64_t nl, uint64_t x)
{
  unsigned z = (unsigned)__builtin_clzll(x);
  uint64_t dn = x << z;
  uint32_t rcp = drdc_fx_reciprocal_3by2((uint32_t)(dn >> 32u), (uint32_t)dn);
  uint64_t uh = nh;
  uint64_t ul = nl;
  uint64_t r;
  uint32_t q1;
  uint32_t q0;

  if (z != 0u) {
    unsigned zr = 64u - z;

    uh = (nh << z) | (nl >> zr); /* N 2^z < x 2^z 2^64 < 2^128 */
    ul = nl << z;
  }
  q1 = drdc_fx_div_3by2((uint32_t)(uh >> 32u), (uint32_t)uh,
                        (uint32_t)(ul >> 32u), dn, rcp, &r);
  q0 = drdc_fx_div_3by2((uint32_t)(r >> 32u), (uint32_t)r, (uint32_t)ul, dn,
                        rcp, &r);
  return ((uint64_t)q1 << 32u) | q0;
}

uint64_t drdc_fx_div_128_64(uint64_t nh, uint64_t nl, uint64_t x)
{
  return div_128_64(nh, nl, x);
}

/* floor(sqrt(t)) for t >= 2^30: integer Newton steps from the tangent of
 * sqrt at 2^30, (t >> 16) + 2^14, which lies above the root; the steps
 * decrease to the floor of the root and stop there. */
static uint32_t isqrt32_big(uint32_t t)
{
  uint32_t g = (t >> 16u) + 16384u;
  uint32_t n = (g + (t / g)) >> 1u;

  while (n < g) {
    g = n;
    n = (g + (t / g)) >> 1u;
  }
  return g;
}

uint64_t drdc_fx_hypot62(int64_t x, int64_t y)
{
  uint64_t ax = fx_abs64(x);
  uint64_t ay = fx_abs64(y);
  uint64_t xh;
  uint64_t xl;
  uint64_t yh;
  uint64_t yl;
  uint64_t nh;
  uint64_t nl;
  uint64_t sh;
  uint64_t sl;
  uint64_t root;
  unsigned len;
  unsigned e;
  unsigned i;
  uint32_t t;

  drdc_fx_mul_u64_u128(ax, ax, &xh, &xl);
  drdc_fx_mul_u64_u128(ay, ay, &yh, &yl);
  nl = xl + yl;
  nh = xh + yh + ((nl < xl) ? 1u : 0u); /* N = x^2 + y^2 <= 2^125 */
  if (nh == 0u) {
    return drdc_fx_sqrt_u64(nl); /* the same rounding */
  }
  /* t = N / 2^e in [2^30, 2^32) with e even; then (isqrt(t) + 1) 2^(e/2)
   * is above sqrt(N) by a relative 2^-15 at most */
  len = 128u - (unsigned)__builtin_clzll(nh); /* 65..126 */
  e = (len - 31u) & ~1u;
  if (e >= 64u) {
    unsigned sr = e - 64u;

    t = (uint32_t)(nh >> sr);
  } else {
    unsigned sl64 = 64u - e;
    uint64_t w = (nh << sl64) | (nl >> e);

    t = (uint32_t)w;
  }
  root = (uint64_t)isqrt32_big(t) + 1u;
  e /= 2u;
  root <<= e;
  /* Two Newton steps from above: relative errors 2^-15, 2^-31, 2^-63;
   * each stays >= floor(sqrt(N)) and the second is at most 2 above it
   * (sqrt(N) < 2^63). */
  for (i = 0u; i < 2u; i++) {
    root = (root + div_128_64(nh, nl, root)) >> 1u;
  }
  drdc_fx_mul_u64_u128(root, root, &sh, &sl);
  while ((sh > nh) || ((sh == nh) && (sl > nl))) {
    root--;
    drdc_fx_mul_u64_u128(root, root, &sh, &sl);
  }
  /* remainder N - root^2 (< 2^65): up when it exceeds root */
  sh = (nh - sh) - ((nl < sl) ? 1u : 0u);
  sl = nl - sl;
  return ((sh != 0u) || (sl > root)) ? (root + 1u) : root;
}

unsigned drdc_fx_headroom(uint64_t v, unsigned limit)
{
  uint64_t w = v;
  unsigned top;
  unsigned s = 0u;

  if ((v == 0u) || (limit == 0u) || (limit > 64u)) {
    return 0u;
  }
  top = limit - 1u;
  /* w < 2^(limit - 1): one more doubling still stays below 2^limit */
  while (((w >> top) == 0u) && (s < limit)) {
    w <<= 1u;
    s++;
  }
  return s;
}
