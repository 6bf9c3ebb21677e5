/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_orient
 * @brief Internal helpers of the orientation module (orient_impl.h).
 */
#include "orient_impl.h"

#include <stddef.h>

#include <drdc/compiler.h>

#include <drdc/fixed_trig.h>

static uint64_t abs64(int64_t x)
{
  return (x < 0) ? (UINT64_C(0) - (uint64_t)x) : (uint64_t)x;
}

/* v 2^n for |v| 2^n <= 2^30, shifted as unsigned (no shift of a signed
 * value) */
static int32_t shl32(int32_t v, unsigned n)
{
  uint32_t u = (uint32_t)v << n;

  return (int32_t)u;
}

/* drdc_fx_rshift_round_s32(v, 1): v / 2 rounded to nearest, ties away
 * from zero (|INT32_MIN| / 2 = 2^30 fits) */
static int32_t halve_part(int32_t v)
{
  uint32_t mag = (orient_abs32(v) + 1u) >> 1;

  return (v < 0) ? -(int32_t)mag : (int32_t)mag;
}

drdc_status_t drdc_orient_impl_scale(const drdc_quat_t *q,
                                     orient_scaled_quat_t *out)
{
  const int32_t s = q->s;
  const int32_t x = q->x;
  const int32_t y = q->y;
  const int32_t z = q->z;
  uint32_t m = orient_abs32(s);
  uint32_t a = orient_abs32(x);
  unsigned shift;

  m = (a > m) ? a : m;
  a = orient_abs32(y);
  m = (a > m) ? a : m;
  a = orient_abs32(z);
  m = (a > m) ? a : m;
  if (m == 0u) {
    return DRDC_E_DOMAIN;
  }
  if (m > (UINT32_C(1) << 30)) {
    /* Halve, rounded: |c| <= 2^30 afterwards (2^31 -> 2^30). */
    out->c[0] = halve_part(s);
    out->c[1] = halve_part(x);
    out->c[2] = halve_part(y);
    out->c[3] = halve_part(z);
    out->k = -1;
  } else {
    /* Exact scaling up by 2^shift: largest part into [2^29, 2^30]; for
     * m <= 2^29 the shift that brings bit 29 to the top, clz(m) - 2. */
    shift = (m > (UINT32_C(1) << 29)) ? 0u : (drdc__clz32(m) - 2u);
    out->c[0] = shl32(s, shift);
    out->c[1] = shl32(x, shift);
    out->c[2] = shl32(y, shift);
    out->c[3] = shl32(z, shift);
    out->k = (int32_t)shift;
  }
  /* each square <= 2^60, the sum <= 2^62 */
  out->n2 = ((int64_t)out->c[0] * out->c[0]) +
            ((int64_t)out->c[1] * out->c[1]) +
            ((int64_t)out->c[2] * out->c[2]) + ((int64_t)out->c[3] * out->c[3]);
  return DRDC_OK;
}

static int add_ok(int64_t a, int64_t b)
{
  return !(((b > 0) && (a > (INT64_MAX - b))) ||
           ((b < 0) && (a < (ORIENT_INT64_MIN - b))));
}

drdc_status_t drdc_orient_impl_sum4(int64_t a, int64_t b, int64_t c, int64_t d,
                                    int64_t *out)
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
  orient_half_t hv;

  orient_half_sincos_mag(a, &hv);
  *s2 = (hv.neg != 0u) ? -(int64_t)hv.s : (int64_t)hv.s;
  *c2 = (int64_t)hv.c;
}

/* round(mag / 2^(k + 1)) for mag / 2^k < 2^32 (to nearest, ties up:
 * the magnitude rounding of drdc_fx_rshift_round_s64()), from the 32-bit
 * t = floor(mag / 2^k): floor((t + 1) / 2) without overflow, with the sign
 * of the value put back. */
static int32_t halve_round(uint64_t mag, unsigned k, int negative)
{
  uint32_t t = (uint32_t)(mag >> k);
  uint32_t r = (t >> 1u) + (t & 1u);

  if (negative != 0) {
    r = 0u - r;
  }
  return (int32_t)r;
}

drdc_status_t drdc_orient_impl_atan2_s64(int64_t y, int64_t x,
                                         drdc_bam32_t *out)
{
  uint64_t my = abs64(y);
  uint64_t mx = abs64(x);
  uint64_t m = (mx > my) ? mx : my;
  unsigned len;
  unsigned k;
  uint32_t t;
  int32_t ys = (int32_t)y;
  int32_t xs = (int32_t)x;

  if (m == 0u) {
    return DRDC_E_DOMAIN;
  }
  /* The smallest n with round(m / 2^n) < 2^31: m >> n < 2^31 from the
   * bit length of m, one more when the rounding carries into bit 31;
   * k = n - 1. Both parts are then rounded by 2^n alike. */
  len = 64u - (unsigned)__builtin_clzll(m);
  if (len > 31u) {
    k = len - 32u;
    t = (uint32_t)(m >> k);
    if (((t >> 1u) + (t & 1u)) >= (UINT32_C(1) << 31)) {
      k++;
    }
    ys = halve_round(my, k, (y < 0) ? 1 : 0);
    xs = halve_round(mx, k, (x < 0) ? 1 : 0);
  }
  return drdc_fx_atan2_bam32(ys, xs, out);
}

void drdc_orient_impl_numerator_row(const int32_t c[4], unsigned i,
                                    int64_t row[3])
{
  const int64_t s = c[0];
  const int64_t x = c[1];
  const int64_t y = c[2];
  const int64_t z = c[3];

  if (i == 0u) {
    row[0] = ((s * s) + (x * x)) - ((y * y) + (z * z));
    row[1] = 2 * ((x * y) - (s * z));
    row[2] = 2 * ((x * z) + (s * y));
  } else if (i == 1u) {
    row[0] = 2 * ((x * y) + (s * z));
    row[1] = ((s * s) + (y * y)) - ((x * x) + (z * z));
    row[2] = 2 * ((y * z) - (s * x));
  } else {
    row[0] = 2 * ((x * z) - (s * y));
    row[1] = 2 * ((y * z) + (s * x));
    row[2] = ((s * s) + (z * z)) - ((x * x) + (y * y));
  }
}
