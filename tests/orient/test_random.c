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

#include <stddef.h>

#include "orient_test_util.h"
#include "suites.h"
#include "unity.h"

#include "vectors_orient_random.h"

/* Measured maxima: quaternion parts in LSB of Q1.30, angles in 1/16
 * binary-angle units (1e-7 degree = 19). */
#define TOL_RANDOM_QUAT      2
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
    d = orient_angle_err(back.roll, ((int64_t)(int32_t)e.roll * 16) + delta[2],
                         16);
    me = (d > me) ? d : me;
  }
  ORIENT_REPORT("random euler->quat LSB", mq);
  ORIENT_REPORT("random quat->euler 1/16 bam", me);
  TEST_ASSERT_TRUE(mq <= TOL_RANDOM_QUAT);
  TEST_ASSERT_TRUE(me <= TOL_RANDOM_EULER_SUB);
}

/* angle_between, nlerp and axis-angle against SciPy / numpy (200 pairs:
 * random, q vs -q, nearly equal, exactly 180 degrees apart). */
#define TOL_ANGLE_BETWEEN_SUB 32 /* 1/16 units: 2 binary-angle units */
#define TOL_NLERP             2
#define TOL_AXIS              1
#define TOL_ROT_ANGLE_SUB     26

static void test_angle_nlerp_axis_match_scipy(void)
{
  int64_t ma = 0;
  int64_t mn = 0;
  int64_t mx = 0;
  int64_t mr = 0;
  size_t i;

  for (i = 0; i < COUNT(orient_extra_vectors); i++) {
    const struct orient_extra_vector *v = &orient_extra_vectors[i];
    const drdc_quat_t a = {v->a[0], v->a[1], v->a[2], v->a[3]};
    const drdc_quat_t b = {v->b[0], v->b[1], v->b[2], v->b[3]};
    drdc_quat_t n;
    drdc_vec3_q1_30_t axis;
    drdc_bam32_t ang;
    int64_t d;

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_angle_between(&a, &b, &ang));
    d = orient_abs64(((int64_t)ang * 16) - v->angle);
    ma = (d > ma) ? d : ma;
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_nlerp(&a, &b, v->t, &n));
    d = orient_qdiff(&n, v->nlerp);
    mn = (d > mn) ? d : mn;
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_axis_angle_from_quat(&a, &axis, &ang));
    d = orient_maxdiff32(&axis.x, v->axis, 3u);
    mx = (d > mx) ? d : mx;
    d = orient_abs64(((int64_t)ang * 16) - v->rot_angle);
    mr = (d > mr) ? d : mr;
  }
  ORIENT_REPORT("angle_between 1/16 bam", ma);
  ORIENT_REPORT("nlerp LSB", mn);
  ORIENT_REPORT("axis from quat LSB", mx);
  ORIENT_REPORT("angle from quat 1/16 bam", mr);
  TEST_ASSERT_TRUE(ma <= TOL_ANGLE_BETWEEN_SUB);
  TEST_ASSERT_TRUE(mn <= TOL_NLERP);
  TEST_ASSERT_TRUE(mx <= TOL_AXIS);
  TEST_ASSERT_TRUE(mr <= TOL_ROT_ANGLE_SUB);
}

void suite_orient_random(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_20000_random_orientations_match_scipy);
  RUN_TEST(test_angle_nlerp_axis_match_scipy);
}
