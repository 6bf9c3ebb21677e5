/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_orient
 * @brief Interpolation of orientations: nlerp, slerp, squad and its
 *        control points.
 *
 * slerp is computed as a * exp(t log(conj(a) * b)): the half angle of the
 * relative rotation comes from atan2(|v|, s) (accurate at small and large
 * angles, no acos), is scaled by t in binary-angle units, and its sine
 * and cosine rebuild the partial rotation about the same axis.
 */
#include <drdc/orient.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>
#include <drdc/fixed_sqrt.h>
#include <drdc/fixed_trig.h>

#include "orient_impl.h"

static int t_ok(drdc_q1_30_t t)
{
  return (t >= 0) && (t <= ORIENT_Q1_30_ONE);
}

static void negate_unit(drdc_quat_t *q)
{
  /* unit parts: |part| <= 2^30, negation is safe */
  q->s = -q->s;
  q->x = -q->x;
  q->y = -q->y;
  q->z = -q->z;
}

/* |v| of a unit quaternion, correctly rounded from the exact sum of
 * squares (<= 2^60). */
static int32_t vec_norm(const drdc_quat_t *q)
{
  return (int32_t)drdc_fx_sqrt_u64(orient_square_u64(q->x)
                                   + orient_square_u64(q->y)
                                   + orient_square_u64(q->z));
}

/* [cos(h), sin(h) v / |v|] for a binary angle h and a non-zero vector v
 * of length vn (Q1.30 parts). */
static void exp_axis(drdc_bam32_t h, const int32_t v[3], int32_t vn,
                     drdc_quat_t *out)
{
  drdc_q1_30_t s;
  drdc_q1_30_t c;

  drdc_fx_sincos_bam32(h, &s, &c);
  /* |v_i| <= vn: each quotient is within [-|s|, |s|]; |s v| <= 2^61 */
  out->s = c;
  out->x = (drdc_q1_30_t)orient_muldiv_round64(s, v[0], vn);
  out->y = (drdc_q1_30_t)orient_muldiv_round64(s, v[1], vn);
  out->z = (drdc_q1_30_t)orient_muldiv_round64(s, v[2], vn);
}

drdc_status_t drdc_quat_nlerp(const drdc_quat_t *a, const drdc_quat_t *b,
                              drdc_q1_30_t t, drdc_quat_t *out)
{
  const int32_t pa[4] = { (a == NULL) ? 0 : a->s, (a == NULL) ? 0 : a->x,
                          (a == NULL) ? 0 : a->y, (a == NULL) ? 0 : a->z };
  const int32_t pb[4] = { (b == NULL) ? 0 : b->s, (b == NULL) ? 0 : b->x,
                          (b == NULL) ? 0 : b->y, (b == NULL) ? 0 : b->z };
  int64_t dot = 0;
  int64_t u = 0;
  int64_t wa;
  int64_t wb;
  drdc_quat_t r;
  int32_t p[4];
  unsigned i;

  if ((a == NULL) || (b == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  if (!t_ok(t)) {
    return DRDC_E_RANGE;
  }
  /* The sign of a . b decides the arc; halved products (<= 2^61 each)
   * cannot overflow the sum of four. */
  for (i = 0u; i < 4u; i++) {
    dot += ((int64_t)pa[i] * pb[i]) / 4;
  }
  wa = (int64_t)ORIENT_Q1_30_ONE - t;
  wb = (dot < 0) ? -(int64_t)t : (int64_t)t;
  /* (1 - t) a + t b in Q60 (<= 2^61 + 2^61), halved to Q1.30 with one
   * extra bit dropped so the sum always fits int32 before normalising. */
  for (i = 0u; i < 4u; i++) {
    u = (wa * pa[i]) + (wb * pb[i]);
    p[i] = (int32_t)drdc_fx_rshift_round_s64(u, 31u);
  }
  r.s = p[0];
  r.x = p[1];
  r.y = p[2];
  r.z = p[3];
  return drdc_quat_normalize(&r, out);
}

static drdc_status_t slerp(const drdc_quat_t *a, const drdc_quat_t *b,
                           drdc_q1_30_t t, int shorter, drdc_quat_t *out)
{
  drdc_quat_t na;
  drdc_quat_t nb;
  drdc_quat_t d;
  drdc_quat_t r;
  int32_t v[3];
  int32_t vn;
  int flip = 0;
  drdc_bam32_t half;
  drdc_bam32_t ht;
  drdc_status_t st;

  st = drdc_quat_normalize(a, &na);
  if (st == DRDC_OK) {
    st = drdc_quat_normalize(b, &nb);
  }
  if (st != DRDC_OK) {
    return st;
  }
  na.x = -na.x; /* conj(a) */
  na.y = -na.y;
  na.z = -na.z;
  (void)drdc_quat_mul(&na, &nb, &d); /* unit operands: no overflow */
  na.x = -na.x;
  na.y = -na.y;
  na.z = -na.z;
  if ((shorter != 0) && (d.s < 0)) {
    negate_unit(&d);
  }
  vn = vec_norm(&d);
  if (vn == 0) {
    /* no rotation between them (or a half turn of the scalar only) */
    if (d.s < 0) {
      flip = 1;
    }
    r.s = ORIENT_Q1_30_ONE;
    r.x = 0;
    r.y = 0;
    r.z = 0;
  } else {
    (void)drdc_fx_atan2_bam32(vn, d.s, &half); /* [0, 2^31] */
    /* t half: half <= 2^31 as unsigned; the product is <= 2^61 */
    ht = (drdc_bam32_t)drdc_fx_rshift_round_s64((int64_t)half * t, 30u);
    v[0] = d.x;
    v[1] = d.y;
    v[2] = d.z;
    exp_axis(ht, v, vn, &r);
  }
  (void)drdc_quat_mul(&na, &r, &d);
  if (flip != 0) {
    negate_unit(&d); /* the scalar-only half turn: a -> -a at t = 1 */
  }
  return drdc_quat_normalize(&d, out);
}

drdc_status_t drdc_quat_slerp(const drdc_quat_t *a, const drdc_quat_t *b,
                              drdc_q1_30_t t, drdc_quat_t *out)
{
  if ((a == NULL) || (b == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  if (!t_ok(t)) {
    return DRDC_E_RANGE;
  }
  return slerp(a, b, t, 1, out);
}

/* log(conj(q1) q) as half-angle times unit axis, in binary-angle units
 * (each part <= 2^30). */
static drdc_status_t log_rel(const drdc_quat_t *q1n, const drdc_quat_t *q,
                             int64_t w[3])
{
  drdc_quat_t c = *q1n;
  drdc_quat_t n;
  drdc_quat_t d;
  drdc_bam32_t half;
  int32_t vn;
  drdc_status_t st = drdc_quat_normalize(q, &n);

  if (st != DRDC_OK) {
    return st;
  }
  c.x = -c.x;
  c.y = -c.y;
  c.z = -c.z;
  (void)drdc_quat_mul(&c, &n, &d);
  if (d.s < 0) {
    negate_unit(&d);
  }
  vn = vec_norm(&d);
  if (vn == 0) {
    w[0] = 0;
    w[1] = 0;
    w[2] = 0;
    return DRDC_OK;
  }
  (void)drdc_fx_atan2_bam32(vn, d.s, &half); /* [0, 2^30] */
  /* half <= 2^30, |d| <= 2^30 + a few: products below 2^61 */
  w[0] = orient_muldiv_round64((int64_t)half, d.x, vn);
  w[1] = orient_muldiv_round64((int64_t)half, d.y, vn);
  w[2] = orient_muldiv_round64((int64_t)half, d.z, vn);
  return DRDC_OK;
}

drdc_status_t drdc_quat_squad_control(const drdc_quat_t *q0,
                                      const drdc_quat_t *q1,
                                      const drdc_quat_t *q2,
                                      drdc_quat_t *out)
{
  drdc_quat_t n1;
  drdc_quat_t e;
  drdc_quat_t r;
  int64_t w0[3];
  int64_t w2[3];
  int32_t v[3];
  uint64_t n2 = 0u;
  unsigned i;
  drdc_status_t st;

  if ((q0 == NULL) || (q1 == NULL) || (q2 == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc_quat_normalize(q1, &n1);
  if (st == DRDC_OK) {
    st = log_rel(&n1, q0, w0);
  }
  if (st == DRDC_OK) {
    st = log_rel(&n1, q2, w2);
  }
  if (st != DRDC_OK) {
    return st;
  }
  /* w = -(w0 + w2) / 4, each part <= 2^29 binary-angle units */
  for (i = 0u; i < 3u; i++) {
    v[i] = (int32_t)-drdc_fx_rshift_round_s64(w0[i] + w2[i], 2u);
    n2 += orient_square_u64(v[i]);
  }
  if (n2 == 0u) {
    *out = n1;
    return DRDC_OK;
  }
  {
    uint64_t ang = drdc_fx_sqrt_u64(n2); /* <= 2^29 sqrt(3) */

    exp_axis((drdc_bam32_t)ang, v, (int32_t)ang, &e);
  }
  (void)drdc_quat_mul(&n1, &e, &r);
  return drdc_quat_normalize(&r, out);
}

drdc_status_t drdc_quat_squad(const drdc_quat_t *q1, const drdc_quat_t *q2,
                              const drdc_quat_t *s1, const drdc_quat_t *s2,
                              drdc_q1_30_t t, drdc_quat_t *out)
{
  drdc_quat_t a;
  drdc_quat_t b;
  drdc_q1_30_t u;
  drdc_status_t st;

  if ((q1 == NULL) || (q2 == NULL) || (s1 == NULL) || (s2 == NULL)
      || (out == NULL)) {
    return DRDC_E_NULL;
  }
  if (!t_ok(t)) {
    return DRDC_E_RANGE;
  }
  st = slerp(q1, q2, t, 1, &a);
  if (st == DRDC_OK) {
    st = slerp(s1, s2, t, 0, &b);
  }
  if (st != DRDC_OK) {
    return st;
  }
  /* 2 t (1 - t) in Q1.30: t (2^30 - t) <= 2^58, result <= 2^29 */
  u = (drdc_q1_30_t)drdc_fx_rshift_round_s64(
      (int64_t)t * ((int64_t)ORIENT_Q1_30_ONE - t), 29u);
  return slerp(&a, &b, u, 0, out);
}
