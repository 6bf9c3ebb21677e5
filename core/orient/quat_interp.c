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

/* Sign (-1, 0, 1) of the exact dot product a . b of any int32 parts.
 * Each product is split as 4 q + r (|r| <= 3): the sum of the q is
 * within 2^62 and the r add at most 12, folded back into q so that the
 * remainder alone (|r| <= 3) cannot outweigh a non-zero q. */
static int dot_sign(const drdc_quat_t *a, const drdc_quat_t *b)
{
  const int64_t p[4] = {(int64_t)a->s * b->s, (int64_t)a->x * b->x,
                        (int64_t)a->y * b->y, (int64_t)a->z * b->z};
  int64_t hi = 0;
  int64_t lo = 0;
  unsigned i;

  for (i = 0u; i < 4u; i++) {
    hi += p[i] / 4;
    lo += p[i] % 4;
  }
  hi += lo / 4;
  lo = lo % 4;
  if (hi == 0) {
    hi = lo;
  }
  return (hi < 0) ? -1 : ((hi > 0) ? 1 : 0);
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
  int64_t u[4];
  uint64_t m = 0u;
  int64_t wa;
  int64_t wb;
  drdc_quat_t r;
  uint64_t v;
  unsigned sh = 0u;
  unsigned step;
  unsigned i;

  if ((a == NULL) || (b == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  if (!t_ok(t)) {
    return DRDC_E_RANGE;
  }
  wa = (int64_t)ORIENT_Q1_30_ONE - t;
  wb = (dot_sign(a, b) < 0) ? -(int64_t)t : (int64_t)t;
  /* (1 - t) a + t b' exactly: |w| <= 2^30 and |part| <= 2^31, so each
   * sum is within 2^62. */
  u[0] = (wa * a->s) + (wb * b->s);
  u[1] = (wa * a->x) + (wb * b->x);
  u[2] = (wa * a->y) + (wb * b->y);
  u[3] = (wa * a->z) + (wb * b->z);
  for (i = 0u; i < 4u; i++) {
    const uint64_t mag = (u[i] < 0) ? (0u - (uint64_t)u[i]) : (uint64_t)u[i];
    m = (mag > m) ? mag : m;
  }
  /* One common shift brings the largest part to at most 2^30 (and above
   * 2^29 whenever a shift is needed), so that short inputs keep their
   * direction to 2^-30 before normalising instead of losing it to a
   * fixed Q60 -> Q1.30 step. */
  v = (m > 0u) ? ((m - 1u) >> 30) : 0u; /* sh = bit length of v */
  for (step = 32u; step > 0u; step /= 2u) {
    if ((v >> step) != 0u) {
      v >>= step;
      sh += step;
    }
  }
  sh += (unsigned)v;
  r.s = (int32_t)drdc_fx_rshift_round_s64(u[0], sh);
  r.x = (int32_t)drdc_fx_rshift_round_s64(u[1], sh);
  r.y = (int32_t)drdc_fx_rshift_round_s64(u[2], sh);
  r.z = (int32_t)drdc_fx_rshift_round_s64(u[3], sh);
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
  /* The arc follows the exact a . b, not the rounded scalar of d: near
   * a quarter turn apart the two can differ in sign. */
  if ((shorter != 0) && (dot_sign(a, b) < 0)) {
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
