/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_orient
 * @brief Rotation of global (Q47.16) vectors by a quaternion, with the
 *        exact rational matrix of q (never rounded to Q1.30). Apart from
 *        the local (Q15.16) rotation of quat_rotate.c, which has a speed
 *        goal, so that this one can be compiled for flash.
 */
#include <drdc/orient.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>

#include "orient_impl.h"

/* Guard bits of each product: |v| 2^6 <= 2^61 for every accepted v. */
#define GUARD_BITS 6u

/*
 * out_i = sum_j p_ij v_j / n2 with the exact Q60 numerators p of the
 * rotation (|p| <= n2): each term p v 2^6 / n2 is correctly rounded
 * (drdc_fx_round_div_128(): 128-bit product, one reciprocal of n2 for the
 * nine divisions), |term| <= 2^61, the sum of three fits int64 and is
 * rounded once more. Error <= 0.5 + 3 / 128 LSB against the exact
 * rotation of q / |q|: the matrix is never rounded. One row of p at a
 * time: the whole matrix never sits on the stack.
 */
static drdc_status_t rotate(const drdc_quat_t *q, const int64_t in[3],
                            int64_t res[3])
{
  orient_scaled_quat_t sq;
  int64_t row[3];
  uint64_t dn;
  unsigned z;
  uint32_t rcp;
  unsigned i;
  unsigned j;
  drdc_status_t st = drdc_orient_impl_scale(q, &sq);

  if (st != DRDC_OK) {
    return st;
  }
  rcp = orient_row_divisor(sq.n2, &dn, &z);
  for (i = 0u; i < 3u; i++) {
    int64_t s = 0;

    drdc_orient_impl_numerator_row(sq.c, i, row);
    for (j = 0u; j < 3u; j++) {
      s += drdc_fx_round_div_128(row[j], in[j] * orient_pow2_s64(GUARD_BITS),
                                 dn, z, rcp);
    }
    res[i] = drdc_fx_rshift_round_s64(s, GUARD_BITS);
  }
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
