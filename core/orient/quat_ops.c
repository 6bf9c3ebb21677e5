/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_orient
 * @brief Quaternion conjugate, inverse and canonical sign: apart from
 *        quat.c, whose product has a speed goal, so that they can be
 *        compiled for flash.
 */
#include <drdc/orient.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>

#include "orient_impl.h"

drdc_status_t drdc_quat_conj(const drdc_quat_t *q, drdc_quat_t *out)
{
  drdc_quat_t r;

  if ((q == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  if ((q->x == INT32_MIN) || (q->y == INT32_MIN) || (q->z == INT32_MIN)) {
    return DRDC_E_OVERFLOW;
  }
  r.s = q->s;
  r.x = -q->x;
  r.y = -q->y;
  r.z = -q->z;
  *out = r;
  return DRDC_OK;
}

drdc_status_t drdc_quat_inverse(const drdc_quat_t *q, drdc_quat_t *out)
{
  orient_scaled_quat_t sq;
  int64_t v[4];
  int64_t num;
  int32_t e;
  drdc_status_t st;
  unsigned i;

  if ((q == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc_orient_impl_scale(q, &sq);
  if (st != DRDC_OK) {
    return st;
  }
  /* With c = q 2^k: q^-1 = conj(c) 2^k / |c|^2, raw parts
   * conj(c) 2^(60 + k) / n2. k >= 2 means |q| < 0.5, |q^-1| > 2. */
  if (sq.k >= 2) {
    return DRDC_E_OVERFLOW;
  }
  e = 60 + sq.k; /* k is -1..1 here: 59..61 */
  num = orient_pow2_s64((unsigned)e);
  for (i = 0u; i < 4u; i++) {
    int32_t c = (i == 0u) ? sq.c[0] : -sq.c[i]; /* |c| <= 2^30 */

    st = drdc_fx_muldiv_s64(c, num, sq.n2, &v[i]);
    if ((st != DRDC_OK) || (v[i] > INT32_MAX) || (v[i] < INT32_MIN)) {
      return DRDC_E_OVERFLOW;
    }
  }
  out->s = (drdc_q1_30_t)v[0];
  out->x = (drdc_q1_30_t)v[1];
  out->y = (drdc_q1_30_t)v[2];
  out->z = (drdc_q1_30_t)v[3];
  return DRDC_OK;
}

drdc_status_t drdc_quat_canonical(const drdc_quat_t *q, drdc_quat_t *out)
{
  const int32_t p[4] = {(q == NULL) ? 0 : q->s, (q == NULL) ? 0 : q->x,
                        (q == NULL) ? 0 : q->y, (q == NULL) ? 0 : q->z};
  unsigned i = 0u;

  if ((q == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  while ((i < 3u) && (p[i] == 0)) {
    i++;
  }
  if (p[i] >= 0) {
    *out = *q;
    return DRDC_OK;
  }
  if ((p[0] == INT32_MIN) || (p[1] == INT32_MIN) || (p[2] == INT32_MIN) ||
      (p[3] == INT32_MIN)) {
    return DRDC_E_OVERFLOW;
  }
  out->s = -p[0];
  out->x = -p[1];
  out->y = -p[2];
  out->z = -p[3];
  return DRDC_OK;
}
