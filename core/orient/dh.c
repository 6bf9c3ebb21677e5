/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_kinematics
 * @brief Denavit-Hartenberg link transforms (standard and modified) and
 *        forward kinematics.
 *
 * Internal formats of the chain product: rotation elements in Q2.61
 * (int64, |r| <= 1 + small, sums of three <= 1.5 2^62), translations in
 * Q17.46 metres (int64; every partial translation is held to the
 * Q15.16 range, +-32 km, so that the chain fails where composing its
 * links one by one would). A link's elements are exact products
 * of two Q1.30 trig values (Q60) and of a Q15.16 length with a Q1.30
 * value (Q46), so the only roundings are those of the trig values and
 * one per element per link (2^-61 and 2^-46 m: negligible).
 */
#include <drdc/orient_kinematics.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>
#include <drdc/fixed_trig.h>

#include "orient_impl.h"

/* v 2^30 without shifting a signed value. */
static int64_t scale30(int64_t v)
{
  return v * orient_pow2_s64(30u);
}

/* One link reduced to its sines and cosines and lengths; its rotation
 * (exact Q60) and translation (exact Q46) elements are formed on demand
 * by link_r() and link_t(), so that no 3x3 int64 matrix of the link sits
 * on the stack. */
typedef struct link_trig {
  drdc_q1_30_t st; /**< sin(theta + q) (or of theta) */
  drdc_q1_30_t ct; /**< cos(theta + q) */
  drdc_q1_30_t sa; /**< sin(alpha) */
  drdc_q1_30_t ca; /**< cos(alpha) */
  int32_t a;       /**< link length, Q15.16 */
  int32_t d;       /**< link offset (plus q if prismatic), Q15.16 */
} link_trig_t;

static inline drdc_status_t link_trig(drdc_dh_convention_t convention,
                                      const drdc_dh_link_t *link, int32_t q,
                                      link_trig_t *out)
{
  drdc_bam32_t theta = link->theta;
  int64_t d = link->d;

  if (link->type == DRDC_JOINT_REVOLUTE) {
    theta += (drdc_bam32_t)q; /* modulo a turn */
  } else if (link->type == DRDC_JOINT_PRISMATIC) {
    d += q;
    if ((d > INT32_MAX) || (d < INT32_MIN)) {
      return DRDC_E_OVERFLOW;
    }
  } else {
    return DRDC_E_RANGE;
  }
  if ((convention != DRDC_DH_STANDARD) && (convention != DRDC_DH_MODIFIED)) {
    return DRDC_E_RANGE;
  }
  drdc_fx_sincos_bam32(theta, &out->st, &out->ct);
  drdc_fx_sincos_bam32(link->alpha, &out->sa, &out->ca);
  out->a = link->a;
  out->d = (int32_t)d;
  return DRDC_OK;
}

/* Element (i, j) of the link rotation, exact Q60. */
static int64_t link_r(drdc_dh_convention_t convention, const link_trig_t *g,
                      unsigned i, unsigned j)
{
  const unsigned k = (3u * i) + j;
  int64_t v;

  if (convention == DRDC_DH_STANDARD) {
    switch (k) {
    case 0u:
      v = scale30(g->ct);
      break;
    case 1u:
      v = -((int64_t)g->st * g->ca);
      break;
    case 2u:
      v = (int64_t)g->st * g->sa;
      break;
    case 3u:
      v = scale30(g->st);
      break;
    case 4u:
      v = (int64_t)g->ct * g->ca;
      break;
    case 5u:
      v = -((int64_t)g->ct * g->sa);
      break;
    case 6u:
      v = 0;
      break;
    case 7u:
      v = scale30(g->sa);
      break;
    default:
      v = scale30(g->ca);
      break;
    }
  } else {
    switch (k) {
    case 0u:
      v = scale30(g->ct);
      break;
    case 1u:
      v = -(scale30(g->st));
      break;
    case 2u:
      v = 0;
      break;
    case 3u:
      v = (int64_t)g->st * g->ca;
      break;
    case 4u:
      v = (int64_t)g->ct * g->ca;
      break;
    case 5u:
      v = -(scale30(g->sa));
      break;
    case 6u:
      v = (int64_t)g->st * g->sa;
      break;
    case 7u:
      v = (int64_t)g->ct * g->sa;
      break;
    default:
      v = scale30(g->ca);
      break;
    }
  }
  return v;
}

/* Part i of the link translation, exact Q46. */
static int64_t link_t(drdc_dh_convention_t convention, const link_trig_t *g,
                      unsigned i)
{
  int64_t v;

  if (convention == DRDC_DH_STANDARD) {
    if (i == 0u) {
      v = (int64_t)g->a * g->ct;
    } else if (i == 1u) {
      v = (int64_t)g->a * g->st;
    } else {
      v = scale30(g->d);
    }
  } else {
    if (i == 0u) {
      v = scale30(g->a);
    } else if (i == 1u) {
      v = -((int64_t)g->d * g->sa);
    } else {
      v = (int64_t)g->d * g->ca;
    }
  }
  return v;
}

/* Q60 or Q46 -> Q1.30 / Q15.16 with the range check of the result. */
static drdc_status_t round30(int64_t v, int32_t *out)
{
  int64_t r = drdc_fx_rshift_round_s64(v, 30u);

  if ((r > INT32_MAX) || (r < INT32_MIN)) {
    return DRDC_E_OVERFLOW;
  }
  *out = (int32_t)r;
  return DRDC_OK;
}

drdc_status_t drdc_dh_link_transform(drdc_dh_convention_t convention,
                                     const drdc_dh_link_t *link, int32_t q,
                                     drdc_transform_t *out)
{
  link_trig_t g;
  int32_t t[3];
  unsigned i;
  unsigned j;
  drdc_status_t st;

  if ((link == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = link_trig(convention, link, q, &g);
  for (i = 0u; (i < 3u) && (st == DRDC_OK); i++) {
    st = round30(link_t(convention, &g, i), &t[i]);
  }
  if (st != DRDC_OK) {
    return st; /* out unchanged: only the translation can overflow */
  }
  for (i = 0u; i < 3u; i++) {
    for (j = 0u; j < 3u; j++) {
      /* |r| <= 2^60: cannot overflow */
      (void)round30(link_r(convention, &g, i, j), &out->r.m[i][j]);
    }
  }
  out->t.x = t[0];
  out->t.y = t[1];
  out->t.z = t[2];
  return DRDC_OK;
}

/* round(a b / 2^n), correctly rounded from the exact 128-bit product. */
static int64_t mul_round(int64_t a, int64_t b, unsigned n)
{
  return drdc_fx_mul_rshift_round(a, b, n);
}

/* Q2.61 value times a Q60 one, as Q2.61: one correct rounding (128-bit
 * product); |result| <= |a| when |b| <= 2^60. */
static int64_t mul61(int64_t a, int64_t b)
{
  return mul_round(a, b, 60u);
}

/* The chain of drdc_dh_forward() as dh_row() reads it. */
typedef struct dh_chain {
  const drdc_dh_link_t *links;     /**< the links */
  const int32_t *q;                /**< their joint variables */
  unsigned n;                      /**< links to go through */
  drdc_dh_convention_t convention; /**< standard or modified */
  drdc_status_t bad;               /**< status of link n's parameters, or OK */
} dh_chain_t;

/* Row i of the chain's rotation (Q2.61) and translation (Q46) through
 * links 0..c->n - 1. Row i of each product depends only on row i of the
 * one before (R' = R R_link, t' = R t_link + t), so each row is carried
 * through the chain on its own with the link's elements formed on
 * demand: four int64 of state instead of the whole 3x3 matrix and
 * translation. The link's sines and cosines are computed once per row
 * (three times per link).
 * Bad parameters of link k: c->n becomes k, c->bad their status, and
 * that status is returned (nothing written); the rows after stop at k.
 * Otherwise writes the rounded rotation row to row[0..2] (Q1.30) and,
 * when no link was bad, the translation to *t (Q15.16).
 * @retval DRDC_OK written
 * @retval DRDC_E_OVERFLOW a partial translation through links 0..k
 *         (k < c->n) rounds outside Q15.16 */
static inline drdc_status_t dh_row(dh_chain_t *c, unsigned i,
                                   drdc_q1_30_t row[3], int32_t *t)
{
  const int64_t one = orient_pow2_s64(61u);
  int64_t r0 = (i == 0u) ? one : 0;
  int64_t r1 = (i == 1u) ? one : 0;
  int64_t r2 = (i == 2u) ? one : 0;
  int64_t ti = 0;
  int32_t tk; /* the partial translation in Q15.16: range check only */
  link_trig_t g;
  unsigned k;
  drdc_status_t st;

  for (k = 0u; k < c->n; k++) {
    const drdc_dh_convention_t cv = c->convention;
    int64_t n0;
    int64_t n1;
    int64_t n2;

    st = link_trig(cv, &c->links[k], c->q[k], &g);
    if (st != DRDC_OK) {
      c->n = k;
      c->bad = st;
      return st;
    }
    /* t += R t_link: Q61 x Q46 / 2^61 -> Q46, correctly rounded each;
     * |R t_link| <= 1.01 |t_link| <= 2^62. Each partial translation
     * T1 ... Tk must round into Q15.16, the rule of composing the links
     * one by one with drdc_transform_compose(); it also keeps |ti| below
     * 2^61 for the next link. */
    if ((drdc_orient_impl_sum4(mul_round(r0, link_t(cv, &g, 0u), 61u),
                               mul_round(r1, link_t(cv, &g, 1u), 61u),
                               mul_round(r2, link_t(cv, &g, 2u), 61u), ti,
                               &ti) != DRDC_OK) ||
        (round30(ti, &tk) != DRDC_OK)) {
      return DRDC_E_OVERFLOW;
    }
    n0 = mul61(r0, link_r(cv, &g, 0u, 0u)) + mul61(r1, link_r(cv, &g, 1u, 0u)) +
         mul61(r2, link_r(cv, &g, 2u, 0u));
    n1 = mul61(r0, link_r(cv, &g, 0u, 1u)) + mul61(r1, link_r(cv, &g, 1u, 1u)) +
         mul61(r2, link_r(cv, &g, 2u, 1u));
    n2 = mul61(r0, link_r(cv, &g, 0u, 2u)) + mul61(r1, link_r(cv, &g, 1u, 2u)) +
         mul61(r2, link_r(cv, &g, 2u, 2u));
    r0 = n0;
    r1 = n1;
    r2 = n2;
  }
  st = (c->bad == DRDC_OK) ? round30(ti, t) : DRDC_OK;
  if (st == DRDC_OK) {
    row[0] = (drdc_q1_30_t)drdc_fx_rshift_round_s64(r0, 31u);
    row[1] = (drdc_q1_30_t)drdc_fx_rshift_round_s64(r1, 31u);
    row[2] = (drdc_q1_30_t)drdc_fx_rshift_round_s64(r2, 31u);
  }
  return st;
}

drdc_status_t drdc_dh_forward(drdc_dh_convention_t convention,
                              const drdc_dh_link_t *links, unsigned n,
                              const int32_t *q, drdc_transform_t *out)
{
  drdc_q1_30_t m[2][3]; /* rows 0 and 1 until the last row succeeds */
  int32_t t[2];         /* their translations */
  drdc_q1_30_t row2[3]; /* row 2 after a bad link: only its status used */
  int32_t t2;
  dh_chain_t c;
  drdc_status_t st;

  if ((out == NULL) || ((n > 0u) && ((links == NULL) || (q == NULL)))) {
    return DRDC_E_NULL;
  }
  if (n > (unsigned)DRDC_DH_MAX_LINKS) {
    return DRDC_E_RANGE;
  }
  if ((convention != DRDC_DH_STANDARD) && (convention != DRDC_DH_MODIFIED)) {
    return DRDC_E_RANGE;
  }
  c.links = links;
  c.q = q;
  c.n = n;
  c.convention = convention;
  c.bad = DRDC_OK;
  /* The statuses of the link-by-link product, in its order: a
   * translation overflowing at link k, in any row, comes before the bad
   * parameters of a later link (the first row finds them, the others
   * stop there), and both before the final range check of the
   * translation. Every overflow is DRDC_E_OVERFLOW: the first found
   * decides. */
  st = dh_row(&c, 0u, m[0], &t[0]);
  if (st != DRDC_E_OVERFLOW) {
    st = dh_row(&c, 1u, m[1], &t[1]);
  }
  if ((st != DRDC_E_OVERFLOW) && (c.bad != DRDC_OK)) {
    st = dh_row(&c, 2u, row2, &t2); /* its overflow status only */
    if (st == DRDC_OK) {
      st = c.bad;
    }
  } else if (st != DRDC_E_OVERFLOW) {
    /* No error left but this row's: it writes out only on success. */
    st = dh_row(&c, 2u, out->r.m[2], &out->t.z);
  } else {
    /* overflow: decided */
  }
  if (st != DRDC_OK) {
    return st;
  }
  out->r.m[0][0] = m[0][0];
  out->r.m[0][1] = m[0][1];
  out->r.m[0][2] = m[0][2];
  out->r.m[1][0] = m[1][0];
  out->r.m[1][1] = m[1][1];
  out->r.m[1][2] = m[1][2];
  out->t.x = t[0];
  out->t.y = t[1];
  return DRDC_OK;
}
