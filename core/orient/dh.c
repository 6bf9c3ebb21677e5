/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_kinematics
 * @brief Denavit-Hartenberg link transforms (standard and modified) and
 *        forward kinematics.
 *
 * Internal formats of the chain product: rotation elements in Q2.61
 * (int64, |r| <= 1 + small, sums of three <= 1.5 2^62), translations in
 * Q17.46 metres (int64, +-131 km). A link's elements are exact products
 * of two Q1.30 trig values (Q60) and of a Q15.16 length with a Q1.30
 * value (Q46), so the only roundings are those of the trig values and
 * one per element per link (2^-61 and 2^-46 m: negligible).
 */
#include <drdc/kinematics.h>

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
  int64_t a;       /**< link length, Q15.16 */
  int64_t d;       /**< link offset (plus q if prismatic), Q15.16 */
} link_trig_t;

static drdc_status_t link_trig(drdc_dh_convention_t convention,
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
  out->d = d;
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
      v = g->a * g->ct;
    } else if (i == 1u) {
      v = g->a * g->st;
    } else {
      v = scale30(g->d);
    }
  } else {
    if (i == 0u) {
      v = scale30(g->a);
    } else if (i == 1u) {
      v = -(g->d * g->sa);
    } else {
      v = g->d * g->ca;
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

/* round(a b / 2^n): out of line (noinline), so that the twelve products
 * of a link do not spill their 128-bit temporaries into the frame of
 * drdc_dh_forward(). */
static __attribute__((noinline)) int64_t mul_round(int64_t a, int64_t b,
                                                   unsigned n)
{
  return orient_mul_rshift_round(a, b, n);
}

/* Q2.61 value times a Q60 one, as Q2.61: one correct rounding (128-bit
 * product); |result| <= |a| when |b| <= 2^60. */
static int64_t mul61(int64_t a, int64_t b)
{
  return mul_round(a, b, 60u);
}

drdc_status_t drdc_dh_forward(drdc_dh_convention_t convention,
                              const drdc_dh_link_t *links, unsigned n,
                              const int32_t *q, drdc_transform_t *out)
{
  int64_t r[3][3]; /* the rotation so far, Q2.61 */
  int64_t t[3];    /* the translation so far, Q46 */
  link_trig_t g;
  int32_t tr[3];
  unsigned k;
  unsigned i;
  unsigned j;
  drdc_status_t st = DRDC_OK;

  if ((out == NULL) || ((n > 0u) && ((links == NULL) || (q == NULL)))) {
    return DRDC_E_NULL;
  }
  if (n > (unsigned)DRDC_DH_MAX_LINKS) {
    return DRDC_E_RANGE;
  }
  if ((convention != DRDC_DH_STANDARD) && (convention != DRDC_DH_MODIFIED)) {
    return DRDC_E_RANGE;
  }
  for (i = 0u; i < 3u; i++) {
    for (j = 0u; j < 3u; j++) {
      r[i][j] = (i == j) ? orient_pow2_s64(61u) : 0;
    }
    t[i] = 0;
  }
  for (k = 0u; k < n; k++) {
    st = link_trig(convention, &links[k], q[k], &g);
    if (st != DRDC_OK) {
      return st;
    }
    for (i = 0u; i < 3u; i++) {
      /* t += R t_link: Q61 x Q46 / 2^61 -> Q46, correctly rounded each;
       * |R t_link| <= 1.01 |t_link| <= 2^62. Row i of the new rotation
       * needs only row i of the old one: replaced in place after. */
      int64_t nr[3];
      int64_t s;

      if (drdc_orient_impl_sum4(
              mul_round(r[i][0], link_t(convention, &g, 0u), 61u),
              mul_round(r[i][1], link_t(convention, &g, 1u), 61u),
              mul_round(r[i][2], link_t(convention, &g, 2u), 61u),
              t[i], &s)
          != DRDC_OK) {
        return DRDC_E_OVERFLOW;
      }
      t[i] = s;
      for (j = 0u; j < 3u; j++) {
        nr[j] = mul61(r[i][0], link_r(convention, &g, 0u, j))
                + mul61(r[i][1], link_r(convention, &g, 1u, j))
                + mul61(r[i][2], link_r(convention, &g, 2u, j));
      }
      r[i][0] = nr[0];
      r[i][1] = nr[1];
      r[i][2] = nr[2];
    }
  }
  for (i = 0u; (i < 3u) && (st == DRDC_OK); i++) {
    st = round30(t[i], &tr[i]);
  }
  if (st != DRDC_OK) {
    return st;
  }
  for (i = 0u; i < 3u; i++) {
    for (j = 0u; j < 3u; j++) {
      out->r.m[i][j] = (drdc_q1_30_t)drdc_fx_rshift_round_s64(r[i][j], 31u);
    }
  }
  out->t.x = tr[0];
  out->t.y = tr[1];
  out->t.z = tr[2];
  return DRDC_OK;
}
