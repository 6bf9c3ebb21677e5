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

#if GOLDEN_TRACE
/* A quaternion input as its four parts (Q1.30), named by names. */
static void golden_quat(golden_t *g, const char *const names[4],
                        const drdc_quat_t *q)
{
  golden_in(g, names[0], q->s);
  golden_in(g, names[1], q->x);
  golden_in(g, names[2], q->y);
  golden_in(g, names[3], q->z);
}

static const char *const a_names[4] = {"a.s", "a.x", "a.y", "a.z"};
static const char *const b_names[4] = {"b.s", "b.x", "b.y", "b.z"};
static const char *const q_names[4] = {"q.s", "q.x", "q.y", "q.z"};

static const char *const dcm_names[9] = {"m00", "m01", "m02", "m10", "m11",
                                         "m12", "m20", "m21", "m22"};
#else
#define golden_quat(g, name, q) ((void)(g))
#endif

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
    drdc_q1_30_t t;
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

    golden_fn(g, "drdc_quat_mul");
    golden_quat(g, a_names, &a);
    golden_quat(g, b_names, &b);
    fold_quat(g, drdc_quat_mul(&a, &b, &r), &r);
    golden_fn(g, "drdc_quat_normalize");
    golden_quat(g, q_names, &b);
    fold_quat(g, drdc_quat_normalize(&b, &r), &r);
    golden_fn(g, "drdc_quat_normalize");
    golden_quat(g, q_names, &a);
    fold_quat(g, drdc_quat_normalize(&a, &a), &a);
    golden_fn(g, "drdc_quat_rotate_q15_16");
    golden_quat(g, q_names, &a);
    golden_in(g, "v.x", v.x);
    golden_in(g, "v.y", v.y);
    golden_in(g, "v.z", v.z);
    golden_i32(g, (int32_t)drdc_quat_rotate_q15_16(&a, &v, &w));
    golden_i32(g, w.x);
    golden_i32(g, w.y);
    golden_i32(g, w.z);
    golden_fn(g, "drdc_euler_from_quat");
    golden_quat(g, q_names, &a);
    golden_i32(g, (int32_t)drdc_euler_from_quat(&a, &back));
    golden_u32(g, back.yaw);
    golden_u32(g, back.pitch);
    golden_u32(g, back.roll);
    golden_fn(g, "drdc_quat_from_euler");
    golden_in(g, "yaw", e.yaw);
    golden_in(g, "pitch", e.pitch);
    golden_in(g, "roll", e.roll);
    fold_quat(g, drdc_quat_from_euler(&e, &b), &b);
    golden_fn(g, "drdc_dcm_from_quat");
    golden_quat(g, q_names, &b);
    golden_i32(g, (int32_t)drdc_dcm_from_quat(&b, &m));
    for (k = 0u; k < 9u; k++) {
      golden_i32(g, m.m[k / 3u][k % 3u]);
    }
    golden_fn(g, "drdc_quat_from_dcm");
    for (k = 0u; k < 9u; k++) {
      golden_in(g, dcm_names[k], m.m[k / 3u][k % 3u]);
    }
    fold_quat(g, drdc_quat_from_dcm(&m, &r), &r);
    t = (drdc_q1_30_t)(golden_next(g) >> 2);
    golden_fn(g, "drdc_quat_slerp");
    golden_quat(g, a_names, &a);
    golden_quat(g, b_names, &b);
    golden_in(g, "t", t);
    fold_quat(g, drdc_quat_slerp(&a, &b, t, &r), &r);
  }
}
