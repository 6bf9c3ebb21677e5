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

/* One link: rotation exact Q60, translation exact Q46. */
typedef struct link_exact {
  int64_t r[3][3];
  int64_t t[3];
} link_exact_t;

static drdc_status_t link_exact(drdc_dh_convention_t convention,
                                const drdc_dh_link_t *link, int32_t q,
                                link_exact_t *out)
{
  drdc_bam32_t theta = link->theta;
  int64_t d = link->d;
  drdc_q1_30_t st;
  drdc_q1_30_t ct;
  drdc_q1_30_t sa;
  drdc_q1_30_t ca;
  const int64_t a = link->a;

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
  drdc_fx_sincos_bam32(theta, &st, &ct);
  drdc_fx_sincos_bam32(link->alpha, &sa, &ca);
  if (convention == DRDC_DH_STANDARD) {
    out->r[0][0] = scale30(ct);
    out->r[0][1] = -((int64_t)st * ca);
    out->r[0][2] = (int64_t)st * sa;
    out->r[1][0] = scale30(st);
    out->r[1][1] = (int64_t)ct * ca;
    out->r[1][2] = -((int64_t)ct * sa);
    out->r[2][0] = 0;
    out->r[2][1] = scale30(sa);
    out->r[2][2] = scale30(ca);
    out->t[0] = a * ct;
    out->t[1] = a * st;
    out->t[2] = scale30(d);
  } else if (convention == DRDC_DH_MODIFIED) {
    out->r[0][0] = scale30(ct);
    out->r[0][1] = -(scale30(st));
    out->r[0][2] = 0;
    out->r[1][0] = (int64_t)st * ca;
    out->r[1][1] = (int64_t)ct * ca;
    out->r[1][2] = -(scale30(sa));
    out->r[2][0] = (int64_t)st * sa;
    out->r[2][1] = (int64_t)ct * sa;
    out->r[2][2] = scale30(ca);
    out->t[0] = scale30(a);
    out->t[1] = -(d * sa);
    out->t[2] = d * ca;
  } else {
    return DRDC_E_RANGE;
  }
  return DRDC_OK;
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
  link_exact_t e;
  drdc_transform_t r;
  unsigned i;
  unsigned j;
  drdc_status_t st;

  if ((link == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = link_exact(convention, link, q, &e);
  if (st != DRDC_OK) {
    return st;
  }
  for (i = 0u; i < 3u; i++) {
    for (j = 0u; j < 3u; j++) {
      (void)round30(e.r[i][j], &r.r.m[i][j]); /* |r| <= 2^60 */
    }
  }
  if (st == DRDC_OK) {
    st = round30(e.t[0], &r.t.x);
  }
  if (st == DRDC_OK) {
    st = round30(e.t[1], &r.t.y);
  }
  if (st == DRDC_OK) {
    st = round30(e.t[2], &r.t.z);
  }
  if (st == DRDC_OK) {
    for (i = 0u; i < 3u; i++) {
      out->r.m[i][0] = r.r.m[i][0];
      out->r.m[i][1] = r.r.m[i][1];
      out->r.m[i][2] = r.r.m[i][2];
    }
    out->t = r.t;
  }
  return st;
}

/* Q2.61 value times a Q60 one, as Q2.61: one correct rounding (128-bit
 * intermediate); |result| <= |a| when |b| <= 2^60. */
static int64_t mul61(int64_t a, int64_t b)
{
  int64_t r = 0;

  (void)drdc_fx_muldiv_s64(a, b, orient_pow2_s64(60u), &r);
  return r;
}

drdc_status_t drdc_dh_forward(drdc_dh_convention_t convention,
                              const drdc_dh_link_t *links, unsigned n,
                              const int32_t *q, drdc_transform_t *out)
{
  int64_t buf[2][3][3]; /* the rotation, alternating: no copy loop */
  unsigned cur = 0u;
  int64_t t[3];
  link_exact_t e;
  drdc_transform_t res;
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
      buf[0][i][j] = (i == j) ? orient_pow2_s64(61u) : 0;
    }
    t[i] = 0;
  }
  for (k = 0u; k < n; k++) {
    int64_t(*r)[3] = buf[cur];
    int64_t(*nr)[3] = buf[cur ^ 1u];

    st = link_exact(convention, &links[k], q[k], &e);
    if (st != DRDC_OK) {
      return st;
    }
    for (i = 0u; i < 3u; i++) {
      /* t += R t_link: Q61 x Q46 / 2^61 -> Q46, correctly rounded each;
       * |R t_link| <= 1.01 |t_link| <= 2^62. */
      int64_t add[3];
      int64_t s;

      for (j = 0u; j < 3u; j++) {
        (void)drdc_fx_muldiv_s64(r[i][j], e.t[j], orient_pow2_s64(61u),
                                 &add[j]);
      }
      if (drdc_orient_impl_sum4(add[0], add[1], add[2], t[i], &s)
          != DRDC_OK) {
        return DRDC_E_OVERFLOW;
      }
      t[i] = s;
      for (j = 0u; j < 3u; j++) {
        nr[i][j] = mul61(r[i][0], e.r[0][j]) + mul61(r[i][1], e.r[1][j])
                   + mul61(r[i][2], e.r[2][j]);
      }
    }
    cur ^= 1u;
  }
  for (i = 0u; i < 3u; i++) {
    for (j = 0u; j < 3u; j++) {
      res.r.m[i][j] =
          (drdc_q1_30_t)drdc_fx_rshift_round_s64(buf[cur][i][j], 31u);
    }
  }
  st = round30(t[0], &res.t.x);
  if (st == DRDC_OK) {
    st = round30(t[1], &res.t.y);
  }
  if (st == DRDC_OK) {
    st = round30(t[2], &res.t.z);
  }
  if (st == DRDC_OK) {
    for (i = 0u; i < 3u; i++) {
      out->r.m[i][0] = res.r.m[i][0];
      out->r.m[i][1] = res.r.m[i][1];
      out->r.m[i][2] = res.r.m[i][2];
    }
    out->t = res.t;
  }
  return st;
}
