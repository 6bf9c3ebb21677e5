/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_orient
 * @brief Rotation of local (Q15.16) and global (Q47.16) vectors by a
 *        quaternion, with the exact rational matrix of q (never rounded
 *        to Q1.30).
 */
#include <drdc/orient.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>

#include "orient_impl.h"

/* Guard bits of each product: |v| 2^6 <= 2^61 for every accepted v. */
#define GUARD_BITS 6u

/*
 * out_i = sum_j p_ij v_j / n2 with the exact Q60 numerators p of the
 * rotation (|p| <= n2): each term p v 2^6 / n2 is correctly rounded by
 * drdc_fx_muldiv_s64() (128-bit intermediate), |term| <= 2^61, the sum of
 * three fits int64 and is rounded once more. Error <= 0.5 + 3 / 128 LSB
 * against the exact rotation of q / |q|: the matrix is never rounded.
 */
static drdc_status_t rotate(const drdc_quat_t *q, const int64_t in[3],
                            int64_t res[3])
{
  int64_t p[3][3];
  int64_t n2;
  unsigned i;
  unsigned j;
  drdc_status_t st = drdc_orient_impl_numerators(q, p, &n2);

  if (st != DRDC_OK) {
    return st;
  }
  for (i = 0u; i < 3u; i++) {
    int64_t t[3];
    int64_t s;

    for (j = 0u; j < 3u; j++) {
      (void)drdc_fx_muldiv_s64(p[i][j], in[j] * orient_pow2_s64(GUARD_BITS),
                               n2, &t[j]);
    }
    s = t[0] + t[1] + t[2];
    res[i] = drdc_fx_rshift_round_s64(s, GUARD_BITS);
  }
  return DRDC_OK;
}

drdc_status_t drdc_quat_rotate_q15_16(const drdc_quat_t *q,
                                      const drdc_vec3_q15_16_t *v,
                                      drdc_vec3_q15_16_t *out)
{
  int64_t in[3];
  int64_t res[3];
  unsigned i;
  drdc_status_t st;

  if ((q == NULL) || (v == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  in[0] = v->x;
  in[1] = v->y;
  in[2] = v->z;
  st = rotate(q, in, res);
  if (st != DRDC_OK) {
    return st;
  }
  for (i = 0u; i < 3u; i++) {
    if ((res[i] > INT32_MAX) || (res[i] < INT32_MIN)) {
      return DRDC_E_OVERFLOW;
    }
  }
  out->x = (drdc_q15_16_t)res[0];
  out->y = (drdc_q15_16_t)res[1];
  out->z = (drdc_q15_16_t)res[2];
  return DRDC_OK;
}

drdc_status_t drdc_quat_rotate_q47_16(const drdc_quat_t *q,
                                      const drdc_vec3_q47_16_t *v,
                                      drdc_vec3_q47_16_t *out)
{
  int64_t in[3];
  int64_t res[3];
  unsigned i;
  drdc_status_t st;

  if ((q == NULL) || (v == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  in[0] = v->x;
  in[1] = v->y;
  in[2] = v->z;
  for (i = 0u; i < 3u; i++) {
    if ((in[i] > DRDC_ORIENT_Q47_16_MAX) || (in[i] < -DRDC_ORIENT_Q47_16_MAX)) {
      return DRDC_E_RANGE;
    }
  }
  st = rotate(q, in, res);
  if (st == DRDC_OK) {
    out->x = res[0];
    out->y = res[1];
    out->z = res[2];
  }
  return st;
}
