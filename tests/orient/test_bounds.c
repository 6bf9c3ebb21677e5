/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The documented bounds of drdc_dh_forward(), the link-by-link
 *        composition and inversion of its transforms, drdc_quat_slerp(),
 *        drdc_quat_nlerp() and drdc_axis_angle_from_quat() on random
 *        inputs over their whole documented domain (tests/ref/
 *        gen_orient_bounds.py: numpy and mpmath oracles on the exact
 *        integers). The tolerances are the headers' bounds;
 *        tools/accuracy/orient_bounds.py measures them on 12 000 and more
 *        cases per function.
 */
#include <drdc/orient_kinematics.h>

#include <stddef.h>

#include "orient_test_util.h"
#include "suites.h"
#include "unity.h"

#include "vectors_orient_bounds.h"

/* drdc_dh_forward(): rotation in LSB of Q1.30 for up to 16 links;
 * position 0.5 LSB of Q15.16 plus TOL_DH_POS_K_HALVES / 2 times 2^-30
 * of the sum of the link lengths. */
#define TOL_DH_ROT          6
#define TOL_DH_POS_K_HALVES 8
/* Link-by-link drdc_transform_compose() from drdc_dh_forward(), LSB. */
#define TOL_CHAIN_ROT 7
#define TOL_CHAIN_POS 13
/* T T^-1 - I: rotation in LSB; translation 1 LSB plus
 * TOL_INV_POS_K times 2^-30 of |t| (the largest part of T's). */
#define TOL_INV_ROT   11
#define TOL_INV_POS_K 12
/* Quaternion parts in LSB of Q1.30; the angle in 1/16 binary-angle
 * units (1.8 units plus the reference's rounding to 1/16). */
#define TOL_SLERP     3
#define TOL_NLERP     1
#define TOL_AXIS      1
#define TOL_ANGLE_SUB 29

static int64_t dh_pos_tol(int64_t span)
{
  /* 2^24 (0.5 / 2^16 + k 2^-30 span / 2^16) in 2^-24 m, plus the
   * reference's own rounding to 2^-24 m */
  const int64_t step = (int64_t)1 << 23;

  return 129 + (((TOL_DH_POS_K_HALVES * span) + step - 1) / step);
}

static void chain_of(const struct bounds_chain *c, drdc_dh_link_t *links,
                     int32_t *q)
{
  int32_t k;

  for (k = 0; k < c->n; k++) {
    links[k] = bounds_links[c->first + k].link;
    q[k] = bounds_links[c->first + k].q;
  }
}

/* The link transforms of links[0 .. n - 1] composed one by one onto
 * *acc; the first status that is not DRDC_OK, in link order. */
static drdc_status_t compose_chain(drdc_dh_convention_t cv,
                                   const drdc_dh_link_t *links,
                                   const int32_t *q, int32_t n,
                                   drdc_transform_t *acc)
{
  drdc_transform_t lt;
  drdc_status_t st = DRDC_OK;
  int32_t k;

  for (k = 0; (k < n) && (st == DRDC_OK); k++) {
    st = drdc_dh_link_transform(cv, &links[k], q[k], &lt);
    if (st == DRDC_OK) {
      st = drdc_transform_compose(acc, &lt, acc);
    }
  }
  return st;
}

static void test_dh_forward_random_chains(void)
{
  int64_t mr = 0;
  int64_t mp = 0;
  size_t i;

  for (i = 0u; i < COUNT(bounds_chains); i++) {
    const struct bounds_chain *c = &bounds_chains[i];
    drdc_dh_link_t links[DRDC_DH_MAX_LINKS];
    int32_t q[DRDC_DH_MAX_LINKS];
    drdc_transform_t t;
    int64_t d;
    unsigned k;

    chain_of(c, links, q);
    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_dh_forward((drdc_dh_convention_t)c->convention,
                                          links, (unsigned)c->n, q, &t));
    for (k = 0u; k < 9u; k++) {
      d = orient_abs64((int64_t)t.r.m[k / 3u][k % 3u] - c->r[k]);
      mr = (d > mr) ? d : mr;
      TEST_ASSERT_TRUE(d <= TOL_DH_ROT);
    }
    for (k = 0u; k < 3u; k++) {
      const int32_t p = (k == 0u) ? t.t.x : ((k == 1u) ? t.t.y : t.t.z);

      d = orient_abs64(((int64_t)p * 256) - c->t[k]);
      mp = (d > mp) ? d : mp;
      TEST_ASSERT_TRUE(d <= dh_pos_tol(c->span));
    }
  }
  ORIENT_REPORT("bounds dh rotation (LSB)", mr);
  ORIENT_REPORT("bounds dh position (2^-24 m)", mp);
}

static int64_t transform_diff(const drdc_transform_t *a,
                              const drdc_transform_t *b, int64_t *pos)
{
  int64_t m = 0;
  unsigned k;

  for (k = 0u; k < 9u; k++) {
    int64_t d =
        orient_abs64((int64_t)a->r.m[k / 3u][k % 3u] - b->r.m[k / 3u][k % 3u]);
    m = (d > m) ? d : m;
  }
  *pos = orient_abs64((int64_t)a->t.x - b->t.x);
  *pos = (orient_abs64((int64_t)a->t.y - b->t.y) > *pos)
             ? orient_abs64((int64_t)a->t.y - b->t.y)
             : *pos;
  *pos = (orient_abs64((int64_t)a->t.z - b->t.z) > *pos)
             ? orient_abs64((int64_t)a->t.z - b->t.z)
             : *pos;
  return m;
}

/* Consistency: the links composed one by one stay within the documented
 * distance of drdc_dh_forward(), and T T^-1 within its of the identity. */
static void test_dh_compose_and_invert_random_chains(void)
{
  const drdc_transform_t ident = {{{{DRDC_Q1_30_ONE, 0, 0},
                                    {0, DRDC_Q1_30_ONE, 0},
                                    {0, 0, DRDC_Q1_30_ONE}}},
                                  {0, 0, 0}};
  int64_t mcr = 0;
  int64_t mcp = 0;
  int64_t mir = 0;
  int64_t mip = 0;
  size_t i;

  for (i = 0u; i < COUNT(bounds_chains); i++) {
    const struct bounds_chain *c = &bounds_chains[i];
    const drdc_dh_convention_t cv = (drdc_dh_convention_t)c->convention;
    drdc_dh_link_t links[DRDC_DH_MAX_LINKS];
    int32_t q[DRDC_DH_MAX_LINKS];
    drdc_transform_t t;
    drdc_transform_t acc = ident;
    drdc_transform_t inv;
    int64_t r;
    int64_t p;
    int64_t tn;

    chain_of(c, links, q);
    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_dh_forward(cv, links, (unsigned)c->n, q, &t));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, compose_chain(cv, links, q, c->n, &acc));
    r = transform_diff(&acc, &t, &p);
    mcr = (r > mcr) ? r : mcr;
    mcp = (p > mcp) ? p : mcp;
    TEST_ASSERT_TRUE(r <= TOL_CHAIN_ROT);
    TEST_ASSERT_TRUE(p <= TOL_CHAIN_POS);
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_transform_invert(&t, &inv));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_transform_compose(&t, &inv, &inv));
    r = transform_diff(&inv, &ident, &p);
    tn = orient_abs64(t.t.x);
    tn = (orient_abs64(t.t.y) > tn) ? orient_abs64(t.t.y) : tn;
    tn = (orient_abs64(t.t.z) > tn) ? orient_abs64(t.t.z) : tn;
    mir = (r > mir) ? r : mir;
    mip = (p > mip) ? p : mip;
    TEST_ASSERT_TRUE(r <= TOL_INV_ROT);
    TEST_ASSERT_TRUE(p <=
                     1 + (((TOL_INV_POS_K * tn) + (((int64_t)1 << 30) - 1)) /
                          ((int64_t)1 << 30)));
  }
  ORIENT_REPORT("bounds chain vs dh rotation (LSB)", mcr);
  ORIENT_REPORT("bounds chain vs dh position (LSB)", mcp);
  ORIENT_REPORT("bounds T T^-1 rotation (LSB)", mir);
  ORIENT_REPORT("bounds T T^-1 translation (LSB)", mip);
}

/* The other side of the overflow rule: chains whose partial translation
 * leaves +-32768 m on the way (half of them ending back in range) fail
 * in the forward kinematics as in the link-by-link composition, and
 * leave the output unchanged. */
static void test_dh_forward_overflow_random_chains(void)
{
  const drdc_transform_t ident = {{{{DRDC_Q1_30_ONE, 0, 0},
                                    {0, DRDC_Q1_30_ONE, 0},
                                    {0, 0, DRDC_Q1_30_ONE}}},
                                  {0, 0, 0}};
  int back = 0;
  size_t i;

  for (i = 0u; i < COUNT(bounds_overflows); i++) {
    const struct bounds_overflow *c = &bounds_overflows[i];
    const drdc_dh_convention_t cv = (drdc_dh_convention_t)c->convention;
    drdc_dh_link_t links[DRDC_DH_MAX_LINKS];
    int32_t q[DRDC_DH_MAX_LINKS];
    drdc_transform_t t = ident;
    drdc_transform_t acc = ident;
    int32_t k;

    for (k = 0; k < c->n; k++) {
      links[k] = bounds_links[c->first + k].link;
      q[k] = bounds_links[c->first + k].q;
    }
    TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                          drdc_dh_forward(cv, links, (unsigned)c->n, q, &t));
    TEST_ASSERT_EQUAL_INT32(DRDC_Q1_30_ONE, t.r.m[0][0]);
    TEST_ASSERT_EQUAL_INT32(0, t.t.x);
    TEST_ASSERT_EQUAL_INT32(0, t.t.z);
    TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                          compose_chain(cv, links, q, c->n, &acc));
    back += c->back;
  }
  TEST_ASSERT_TRUE(back > 0);
}

static void quat_of(const int32_t p[4], drdc_quat_t *q)
{
  q->s = p[0];
  q->x = p[1];
  q->y = p[2];
  q->z = p[3];
}

typedef drdc_status_t (*interp_fn)(const drdc_quat_t *a, const drdc_quat_t *b,
                                   drdc_q1_30_t t, drdc_quat_t *out);

/* the largest distance of interp() from the oracle over n pairs, each
 * within tol */
static int64_t check_interp(interp_fn interp, const struct bounds_interp *v,
                            size_t n, int64_t tol)
{
  int64_t m = 0;
  size_t i;

  for (i = 0u; i < n; i++) {
    drdc_quat_t a;
    drdc_quat_t b;
    drdc_quat_t r;
    int64_t d;

    quat_of(v[i].a, &a);
    quat_of(v[i].b, &b);
    TEST_ASSERT_EQUAL_INT(DRDC_OK, interp(&a, &b, v[i].t, &r));
    d = orient_qdiff_signed(&r, v[i].q);
    m = (d > m) ? d : m;
    TEST_ASSERT_TRUE(d <= tol);
  }
  return m;
}

static void test_slerp_random_pairs(void)
{
  ORIENT_REPORT("bounds slerp (LSB)",
                check_interp(drdc_quat_slerp, bounds_slerp, COUNT(bounds_slerp),
                             TOL_SLERP));
}

static void test_nlerp_random_pairs(void)
{
  ORIENT_REPORT("bounds nlerp (LSB)",
                check_interp(drdc_quat_nlerp, bounds_nlerp, COUNT(bounds_nlerp),
                             TOL_NLERP));
}

/* The arcs from the exact dot product: a quarter turn apart within one
 * unit of a . b (cos -3.3e-10), where b's normalised scalar part rounds
 * to 0; and nlerp's dot of exactly -1, which a truncated sum took as 0.
 * The expected values are mpmath's (40 digits), rounded. */
static void test_interp_arc_from_exact_dot(void)
{
  const drdc_quat_t a = {DRDC_Q1_30_ONE, 0, 0, 0};
  const drdc_quat_t b = {-1, INT32_MAX, INT32_MAX, 0};
  const int32_t half[4] = {759250125, -536870912, -536870912, 0};
  const drdc_quat_t c = {1, 1, 0, 0};
  const drdc_quat_t e = {2, -3, 0, 0};
  const int32_t mid[4] = {-260420644, 1041682578, 0, 0};
  drdc_quat_t r;

  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_quat_slerp(&a, &b, DRDC_Q1_30_ONE / 2, &r));
  TEST_ASSERT_TRUE(orient_qdiff_signed(&r, half) <= TOL_SLERP);
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_quat_nlerp(&c, &e, DRDC_Q1_30_ONE / 2, &r));
  TEST_ASSERT_TRUE(orient_qdiff_signed(&r, mid) <= TOL_NLERP);
}

static void test_axis_angle_random_quaternions(void)
{
  int64_t ma = 0;
  int64_t mg = 0;
  size_t i;

  for (i = 0u; i < COUNT(bounds_axang); i++) {
    const struct bounds_axang *v = &bounds_axang[i];
    drdc_quat_t q;
    drdc_vec3_q1_30_t axis;
    drdc_bam32_t angle;
    int32_t got[3];
    int64_t d;

    quat_of(v->q, &q);
    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_axis_angle_from_quat(&q, &axis, &angle));
    got[0] = axis.x;
    got[1] = axis.y;
    got[2] = axis.z;
    d = orient_maxdiff32(got, v->axis, 3u);
    ma = (d > ma) ? d : ma;
    TEST_ASSERT_TRUE(d <= TOL_AXIS);
    d = orient_angle_err(angle, v->angle, BOUNDS_ANGLE_SUB);
    mg = (d > mg) ? d : mg;
    TEST_ASSERT_TRUE(d <= TOL_ANGLE_SUB);
  }
  ORIENT_REPORT("bounds axis (LSB)", ma);
  ORIENT_REPORT("bounds angle (1/16 units)", mg);
}

void suite_orient_bounds(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_dh_forward_random_chains);
  RUN_TEST(test_dh_compose_and_invert_random_chains);
  RUN_TEST(test_dh_forward_overflow_random_chains);
  RUN_TEST(test_slerp_random_pairs);
  RUN_TEST(test_nlerp_random_pairs);
  RUN_TEST(test_interp_arc_from_exact_dot);
  RUN_TEST(test_axis_angle_random_quaternions);
}
