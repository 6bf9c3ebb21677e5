/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Benchmark cases of core/orient, and the floor the quaternion
 *        product is measured against: the 16 multiply-accumulates of a
 *        Q1.30 product written by hand, without rounding or checks.
 */
#include <drdc/orient.h>

#include "operands.h"

static uint32_t quat_mul(uint32_t k)
{
  drdc_quat_t r = {0, 0, 0, 0};

  (void)drdc_quat_mul(&bench_qa[k], &bench_qb[k], &r);
  return (uint32_t)(r.s ^ r.x ^ r.y ^ r.z);
}

/* The floor: the product as an engineer writes it by hand, behind the
 * same interface as drdc_quat_mul() (operands and result through
 * pointers, not inlined into the loop nor specialised to its call site,
 * so both pay the same call and memory round trip): the 16 products accumulated
 * in int64 and shifted back, truncating, without checks or rounding. */
static __attribute__((noipa)) void
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

static uint32_t quat_mul_by_hand(uint32_t k)
{
  drdc_quat_t r = {0, 0, 0, 0};

  quat_mul_hand(&bench_qa[k], &bench_qb[k], &r);
  return (uint32_t)(r.s ^ r.x ^ r.y ^ r.z);
}

static uint32_t quat_rotate(uint32_t k)
{
  drdc_vec3_q15_16_t r = {0, 0, 0};

  (void)drdc_quat_rotate_q15_16(&bench_qa[k], &bench_vec[k], &r);
  return (uint32_t)(r.x ^ r.y ^ r.z);
}

static uint32_t euler_to_quat(uint32_t k)
{
  drdc_quat_t q = {0, 0, 0, 0};

  (void)drdc_quat_from_euler(&bench_euler[k], &q);
  return (uint32_t)(q.s ^ q.x ^ q.y ^ q.z);
}

static uint32_t quat_to_euler(uint32_t k)
{
  drdc_euler_t e = {0u, 0u, 0u};

  (void)drdc_euler_from_quat(&bench_qa[k], &e);
  return e.yaw ^ e.pitch ^ e.roll;
}

BENCH_LOOP(run_quat_mul, quat_mul(k))
BENCH_LOOP(run_quat_mul_by_hand, quat_mul_by_hand(k))
BENCH_LOOP(run_quat_rotate, quat_rotate(k))
BENCH_LOOP(run_euler_to_quat, euler_to_quat(k))
BENCH_LOOP(run_quat_to_euler, quat_to_euler(k))

const bench_case_t bench_cases_orient[] = {
    {"quat_mul", "drdc", "drdc_quat_mul", run_quat_mul},
    {"quat_mul", "hand", "run_quat_mul_by_hand", run_quat_mul_by_hand},
    {"quat_rotate", "drdc", "drdc_quat_rotate_q15_16", run_quat_rotate},
    {"euler_to_quat", "drdc", "drdc_quat_from_euler", run_euler_to_quat},
    {"quat_to_euler", "drdc", "drdc_euler_from_quat", run_quat_to_euler},
    {0, 0, 0, 0},
};
