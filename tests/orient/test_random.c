/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief 20 000 random orientations against SciPy (oracle checks): Euler
 *        Z-Y-X -> quaternion, and the exact integer quaternion -> Euler.
 *        Host and PowerPC only: the table (560 KB) does not fit the
 *        Cortex-M3 flash, whose image runs the same random inputs through
 *        the round-trip consistency checks of test_quat.c instead.
 */
#include <drdc/orient.h>

#include "orient_test_util.h"
#include "suites.h"
#include "unity.h"

#if !ORIENT_FLASH_SMALL
#include "vectors_orient_random.h"

/* Measured maxima: quaternion parts in LSB of Q1.30, angles in 1/16
 * binary-angle units (1e-7 degree = 19). */
#define TOL_RANDOM_QUAT 2
#define TOL_RANDOM_EULER_SUB 15

/* The generator's sequence: yaw, pitch in [-89, 89] degrees, roll. */
static void orient_random_euler(uint32_t *x, drdc_euler_t *e)
{
  const uint32_t span = (2u * ORIENT_RANDOM_PITCH_MAX) + 1u;

  e->yaw = orient_rand(x);
  e->pitch = (orient_rand(x) % span) - ORIENT_RANDOM_PITCH_MAX;
  e->roll = orient_rand(x);
}

static void test_20000_random_orientations_match_scipy(void)
{
  uint32_t x = ORIENT_RANDOM_SEED;
  int64_t mq = 0;
  int64_t me = 0;
  uint32_t i;

  for (i = 0u; i < ORIENT_RANDOM_COUNT; i++) {
    const int32_t *want = &orient_random_q[4u * i];
    const int16_t *delta = &orient_random_euler_delta[3u * i];
    drdc_euler_t e;
    drdc_euler_t back;
    drdc_quat_t q;
    int64_t d;

    orient_random_euler(&x, &e);
    (void)drdc_quat_from_euler(&e, &q);
    d = orient_qdiff_signed(&q, want);
    mq = (d > mq) ? d : mq;
    q.s = want[0];
    q.x = want[1];
    q.y = want[2];
    q.z = want[3];
    (void)drdc_euler_from_quat(&q, &back);
    d = orient_angle_err(back.yaw, ((int64_t)(int32_t)e.yaw * 16) + delta[0],
                         16);
    me = (d > me) ? d : me;
    d = orient_angle_err(back.pitch,
                         ((int64_t)(int32_t)e.pitch * 16) + delta[1], 16);
    me = (d > me) ? d : me;
    d = orient_angle_err(back.roll,
                         ((int64_t)(int32_t)e.roll * 16) + delta[2], 16);
    me = (d > me) ? d : me;
  }
  ORIENT_REPORT("random euler->quat LSB", mq);
  ORIENT_REPORT("random quat->euler 1/16 bam", me);
  TEST_ASSERT_TRUE(mq <= TOL_RANDOM_QUAT);
  TEST_ASSERT_TRUE(me <= TOL_RANDOM_EULER_SUB);
}
#endif

void suite_orient_random(void)
{
  UnitySetTestFile(__FILE__);
#if !ORIENT_FLASH_SMALL
  RUN_TEST(test_20000_random_orientations_match_scipy);
#endif
}
