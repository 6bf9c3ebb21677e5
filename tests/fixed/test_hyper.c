/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Tests of fixed/ hyperbolic functions against mpmath: a grid over
 *        each domain (both signs by symmetry), random arguments of every
 *        magnitude, the domain edges, overflow and NULL outputs.
 */
#include <drdc/fixed_hyper.h>

#include <stddef.h>

#include "suites.h"
#include "unity.h"
#include "vectors_hyper.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

/* Documented max errors in LSB of Q5.58 (fixed_hyper.h). */
#define SINH_TOL  3
#define COSH_TOL  3
#define ATANH_TOL 1
#define ASINH_TOL 1

typedef drdc_status_t (*hyper_fn)(drdc_q5_58_t, drdc_q5_58_t *);

static int64_t worst;

/* Call f(x) and note its error against want. */
static void note(hyper_fn f, int64_t x, int64_t want)
{
  int64_t got = 0;
  int64_t e;

  TEST_ASSERT_EQUAL_INT(DRDC_OK, f(x, &got));
  e = (got > want) ? (got - want) : (want - got);
  if (e > worst) {
    worst = e;
  }
}

/* f on the grid k step for both signs (odd: f(-x) = -f(x); even:
 * f(-x) = f(x)), and on the stored random arguments. */
static int64_t check(hyper_fn f, int odd, const int64_t *grid, size_t count,
                     int64_t step, const struct hyper_vector *v, size_t nv)
{
  size_t k;

  worst = 0;
  for (k = 0; k < count; k++) {
    int64_t x = (int64_t)k * step;

    note(f, x, grid[k]);
    note(f, -x, odd ? -grid[k] : grid[k]);
  }
  for (k = 0; k < nv; k++) {
    note(f, v[k].x, v[k].y);
  }
  return worst;
}

static void test_sinh(void)
{
  int64_t worst_sinh = check(drdc_fx_sinh_q5_58, 1, sinh_grid, COUNT(sinh_grid),
                             SINH_GRID_STEP, sinh_vectors, COUNT(sinh_vectors));

  TEST_ASSERT_LESS_OR_EQUAL_INT64(SINH_TOL, worst_sinh);
}

static void test_cosh(void)
{
  int64_t worst_cosh = check(drdc_fx_cosh_q5_58, 0, cosh_grid, COUNT(cosh_grid),
                             COSH_GRID_STEP, cosh_vectors, COUNT(cosh_vectors));

  TEST_ASSERT_LESS_OR_EQUAL_INT64(COSH_TOL, worst_cosh);
}

static void test_atanh(void)
{
  int64_t worst_atanh =
      check(drdc_fx_atanh_q5_58, 1, atanh_grid, COUNT(atanh_grid),
            ATANH_GRID_STEP, atanh_vectors, COUNT(atanh_vectors));

  TEST_ASSERT_LESS_OR_EQUAL_INT64(ATANH_TOL, worst_atanh);
}

static void test_asinh(void)
{
  int64_t worst_asinh =
      check(drdc_fx_asinh_q5_58, 1, asinh_grid, COUNT(asinh_grid),
            ASINH_GRID_STEP, asinh_vectors, COUNT(asinh_vectors));

  TEST_ASSERT_LESS_OR_EQUAL_INT64(ASINH_TOL, worst_asinh);
}

/* Exact points, domain edges, overflow, NULL: outputs unchanged. */
static void test_edges_and_bad_inputs(void)
{
  drdc_q5_58_t y = 0;

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_sinh_q5_58(0, &y));
  TEST_ASSERT_EQUAL_INT64(0, y);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_cosh_q5_58(0, &y));
  TEST_ASSERT_EQUAL_INT64(DRDC_Q5_58_ONE, y);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_atanh_q5_58(0, &y));
  TEST_ASSERT_EQUAL_INT64(0, y);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_asinh_q5_58(0, &y));
  TEST_ASSERT_EQUAL_INT64(0, y);
  y = 77;
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_fx_sinh_q5_58(INT64_C(5) << 58, &y));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_fx_sinh_q5_58(INT64_MIN, &y));
  /* just past asinh(32) = 4.159127 and acosh(32) = 4.158639 */
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_fx_sinh_q5_58(INT64_C(1198886316569530240), &y));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_fx_cosh_q5_58(INT64_C(1198745575393886320), &y));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_fx_cosh_q5_58(INT64_MAX, &y));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_fx_atanh_q5_58(DRDC_Q5_58_ONE, &y));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                        drdc_fx_atanh_q5_58(-DRDC_Q5_58_ONE, &y));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_fx_atanh_q5_58(INT64_MIN, &y));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_sinh_q5_58(0, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_cosh_q5_58(0, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_atanh_q5_58(0, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_asinh_q5_58(0, NULL));
  TEST_ASSERT_EQUAL_INT64(77, y);
}

void suite_fixed_hyper(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_sinh);
  RUN_TEST(test_cosh);
  RUN_TEST(test_atanh);
  RUN_TEST(test_asinh);
  RUN_TEST(test_edges_and_bad_inputs);
}
