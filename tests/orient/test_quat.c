/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Tests of the quaternion algebra and the conversions between
 *        quaternions, Euler Z-Y-X angles, rotation matrices and
 *        axis-angle: SciPy reference tables (oracle checks), in-test
 *        random cases checked by exact identities (consistency checks),
 *        and named boundary conditions.
 *
 * Tolerances are the measured maxima (docs/accuracy.md), never wider than
 * the goals: Euler -> quaternion and products within 4 LSB per
 * part, quaternion -> Euler within 1e-7 degree (1.19 binary-angle units,
 * 19 of the 1/16 units of the tables) away from gimbal lock, |q| - 1
 * within 2 LSB after normalisation.
 */
#include <drdc/orient.h>

#include <stddef.h>

#include "orient_test_util.h"
#include "suites.h"
#include "unity.h"
#include "vectors_orient.h"

/* Measured maxima (LSB of Q1.30 unless said otherwise). */
#define TOL_EULER_TO_QUAT     1  /* Euler -> quaternion, per part */
#define TOL_EULER_TO_DCM      1  /* Euler -> matrix, per element */
#define TOL_QUAT_TO_DCM       2  /* quaternion -> matrix (2: parts > 1.0) */
#define TOL_QUAT_TO_EULER_SUB 18 /* 1/16 binary-angle units (1e-7 deg = 19) */
#define TOL_DCM_TO_EULER_SUB  25 /* rounded matrix -> Euler, 1/16 units */
#define TOL_DCM_TO_QUAT       1  /* matrix -> quaternion, per part */
#define TOL_NORM_LSB2         (INT64_C(1) << 32) /* |q|^2 - 1: 2 LSB of |q| - 1 */
#define TOL_ROT_Q15_16        0 /* rotated local vector, LSB of Q15.16 */
#define TOL_ROT_Q47_16        1 /* rotated global vector, LSB of Q47.16 */
#define TOL_AXIS_ANGLE        1 /* axis-angle -> quaternion, per part */
#define TOL_SLERP             2 /* slerp against SciPy's Slerp, per part */
#define TOL_ROUND_TRIP_EULER  3 /* Euler -> q -> Euler, binary-angle units */
#define TOL_ROUND_TRIP_DCM    1 /* q -> matrix -> q, per part */
#define TOL_Q_CONJ_Q          2 /* q conj(q) - 1 = 2 (|q| - 1), rounded */

/* Number of in-test random cases of each consistency check. */
#define RANDOM_CASES 20000u

/* Gimbal-lock margin of the oracle checks: 0.001 degree in binary-angle
 * units (11 930). */
#define GIMBAL_MARGIN_BAM 11930

static drdc_quat_t quat_of(const int32_t p[4])
{
  drdc_quat_t q;

  q.s = p[0];
  q.x = p[1];
  q.y = p[2];
  q.z = p[3];
  return q;
}

/* The parts of q in the tables' order, s first. */
static void parts_of(const drdc_quat_t *q, int32_t p[4])
{
  p[0] = q->s;
  p[1] = q->x;
  p[2] = q->y;
  p[3] = q->z;
}

/* Each product of a table: the status, and on success the four parts,
 * exactly (the tables hold the correctly rounded product). */
static void expect_mul_table(const struct orient_mul_vector *vectors, size_t n)
{
  size_t i;

  for (i = 0; i < n; i++) {
    const struct orient_mul_vector *v = &vectors[i];
    drdc_quat_t a = quat_of(v->a);
    drdc_quat_t b = quat_of(v->b);
    drdc_quat_t p = {7, 7, 7, 7};

    TEST_ASSERT_EQUAL_INT(v->status, drdc_quat_mul(&a, &b, &p));
    if (v->status == 0) {
      TEST_ASSERT_EQUAL_INT32(v->p[0], p.s);
      TEST_ASSERT_EQUAL_INT32(v->p[1], p.x);
      TEST_ASSERT_EQUAL_INT32(v->p[2], p.y);
      TEST_ASSERT_EQUAL_INT32(v->p[3], p.z);
    } else {
      /* unchanged on error, every part */
      TEST_ASSERT_EQUAL_INT32(7, p.s);
      TEST_ASSERT_EQUAL_INT32(7, p.x);
      TEST_ASSERT_EQUAL_INT32(7, p.y);
      TEST_ASSERT_EQUAL_INT32(7, p.z);
    }
  }
}

static int64_t dcm_diff(const drdc_dcm_t *m, const int32_t r[9])
{
  return orient_maxdiff32(&m->m[0][0], r, 9u);
}

static int64_t pitch_from_lock(uint32_t pitch)
{
  int64_t p = orient_abs64((int64_t)(int32_t)pitch);

  return ((int64_t)1 << 30) - p;
}

/* ---------------------------------------------------------- oracle */

static void test_euler_to_quat_and_dcm_match_scipy(void)
{
  int64_t mq = 0;
  int64_t mm = 0;
  size_t i;

  for (i = 0; i < COUNT(orient_euler_vectors); i++) {
    const struct orient_euler_vector *v = &orient_euler_vectors[i];
    drdc_euler_t e;
    drdc_quat_t q;
    drdc_dcm_t m;
    int64_t d;

    e.yaw = v->e[0];
    e.pitch = v->e[1];
    e.roll = v->e[2];
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_from_euler(&e, &q));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_dcm_from_euler(&e, &m));
    d = orient_qdiff_signed(&q, v->q);
    mq = (d > mq) ? d : mq;
    d = dcm_diff(&m, v->m);
    mm = (d > mm) ? d : mm;
  }
  ORIENT_REPORT("euler->quat LSB", mq);
  ORIENT_REPORT("euler->dcm LSB", mm);
  TEST_ASSERT_TRUE(mq <= TOL_EULER_TO_QUAT);
  TEST_ASSERT_TRUE(mm <= TOL_EULER_TO_DCM);
}

static void test_quat_to_euler_and_dcm_match_scipy(void)
{
  int64_t me = 0;
  int64_t mm = 0;
  int64_t md = 0;
  size_t i;
  unsigned checked = 0u;

  for (i = 0; i < COUNT(orient_quat_vectors); i++) {
    const struct orient_quat_vector *v = &orient_quat_vectors[i];
    drdc_quat_t q = quat_of(v->q);
    drdc_euler_t e;
    drdc_dcm_t m;
    drdc_euler_t e2;
    int64_t d;

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_euler_from_quat(&q, &e));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_dcm_from_quat(&q, &m));
    d = dcm_diff(&m, v->m);
    mm = (d > mm) ? d : mm;
    /* Exactly in gimbal lock (both sides agree roll = 0) or at least
     * 0.001 degree away from it: the oracle applies. */
    if ((pitch_from_lock(e.pitch) >= GIMBAL_MARGIN_BAM) || (e.roll == 0u)) {
      d = orient_angle_err(e.yaw, v->e[0], ORIENT_EULER_SUB);
      me = (d > me) ? d : me;
      d = orient_angle_err(e.pitch, v->e[1], ORIENT_EULER_SUB);
      me = (d > me) ? d : me;
      d = orient_angle_err(e.roll, v->e[2], ORIENT_EULER_SUB);
      me = (d > me) ? d : me;
      checked++;
    }
    /* the matrix path gives the same angles within the matrix rounding
     * (0.5 LSB of Q1.30, 2^-31 rad / cos(pitch) in yaw and roll) */
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_euler_from_dcm(&m, &e2));
    if (pitch_from_lock(e.pitch) >= (INT32_C(1) << 27)) { /* |pitch| <= 78.75 */
      d = orient_angle_err(e2.yaw, v->e[0], ORIENT_EULER_SUB);
      md = (d > md) ? d : md;
      d = orient_angle_err(e2.pitch, v->e[1], ORIENT_EULER_SUB);
      md = (d > md) ? d : md;
      d = orient_angle_err(e2.roll, v->e[2], ORIENT_EULER_SUB);
      md = (d > md) ? d : md;
    }
  }
  ORIENT_REPORT("dcm->euler 1/16 bam (|pitch| <= 78.75)", md);
  TEST_ASSERT_TRUE(md <= TOL_DCM_TO_EULER_SUB);
  ORIENT_REPORT("quat->euler 1/16 bam", me);
  ORIENT_REPORT("quat->dcm LSB", mm);
  TEST_ASSERT_TRUE(checked > (COUNT(orient_quat_vectors) * 9u) / 10u);
  TEST_ASSERT_TRUE(me <= TOL_QUAT_TO_EULER_SUB);
  TEST_ASSERT_TRUE(mm <= TOL_QUAT_TO_DCM);
}

static void test_dcm_to_quat_matches_scipy_at_every_angle(void)
{
  int64_t mq = 0;
  size_t i;

  for (i = 0; i < COUNT(orient_dcm_vectors); i++) {
    const struct orient_dcm_vector *v = &orient_dcm_vectors[i];
    drdc_dcm_t m;
    drdc_quat_t q;
    int64_t d;
    unsigned r;

    for (r = 0u; r < 9u; r++) {
      m.m[r / 3u][r % 3u] = v->m[r];
    }
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_from_dcm(&m, &q));
    /* 180-degree rotations have s = 0: either sign is the same rotation */
    d = orient_qdiff(&q, v->q);
    mq = (d > mq) ? d : mq;
    TEST_ASSERT_TRUE(orient_norm_err(&q) <= TOL_NORM_LSB2);
  }
  ORIENT_REPORT("dcm->quat LSB", mq);
  TEST_ASSERT_TRUE(mq <= TOL_DCM_TO_QUAT);
}

static void test_mul_is_correctly_rounded(void)
{
  expect_mul_table(orient_mul_vectors, COUNT(orient_mul_vectors));
}

/* Parts at exactly +-1.0 and one LSB either side: the edge between the
 * product's unchecked sums (parts in (-1, 1]) and its checked ones. */
static void test_mul_at_the_unit_edges(void)
{
  expect_mul_table(orient_mul_edge_vectors, COUNT(orient_mul_edge_vectors));
}

/* Exact rotation (Python integers), rounded once: the first rows are
 * cases that the former method (each term rounded with 6 guard bits,
 * then the sum) put on the wrong side of a half: regression of the
 * rounding of drdc_quat_rotate_q15_16(). */
static void test_rotate_q15_16_is_correctly_rounded(void)
{
  size_t i;

  for (i = 0; i < COUNT(orient_rotate_exact_vectors); i++) {
    const struct orient_rotate_exact_vector *v =
        &orient_rotate_exact_vectors[i];
    drdc_quat_t q = quat_of(v->q);
    drdc_vec3_q15_16_t l = {v->v[0], v->v[1], v->v[2]};

    TEST_ASSERT_EQUAL_INT(v->status, drdc_quat_rotate_q15_16(&q, &l, &l));
    if (v->status == 0) {
      TEST_ASSERT_EQUAL_INT32(v->out[0], l.x);
      TEST_ASSERT_EQUAL_INT32(v->out[1], l.y);
      TEST_ASSERT_EQUAL_INT32(v->out[2], l.z);
    } else {
      TEST_ASSERT_EQUAL_INT32(v->v[0], l.x); /* unchanged on error */
      TEST_ASSERT_EQUAL_INT32(v->v[2], l.z);
    }
  }
}

static void test_rotate_vectors_match_scipy_and_mpmath(void)
{
  int64_t ml = 0;
  int64_t mg = 0;
  size_t i;

  for (i = 0; i < COUNT(orient_rotate_vectors); i++) {
    const struct orient_rotate_vector *v = &orient_rotate_vectors[i];
    drdc_quat_t q = quat_of(v->q);
    drdc_vec3_q15_16_t l = {v->v[0], v->v[1], v->v[2]};
    drdc_vec3_q47_16_t g = {v->g[0], v->g[1], v->g[2]};
    int64_t d;

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_rotate_q15_16(&q, &l, &l));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_rotate_q47_16(&q, &g, &g));
    d = orient_maxdiff32(&l.x, v->out, 3u);
    ml = (d > ml) ? d : ml;
    d = orient_abs64(g.x - v->gout[0]);
    mg = (d > mg) ? d : mg;
    d = orient_abs64(g.y - v->gout[1]);
    mg = (d > mg) ? d : mg;
    d = orient_abs64(g.z - v->gout[2]);
    mg = (d > mg) ? d : mg;
  }
  ORIENT_REPORT("rotate q15.16 LSB", ml);
  ORIENT_REPORT("rotate q47.16 LSB", mg);
  TEST_ASSERT_TRUE(ml <= TOL_ROT_Q15_16);
  TEST_ASSERT_TRUE(mg <= TOL_ROT_Q47_16);
}

static void test_axis_angle_matches_scipy(void)
{
  int64_t mq = 0;
  size_t i;

  for (i = 0; i < COUNT(orient_axis_vectors); i++) {
    const struct orient_axis_vector *v = &orient_axis_vectors[i];
    drdc_vec3_q1_30_t axis = {v->axis[0], v->axis[1], v->axis[2]};
    drdc_vec3_q1_30_t back;
    drdc_quat_t q;
    drdc_bam32_t angle;
    int64_t d;

    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_quat_from_axis_angle(&axis, v->angle, &q));
    d = orient_qdiff_signed(&q, v->q);
    mq = (d > mq) ? d : mq;
    /* and back: the same rotation (angle in [0, 180] degrees) */
    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_axis_angle_from_quat(&q, &back, &angle));
    TEST_ASSERT_TRUE(angle <= (UINT32_C(1) << 31));
  }
  ORIENT_REPORT("axis-angle->quat LSB", mq);
  TEST_ASSERT_TRUE(mq <= TOL_AXIS_ANGLE);
}

static void test_slerp_matches_scipy(void)
{
  int64_t mq = 0;
  size_t i;

  for (i = 0; i < COUNT(orient_slerp_vectors); i++) {
    const struct orient_slerp_vector *v = &orient_slerp_vectors[i];
    drdc_quat_t a = quat_of(v->a);
    drdc_quat_t b = quat_of(v->b);
    drdc_quat_t q;
    int64_t d;

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_slerp(&a, &b, v->t, &q));
    d = orient_qdiff(&q, v->q);
    mq = (d > mq) ? d : mq;
    TEST_ASSERT_TRUE(orient_norm_err(&q) <= TOL_NORM_LSB2);
  }
  ORIENT_REPORT("slerp LSB", mq);
  TEST_ASSERT_TRUE(mq <= TOL_SLERP);
}

/* ---------------------------------------------------- consistency */

/* Consistency check (not an oracle): random Euler angles at least 0.001
 * degree from gimbal lock survive Euler -> quaternion -> Euler. */
static void test_random_euler_round_trip(void)
{
  uint32_t seed = 0x2468ACE1u;
  int64_t me = 0;
  int64_t mn = 0;
  unsigned i;

  for (i = 0u; i < RANDOM_CASES; i++) {
    drdc_euler_t e;
    drdc_euler_t back;
    drdc_quat_t q;
    int64_t d;

    e.yaw = orient_rand(&seed);
    e.pitch = orient_rand(&seed) >> 1;
    e.pitch -= UINT32_C(1) << 30; /* [-90, 90) degrees */
    e.roll = orient_rand(&seed);
    if (pitch_from_lock(e.pitch) < GIMBAL_MARGIN_BAM) {
      continue;
    }
    (void)drdc_quat_from_euler(&e, &q);
    d = orient_norm_err(&q);
    mn = (d > mn) ? d : mn;
    (void)drdc_euler_from_quat(&q, &back);
    /* errors grow as 1 / cos(pitch) near the lock: scale them */
    d = orient_abs64(orient_bam_diff(back.pitch, e.pitch));
    me = (d > me) ? d : me;
    if (pitch_from_lock(e.pitch) > (INT32_C(1) << 28)) { /* |pitch| < 67.5 */
      d = orient_abs64(orient_bam_diff(back.yaw, e.yaw));
      me = (d > me) ? d : me;
      d = orient_abs64(orient_bam_diff(back.roll, e.roll));
      me = (d > me) ? d : me;
    }
  }
  ORIENT_REPORT("euler round trip bam", me);
  ORIENT_REPORT("euler->quat |q|^2-1 (2^-60)", mn);
  TEST_ASSERT_TRUE(me <= TOL_ROUND_TRIP_EULER);
}

/* Consistency check: normalising quaternions of random length, from a few
 * LSB to INT32_MIN parts, gives |q| - 1 within 2 LSB, and q conj(q) = 1. */
static void test_random_normalize_is_unit(void)
{
  uint32_t seed = 0x13579BDFu;
  int64_t mn = 0;
  int64_t mc = 0;
  unsigned i;

  for (i = 0u; i < RANDOM_CASES; i++) {
    unsigned sh = orient_rand(&seed) % 31u;
    drdc_quat_t q;
    drdc_quat_t n;
    drdc_quat_t c;
    drdc_quat_t p;
    int64_t d;

    q.s = (int32_t)orient_rand(&seed) >> sh;
    q.x = (int32_t)orient_rand(&seed) >> sh;
    q.y = (int32_t)orient_rand(&seed) >> sh;
    q.z = (int32_t)orient_rand(&seed) >> sh;
    if ((q.s | q.x | q.y | q.z) == 0) {
      continue;
    }
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_normalize(&q, &n));
    d = orient_norm_err(&n);
    mn = (d > mn) ? d : mn;
    (void)drdc_quat_conj(&n, &c);
    (void)drdc_quat_mul(&n, &c, &p);
    d = orient_abs64((int64_t)p.s - DRDC_Q1_30_ONE);
    d = (orient_abs64(p.x) > d) ? orient_abs64(p.x) : d;
    d = (orient_abs64(p.y) > d) ? orient_abs64(p.y) : d;
    d = (orient_abs64(p.z) > d) ? orient_abs64(p.z) : d;
    mc = (d > mc) ? d : mc;
  }
  ORIENT_REPORT("normalize |q|^2-1 (2^-60)", mn);
  ORIENT_REPORT("q conj(q) - 1 LSB", mc);
  TEST_ASSERT_TRUE(mn <= TOL_NORM_LSB2);
  TEST_ASSERT_TRUE(mc <= TOL_Q_CONJ_Q);
}

/* Consistency check: quaternion -> matrix -> quaternion at random
 * orientations (uniform parts, normalised). */
static void test_random_dcm_round_trip(void)
{
  uint32_t seed = 0x0BADF00Du;
  int64_t mq = 0;
  unsigned i;

  for (i = 0u; i < RANDOM_CASES / 4u; i++) {
    drdc_quat_t q;
    drdc_quat_t back;
    drdc_dcm_t m;
    int32_t r[4];
    int64_t d;

    q.s = (int32_t)orient_rand(&seed) >> 1;
    q.x = (int32_t)orient_rand(&seed) >> 1;
    q.y = (int32_t)orient_rand(&seed) >> 1;
    q.z = (int32_t)orient_rand(&seed) >> 1;
    if (drdc_quat_normalize(&q, &q) != DRDC_OK) {
      continue;
    }
    (void)drdc_dcm_from_quat(&q, &m);
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_from_dcm(&m, &back));
    parts_of(&q, r);
    d = orient_qdiff(&back, r);
    mq = (d > mq) ? d : mq;
  }
  ORIENT_REPORT("dcm round trip LSB", mq);
  TEST_ASSERT_TRUE(mq <= TOL_ROUND_TRIP_DCM);
}

/* ------------------------------------------------------- boundaries */

/* drdc_euler_canonical: exact, pitch beyond 90 degrees and the lock. */
static void test_euler_canonical(void)
{
  static const uint32_t in[4][3] = {
      {0u, UINT32_C(0x50000000), 0u}, /* pitch 112.5 */
      {5u, UINT32_C(0xB0000000), 7u}, /* pitch -112.5 */
      {UINT32_C(0x20000000), UINT32_C(0x40000000), UINT32_C(0x10000000)},
      {UINT32_C(0x20000000), UINT32_C(0xC0000000), UINT32_C(0x10000000)},
  };
  static const uint32_t want[4][3] = {
      {UINT32_C(0x80000000), UINT32_C(0x30000000), UINT32_C(0x80000000)},
      {UINT32_C(0x80000005), UINT32_C(0xD0000000), UINT32_C(0x80000007)},
      {UINT32_C(0x10000000), UINT32_C(0x40000000), 0u},
      {UINT32_C(0x30000000), UINT32_C(0xC0000000), 0u},
  };
  unsigned k;

  for (k = 0u; k < 4u; k++) {
    drdc_euler_t e = {in[k][0], in[k][1], in[k][2]};

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_euler_canonical(&e, &e));
    TEST_ASSERT_EQUAL_HEX32(want[k][0], e.yaw);
    TEST_ASSERT_EQUAL_HEX32(want[k][1], e.pitch);
    TEST_ASSERT_EQUAL_HEX32(want[k][2], e.roll);
  }
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_euler_canonical(NULL, NULL));
}

static void test_gimbal_lock_sets_roll_to_zero(void)
{
  static const uint32_t pitches[2] = {UINT32_C(1) << 30, UINT32_C(3) << 30};
  unsigned k;

  for (k = 0u; k < 2u; k++) {
    drdc_euler_t e = {UINT32_C(0x15555555), pitches[k], UINT32_C(1) << 28};
    drdc_euler_t back;
    drdc_dcm_t m;
    drdc_dcm_t m2;
    drdc_quat_t q;

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_from_euler(&e, &q));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_euler_from_quat(&q, &back));
    TEST_ASSERT_EQUAL_UINT32(0u, back.roll);
    TEST_ASSERT_TRUE(orient_abs64(orient_bam_diff(back.pitch, pitches[k])) <=
                     64);
    /* yaw - roll (pitch +90) or yaw + roll (pitch -90) carries it all */
    TEST_ASSERT_TRUE(
        orient_abs64(orient_bam_diff(
            back.yaw, (k == 0u) ? (e.yaw - e.roll) : (e.yaw + e.roll))) <= 64);
    /* and it is the same rotation */
    (void)drdc_dcm_from_quat(&q, &m);
    (void)drdc_dcm_from_euler(&back, &m2);
    TEST_ASSERT_TRUE(orient_maxdiff32(&m.m[0][0], &m2.m[0][0], 9u) <= 128);
    /* the matrix path agrees */
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_euler_from_dcm(&m, &back));
    TEST_ASSERT_EQUAL_UINT32(0u, back.roll);
  }
}

/* Within 0.001 degree of the lock the angles are ill-conditioned, so only
 * the rotation they describe is checked (consistency). */
static void test_near_gimbal_lock_keeps_the_rotation(void)
{
  uint32_t seed = 0xC0FFEEu;
  int64_t mm = 0;
  unsigned i;

  for (i = 0u; i < 2000u; i++) {
    drdc_euler_t e;
    drdc_euler_t back;
    drdc_quat_t q;
    drdc_dcm_t m;
    drdc_dcm_t m2;
    int64_t d;
    uint32_t off = orient_rand(&seed) % (2u * GIMBAL_MARGIN_BAM);

    e.yaw = orient_rand(&seed);
    e.roll = orient_rand(&seed);
    e.pitch = ((i & 1u) != 0u) ? ((UINT32_C(1) << 30) - off)
                               : ((UINT32_C(3) << 30) + off);
    (void)drdc_quat_from_euler(&e, &q);
    (void)drdc_euler_from_quat(&q, &back);
    (void)drdc_dcm_from_quat(&q, &m);
    (void)drdc_dcm_from_euler(&back, &m2);
    d = orient_maxdiff32(&m.m[0][0], &m2.m[0][0], 9u);
    mm = (d > mm) ? d : mm;
  }
  ORIENT_REPORT("near-lock rotation LSB", mm);
  TEST_ASSERT_TRUE(mm <= 3);
}

static void test_zero_and_null_inputs(void)
{
  const drdc_quat_t zero = {0, 0, 0, 0};
  drdc_quat_t out = {5, 5, 5, 5};
  drdc_euler_t e = {1u, 2u, 3u};
  drdc_dcm_t m;
  drdc_vec3_q1_30_t axis = {0, 0, 0};

  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_quat_normalize(&zero, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_euler_from_quat(&zero, &e));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_dcm_from_quat(&zero, &m));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_quat_inverse(&zero, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                        drdc_quat_from_axis_angle(&axis, 5u, &out));
  TEST_ASSERT_EQUAL_INT32(5, out.s);
  TEST_ASSERT_EQUAL_UINT32(1u, e.yaw);
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_normalize(NULL, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_mul(&zero, &zero, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_from_euler(NULL, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_euler_from_quat(&zero, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_from_dcm(NULL, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_axis_angle_from_quat(&zero, NULL, NULL));
  {
    unsigned k;

    for (k = 0u; k < 9u; k++) {
      m.m[k / 3u][k % 3u] = 0;
    }
  }
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_quat_from_dcm(&m, &out));
}

/* Includes the regression of a shift by 64 in the root's headroom
 * (|q|^2 = 2^62 after scaling, e.g. four equal parts of 1.0), which
 * host-asan reported as undefined behaviour. */
static void test_near_zero_and_huge_quaternions(void)
{
  static const drdc_quat_t in[] = {
      {1, 0, 0, 0},
      {0, 0, 0, -1},
      {1, 1, 1, 1},
      {INT32_MIN, INT32_MIN, INT32_MIN, INT32_MIN},
      {INT32_MAX, INT32_MAX, INT32_MAX, INT32_MAX},
      {INT32_MIN, 0, 0, 0},
      {INT32_MAX, 1, 0, -1},
  };
  static const drdc_quat_t want[] = {
      {1 << 30, 0, 0, 0},
      {0, 0, 0, -(1 << 30)},
      {1 << 29, 1 << 29, 1 << 29, 1 << 29},
      {-(1 << 29), -(1 << 29), -(1 << 29), -(1 << 29)},
      {1 << 29, 1 << 29, 1 << 29, 1 << 29},
      {-(1 << 30), 0, 0, 0},
      {1 << 30, 1, 0, -1}, /* 1 / (2^31 - 1) 2^30 = 0.5000000002 */
  };
  size_t i;

  for (i = 0; i < COUNT(in); i++) {
    drdc_quat_t n;

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_normalize(&in[i], &n));
    TEST_ASSERT_EQUAL_INT32(want[i].s, n.s);
    TEST_ASSERT_EQUAL_INT32(want[i].x, n.x);
    TEST_ASSERT_EQUAL_INT32(want[i].y, n.y);
    TEST_ASSERT_EQUAL_INT32(want[i].z, n.z);
  }
}

static void test_conj_inverse_canonical(void)
{
  drdc_quat_t q = {1 << 29, -(1 << 29), 1 << 29, 1 << 29};
  drdc_quat_t r;
  drdc_quat_t big = {INT32_MIN, INT32_MIN, 0, 0};
  drdc_quat_t half = {1 << 29, 0, 0, 0};
  drdc_quat_t small = {1 << 28, 0, 0, 0};

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_conj(&q, &r));
  TEST_ASSERT_EQUAL_INT32(1 << 29, r.s);
  TEST_ASSERT_EQUAL_INT32(1 << 29, r.x);
  TEST_ASSERT_EQUAL_INT32(-(1 << 29), r.y);
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_quat_conj(&big, &r));
  /* inverse of 0.5 is 2.0: out of Q1.30 */
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_quat_inverse(&small, &r));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_quat_inverse(&half, &r));
  /* inverse of a non-unit quaternion: q q^-1 = 1 */
  q.s = 3 << 28; /* |q| = 1.2 */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_inverse(&q, &r));
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_mul(&q, &r, &r));
  TEST_ASSERT_INT32_WITHIN(1, 1 << 30, r.s);
  TEST_ASSERT_INT32_WITHIN(1, 0, r.x);
  TEST_ASSERT_INT32_WITHIN(1, 0, r.y);
  TEST_ASSERT_INT32_WITHIN(1, 0, r.z);
  /* canonical sign */
  q.s = 0;
  q.x = 0;
  q.y = -5;
  q.z = 3;
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_canonical(&q, &r));
  TEST_ASSERT_EQUAL_INT32(5, r.y);
  TEST_ASSERT_EQUAL_INT32(-3, r.z);
  q.s = -1;
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_canonical(&q, &r));
  TEST_ASSERT_EQUAL_INT32(1, r.s);
}

static void test_compose_difference_and_angle(void)
{
  /* yaw 30 degrees then 60 more: 90 degrees between them */
  drdc_euler_t e1 = {UINT32_C(0x15555555), 0u, 0u};
  drdc_euler_t e2 = {UINT32_C(0x40000000), 0u, 0u};
  drdc_quat_t a;
  drdc_quat_t b;
  drdc_quat_t d;
  drdc_quat_t c;
  drdc_quat_t nb;
  drdc_bam32_t ang;
  int32_t want[4];

  (void)drdc_quat_from_euler(&e1, &a);
  (void)drdc_quat_from_euler(&e2, &b);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_difference(&a, &b, &d));
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_compose(&a, &d, &c));
  parts_of(&b, want);
  TEST_ASSERT_TRUE(orient_qdiff(&c, want) <= 2);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_angle_between(&a, &b, &ang));
  TEST_ASSERT_TRUE(orient_abs64(orient_bam_diff(ang, UINT32_C(0x2AAAAAAB))) <=
                   4);
  /* q and -q: angle 0 */
  nb.s = -b.s;
  nb.x = -b.x;
  nb.y = -b.y;
  nb.z = -b.z;
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_angle_between(&b, &nb, &ang));
  TEST_ASSERT_EQUAL_UINT32(0u, ang);
}

static void test_frames(void)
{
  drdc_vec3_q15_16_t v = {1, 2, 3};
  drdc_vec3_q47_16_t g = {INT64_C(1) << 40, -2, 3};
  drdc_quat_t q;
  drdc_quat_t r;
  drdc_quat_t back;
  drdc_euler_t e = {UINT32_C(0x20000000), 0u, 0u}; /* yaw 45 degrees */
  drdc_dcm_t m;
  int32_t want[4];

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_frame_frd_flu_q15_16(&v, &v));
  TEST_ASSERT_EQUAL_INT32(-2, v.y);
  TEST_ASSERT_EQUAL_INT32(-3, v.z);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_frame_ned_enu_q15_16(&v, &v));
  TEST_ASSERT_EQUAL_INT32(-2, v.x);
  TEST_ASSERT_EQUAL_INT32(1, v.y);
  TEST_ASSERT_EQUAL_INT32(3, v.z);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_frame_ned_enu_q47_16(&g, &g));
  TEST_ASSERT_TRUE(g.y == (INT64_C(1) << 40));
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_frame_frd_flu_q47_16(&g, &g));
  TEST_ASSERT_TRUE(g.z == 3);
  v.z = INT32_MIN;
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_frame_ned_enu_q15_16(&v, &v));
  /* heading 45 degrees (north-east) in NED/FRD is, in ENU/FLU, a yaw of
   * +45 degrees counter-clockwise from east: the body x axis still points
   * north-east, and the body z (up in FLU) is world up. */
  (void)drdc_quat_from_euler(&e, &q);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_frame_ned_enu_quat(&q, &r));
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_frame_frd_flu_quat(&r, &r));
  (void)drdc_dcm_from_quat(&r, &m);
  TEST_ASSERT_INT32_WITHIN(2, 759250125, m.m[0][0]); /* x_body . east */
  TEST_ASSERT_INT32_WITHIN(2, 759250125, m.m[1][0]); /* x_body . north */
  TEST_ASSERT_INT32_WITHIN(2, 1 << 30, m.m[2][2]);   /* z_body . up */
  /* each map is its own inverse (up to the sign of q) */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_frame_frd_flu_quat(&r, &back));
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_frame_ned_enu_quat(&back, &back));
  parts_of(&q, want);
  TEST_ASSERT_TRUE(orient_qdiff(&back, want) <= 2);
}

static void test_nlerp_squad_ends(void)
{
  drdc_euler_t e0 = {0u, 0u, 0u};
  drdc_euler_t e1 = {UINT32_C(0x10000000), UINT32_C(0x08000000), 0u};
  drdc_euler_t e2 = {UINT32_C(0x20000000), 0u, UINT32_C(0x04000000)};
  drdc_euler_t e3 = {UINT32_C(0x30000000), UINT32_C(0xF8000000), 0u};
  drdc_quat_t q0;
  drdc_quat_t q1;
  drdc_quat_t q2;
  drdc_quat_t q3;
  drdc_quat_t s1;
  drdc_quat_t s2;
  drdc_quat_t r;
  int32_t w1[4];
  int32_t w2[4];

  (void)drdc_quat_from_euler(&e0, &q0);
  (void)drdc_quat_from_euler(&e1, &q1);
  (void)drdc_quat_from_euler(&e2, &q2);
  (void)drdc_quat_from_euler(&e3, &q3);
  parts_of(&q1, w1);
  parts_of(&q2, w2);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_nlerp(&q1, &q2, 0, &r));
  TEST_ASSERT_TRUE(orient_qdiff(&r, w1) <= 2);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_nlerp(&q1, &q2, 1 << 30, &r));
  TEST_ASSERT_TRUE(orient_qdiff(&r, w2) <= 2);
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_quat_nlerp(&q1, &q2, -1, &r));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_quat_slerp(&q1, &q2, (1 << 30) + 1, &r));
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_squad_control(&q0, &q1, &q2, &s1));
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_squad_control(&q1, &q2, &q3, &s2));
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_squad(&q1, &q2, &s1, &s2, 0, &r));
  TEST_ASSERT_TRUE(orient_qdiff(&r, w1) <= 3);
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_quat_squad(&q1, &q2, &s1, &s2, 1 << 30, &r));
  TEST_ASSERT_TRUE(orient_qdiff(&r, w2) <= 3);
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_quat_squad(&q1, &q2, &s1, &s2, 1 << 29, &r));
  TEST_ASSERT_TRUE(orient_norm_err(&r) <= TOL_NORM_LSB2);
}

void suite_orient_quat(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_euler_to_quat_and_dcm_match_scipy);
  RUN_TEST(test_quat_to_euler_and_dcm_match_scipy);
  RUN_TEST(test_dcm_to_quat_matches_scipy_at_every_angle);
  RUN_TEST(test_mul_is_correctly_rounded);
  RUN_TEST(test_mul_at_the_unit_edges);
  RUN_TEST(test_rotate_vectors_match_scipy_and_mpmath);
  RUN_TEST(test_rotate_q15_16_is_correctly_rounded);
  RUN_TEST(test_axis_angle_matches_scipy);
  RUN_TEST(test_slerp_matches_scipy);
  RUN_TEST(test_random_euler_round_trip);
  RUN_TEST(test_random_normalize_is_unit);
  RUN_TEST(test_random_dcm_round_trip);
  RUN_TEST(test_euler_canonical);
  RUN_TEST(test_gimbal_lock_sets_roll_to_zero);
  RUN_TEST(test_near_gimbal_lock_keeps_the_rotation);
  RUN_TEST(test_zero_and_null_inputs);
  RUN_TEST(test_near_zero_and_huge_quaternions);
  RUN_TEST(test_conj_inverse_canonical);
  RUN_TEST(test_compose_difference_and_angle);
  RUN_TEST(test_frames);
  RUN_TEST(test_nlerp_squad_ends);
}
