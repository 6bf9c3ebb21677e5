/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_transform
 * @brief Homogeneous transforms, local (Q15.16) and global (Q47.16).
 */
#include <drdc/orient_transform.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>

#include "orient_impl.h"

/* Element-wise copy: a struct copy of a matrix becomes a memcpy call on
 * the freestanding PowerPC build, which links no libc. */
static void copy_dcm(const drdc_dcm_t *r, drdc_dcm_t *out)
{
  unsigned i;

  for (i = 0u; i < 3u; i++) {
    out->m[i][0] = r->m[i][0];
    out->m[i][1] = r->m[i][1];
    out->m[i][2] = r->m[i][2];
  }
}

/* t_out = R v + t (all int64, v and t in the same Q.16 scale): each part
 * one rounding of an exact Q46 sum (|R v| <= 2^30 |v| <= 2^61.8 for
 * |v| < 2^31), then an overflow-checked addition. */
static drdc_status_t affine_rows(const drdc_dcm_t *r, int transpose,
                                 const int32_t v[3], const int64_t t[3],
                                 int64_t out[3])
{
  unsigned i;

  for (i = 0u; i < 3u; i++) {
    int64_t s;
    int64_t rv;
    int64_t ti = (t == NULL) ? 0 : t[i];
    /* row i of R, or column i for R^T (no transposed copy) */
    int32_t m0 = (transpose != 0) ? r->m[0][i] : r->m[i][0];
    int32_t m1 = (transpose != 0) ? r->m[1][i] : r->m[i][1];
    int32_t m2 = (transpose != 0) ? r->m[2][i] : r->m[i][2];
    drdc_status_t st = drdc_orient_impl_sum4(
        (int64_t)m0 * v[0], (int64_t)m1 * v[1], (int64_t)m2 * v[2], 0, &s);

    if (st != DRDC_OK) {
      return st;
    }
    rv = drdc_fx_rshift_round_s64(s, 30u);
    if (((ti > 0) && (rv > (INT64_MAX - ti))) ||
        ((ti < 0) && (rv < (ORIENT_INT64_MIN - ti)))) {
      return DRDC_E_OVERFLOW;
    }
    out[i] = rv + ti;
  }
  return DRDC_OK;
}

static drdc_status_t affine(const drdc_dcm_t *r, const int32_t v[3],
                            const int64_t t[3], int64_t out[3])
{
  return affine_rows(r, 0, v, t, out);
}

static drdc_status_t to_local(const int64_t v[3], drdc_vec3_q15_16_t *out)
{
  unsigned i;

  for (i = 0u; i < 3u; i++) {
    if ((v[i] > INT32_MAX) || (v[i] < INT32_MIN)) {
      return DRDC_E_OVERFLOW;
    }
  }
  out->x = (drdc_q15_16_t)v[0];
  out->y = (drdc_q15_16_t)v[1];
  out->z = (drdc_q15_16_t)v[2];
  return DRDC_OK;
}

drdc_status_t drdc_transform_from_quat(const drdc_quat_t *q,
                                       const drdc_vec3_q15_16_t *t,
                                       drdc_transform_t *out)
{
  drdc_status_t st;

  if ((q == NULL) || (t == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  /* Straight into out: drdc_dcm_from_quat() writes nothing on error, and
   * t (which may be &out->t) is read after the matrix is written. */
  st = drdc_dcm_from_quat(q, &out->r);
  if (st == DRDC_OK) {
    out->t = *t;
  }
  return st;
}

drdc_status_t drdc_transform_compose(const drdc_transform_t *a,
                                     const drdc_transform_t *b,
                                     drdc_transform_t *out)
{
  const int32_t v[3] = {(b == NULL) ? 0 : b->t.x, (b == NULL) ? 0 : b->t.y,
                        (b == NULL) ? 0 : b->t.z};
  const int64_t t[3] = {(a == NULL) ? 0 : a->t.x, (a == NULL) ? 0 : a->t.y,
                        (a == NULL) ? 0 : a->t.z};
  int64_t res[3];
  drdc_vec3_q15_16_t nt;
  drdc_status_t st;

  if ((a == NULL) || (b == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = affine(&a->r, v, t, res);
  if (st == DRDC_OK) {
    st = to_local(res, &nt);
  }
  /* drdc_dcm_mul() writes out->r only on success and reads a->r and
   * b->r first (out may be a or b); nt is already computed */
  if (st == DRDC_OK) {
    st = drdc_dcm_mul(&a->r, &b->r, &out->r);
  }
  if (st == DRDC_OK) {
    out->t = nt;
  }
  return st;
}

drdc_status_t drdc_transform_invert(const drdc_transform_t *a,
                                    drdc_transform_t *out)
{
  const int32_t v[3] = {(a == NULL) ? 0 : a->t.x, (a == NULL) ? 0 : a->t.y,
                        (a == NULL) ? 0 : a->t.z};
  const int64_t zero[3] = {0, 0, 0};
  int64_t res[3];
  drdc_dcm_t rt;
  unsigned i;
  drdc_status_t st;

  if ((a == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  (void)drdc_dcm_transpose(&a->r, &rt);
  st = affine(&rt, v, zero, res);
  if (st != DRDC_OK) {
    return st;
  }
  for (i = 0u; i < 3u; i++) {
    res[i] = -res[i]; /* |res| < 2^62: no overflow */
  }
  st = to_local(res, &out->t);
  if (st == DRDC_OK) {
    copy_dcm(&rt, &out->r);
  }
  return st;
}

drdc_status_t drdc_transform_point(const drdc_transform_t *a,
                                   const drdc_vec3_q15_16_t *p,
                                   drdc_vec3_q15_16_t *out)
{
  const int32_t v[3] = {(p == NULL) ? 0 : p->x, (p == NULL) ? 0 : p->y,
                        (p == NULL) ? 0 : p->z};
  const int64_t t[3] = {(a == NULL) ? 0 : a->t.x, (a == NULL) ? 0 : a->t.y,
                        (a == NULL) ? 0 : a->t.z};
  int64_t res[3];
  drdc_status_t st;

  if ((a == NULL) || (p == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = affine(&a->r, v, t, res);
  if (st == DRDC_OK) {
    st = to_local(res, out);
  }
  return st;
}

drdc_status_t drdc_transform_direction(const drdc_transform_t *a,
                                       const drdc_vec3_q15_16_t *d,
                                       drdc_vec3_q15_16_t *out)
{
  if ((a == NULL) || (d == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  return drdc_dcm_apply_q15_16(&a->r, d, out);
}

drdc_status_t drdc_transform_global_compose(const drdc_transform_global_t *g,
                                            const drdc_transform_t *b,
                                            drdc_transform_global_t *out)
{
  const int32_t v[3] = {(b == NULL) ? 0 : b->t.x, (b == NULL) ? 0 : b->t.y,
                        (b == NULL) ? 0 : b->t.z};
  const int64_t t[3] = {(g == NULL) ? 0 : g->t.x, (g == NULL) ? 0 : g->t.y,
                        (g == NULL) ? 0 : g->t.z};
  int64_t res[3];
  drdc_status_t st;

  if ((g == NULL) || (b == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = affine(&g->r, v, t, res);
  /* drdc_dcm_mul() writes out->r only on success and reads g->r and
   * b->r first (out may be g); res is already computed */
  if (st == DRDC_OK) {
    st = drdc_dcm_mul(&g->r, &b->r, &out->r);
  }
  if (st == DRDC_OK) {
    out->t.x = res[0];
    out->t.y = res[1];
    out->t.z = res[2];
  }
  return st;
}

drdc_status_t drdc_transform_global_to_world(const drdc_transform_global_t *g,
                                             const drdc_vec3_q15_16_t *p,
                                             drdc_vec3_q47_16_t *out)
{
  const int32_t v[3] = {(p == NULL) ? 0 : p->x, (p == NULL) ? 0 : p->y,
                        (p == NULL) ? 0 : p->z};
  const int64_t t[3] = {(g == NULL) ? 0 : g->t.x, (g == NULL) ? 0 : g->t.y,
                        (g == NULL) ? 0 : g->t.z};
  int64_t res[3];
  drdc_status_t st;

  if ((g == NULL) || (p == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = affine(&g->r, v, t, res);
  if (st == DRDC_OK) {
    out->x = res[0];
    out->y = res[1];
    out->z = res[2];
  }
  return st;
}

drdc_status_t drdc_transform_global_to_local(const drdc_transform_global_t *g,
                                             const drdc_vec3_q47_16_t *p,
                                             drdc_vec3_q15_16_t *out)
{
  int64_t diff[3];
  int32_t v[3];
  int64_t res[3];
  unsigned i;
  drdc_status_t st;

  if ((g == NULL) || (p == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  diff[0] = p->x;
  diff[1] = p->y;
  diff[2] = p->z;
  {
    const int64_t t[3] = {g->t.x, g->t.y, g->t.z};

    for (i = 0u; i < 3u; i++) {
      /* the difference must be a local length: rule out overflow first */
      if (((t[i] < 0) && (diff[i] > (INT64_MAX + t[i]))) ||
          ((t[i] > 0) && (diff[i] < (ORIENT_INT64_MIN + t[i])))) {
        return DRDC_E_OVERFLOW;
      }
      diff[i] -= t[i];
      if ((diff[i] > INT32_MAX) || (diff[i] < INT32_MIN)) {
        return DRDC_E_OVERFLOW;
      }
      v[i] = (int32_t)diff[i];
    }
  }
  st = affine_rows(&g->r, 1, v, NULL, res); /* R^T (p - t) */
  if (st == DRDC_OK) {
    st = to_local(res, out);
  }
  return st;
}
