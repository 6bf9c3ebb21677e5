/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Golden inputs and outputs of core/orient: random quaternions of
 *        any length (zero included), Euler angles anywhere on the circle,
 *        through products, normalisation, conversions and interpolation.
 */
#include <drdc/orient.h>

#include "golden.h"

static void fold_quat(golden_t *g, drdc_status_t st, const drdc_quat_t *q)
{
  golden_i32(g, (int32_t)st);
  golden_i32(g, q->s);
  golden_i32(g, q->x);
  golden_i32(g, q->y);
  golden_i32(g, q->z);
}

void golden_orient(golden_t *g)
{
  int i;

  for (i = 0; i < 1024; i++) {
    drdc_quat_t a;
    drdc_quat_t b;
    drdc_quat_t r = {0, 0, 0, 0};
    drdc_euler_t e;
    drdc_euler_t back = {0u, 0u, 0u};
    drdc_dcm_t m;
    drdc_vec3_q15_16_t v;
    drdc_vec3_q15_16_t w = {0, 0, 0};
    unsigned k;

    /* parts of any size: unit-scale (>> 2) for the first, raw for b */
    a.s = (int32_t)golden_next(g) / 4;
    a.x = (int32_t)golden_next(g) / 4;
    a.y = (int32_t)golden_next(g) / 4;
    a.z = (int32_t)golden_next(g) / 4;
    b.s = (int32_t)golden_next(g);
    b.x = (int32_t)golden_next(g);
    b.y = (int32_t)golden_next(g);
    b.z = (int32_t)golden_next(g);
    e.yaw = golden_next(g);
    e.pitch = golden_next(g);
    e.roll = golden_next(g);
    v.x = (int32_t)golden_next(g);
    v.y = (int32_t)golden_next(g);
    v.z = (int32_t)golden_next(g);

    fold_quat(g, drdc_quat_mul(&a, &b, &r), &r);
    fold_quat(g, drdc_quat_normalize(&b, &r), &r);
    fold_quat(g, drdc_quat_normalize(&a, &a), &a);
    golden_i32(g, (int32_t)drdc_quat_rotate_q15_16(&a, &v, &w));
    golden_i32(g, w.x);
    golden_i32(g, w.y);
    golden_i32(g, w.z);
    golden_i32(g, (int32_t)drdc_euler_from_quat(&a, &back));
    golden_u32(g, back.yaw);
    golden_u32(g, back.pitch);
    golden_u32(g, back.roll);
    fold_quat(g, drdc_quat_from_euler(&e, &b), &b);
    golden_i32(g, (int32_t)drdc_dcm_from_quat(&b, &m));
    for (k = 0u; k < 9u; k++) {
      golden_i32(g, m.m[k / 3u][k % 3u]);
    }
    fold_quat(g, drdc_quat_from_dcm(&m, &r), &r);
    fold_quat(g,
              drdc_quat_slerp(&a, &b, (drdc_q1_30_t)(golden_next(g) >> 2), &r),
              &r);
  }
}
