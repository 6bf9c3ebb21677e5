/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Tests of fixed/ trig against mpmath: full-circle grids rebuilt
 *        from one stored quadrant or octant by exact symmetries, random
 *        and named angles stored whole, poles, domain errors and NULLs.
 *
 * Tolerances are the documented bounds (fixed_trig.h), equal to the
 * largest error measured on these vectors.
 */
#include <drdc/fixed_trig.h>

#include <stddef.h>

#include "suites.h"
#include "unity.h"
#include "vectors_trig.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

/* Documented max errors: LSB of Q1.30, Q15.16 and binary-angle units. */
#define SIN_TOL   1
#define TAN_TOL   1
#define ATAN2_TOL 1
#define ASIN_TOL  1

static int32_t worst; /* largest |error| of the running test */

static void note(int32_t got, int32_t want)
{
  int64_t e = (int64_t)got - want;

  if (e < 0) {
    e = -e;
  }
  if (e > worst) {
    worst = (int32_t)((e > INT32_MAX) ? INT32_MAX : e);
  }
}

/* Angles compare modulo one turn. */
static void note_angle(uint32_t got, uint32_t want)
{
  int64_t d = (int64_t)(got - want);

  if (d >= ((int64_t)1 << 31)) {
    d -= (int64_t)1 << 32;
  }
  note((d < INT32_MIN + 1) ? INT32_MAX : (int32_t)((d < 0) ? -d : d), 0);
}

/* The grids are stored as second differences from R[0] = 0 and R[1] =
 * `first`: R[k + 1] = 2 R[k] - R[k - 1] + dd[k - 1] (v = R[k], prev =
 * R[k - 1]) up to the last point n; after it, 0 (never compared). */
static int32_t grid_next(int32_t k, int32_t n, int32_t first, const int8_t *dd,
                         int32_t v, int32_t prev)
{
  if (k == 0) {
    return first;
  }
  if (k < n) {
    return (2 * v) - prev + dd[k - 1];
  }
  return 0;
}

/* Every grid angle k 2^16 of the circle, sin and cos (131 072 values),
 * from the stored first quadrant by sin(pi - a) = sin(a), sin(pi + a) =
 * -sin(a), cos(pi/2 -+ a) = +-sin(a), cos(3pi/2 -+ a) = -+sin(a). */
static void test_sin_cos_full_circle_grid(void)
{
  int32_t prev = 0;
  int32_t v = 0;
  int32_t k;

  worst = 0;
  for (k = 0; k <= TRIG_GRID_QUAD; k++) {
    uint32_t a = (uint32_t)k * TRIG_GRID_STEP;
    int32_t next;

    next = grid_next(k, TRIG_GRID_QUAD, SIN_GRID_1, sin_dd, v, prev);
    note(drdc_fx_sin_bam32(a), v);
    note(drdc_fx_sin_bam32((UINT32_C(1) << 31) - a), v);
    note(drdc_fx_sin_bam32((UINT32_C(1) << 31) + a), -v);
    note(drdc_fx_sin_bam32(0u - a), -v);
    note(drdc_fx_cos_bam32((UINT32_C(1) << 30) - a), v);
    note(drdc_fx_cos_bam32((UINT32_C(1) << 30) + a), -v);
    note(drdc_fx_cos_bam32((UINT32_C(3) << 30) - a), -v);
    note(drdc_fx_cos_bam32((UINT32_C(3) << 30) + a), v);
    prev = v;
    v = next;
  }
  TEST_ASSERT_EQUAL_INT32(1 << 30, prev); /* the rebuild ended at sin(90) */
  TEST_ASSERT_LESS_OR_EQUAL_INT32(SIN_TOL, worst);
}

static void test_sin_cos_random_and_named(void)
{
  size_t i;

  worst = 0;
  for (i = 0; i < COUNT(sin_vectors); i++) {
    drdc_q1_30_t s = 0;
    drdc_q1_30_t c = 0;

    drdc_fx_sincos_bam32(sin_vectors[i].a, &s, &c);
    note(s, sin_vectors[i].s);
    note(c, sin_vectors[i].c);
    TEST_ASSERT_EQUAL_INT32(s, drdc_fx_sin_bam32(sin_vectors[i].a));
    TEST_ASSERT_EQUAL_INT32(c, drdc_fx_cos_bam32(sin_vectors[i].a));
  }
  TEST_ASSERT_LESS_OR_EQUAL_INT32(SIN_TOL, worst);
}

/* Exact values at the quadrant boundaries, and NULL outputs skipped. */
static void test_sin_cos_exact_points(void)
{
  drdc_q1_30_t s = 5;

  TEST_ASSERT_EQUAL_INT32(0, drdc_fx_sin_bam32(0u));
  TEST_ASSERT_EQUAL_INT32(1 << 30, drdc_fx_sin_bam32(UINT32_C(1) << 30));
  TEST_ASSERT_EQUAL_INT32(0, drdc_fx_sin_bam32(UINT32_C(1) << 31));
  TEST_ASSERT_EQUAL_INT32(-(1 << 30), drdc_fx_sin_bam32(UINT32_C(3) << 30));
  TEST_ASSERT_EQUAL_INT32(1 << 30, drdc_fx_cos_bam32(0u));
  TEST_ASSERT_EQUAL_INT32(0, drdc_fx_cos_bam32(UINT32_C(1) << 30));
  TEST_ASSERT_EQUAL_INT32(-(1 << 30), drdc_fx_cos_bam32(UINT32_C(1) << 31));
  TEST_ASSERT_EQUAL_INT32(0, drdc_fx_cos_bam32(UINT32_C(3) << 30));
  TEST_ASSERT_EQUAL_INT32(759250125, drdc_fx_sin_bam32(UINT32_C(1) << 29));
  drdc_fx_sincos_bam32(1u, NULL, NULL);
  drdc_fx_sincos_bam32(1u, &s, NULL);
  TEST_ASSERT_EQUAL_INT32(2, s); /* sin(1.46e-9 rad) 2^30 = 1.57 */
}

/* tan on the 65 536-point grid minus the poles, from the first quadrant
 * by tan(-a) = -tan(a) and tan(pi + a) = tan(a). */
static void test_tan_full_circle_grid(void)
{
  size_t pos = 0;
  int32_t t = 0;
  int32_t k;

  worst = 0;
  for (k = 0; k < TRIG_GRID_QUAD; k++) {
    uint32_t a = (uint32_t)k * TRIG_GRID_STEP;
    drdc_q15_16_t got[4] = {0, 0, 0, 0};

    if (k > 0) {
      uint32_t diff = 0;
      unsigned shift = 0;
      uint8_t byte;

      do {
        byte = tan_leb[pos++];
        diff |= (uint32_t)(byte & 0x7Fu) << shift;
        shift += 7u;
      } while ((byte & 0x80u) != 0u);
      t += (int32_t)diff;
    }
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_tan_bam32(a, &got[0]));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_tan_bam32(0u - a, &got[1]));
    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_fx_tan_bam32((UINT32_C(1) << 31) + a, &got[2]));
    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_fx_tan_bam32((UINT32_C(1) << 31) - a, &got[3]));
    note(got[0], t);
    note(got[1], -t);
    note(got[2], t);
    note(got[3], -t);
  }
  TEST_ASSERT_EQUAL_UINT32(COUNT(tan_leb), pos);
  TEST_ASSERT_LESS_OR_EQUAL_INT32(TAN_TOL, worst);
}

/* Near the poles and random: overflow reported, saturation clamps. */
static void test_tan_near_poles_and_random(void)
{
  size_t i;

  worst = 0;
  for (i = 0; i < COUNT(tan_vectors); i++) {
    const struct tan_vector *v = &tan_vectors[i];
    drdc_q15_16_t t = 0x1234;

    if (v->over) {
      TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_fx_tan_bam32(v->a, &t));
      TEST_ASSERT_EQUAL_INT32(0x1234, t);
      TEST_ASSERT_EQUAL_INT(DRDC_W_SATURATED, drdc_fx_tan_bam32_sat(v->a, &t));
      TEST_ASSERT_EQUAL_INT32(v->t, t);
    } else {
      TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_tan_bam32(v->a, &t));
      note(t, v->t);
      TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_tan_bam32_sat(v->a, &t));
    }
  }
  TEST_ASSERT_LESS_OR_EQUAL_INT32(TAN_TOL, worst);
}

static void test_tan_poles_and_bad_inputs(void)
{
  drdc_q15_16_t t = 77;

  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                        drdc_fx_tan_bam32(UINT32_C(1) << 30, &t));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                        drdc_fx_tan_bam32(UINT32_C(3) << 30, &t));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                        drdc_fx_tan_bam32_sat(UINT32_C(1) << 30, &t));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_tan_bam32(0u, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_tan_bam32_sat(0u, NULL));
  TEST_ASSERT_EQUAL_INT32(77, t);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_tan_bam32(UINT32_C(1) << 29, &t));
  TEST_ASSERT_EQUAL_INT32(1 << 16, t);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_tan_bam32(UINT32_C(3) << 29, &t));
  TEST_ASSERT_EQUAL_INT32(-(1 << 16), t);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_tan_bam32(UINT32_C(1) << 31, &t));
  TEST_ASSERT_EQUAL_INT32(0, t);
}

/* Regression: before tan used the cot series within 2^21 units of a pole,
 * the quotient of two kernel values there was off by up to 53 LSB (the
 * kernel's 2^-38.9 absolute precision on a tiny denominator). mpmath
 * values, exactly on both sides of the pole at 90 degrees. */
static void test_regression_tan_near_pole_precision(void)
{
  static const struct {
    uint32_t d;      /* distance from the pole, units */
    int32_t tan_q16; /* tan(90 deg - d), rounded */
  } pt[] = {
      {100000u, 447981336},                 /* 447981335.806 */
      {(UINT32_C(1) << 21) - 1u, 21361358}, /* last cot-series point */
      {UINT32_C(1) << 21, 21361348},        /* first kernel point */
      {UINT32_C(1) << 24, 2669641},
  };
  size_t i;

  for (i = 0; i < COUNT(pt); i++) {
    drdc_q15_16_t t = 0;

    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_fx_tan_bam32((UINT32_C(1) << 30) - pt[i].d, &t));
    TEST_ASSERT_EQUAL_INT32(pt[i].tan_q16, t);
    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_fx_tan_bam32((UINT32_C(1) << 30) + pt[i].d, &t));
    TEST_ASSERT_EQUAL_INT32(-pt[i].tan_q16, t);
  }
}

/* 8 octants x 8 193 grid points from the stored octant. */
static void test_atan2_full_circle_grid(void)
{
  const uint32_t q = UINT32_C(1) << 30;
  int32_t prev = 0;
  int32_t v = 0;
  int32_t k;

  worst = 0;
  for (k = 0; k <= ATAN_GRID_OCT; k++) {
    int32_t X = INT32_MAX;
    int32_t Y = (int32_t)(((int64_t)k * INT32_MAX) / ATAN_GRID_OCT);
    uint32_t A = (uint32_t)v;
    struct {
      int32_t y, x;
      uint32_t want;
    } pt[8];
    int j;
    int32_t next;

    next = grid_next(k, ATAN_GRID_OCT, ATAN_GRID_1, atan_dd, v, prev);
    pt[0].y = Y;
    pt[0].x = X;
    pt[0].want = A;
    pt[1].y = X;
    pt[1].x = Y;
    pt[1].want = q - A;
    pt[2].y = X;
    pt[2].x = -Y;
    pt[2].want = q + A;
    pt[3].y = Y;
    pt[3].x = -X;
    pt[3].want = (2u * q) - A;
    pt[4].y = -Y;
    pt[4].x = -X;
    pt[4].want = (2u * q) + A;
    pt[5].y = -X;
    pt[5].x = -Y;
    pt[5].want = (3u * q) - A;
    pt[6].y = -X;
    pt[6].x = Y;
    pt[6].want = (3u * q) + A;
    pt[7].y = -Y;
    pt[7].x = X;
    pt[7].want = 0u - A;
    for (j = 0; j < 8; j++) {
      drdc_bam32_t got = 0;

      TEST_ASSERT_EQUAL_INT(DRDC_OK,
                            drdc_fx_atan2_bam32(pt[j].y, pt[j].x, &got));
      note_angle(got, pt[j].want);
    }
    prev = v;
    v = next;
  }
  TEST_ASSERT_EQUAL_INT32(1 << 29, prev);
  TEST_ASSERT_LESS_OR_EQUAL_INT32(ATAN2_TOL, worst);
}

static void test_atan2_random_and_extremes(void)
{
  size_t i;
  drdc_bam32_t a = 5;

  worst = 0;
  for (i = 0; i < COUNT(atan2_vectors); i++) {
    drdc_bam32_t got = 0;

    TEST_ASSERT_EQUAL_INT(
        DRDC_OK,
        drdc_fx_atan2_bam32(atan2_vectors[i].y, atan2_vectors[i].x, &got));
    note_angle(got, atan2_vectors[i].a);
  }
  TEST_ASSERT_LESS_OR_EQUAL_INT32(ATAN2_TOL, worst);
  /* exact directions */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_atan2_bam32(0, INT32_MIN, &a));
  TEST_ASSERT_EQUAL_UINT32(UINT32_C(1) << 31, a);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_atan2_bam32(INT32_MIN, INT32_MIN, &a));
  TEST_ASSERT_EQUAL_UINT32(UINT32_C(5) << 29, a);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_atan2_bam32(1, -1, &a));
  TEST_ASSERT_EQUAL_UINT32(UINT32_C(3) << 29, a);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_atan2_bam32(-7, 0, &a));
  TEST_ASSERT_EQUAL_UINT32(UINT32_C(3) << 30, a);
  a = 5;
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_fx_atan2_bam32(0, 0, &a));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_atan2_bam32(1, 1, NULL));
  TEST_ASSERT_EQUAL_UINT32(5u, a);
}

/* atan2 midway between the nodes of the atan table (t = i / 128), where
 * the cubic's truncation is largest (|h| = 2^-8, 0.031 units): y / x =
 * (2k + 1) / 256 for k = 0..127, x = 2^30 (t exact in Q32; the tie goes
 * to the upper node, h = -2^-8). mpmath's atan, rounded
 * (tests/ref/gen_fixed_trig.py). */
static void test_atan2_between_atan_nodes(void)
{
  size_t k;

  worst = 0;
  for (k = 0; k < COUNT(atan2_midnode); k++) {
    drdc_bam32_t got = 0;

    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_fx_atan2_bam32((int32_t)(((2u * k) + 1u) << 22),
                                              INT32_C(1) << 30, &got));
    note_angle(got, atan2_midnode[k]);
  }
  TEST_ASSERT_LESS_OR_EQUAL_INT32(ATAN2_TOL, worst);
}

/* asin and acos of the 16 385 grid sines and their negatives. */
static void test_asin_acos_grid(void)
{
  size_t big = 0;
  int32_t prev = 0;
  int32_t v = 0;
  int32_t k;

  worst = 0;
  for (k = 0; k <= TRIG_GRID_QUAD; k++) {
    uint32_t want = (uint32_t)k * TRIG_GRID_STEP;
    drdc_bam32_t got[4] = {0, 0, 0, 0};
    int32_t next;

    int32_t dev = asin_dev[k];

    if (dev == -128) {
      TEST_ASSERT_EQUAL_UINT16(k, asin_dev_big[big].k);
      dev = asin_dev_big[big++].dev;
    }
    want = want + (uint32_t)dev;
    next = grid_next(k, TRIG_GRID_QUAD, SIN_GRID_1, sin_dd, v, prev);
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_asin_q1_30(v, &got[0]));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_asin_q1_30(-v, &got[1]));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_acos_q1_30(v, &got[2]));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_acos_q1_30(-v, &got[3]));
    note_angle(got[0], want);
    note_angle(got[1], 0u - want);
    note_angle(got[2], (UINT32_C(1) << 30) - want);
    note_angle(got[3], (UINT32_C(1) << 30) + want);
    prev = v;
    v = next;
  }
  TEST_ASSERT_EQUAL_UINT32(COUNT(asin_dev_big), big);
  TEST_ASSERT_LESS_OR_EQUAL_INT32(ASIN_TOL, worst);
}

static void test_asin_acos_random_and_bad_inputs(void)
{
  size_t i;
  drdc_bam32_t a = 9;

  worst = 0;
  for (i = 0; i < COUNT(asin_vectors); i++) {
    drdc_bam32_t s = 0;
    drdc_bam32_t c = 0;

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_asin_q1_30(asin_vectors[i].x, &s));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_acos_q1_30(asin_vectors[i].x, &c));
    note_angle(s, asin_vectors[i].a);
    note_angle(c, (UINT32_C(1) << 30) - asin_vectors[i].a);
  }
  TEST_ASSERT_LESS_OR_EQUAL_INT32(ASIN_TOL, worst);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_asin_q1_30(1 << 30, &a));
  TEST_ASSERT_EQUAL_UINT32(UINT32_C(1) << 30, a);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_acos_q1_30(-(1 << 30), &a));
  TEST_ASSERT_EQUAL_UINT32(UINT32_C(1) << 31, a);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_acos_q1_30(1 << 30, &a));
  TEST_ASSERT_EQUAL_UINT32(0u, a);
  a = 9;
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_fx_asin_q1_30((1 << 30) + 1, &a));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_fx_asin_q1_30(INT32_MIN, &a));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_fx_acos_q1_30(-(1 << 30) - 1, &a));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_fx_acos_q1_30(INT32_MAX, &a));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_asin_q1_30(0, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_acos_q1_30(0, NULL));
  TEST_ASSERT_EQUAL_UINT32(9u, a);
}

void suite_fixed_trig(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_sin_cos_full_circle_grid);
  RUN_TEST(test_sin_cos_random_and_named);
  RUN_TEST(test_sin_cos_exact_points);
  RUN_TEST(test_tan_full_circle_grid);
  RUN_TEST(test_tan_near_poles_and_random);
  RUN_TEST(test_tan_poles_and_bad_inputs);
  RUN_TEST(test_regression_tan_near_pole_precision);
  RUN_TEST(test_atan2_full_circle_grid);
  RUN_TEST(test_atan2_random_and_extremes);
  RUN_TEST(test_atan2_between_atan_nodes);
  RUN_TEST(test_asin_acos_grid);
  RUN_TEST(test_asin_acos_random_and_bad_inputs);
}
