/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Tests of homogeneous transforms and Denavit-Hartenberg forward
 *        kinematics: an independent numpy model of the PUMA 560 and of a
 *        7-link arm with prismatic joints (oracle checks), identities of
 *        compose/invert/apply (consistency checks), named bad inputs.
 *
 * The goals: position under 10 um, rotation within 8 LSB per element;
 * the tolerances below are the measured maxima.
 */
#include <drdc/orient_kinematics.h>
#include <drdc/orient_transform.h>

#include <stddef.h>

#include "orient_test_util.h"
#include "suites.h"
#include "unity.h"
#include "vectors_dh.h"

#define TOL_DH_ROT      2   /* LSB of Q1.30 per element */
#define TOL_DH_POS_SUB  127 /* 2^-24 m units: 7.6 um */
#define TOL_CHAIN_ROT   3   /* link-by-link compose vs forward, LSB */
#define TOL_CHAIN_POS   3   /* LSB of Q15.16 */
#define TOL_INVERSE_ROT 4   /* T T^-1 - I, LSB of Q1.30 */
#define TOL_INVERSE_POS 1   /* LSB of Q15.16 */

/* In-test random configurations of the consistency checks. */
#define CHAIN_CASES 500u

static void check_table(drdc_dh_convention_t conv, const drdc_dh_link_t *links,
                        unsigned n, const struct dh_vector *v, size_t count,
                        const char *name)
{
  int64_t mr = 0;
  int64_t mp = 0;
  size_t i;

  for (i = 0; i < count; i++) {
    drdc_transform_t t;
    int64_t d;
    int32_t pos[3];

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_dh_forward(conv, links, n, v[i].q, &t));
    d = orient_maxdiff32(&t.r.m[0][0], v[i].r, 9u);
    mr = (d > mr) ? d : mr;
    pos[0] = t.t.x;
    pos[1] = t.t.y;
    pos[2] = t.t.z;
    {
      unsigned k;

      for (k = 0u; k < 3u; k++) {
        d = orient_abs64(((int64_t)pos[k] * (DH_POS_SUB / 65536)) - v[i].t[k]);
        mp = (d > mp) ? d : mp;
      }
    }
  }
  ORIENT_REPORT(name, mr);
  ORIENT_REPORT("  position (2^-24 m)", mp);
  TEST_ASSERT_TRUE(mr <= TOL_DH_ROT);
  TEST_ASSERT_TRUE(mp <= TOL_DH_POS_SUB);
}

static void test_puma560_standard_matches_numpy(void)
{
  check_table(DRDC_DH_STANDARD, dh_puma560_standard, 6u, dh_puma_std_vectors,
              COUNT(dh_puma_std_vectors), "dh puma std rot LSB");
}

static void test_puma560_modified_matches_numpy(void)
{
  check_table(DRDC_DH_MODIFIED, dh_puma560_modified, 6u, dh_puma_mod_vectors,
              COUNT(dh_puma_mod_vectors), "dh puma mod rot LSB");
}

static void test_arm7_prismatic_standard_matches_numpy(void)
{
  check_table(DRDC_DH_STANDARD, dh_arm7_prismatic, 7u, dh_arm7_std_vectors,
              COUNT(dh_arm7_std_vectors), "dh arm7 std rot LSB");
}

static void test_arm7_prismatic_modified_matches_numpy(void)
{
  check_table(DRDC_DH_MODIFIED, dh_arm7_prismatic, 7u, dh_arm7_mod_vectors,
              COUNT(dh_arm7_mod_vectors), "dh arm7 mod rot LSB");
}

/* Consistency: composing the link transforms one by one (each rounded to
 * Q1.30 / Q15.16) agrees with the forward kinematics, and T T^-1 = I. */
static void test_chain_compose_and_invert(void)
{
  uint32_t seed = 0x5EED1234u;
  int64_t mr = 0;
  int64_t mp = 0;
  int64_t ir = 0;
  int64_t ip = 0;
  unsigned c;

  for (c = 0u; c < CHAIN_CASES; c++) {
    const drdc_dh_convention_t conv =
        ((c & 1u) != 0u) ? DRDC_DH_MODIFIED : DRDC_DH_STANDARD;
    int32_t q[16];
    drdc_dh_link_t links[16];
    drdc_transform_t fk;
    drdc_transform_t acc;
    drdc_transform_t lt;
    drdc_transform_t inv;
    unsigned k;
    unsigned n = 1u + (c % 16u);
    int64_t d;

    for (k = 0u; k < n; k++) {
      links[k] = dh_arm7_prismatic[k % 7u];
      q[k] = (links[k].type == DRDC_JOINT_REVOLUTE)
                 ? (int32_t)orient_rand(&seed)
                 : (int32_t)(orient_rand(&seed) % 40000u);
    }
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_dh_forward(conv, links, n, q, &fk));
    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_dh_link_transform(conv, &links[0], q[0], &acc));
    for (k = 1u; k < n; k++) {
      TEST_ASSERT_EQUAL_INT(DRDC_OK,
                            drdc_dh_link_transform(conv, &links[k], q[k], &lt));
      TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_transform_compose(&acc, &lt, &acc));
    }
    d = orient_maxdiff32(&fk.r.m[0][0], &acc.r.m[0][0], 9u);
    mr = (d > mr) ? d : mr;
    d = orient_maxdiff32(&fk.t.x, &acc.t.x, 3u);
    mp = (d > mp) ? d : mp;
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_transform_invert(&fk, &inv));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_transform_compose(&fk, &inv, &acc));
    for (k = 0u; k < 9u; k++) {
      int32_t want = ((k % 4u) == 0u) ? DRDC_Q1_30_ONE : 0;

      d = orient_abs64((int64_t)(&acc.r.m[0][0])[k] - want);
      ir = (d > ir) ? d : ir;
    }
    d = orient_abs64(acc.t.x);
    d = (orient_abs64(acc.t.y) > d) ? orient_abs64(acc.t.y) : d;
    d = (orient_abs64(acc.t.z) > d) ? orient_abs64(acc.t.z) : d;
    ip = (d > ip) ? d : ip;
  }
  ORIENT_REPORT("chain vs forward rot LSB", mr);
  ORIENT_REPORT("chain vs forward pos LSB", mp);
  ORIENT_REPORT("T T^-1 rot LSB", ir);
  ORIENT_REPORT("T T^-1 pos LSB", ip);
  TEST_ASSERT_TRUE(mr <= TOL_CHAIN_ROT);
  TEST_ASSERT_TRUE(mp <= TOL_CHAIN_POS);
  TEST_ASSERT_TRUE(ir <= TOL_INVERSE_ROT);
  TEST_ASSERT_TRUE(ip <= TOL_INVERSE_POS);
}

/* Local <-> global: a frame 6.4e6 m from the origin (ECEF scale), a point
 * 10 m from it: to world and back is exact to the rounding of R. */
static void test_global_local_round_trip(void)
{
  const drdc_quat_t q = {759250125, 0, 0, 759250125}; /* yaw 90 deg */
  const drdc_vec3_q15_16_t zero = {0, 0, 0};
  const drdc_vec3_q15_16_t p = {10 << 16, 3 << 16, -(1 << 15)};
  drdc_transform_t local;
  drdc_transform_global_t g;
  drdc_transform_global_t g2;
  drdc_vec3_q47_16_t w;
  drdc_vec3_q15_16_t back;
  drdc_vec3_q15_16_t dir;

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_transform_from_quat(&q, &zero, &local));
  {
    unsigned k; /* element copy: no memcpy on the freestanding targets */

    for (k = 0u; k < 3u; k++) {
      g.r.m[k][0] = local.r.m[k][0];
      g.r.m[k][1] = local.r.m[k][1];
      g.r.m[k][2] = local.r.m[k][2];
    }
  }
  g.t.x = INT64_C(6400000) << 16;
  g.t.y = -(INT64_C(12345) << 16);
  g.t.z = INT64_C(5) << 16;
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_transform_global_to_world(&g, &p, &w));
  /* yaw 90: body x (10 m) points east (+y), body y (3 m) points west */
  TEST_ASSERT_TRUE(w.x == (INT64_C(6400000) << 16) - (INT64_C(3) << 16));
  TEST_ASSERT_TRUE(w.y == -(INT64_C(12345) << 16) + (INT64_C(10) << 16));
  TEST_ASSERT_TRUE(w.z == (INT64_C(5) << 16) - (1 << 15));
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_transform_global_to_local(&g, &w, &back));
  TEST_ASSERT_INT32_WITHIN(1, p.x, back.x);
  TEST_ASSERT_INT32_WITHIN(1, p.y, back.y);
  TEST_ASSERT_INT32_WITHIN(1, p.z, back.z);
  /* far beyond the local range: reported, not wrapped */
  w.x += INT64_C(40000) << 16;
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_transform_global_to_local(&g, &w, &back));
  /* a global frame followed by a local one */
  local.t = p;
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_transform_global_compose(&g, &local, &g2));
  TEST_ASSERT_TRUE(g2.t.y == -(INT64_C(12345) << 16) + (INT64_C(10) << 16));
  /* directions ignore the translation */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_transform_direction(&local, &p, &dir));
  TEST_ASSERT_INT32_WITHIN(1, -p.y, dir.x);
  TEST_ASSERT_INT32_WITHIN(1, p.x, dir.y);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_transform_point(&local, &p, &dir));
  TEST_ASSERT_INT32_WITHIN(1, p.x - p.y, dir.x);
}

static void test_dh_bad_inputs(void)
{
  drdc_transform_t t;
  drdc_dh_link_t bad = dh_arm7_prismatic[1];
  int32_t q[17];
  drdc_dh_link_t links[17];
  unsigned k;

  t.t.x = 99;
  for (k = 0u; k < 17u; k++) {
    links[k] = dh_puma560_standard[k % 6u];
    q[k] = (int32_t)(k * 12345u);
  }
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_dh_forward(DRDC_DH_STANDARD, links, 17u, q, &t));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_dh_forward(DRDC_DH_STANDARD, NULL, 2u, q, &t));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE, drdc_dh_forward((drdc_dh_convention_t)7, links, 2u, q, &t));
  /* prismatic joint beyond the Q15.16 range */
  bad.d = INT32_MAX - 5;
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_dh_link_transform(DRDC_DH_STANDARD, &bad, 10, &t));
  bad.type = (drdc_joint_type_t)3;
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_dh_link_transform(DRDC_DH_STANDARD, &bad, 0, &t));
  TEST_ASSERT_EQUAL_INT32(99, t.t.x);
  /* no links: the identity */
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_dh_forward(DRDC_DH_MODIFIED, NULL, 0u, NULL, &t));
  TEST_ASSERT_EQUAL_INT32(DRDC_Q1_30_ONE, t.r.m[1][1]);
  TEST_ASSERT_EQUAL_INT32(0, t.t.x);
}

/* Links along z (alpha = theta = 0, a = 0) of offsets d: the partial
 * translations are exact sums, so the edge of the Q15.16 range can be
 * hit to the LSB. */
static void z_links(drdc_dh_link_t *links, const int32_t *d, unsigned n)
{
  unsigned k;

  for (k = 0u; k < n; k++) {
    links[k].a = 0;
    links[k].alpha = 0u;
    links[k].d = d[k];
    links[k].theta = 0u;
    links[k].type = DRDC_JOINT_REVOLUTE;
  }
}

/* drdc_transform_compose() of the link transforms one by one: its
 * status, the first error in link order. */
static drdc_status_t compose_links(drdc_dh_convention_t cv,
                                   const drdc_dh_link_t *links, unsigned n,
                                   const int32_t *q)
{
  drdc_transform_t acc;
  drdc_transform_t lt;
  drdc_status_t st = drdc_dh_forward(cv, links, 0u, q, &acc); /* identity */
  unsigned k;

  for (k = 0u; (k < n) && (st == DRDC_OK); k++) {
    st = drdc_dh_link_transform(cv, &links[k], q[k], &lt);
    if (st == DRDC_OK) {
      st = drdc_transform_compose(&acc, &lt, &acc);
    }
  }
  return st;
}

/* One DRDC_E_OVERFLOW rule for drdc_dh_forward(): a partial translation
 * T1 ... Tk leaving the Q15.16 range fails the chain, as composing the
 * links one by one does, even when later links bring it back. Both sides
 * of the edge (+32768 - 2^-16 m and -32768 m are in range), in both
 * conventions, and the statuses in the order of the link-by-link
 * product although drdc_dh_forward() carries the chain row by row. */
static void test_dh_overflow_rule(void)
{
  static const int32_t edge_in[2] = {INT32_C(1) << 30, (INT32_C(1) << 30) - 1};
  static const int32_t edge_out[2] = {INT32_C(1) << 30, INT32_C(1) << 30};
  static const int32_t neg_in[2] = {-(INT32_C(1) << 30), -(INT32_C(1) << 30)};
  static const int32_t neg_out[3] = {-(INT32_C(1) << 30), -(INT32_C(1) << 30),
                                     -1};
  static const int32_t there_back[3] = {
      INT32_C(30000) << 16, INT32_C(30000) << 16, -(INT32_C(30000) << 16)};
  static const int32_t q[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  drdc_transform_t t;
  drdc_dh_link_t links[8];
  int32_t d8[8];
  unsigned cv;
  unsigned k;

  for (cv = 0u; cv < 2u; cv++) {
    const drdc_dh_convention_t c = (drdc_dh_convention_t)cv;

    z_links(links, edge_in, 2u);
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_dh_forward(c, links, 2u, q, &t));
    TEST_ASSERT_EQUAL_INT32(INT32_MAX, t.t.z);
    TEST_ASSERT_EQUAL_INT(DRDC_OK, compose_links(c, links, 2u, q));
    z_links(links, edge_out, 2u);
    t.t.z = 99;
    TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                          drdc_dh_forward(c, links, 2u, q, &t));
    TEST_ASSERT_EQUAL_INT32(99, t.t.z);
    TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, compose_links(c, links, 2u, q));
    z_links(links, neg_in, 2u);
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_dh_forward(c, links, 2u, q, &t));
    TEST_ASSERT_EQUAL_INT32(INT32_MIN, t.t.z);
    TEST_ASSERT_EQUAL_INT(DRDC_OK, compose_links(c, links, 2u, q));
    z_links(links, neg_out, 3u);
    TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                          drdc_dh_forward(c, links, 3u, q, &t));
    TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, compose_links(c, links, 3u, q));
    /* out to 60 km and back to 30 km: the end is in range, the way not */
    z_links(links, there_back, 3u);
    TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                          drdc_dh_forward(c, links, 3u, q, &t));
    TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, compose_links(c, links, 3u, q));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_dh_forward(c, &links[1], 2u, q, &t));
    TEST_ASSERT_EQUAL_INT32(0, t.t.z);
  }
  /* along x (row 0): standard DH puts a along the rotated x */
  z_links(links, q, 2u);
  links[0].a = INT32_C(20000) << 16;
  links[1].a = INT32_C(12768) << 16;
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_dh_forward(DRDC_DH_STANDARD, links, 2u, q, &t));
  links[1].a -= 1;
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_dh_forward(DRDC_DH_STANDARD, links, 2u, q, &t));
  TEST_ASSERT_EQUAL_INT32(INT32_MAX, t.t.x);

  /* Status order: 30 000 m per link along z, so links 0..1 reach
   * 60 000 m. */
  for (k = 0u; k < 8u; k++) {
    d8[k] = INT32_C(30000) << 16;
  }
  z_links(links, d8, 8u);
  t.r.m[2][2] = 99;
  t.t.z = 99;
  /* the overflow at link 1 comes before the bad joint type of link 2 */
  links[2].type = (drdc_joint_type_t)3;
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_dh_forward(DRDC_DH_STANDARD, links, 3u, q, &t));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        compose_links(DRDC_DH_STANDARD, links, 3u, q));
  TEST_ASSERT_EQUAL_INT32(99, t.t.z);
  /* a bad type at link 1 comes before it; found by the first row, while
   * the overflow would be the last row's */
  links[2].type = DRDC_JOINT_REVOLUTE;
  links[1].type = (drdc_joint_type_t)3;
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_dh_forward(DRDC_DH_MODIFIED, links, 8u, q, &t));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        compose_links(DRDC_DH_MODIFIED, links, 8u, q));
  TEST_ASSERT_EQUAL_INT32(99, t.r.m[2][2]);
  /* the overflow in the last row (link 1) before the bad type of link 6,
   * found by the first */
  links[1].type = DRDC_JOINT_REVOLUTE;
  links[6].type = (drdc_joint_type_t)3;
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_dh_forward(DRDC_DH_MODIFIED, links, 8u, q, &t));
  TEST_ASSERT_EQUAL_INT32(99, t.t.z);
  /* a prismatic d + q beyond Q15.16 is an overflow too */
  links[6].type = DRDC_JOINT_PRISMATIC;
  links[0].d = INT32_MAX - 5;
  links[0].type = DRDC_JOINT_PRISMATIC;
  d8[0] = 10;
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_dh_forward(DRDC_DH_MODIFIED, links, 1u, d8, &t));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        compose_links(DRDC_DH_MODIFIED, links, 1u, d8));
  TEST_ASSERT_EQUAL_INT32(99, t.r.m[2][2]);
}

void suite_orient_transform(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_puma560_standard_matches_numpy);
  RUN_TEST(test_puma560_modified_matches_numpy);
  RUN_TEST(test_arm7_prismatic_standard_matches_numpy);
  RUN_TEST(test_arm7_prismatic_modified_matches_numpy);
  RUN_TEST(test_chain_compose_and_invert);
  RUN_TEST(test_global_local_round_trip);
  RUN_TEST(test_dh_bad_inputs);
  RUN_TEST(test_dh_overflow_rule);
}
