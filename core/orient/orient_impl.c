/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_orient
 * @brief Internal helpers of the orientation module (orient_impl.h).
 */
#include "orient_impl.h"

#include <stddef.h>

#include <drdc/fixed_trig.h>

static uint32_t abs32(int32_t x)
{
  return (x < 0) ? (0u - (uint32_t)x) : (uint32_t)x;
}

static uint64_t abs64(int64_t x)
{
  return (x < 0) ? (UINT64_C(0) - (uint64_t)x) : (uint64_t)x;
}

unsigned drdc_orient_impl_headroom(uint64_t v, unsigned limit)
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

drdc_status_t drdc_orient_impl_scale(const drdc_quat_t *q,
                                     orient_scaled_quat_t *out)
{
  const int32_t in[4] = { q->s, q->x, q->y, q->z };
  uint32_t m = 0u;
  unsigned i;
  unsigned shift;
  int64_t n2 = 0;

  for (i = 0u; i < 4u; i++) {
    uint32_t a = abs32(in[i]);
    m = (a > m) ? a : m;
  }
  if (m == 0u) {
    return DRDC_E_DOMAIN;
  }
  if (m > (UINT32_C(1) << 30)) {
    /* Halve, rounded: |c| <= 2^30 afterwards (2^31 -> 2^30). */
    for (i = 0u; i < 4u; i++) {
      out->c[i] = drdc_fx_rshift_round_s32(in[i], 1u);
    }
    out->k = -1;
  } else {
    /* Exact scaling up by 2^shift: largest part into [2^29, 2^30]. */
    shift = (m > (UINT32_C(1) << 29))
                ? 0u
                : (drdc_orient_impl_headroom(m, 31u) - 1u);
    for (i = 0u; i < 4u; i++) {
      out->c[i] = (int32_t)((int64_t)in[i] * orient_pow2_s64(shift));
    }
    out->k = (int32_t)shift;
  }
  for (i = 0u; i < 4u; i++) {
    n2 += (int64_t)out->c[i] * out->c[i]; /* each <= 2^60, sum <= 2^62 */
  }
  out->n2 = n2;
  return DRDC_OK;
}

static int add_ok(int64_t a, int64_t b)
{
  return !(((b > 0) && (a > (INT64_MAX - b)))
           || ((b < 0) && (a < (ORIENT_INT64_MIN - b))));
}

drdc_status_t drdc_orient_impl_sum4(int64_t a, int64_t b, int64_t c,
                                    int64_t d, int64_t *out)
{
  int64_t ab;
  int64_t cd;

  if (!add_ok(a, b) || !add_ok(c, d)) {
    return DRDC_E_OVERFLOW;
  }
  ab = a + b;
  cd = c + d;
  if (!add_ok(ab, cd)) {
    return DRDC_E_OVERFLOW;
  }
  *out = ab + cd;
  return DRDC_OK;
}

void drdc_orient_impl_half_sincos(drdc_bam32_t a, int64_t *s2, int64_t *c2)
{
  /* floor(a / 2) of the signed angle, computed on the unsigned bits: an
   * arithmetic shift by one that keeps the sign bit. */
  drdc_bam32_t h = (a >> 1u) | (a & 0x80000000u);
  drdc_q1_30_t s0;
  drdc_q1_30_t c0;
  drdc_q1_30_t s1;
  drdc_q1_30_t c1;

  drdc_fx_sincos_bam32(h, &s0, &c0);
  if ((a & 1u) == 0u) {
    *s2 = (int64_t)s0 * 2;
    *c2 = (int64_t)c0 * 2;
  } else {
    drdc_fx_sincos_bam32(h + 1u, &s1, &c1);
    *s2 = (int64_t)s0 + s1;
    *c2 = (int64_t)c0 + c1;
  }
}

drdc_status_t drdc_orient_impl_atan2_s64(int64_t y, int64_t x,
                                         drdc_bam32_t *out)
{
  uint64_t m = abs64(y);
  uint64_t mx = abs64(x);
  unsigned n = 0u;

  m = (mx > m) ? mx : m;
  if (m == 0u) {
    return DRDC_E_DOMAIN;
  }
  /* Smallest n with round(m / 2^n) < 2^31. */
  while ((m >> n) >= (UINT64_C(1) << 31)) {
    n++;
  }
  if (n > 0u) {
    unsigned below = n - 1u; /* the rounding bit, just below the cut */

    if (((m >> n) + ((m >> below) & 1u)) >= (UINT64_C(1) << 31)) {
      n++;
    }
  }
  return drdc_fx_atan2_bam32((int32_t)drdc_fx_rshift_round_s64(y, n),
                             (int32_t)drdc_fx_rshift_round_s64(x, n), out);
}
