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
  return (int32_t)drdc_fx_sqrt_u64(orient_square_u64(q->x) +
                                   orient_square_u64(q->y) +
                                   orient_square_u64(q->z));
}

/* [cos(h), sin(h) v / |v|] for a binary angle h and the non-zero vector
 * part v of *vq (its scalar part unused) of length vn (Q1.30 parts). */
static void exp_axis(drdc_bam32_t h, const drdc_quat_t *vq, int32_t vn,
                     drdc_quat_t *out)
{
  drdc_q1_30_t s;
  drdc_q1_30_t c;

  drdc_fx_sincos_bam32(h, &s, &c);
  /* |v_i| <= vn: each quotient is within [-|s|, |s|]; |s v| <= 2^61 */
  out->x = (drdc_q1_30_t)drdc_fx_muldiv_round64(s, vq->x, vn);
  out->y = (drdc_q1_30_t)drdc_fx_muldiv_round64(s, vq->y, vn);
  out->z = (drdc_q1_30_t)drdc_fx_muldiv_round64(s, vq->z, vn);
  out->s = c;
}

drdc_status_t drdc_quat_nlerp(const drdc_quat_t *a, const drdc_quat_t *b,
                              drdc_q1_30_t t, drdc_quat_t *out)
{
  const int32_t pa[4] = {(a == NULL) ? 0 : a->s, (a == NULL) ? 0 : a->x,
                         (a == NULL) ? 0 : a->y, (a == NULL) ? 0 : a->z};
  const int32_t pb[4] = {(b == NULL) ? 0 : b->s, (b == NULL) ? 0 : b->x,
                         (b == NULL) ? 0 : b->y, (b == NULL) ? 0 : b->z};
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

/* The slerp of the key frames a and b at t, along the shorter arc when
 * shorter is non-zero: a d^t with d = conj(a) b, both made unit first. */
static drdc_status_t slerp(const drdc_quat_t *a, const drdc_quat_t *b,
                           drdc_q1_30_t t, int shorter, drdc_quat_t *out)
{
  drdc_quat_t na;
  drdc_quat_t nb;
  drdc_quat_t conj_a;
  drdc_quat_t d;    /* the relative rotation conj(a) b */
  drdc_quat_t pow;  /* d^t */
  drdc_quat_t prod; /* a d^t */
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
  conj_a.s = na.s; /* unit parts: the negations are exact */
  conj_a.x = -na.x;
  conj_a.y = -na.y;
  conj_a.z = -na.z;
  (void)drdc_quat_mul(&conj_a, &nb, &d); /* unit operands: no overflow */
  if ((shorter != 0) && (d.s < 0)) {
    negate_unit(&d);
  }
  vn = vec_norm(&d);
  if (vn == 0) {
    /* no rotation between them (or a half turn of the scalar only) */
    if (d.s < 0) {
      flip = 1;
    }
    pow.s = ORIENT_Q1_30_ONE;
    pow.x = 0;
    pow.y = 0;
    pow.z = 0;
  } else {
    (void)drdc_fx_atan2_bam32(vn, d.s, &half); /* [0, 2^31] */
    /* t half: half <= 2^31 as unsigned; the product is <= 2^61 */
    ht = (drdc_bam32_t)drdc_fx_rshift_round_s64((int64_t)half * t, 30u);
    exp_axis(ht, &d, vn, &pow);
  }
  (void)drdc_quat_mul(&na, &pow, &prod);
  if (flip != 0) {
    negate_unit(&prod); /* the scalar-only half turn: a -> -a at t = 1 */
  }
  return drdc_quat_normalize(&prod, out);
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

/* log(c q) for c = conj(q1) (unit), as half-angle times unit axis in
 * binary-angle units (each part <= 2^30) in w->x, w->y, w->z (w->s
 * unused); w is written only on success. */
static drdc_status_t log_rel(const drdc_quat_t *c, const drdc_quat_t *q,
                             drdc_quat_t *w)
{
  drdc_quat_t nq;
  drdc_quat_t d; /* c q / |q| */
  drdc_bam32_t half;
  int32_t vn;
  drdc_status_t st = drdc_quat_normalize(q, &nq);

  if (st != DRDC_OK) {
    return st;
  }
  (void)drdc_quat_mul(c, &nq, &d);
  if (d.s < 0) {
    negate_unit(&d);
  }
  vn = vec_norm(&d);
  if (vn == 0) {
    w->x = 0;
    w->y = 0;
    w->z = 0;
    return DRDC_OK;
  }
  (void)drdc_fx_atan2_bam32(vn, d.s, &half); /* [0, 2^30] */
  /* half <= 2^30, |d| <= 2^30 + a few: products below 2^61, quotients
   * within [-half, half] */
  w->x = (int32_t)drdc_fx_muldiv_round64((int64_t)half, d.x, vn);
  w->y = (int32_t)drdc_fx_muldiv_round64((int64_t)half, d.y, vn);
  w->z = (int32_t)drdc_fx_muldiv_round64((int64_t)half, d.z, vn);
  return DRDC_OK;
}

/* -(a + b) / 4 rounded, for |a|, |b| <= 2^30 */
static int32_t quarter_sum(int32_t a, int32_t b)
{
  return (int32_t)-drdc_fx_rshift_round_s64((int64_t)a + b, 2u);
}

drdc_status_t drdc_quat_squad_control(const drdc_quat_t *q0,
                                      const drdc_quat_t *q1,
                                      const drdc_quat_t *q2, drdc_quat_t *out)
{
  drdc_quat_t n1;
  drdc_quat_t c;    /* conj(q1 / |q1|) */
  drdc_quat_t w0;   /* log(c q0) */
  drdc_quat_t w2;   /* log(c q2) */
  drdc_quat_t w;    /* -(w0 + w2) / 4 */
  drdc_quat_t ew;   /* exp(w) */
  drdc_quat_t prod; /* q1 exp(w) */
  uint64_t n2;
  uint64_t ang;
  drdc_status_t st;

  if ((q0 == NULL) || (q1 == NULL) || (q2 == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc_quat_normalize(q1, &n1);
  if (st != DRDC_OK) {
    return st;
  }
  c.s = n1.s; /* unit parts: the negations are exact */
  c.x = -n1.x;
  c.y = -n1.y;
  c.z = -n1.z;
  st = log_rel(&c, q0, &w0);
  if (st == DRDC_OK) {
    st = log_rel(&c, q2, &w2);
  }
  if (st != DRDC_OK) {
    return st;
  }
  /* w = -(w0 + w2) / 4, each part <= 2^29 binary-angle units */
  w.s = 0;
  w.x = quarter_sum(w0.x, w2.x);
  w.y = quarter_sum(w0.y, w2.y);
  w.z = quarter_sum(w0.z, w2.z);
  n2 = orient_square_u64(w.x) + orient_square_u64(w.y) + orient_square_u64(w.z);
  if (n2 == 0u) {
    *out = n1;
    return DRDC_OK;
  }
  ang = drdc_fx_sqrt_u64(n2); /* <= 2^29 sqrt(3) */
  exp_axis((drdc_bam32_t)ang, &w, (int32_t)ang, &ew);
  (void)drdc_quat_mul(&n1, &ew, &prod);
  return drdc_quat_normalize(&prod, out);
}

drdc_status_t drdc_quat_squad(const drdc_quat_t *q1, const drdc_quat_t *q2,
                              const drdc_quat_t *s1, const drdc_quat_t *s2,
                              drdc_q1_30_t t, drdc_quat_t *out)
{
  drdc_quat_t ctrl; /* slerp(s1, s2, t) */
  drdc_quat_t keys; /* slerp(q1, q2, t) */
  drdc_q1_30_t u;
  drdc_status_t st;

  if ((q1 == NULL) || (q2 == NULL) || (s1 == NULL) || (s2 == NULL) ||
      (out == NULL)) {
    return DRDC_E_NULL;
  }
  if (!t_ok(t)) {
    return DRDC_E_RANGE;
  }
  /* Either slerp can fail only with DRDC_E_DOMAIN (a zero quaternion),
   * so their order does not change the status; out is written only when
   * both succeeded. */
  st = slerp(s1, s2, t, 0, &ctrl);
  if (st == DRDC_OK) {
    st = slerp(q1, q2, t, 1, &keys);
  }
  if (st != DRDC_OK) {
    return st;
  }
  /* 2 t (1 - t) in Q1.30: t (2^30 - t) <= 2^58, result <= 2^29 */
  u = (drdc_q1_30_t)drdc_fx_rshift_round_s64(
      (int64_t)t * ((int64_t)ORIENT_Q1_30_ONE - t), 29u);
  return slerp(&keys, &ctrl, u, 0, out);
}
