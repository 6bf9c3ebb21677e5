/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Benchmark cases of core/orient, and the floor the quaternion
 *        product is measured against: the 16 multiply-accumulates of a
 *        Q1.30 product written by hand, without rounding or checks.
 */
#include <drdc/orient.h>

#include "bench.h"

/* unit-scale quaternion parts from an input word (|part| < 2^29) */
static drdc_quat_t quat_of(uint32_t x)
{
  drdc_quat_t q;

  q.s = (int32_t)(x >> 3);
  q.x = (int32_t)((x << 7) >> 3) - (INT32_C(1) << 28);
  q.y = (int32_t)((x << 13) >> 3) - (INT32_C(1) << 28);
  q.z = (int32_t)((x << 21) >> 3) - (INT32_C(1) << 28);
  return q;
}

static uint32_t quat_mul(uint32_t x)
{
  drdc_quat_t a = quat_of(x);
  drdc_quat_t b = quat_of(x * 2654435761u);
  drdc_quat_t r = {0, 0, 0, 0};

  (void)drdc_quat_mul(&a, &b, &r);
  return (uint32_t)(r.s ^ r.x ^ r.y ^ r.z);
}

/* The floor: the product as an engineer writes it by hand, behind the
 * same interface as drdc_quat_mul() (operands and result through
 * pointers, not inlined into the loop, so both pay the same call and
 * memory round trip): the 16 products accumulated in int64 and shifted
 * back, truncating, without checks or rounding. */
static __attribute__((noinline)) void
quat_mul_hand(const drdc_quat_t *a, const drdc_quat_t *b, drdc_quat_t *out)
{
  int64_t s = ((int64_t)a->s * b->s) - ((int64_t)a->x * b->x) -
              ((int64_t)a->y * b->y) - ((int64_t)a->z * b->z);
  int64_t i = ((int64_t)a->s * b->x) + ((int64_t)a->x * b->s) +
              ((int64_t)a->y * b->z) - ((int64_t)a->z * b->y);
  int64_t j = ((int64_t)a->s * b->y) - ((int64_t)a->x * b->z) +
              ((int64_t)a->y * b->s) + ((int64_t)a->z * b->x);
  int64_t k = ((int64_t)a->s * b->z) + ((int64_t)a->x * b->y) -
              ((int64_t)a->y * b->x) + ((int64_t)a->z * b->s);

  out->s = (int32_t)(s >> 30);
  out->x = (int32_t)(i >> 30);
  out->y = (int32_t)(j >> 30);
  out->z = (int32_t)(k >> 30);
}

static uint32_t quat_mul_by_hand(uint32_t x)
{
  drdc_quat_t a = quat_of(x);
  drdc_quat_t b = quat_of(x * 2654435761u);
  drdc_quat_t r = {0, 0, 0, 0};

  quat_mul_hand(&a, &b, &r);
  return (uint32_t)(r.s ^ r.x ^ r.y ^ r.z);
}

static uint32_t quat_rotate(uint32_t x)
{
  drdc_quat_t q = quat_of(x);
  drdc_vec3_q15_16_t v;
  drdc_vec3_q15_16_t r = {0, 0, 0};

  v.x = (int32_t)(x & 0xFFFFFu);
  v.y = (int32_t)(x >> 12);
  v.z = -(int32_t)(x & 0xFFFFu);
  (void)drdc_quat_rotate_q15_16(&q, &v, &r);
  return (uint32_t)(r.x ^ r.y ^ r.z);
}

static uint32_t euler_to_quat(uint32_t x)
{
  drdc_euler_t e;
  drdc_quat_t q = {0, 0, 0, 0};

  e.yaw = x;
  e.pitch = (x * 2654435761u) >> 2;
  e.roll = x * 40503u;
  (void)drdc_quat_from_euler(&e, &q);
  return (uint32_t)(q.s ^ q.z);
}

static uint32_t quat_to_euler(uint32_t x)
{
  drdc_quat_t q = quat_of(x);
  drdc_euler_t e = {0u, 0u, 0u};

  (void)drdc_euler_from_quat(&q, &e);
  return e.yaw ^ e.pitch ^ e.roll;
}

BENCH_LOOP(run_quat_mul, quat_mul(x))
BENCH_LOOP(run_quat_mul_by_hand, quat_mul_by_hand(x))
BENCH_LOOP(run_quat_rotate, quat_rotate(x))
BENCH_LOOP(run_euler_to_quat, euler_to_quat(x))
BENCH_LOOP(run_quat_to_euler, quat_to_euler(x))

const bench_case_t bench_cases_orient[] = {
    {"quat_mul", "drdc", "drdc_quat_mul", run_quat_mul},
    {"quat_mul", "hand", "run_quat_mul_by_hand", run_quat_mul_by_hand},
    {"quat_rotate", "drdc", "drdc_quat_rotate_q15_16", run_quat_rotate},
    {"euler_to_quat", "drdc", "drdc_quat_from_euler", run_euler_to_quat},
    {"quat_to_euler", "drdc", "drdc_euler_from_quat", run_quat_to_euler},
    {0, 0, 0, 0},
};
