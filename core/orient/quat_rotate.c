/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_orient
 * @brief Rotation of local (Q15.16) vectors by a quaternion, with the
 *        exact rational matrix of q (never rounded to Q1.30); global
 *        (Q47.16) ones in quat_rotate_q47_16.c.
 */
#include <drdc/orient.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>

#include "orient_impl.h"

/* p v as the high part ph v + hi(pl v) (int64_t) and the low word of
 * pl v, with p = ph 2^32 + pl and pl the low word taken as signed (in
 * [-2^31, 2^31)), so that pl v is one signed 32x32 product. */
static inline int64_t rotate_term(int64_t p, int32_t v, uint64_t *lo)
{
  uint64_t pu = (uint64_t)p;
  int32_t pl = (int32_t)(uint32_t)pu;
  /* (p - pl) / 2^32, exact: the high word plus the sign bit of pl */
  uint32_t hw = (uint32_t)(pu >> 32u);
  uint32_t phu = hw + ((uint32_t)pu >> 31u);
  int32_t ph = (int32_t)phu;
  int64_t t = (int64_t)pl * v;
  uint64_t tu = (uint64_t)t;
  uint32_t th = (uint32_t)(tu >> 32u);
  int32_t high = (int32_t)th; /* the signed high word of pl v */

  *lo += (uint32_t)tu;
  return ((int64_t)ph * v) + high;
}

/*
 * One part of R(q) v for a local vector: round(S / n2) with the exact
 * S = p0 v0 + p1 v1 + p2 v2, held as a 96-bit two's complement
 * a 2^32 + lo: |ph v| <= 2^61 and the high words of pl v (<= 2^30) add up
 * exactly in int64_t, the low words of pl v in a uint64_t (< 3 2^32).
 * A row of p has the length n2 (R(q) is orthogonal) and |v| <= sqrt(3)
 * 2^31 < 2^32, so |S| < n2 2^32: |S| 2^z (z = 1..5, the normalisation of
 * n2) fits three words u2 u1 u0 with u2 2^32 + u1 < dn = n2 2^z, and one
 * quotient word of drdc_fx_div_3by2() is the whole quotient. The remainder
 * rounds it to nearest, ties away from zero.
 * Returns 0, or 1 when the part is outside int32_t.
 */
static int rotate_part_q15_16(const int64_t p[3], const drdc_vec3_q15_16_t *v,
                              uint64_t dn, unsigned z, uint32_t rcp,
                              int32_t *out)
{
  uint64_t lo = 0u;
  int64_t a = rotate_term(p[0], v->x, &lo) + rotate_term(p[1], v->y, &lo) +
              rotate_term(p[2], v->z, &lo);
  uint64_t mag_hi;
  uint32_t mag_lo;
  uint32_t w1;
  uint32_t w0;
  uint32_t u2;
  uint32_t u1;
  uint32_t u0;
  uint64_t r;
  uint64_t quo;
  uint64_t carry = lo >> 32u;
  uint32_t neg = 0u;
  uint32_t low;

  a += (int64_t)carry;
  mag_lo = (uint32_t)lo;
  if (a < 0) {
    neg = 1u;
    /* -(a 2^32 + lo) = (-a - [lo != 0]) 2^32 + (2^32 - lo) */
    mag_hi = (0u - (uint64_t)a) - ((mag_lo != 0u) ? 1u : 0u);
    mag_lo = 0u - mag_lo;
  } else {
    mag_hi = (uint64_t)a;
  }
  /* the magnitude times 2^z, 0 < z < 32, word by word */
  w1 = (uint32_t)(mag_hi >> 32u);
  w0 = (uint32_t)mag_hi;
  u2 = (w1 << z) | (w0 >> (32u - z));
  u1 = (w0 << z) | (mag_lo >> (32u - z));
  u0 = mag_lo << z;
  quo = drdc_fx_div_3by2(u2, u1, u0, dn, rcp, &r);
  if (r >= (dn - r)) {
    quo++; /* remainder >= half of the divisor: away from zero */
  }
  if (quo > ((uint64_t)INT32_MAX + neg)) {
    return 1;
  }
  low = (uint32_t)quo;
  if (neg != 0u) {
    low = 0u - low;
  }
  *out = (int32_t)low;
  return 0;
}

drdc_status_t drdc_quat_rotate_q15_16(const drdc_quat_t *q,
                                      const drdc_vec3_q15_16_t *v,
                                      drdc_vec3_q15_16_t *out)
{
  orient_scaled_quat_t sq;
  int64_t row[3];
  int32_t res[3];
  uint64_t dn;
  unsigned z;
  uint32_t rcp;
  unsigned i;
  drdc_status_t st;

  if ((q == NULL) || (v == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc_orient_impl_scale(q, &sq);
  if (st != DRDC_OK) {
    return st;
  }
  /* n2 in [2^58, 2^62] normalised, its reciprocal */
  rcp = orient_row_divisor(sq.n2, &dn, &z);
  for (i = 0u; i < 3u; i++) {
    drdc_orient_impl_numerator_row(sq.c, i, row);
    if (rotate_part_q15_16(row, v, dn, z, rcp, &res[i]) != 0) {
      return DRDC_E_OVERFLOW;
    }
  }
  out->x = res[0];
  out->y = res[1];
  out->z = res[2];
  return DRDC_OK;
}
