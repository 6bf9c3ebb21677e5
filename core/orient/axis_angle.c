/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_orient
 * @brief Axis-angle <-> quaternion.
 */
#include <drdc/orient.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>
#include <drdc/fixed_sqrt.h>
#include <drdc/fixed_trig.h>

#include "orient_impl.h"

drdc_status_t drdc_quat_from_axis_angle(const drdc_vec3_q1_30_t *axis,
                                        drdc_bam32_t angle, drdc_quat_t *out)
{
  drdc_quat_t a;
  drdc_quat_t n;
  int64_t s2;
  int64_t c2;
  drdc_status_t st;

  if ((axis == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  a.s = 0;
  a.x = axis->x;
  a.y = axis->y;
  a.z = axis->z;
  st = drdc_quat_normalize(&a, &n); /* the unit axis, 0.75 LSB per part */
  if (st != DRDC_OK) {
    return st;
  }
  /* Doubled half-angle sine and cosine (Q1.31 scale, |.| <= 2^31): the
   * products with the Q1.30 axis are <= 2^61; one rounding each. */
  drdc_orient_impl_half_sincos(angle, &s2, &c2);
  out->s = (drdc_q1_30_t)drdc_fx_rshift_round_s64(c2, 1u);
  out->x = (drdc_q1_30_t)drdc_fx_rshift_round_s64(s2 * n.x, 31u);
  out->y = (drdc_q1_30_t)drdc_fx_rshift_round_s64(s2 * n.y, 31u);
  out->z = (drdc_q1_30_t)drdc_fx_rshift_round_s64(s2 * n.z, 31u);
  return DRDC_OK;
}

/* Bit length of v (0 for 0). */
static unsigned bits_of(uint64_t v)
{
  uint64_t w = v;
  unsigned n = 0u;
  unsigned step;

  for (step = 32u; step > 0u; step /= 2u) {
    if ((w >> step) != 0u) {
      w >>= step;
      n += step;
    }
  }
  return n + (unsigned)w;
}

drdc_status_t drdc_axis_angle_from_quat(const drdc_quat_t *q,
                                        drdc_vec3_q1_30_t *axis,
                                        drdc_bam32_t *angle)
{
  int32_t ax[3];
  uint64_t vv;  /* exact |v|^2 of the input, <= 3 2^62 */
  uint64_t s;   /* |s| of the input, <= 2^31 */
  uint64_t big; /* max(|v|^2, s^2) */
  uint64_t y;
  uint64_t x;
  unsigned len;
  drdc_bam32_t half = 0u;

  if ((q == NULL) || ((axis == NULL) && (angle == NULL))) {
    return DRDC_E_NULL;
  }
  if ((q->s == 0) && (q->x == 0) && (q->y == 0) && (q->z == 0)) {
    return DRDC_E_DOMAIN;
  }
  /* The half angle atan2(|v|, |s|) from the input's exact parts: both
   * scaled by one power of two so that the larger lies in [2^30, 2^31]
   * (|v| the correctly rounded root of the scaled exact sum of squares),
   * so that only the root's and the atan2's roundings remain, whatever
   * the input's length. */
  vv = orient_square_u64(q->x) + orient_square_u64(q->y) +
       orient_square_u64(q->z);
  s = (uint64_t)(int64_t)q->s;
  if (q->s < 0) {
    s = 0u - s;
  }
  if (vv != 0u) {
    big = s * s;
    if (vv > big) {
      big = vv;
    }
    len = bits_of(big);
    if (len > 62u) {
      /* scale 1/2: the floor of vv / 4 moves the root by < 2^-30 */
      y = drdc_fx_sqrt_u64(vv >> 2);
      x = (s + 1u) >> 1; /* s / 2 rounded half up: s >= 0 */
    } else {
      const unsigned k = (62u - len) / 2u; /* big 4^k in [2^60, 2^62) */
      const unsigned k2 = 2u * k;

      y = drdc_fx_sqrt_u64(vv << k2);
      x = s << k;
    }
    if (y > (uint64_t)INT32_MAX) {
      y = (uint64_t)INT32_MAX; /* 2^31: the root of nearly 2^62 */
    }
    if (x > (uint64_t)INT32_MAX) {
      x = (uint64_t)INT32_MAX;
    }
    (void)drdc_fx_atan2_bam32((int32_t)y, (int32_t)x, &half); /* [0, 2^30] */
  }
  /* The axis is the input's own vector part over its length (not that
   * of a rounded q / |q|: near the identity that is a few LSB, and its
   * rounding would turn the axis by degrees), the length again the
   * correctly rounded root of the exact sum of squares scaled into
   * [2^30, 2^31], so each part is within 1 LSB (half from the root,
   * half from the quotient). Signed with the input's scalar part so
   * that the angle is at most 180 degrees. */
  if (vv == 0u) {
    ax[0] = ORIENT_Q1_30_ONE; /* identity rotation: any axis; x by convention */
    ax[1] = 0;
    ax[2] = 0;
  } else {
    int32_t unit = ORIENT_Q1_30_ONE; /* 2^30 / |v| scaled as the root */
    unsigned k = 0u;
    uint64_t root;

    len = bits_of(vv);
    if (len > 62u) {
      root = drdc_fx_sqrt_u64(vv >> 2); /* |v| / 2 */
      unit = ORIENT_Q1_30_ONE / 2;
    } else {
      const unsigned k2 = (62u - len) & ~1u; /* vv 2^k2 in [2^60, 2^62) */

      k = k2 / 2u;
      root = drdc_fx_sqrt_u64(vv << k2);
    }
    if (root > (uint64_t)INT32_MAX) {
      root = (uint64_t)INT32_MAX;
    }
    if (q->s < 0) {
      unit = -unit;
    }
    /* |part| 2^k <= root < 2^31: the products are below 2^61 */
    ax[0] = (int32_t)drdc_fx_muldiv_round64((int64_t)q->x * orient_pow2_s64(k),
                                            unit, (int32_t)root);
    ax[1] = (int32_t)drdc_fx_muldiv_round64((int64_t)q->y * orient_pow2_s64(k),
                                            unit, (int32_t)root);
    ax[2] = (int32_t)drdc_fx_muldiv_round64((int64_t)q->z * orient_pow2_s64(k),
                                            unit, (int32_t)root);
  }
  if (axis != NULL) {
    axis->x = ax[0];
    axis->y = ax[1];
    axis->z = ax[2];
  }
  if (angle != NULL) {
    *angle = half * 2u;
  }
  return DRDC_OK;
}
