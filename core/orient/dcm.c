/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_orient
 * @brief Rotation matrices: from and to quaternions, product, transpose,
 *        applied to local and global vectors.
 */
#include <drdc/orient.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>
#include <drdc/fixed_sqrt.h>

#include "orient_impl.h"

drdc_status_t drdc_dcm_from_quat(const drdc_quat_t *q, drdc_dcm_t *out)
{
  orient_scaled_quat_t sq;
  int64_t row[3];
  uint64_t dn;
  unsigned z;
  uint32_t rcp;
  unsigned i;
  unsigned j;
  drdc_status_t st;

  if ((q == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc_orient_impl_scale(q, &sq);
  if (st != DRDC_OK) {
    return st;
  }
  /* n2 in [2^58, 2^62]: normalised by z = 1..5; one reciprocal for the
   * nine divisions p 2^30 / n2 (|p| <= n2: quotients within 2^30) */
  rcp = orient_row_divisor(sq.n2, &dn, &z);
  for (i = 0u; i < 3u; i++) {
    drdc_orient_impl_numerator_row(sq.c, i, row);
    for (j = 0u; j < 3u; j++) {
      uint32_t e = drdc_fx_round_div_shifted(row[j], 30u + z, dn, rcp);

      out->m[i][j] = (drdc_q1_30_t)e;
    }
  }
  return DRDC_OK;
}

drdc_status_t drdc_quat_from_dcm(const drdc_dcm_t *r, drdc_quat_t *out)
{
  const int64_t one = orient_pow2_s64(30u);
  int64_t d[4];
  int64_t num[4];
  int32_t part[4];
  unsigned best = 0u;
  unsigned i;
  uint64_t root;
  drdc_quat_t q;

  if ((r == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  /* 4 s^2, 4 x^2, 4 y^2, 4 z^2 in Q1.30 (each <= 4, int64). */
  d[0] = one + (int64_t)r->m[0][0] + r->m[1][1] + r->m[2][2];
  d[1] = one + (int64_t)r->m[0][0] - r->m[1][1] - r->m[2][2];
  d[2] = one - (int64_t)r->m[0][0] + r->m[1][1] - r->m[2][2];
  d[3] = one - (int64_t)r->m[0][0] - r->m[1][1] + r->m[2][2];
  for (i = 1u; i < 4u; i++) {
    if (d[i] > d[best]) {
      best = i;
    }
  }
  if (d[best] <= 0) {
    return DRDC_E_DOMAIN;
  }
  /* The largest of the four is >= 1 for a rotation, so its root
   * 2 |part| = sqrt(d 2^30) (Q1.30, in [1, 2]) has 31 significant bits.
   * Sums and differences of opposite elements give 4 part * other part. */
  root = drdc_fx_sqrt_u64((uint64_t)d[best] << 30);
  switch (best) {
  case 0u:
    num[0] = d[0];
    num[1] = (int64_t)r->m[2][1] - r->m[1][2];
    num[2] = (int64_t)r->m[0][2] - r->m[2][0];
    num[3] = (int64_t)r->m[1][0] - r->m[0][1];
    break;
  case 1u:
    num[0] = (int64_t)r->m[2][1] - r->m[1][2];
    num[1] = d[1];
    num[2] = (int64_t)r->m[0][1] + r->m[1][0];
    num[3] = (int64_t)r->m[0][2] + r->m[2][0];
    break;
  case 2u:
    num[0] = (int64_t)r->m[0][2] - r->m[2][0];
    num[1] = (int64_t)r->m[0][1] + r->m[1][0];
    num[2] = d[2];
    num[3] = (int64_t)r->m[1][2] + r->m[2][1];
    break;
  default:
    num[0] = (int64_t)r->m[1][0] - r->m[0][1];
    num[1] = (int64_t)r->m[0][2] + r->m[2][0];
    num[2] = (int64_t)r->m[1][2] + r->m[2][1];
    num[3] = d[3];
    break;
  }
  /* part = num / (2 root) in real units: num 2^29 / root in Q1.30,
   * |part| <= 1 + a few LSB for a matrix near a rotation. */
  for (i = 0u; i < 4u; i++) {
    int64_t v;

    (void)drdc_fx_muldiv_s64(num[i], orient_pow2_s64(29u), (int64_t)root, &v);
    if ((v > INT32_MAX) || (v < INT32_MIN)) {
      return DRDC_E_DOMAIN;
    }
    part[i] = (int32_t)v;
  }
  q.s = part[0];
  q.x = part[1];
  q.y = part[2];
  q.z = part[3];
  /* |q|^2 of a rotation is 1 (+ a few LSB): outside [0.5, 2] the matrix
   * is far from a rotation (e.g. the zero matrix gives 0.25). */
  {
    int64_t n2 = 0;

    for (i = 0u; i < 4u; i++) {
      n2 += ((int64_t)part[i] * part[i]) / 4; /* each <= 2^60 */
    }
    if ((n2 < orient_pow2_s64(57u)) || (n2 > orient_pow2_s64(59u))) {
      return DRDC_E_DOMAIN;
    }
  }
  return drdc_quat_normalize(&q, out);
}

drdc_status_t drdc_dcm_mul(const drdc_dcm_t *a, const drdc_dcm_t *b,
                           drdc_dcm_t *out)
{
  drdc_dcm_t r;
  unsigned i;
  unsigned j;
  uint32_t ovf = 0u;

  if ((a == NULL) || (b == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  for (i = 0u; i < 3u; i++) {
    for (j = 0u; j < 3u; j++) {
      /* the exact sum of three products, rounded once (bit 30 or 31 of
       * ovf: it does not fit int64 or the element is outside [-2, 2)) */
      uint32_t e = orient_sum4_round_bits(
          (int64_t)a->m[i][0] * b->m[0][j], (int64_t)a->m[i][1] * b->m[1][j],
          (int64_t)a->m[i][2] * b->m[2][j], 0, &ovf);

      r.m[i][j] = (drdc_q1_30_t)e;
    }
  }
  if ((ovf >> 30u) != 0u) {
    return DRDC_E_OVERFLOW;
  }
  /* element by element: a struct copy becomes a memcpy call on the
   * freestanding PowerPC build */
  for (i = 0u; i < 3u; i++) {
    out->m[i][0] = r.m[i][0];
    out->m[i][1] = r.m[i][1];
    out->m[i][2] = r.m[i][2];
  }
  return DRDC_OK;
}

drdc_status_t drdc_dcm_transpose(const drdc_dcm_t *r, drdc_dcm_t *out)
{
  unsigned i;
  unsigned j;

  if ((r == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  /* Pairwise swaps, so r == out works; element by element, so no
   * memcpy call appears on freestanding targets. */
  for (i = 0u; i < 3u; i++) {
    out->m[i][i] = r->m[i][i];
    for (j = i + 1u; j < 3u; j++) {
      drdc_q1_30_t a = r->m[i][j];
      drdc_q1_30_t b = r->m[j][i];

      out->m[i][j] = b;
      out->m[j][i] = a;
    }
  }
  return DRDC_OK;
}

drdc_status_t drdc_dcm_apply_q15_16(const drdc_dcm_t *r,
                                    const drdc_vec3_q15_16_t *v,
                                    drdc_vec3_q15_16_t *out)
{
  const int32_t in[3] = {(v == NULL) ? 0 : v->x, (v == NULL) ? 0 : v->y,
                         (v == NULL) ? 0 : v->z};
  int32_t res[3];
  unsigned i;

  if ((r == NULL) || (v == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  for (i = 0u; i < 3u; i++) {
    int64_t s;
    int64_t t;
    drdc_status_t st = drdc_orient_impl_sum4(
        (int64_t)r->m[i][0] * in[0], (int64_t)r->m[i][1] * in[1],
        (int64_t)r->m[i][2] * in[2], 0, &s);

    if (st != DRDC_OK) {
      return st;
    }
    t = drdc_fx_rshift_round_s64(s, 30u);
    if ((t > INT32_MAX) || (t < INT32_MIN)) {
      return DRDC_E_OVERFLOW;
    }
    res[i] = (int32_t)t;
  }
  out->x = res[0];
  out->y = res[1];
  out->z = res[2];
  return DRDC_OK;
}

/* Guard bits of the global product: 2^55 2^6 fits with room for 3 terms. */
#define GUARD_BITS 6u

drdc_status_t drdc_dcm_apply_q47_16(const drdc_dcm_t *r,
                                    const drdc_vec3_q47_16_t *v,
                                    drdc_vec3_q47_16_t *out)
{
  const int64_t in[3] = {(v == NULL) ? 0 : v->x, (v == NULL) ? 0 : v->y,
                         (v == NULL) ? 0 : v->z};
  int64_t res[3];
  unsigned i;
  unsigned j;

  if ((r == NULL) || (v == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  for (j = 0u; j < 3u; j++) {
    if ((in[j] > DRDC_ORIENT_Q47_16_MAX) || (in[j] < -DRDC_ORIENT_Q47_16_MAX)) {
      return DRDC_E_RANGE;
    }
  }
  for (i = 0u; i < 3u; i++) {
    int64_t t[3];
    int64_t s;

    for (j = 0u; j < 3u; j++) {
      /* |m| <= 2^31, |v| <= 2^55: |t| = |m v| / 2^24 <= 2^62. */
      t[j] = drdc_fx_mul_rshift_round(r->m[i][j], in[j], 30u - GUARD_BITS);
    }
    /* For |m| <= 1.0 each |t| <= 2^61 and the sum fits; checked anyway
     * for matrices with elements up to 2.0. */
    if (drdc_orient_impl_sum4(t[0], t[1], t[2], 0, &s) != DRDC_OK) {
      return DRDC_E_OVERFLOW;
    }
    res[i] = drdc_fx_rshift_round_s64(s, GUARD_BITS);
  }
  out->x = res[0];
  out->y = res[1];
  out->z = res[2];
  return DRDC_OK;
}
