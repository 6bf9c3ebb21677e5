/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Tests of the Q5.58 functions of fixed/ (fixed_q5_58.h and
 *        drdc_fx_mul_q5_58()) against mpmath: sin/cos on a grid and at
 *        random and extreme arguments, atan2 at every magnitude, sqrt of
 *        every magnitude, products and quotients exactly; bad inputs.
 */
#include <drdc/fixed_arith.h>
#include <drdc/fixed_q5_58.h>

#include <stddef.h>

#include "suites.h"
#include "unity.h"
#include "vectors_q5_58.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

/* Documented max errors in LSB of Q5.58 (fixed_q5_58.h). */
#define SINCOS_TOL     2 /* |x| <= 8 */
#define SINCOS_FAR_TOL 7 /* every x */
#define ATAN2_TOL      3
#define SQRT_TOL       1

static int64_t err(int64_t got, int64_t want)
{
  /* both within Q5.58 of sin, cos, atan2, sqrt: no overflow */
  return (got > want) ? (got - want) : (want - got);
}

static void test_sincos_grid_and_symmetry(void)
{
  int64_t worst = 0;
  size_t k;

  for (k = 0; k < COUNT(q5_58_sincos_grid); k++) {
    int64_t x = (int64_t)k * Q5_58_SINCOS_STEP;
    int64_t s = 0;
    int64_t c = 0;
    int64_t e;

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_sincos_q5_58(x, &s, &c));
    e = err(s, q5_58_sincos_grid[k][0]);
    e = (err(c, q5_58_sincos_grid[k][1]) > e) ? err(c, q5_58_sincos_grid[k][1])
                                              : e;
    worst = (e > worst) ? e : worst;
    /* sin is odd, cos even */
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_sincos_q5_58(-x, &s, &c));
    e = err(s, -q5_58_sincos_grid[k][0]);
    e = (err(c, q5_58_sincos_grid[k][1]) > e) ? err(c, q5_58_sincos_grid[k][1])
                                              : e;
    worst = (e > worst) ? e : worst;
  }
  TEST_ASSERT_LESS_OR_EQUAL_INT64(SINCOS_TOL, worst);
}

static void test_sincos_random_and_extremes(void)
{
  int64_t near = 0;
  int64_t far = 0;
  size_t i;

  for (i = 0; i < COUNT(q5_58_sincos_vectors); i++) {
    const struct q5_58_sincos_vector *v = &q5_58_sincos_vectors[i];
    int64_t s = 0;
    int64_t c = 0;
    int64_t e;

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_sincos_q5_58(v->x, &s, &c));
    e = (err(s, v->s) > err(c, v->c)) ? err(s, v->s) : err(c, v->c);
    if ((v->x <= (8 * DRDC_Q5_58_ONE)) && (v->x >= (-8 * DRDC_Q5_58_ONE))) {
      near = (e > near) ? e : near;
    } else {
      far = (e > far) ? e : far;
    }
  }
  TEST_ASSERT_LESS_OR_EQUAL_INT64(SINCOS_TOL, near);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(SINCOS_FAR_TOL, far);
}

static void test_atan2_every_magnitude(void)
{
  int64_t worst = 0;
  size_t i;

  for (i = 0; i < COUNT(q5_58_atan2_vectors); i++) {
    const struct q5_58_atan2_vector *v = &q5_58_atan2_vectors[i];
    int64_t a = 0;
    int64_t e;

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_atan2_q5_58(v->y, v->x, &a));
    TEST_ASSERT_TRUE(a <= DRDC_Q5_58_PI);
    TEST_ASSERT_TRUE(a > -DRDC_Q5_58_PI);
    /* the same angle: an angle that rounds to -pi is returned as +pi,
     * the header's range (-pi, pi] */
    e = err(a, v->angle);
    if (e > DRDC_Q5_58_PI) {
      e = err(e, DRDC_Q5_58_TWO_PI);
    }
    worst = (e > worst) ? e : worst;
  }
  TEST_ASSERT_LESS_OR_EQUAL_INT64(ATAN2_TOL, worst);
}

static void test_sqrt_every_magnitude(void)
{
  int64_t worst = 0;
  size_t i;

  for (i = 0; i < COUNT(q5_58_sqrt_vectors); i++) {
    const struct q5_58_sqrt_vector *v = &q5_58_sqrt_vectors[i];
    int64_t r = -1;

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_sqrt_q5_58(v->x, &r));
    worst = (err(r, v->root) > worst) ? err(r, v->root) : worst;
  }
  TEST_ASSERT_LESS_OR_EQUAL_INT64(SQRT_TOL, worst);
}

/* correctly rounded: every product and quotient exact, overflow where
 * the rounded result leaves int64_t (output unchanged) */
static void test_mul_and_div_exact(void)
{
  size_t i;

  for (i = 0; i < COUNT(q5_58_mul_vectors); i++) {
    const struct q5_58_pair_vector *v = &q5_58_mul_vectors[i];
    int64_t r = 77;

    if (v->fits != 0) {
      TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_mul_q5_58(v->a, v->b, &r));
      TEST_ASSERT_EQUAL_INT64(v->want, r);
    } else {
      TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_fx_mul_q5_58(v->a, v->b, &r));
      TEST_ASSERT_EQUAL_INT64(77, r);
    }
  }
  for (i = 0; i < COUNT(q5_58_div_vectors); i++) {
    const struct q5_58_pair_vector *v = &q5_58_div_vectors[i];
    int64_t r = 77;

    if (v->fits != 0) {
      TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_div_q5_58(v->a, v->b, &r));
      TEST_ASSERT_EQUAL_INT64(v->want, r);
    } else {
      TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_fx_div_q5_58(v->a, v->b, &r));
      TEST_ASSERT_EQUAL_INT64(77, r);
    }
  }
}

/* named ties: 0.5 LSB rounds away from zero */
static void test_mul_and_div_ties(void)
{
  int64_t r = 0;

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_mul_q5_58(1, INT64_C(1) << 57, &r));
  TEST_ASSERT_EQUAL_INT64(1, r);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_mul_q5_58(-1, INT64_C(1) << 57, &r));
  TEST_ASSERT_EQUAL_INT64(-1, r);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_div_q5_58(1, INT64_C(1) << 59, &r));
  TEST_ASSERT_EQUAL_INT64(1, r);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_div_q5_58(-1, INT64_C(1) << 59, &r));
  TEST_ASSERT_EQUAL_INT64(-1, r);
}

/* the quotient without status: every stored quotient that fits, bit for
 * bit, and 0 where drdc_fx_div_q5_58() fails */
static void test_div_unchecked_exact(void)
{
  size_t i;

  for (i = 0; i < COUNT(q5_58_div_vectors); i++) {
    const struct q5_58_pair_vector *v = &q5_58_div_vectors[i];

    TEST_ASSERT_EQUAL_INT64((v->fits != 0) ? v->want : 0,
                            drdc_fx_div_q5_58_unchecked(v->a, v->b));
  }
  TEST_ASSERT_EQUAL_INT64(-1,
                          drdc_fx_div_q5_58_unchecked(-1, INT64_C(1) << 59));
  TEST_ASSERT_EQUAL_INT64(0, drdc_fx_div_q5_58_unchecked(1, 0));
}

/* the inline product without status: every stored product that fits,
 * against mpmath (the same vectors as drdc_fx_mul_q5_58()), and the
 * named ties */
static void test_mul_unchecked_exact(void)
{
  size_t i;

  for (i = 0; i < COUNT(q5_58_mul_vectors); i++) {
    const struct q5_58_pair_vector *v = &q5_58_mul_vectors[i];

    if (v->fits != 0) {
      TEST_ASSERT_EQUAL_INT64(v->want, drdc_fx_mul_q5_58_unchecked(v->a, v->b));
    }
  }
  TEST_ASSERT_EQUAL_INT64(1, drdc_fx_mul_q5_58_unchecked(1, INT64_C(1) << 57));
  TEST_ASSERT_EQUAL_INT64(-1,
                          drdc_fx_mul_q5_58_unchecked(-1, INT64_C(1) << 57));
  TEST_ASSERT_EQUAL_INT64(
      0, drdc_fx_mul_q5_58_unchecked(1, (INT64_C(1) << 57) - 1));
}

/* the short product (one factor below 2^32 raw): the stored products
 * whose second factor is that small, against mpmath; then bit for bit
 * against the full product for pseudo-random a of every sign and b of
 * every bit length up to 32, and the ties */
static void test_mul_short_exact(void)
{
  uint64_t x = UINT64_C(0x9E3779B97F4A7C15);
  size_t i;
  unsigned bits;

  for (i = 0; i < COUNT(q5_58_mul_vectors); i++) {
    const struct q5_58_pair_vector *v = &q5_58_mul_vectors[i];

    if ((v->fits != 0) && (v->b < (INT64_C(1) << 32)) &&
        (v->b > -(INT64_C(1) << 32))) {
      TEST_ASSERT_EQUAL_INT64(v->want, drdc_fx_mul_q5_58_short(v->a, v->b));
    }
  }
  for (bits = 0u; bits <= 32u; bits++) {
    for (i = 0; i < 64u; i++) {
      int64_t a;
      int64_t b;

      x ^= x << 13;
      x ^= x >> 7;
      x ^= x << 17;
      a = (int64_t)x / (int64_t)((i % 4u) + 1u);
      b = (bits == 0u) ? 0 : (int64_t)((x >> 7) & ((UINT64_C(1) << bits) - 1u));
      if (bits == 32u) {
        b = (i < 2u) ? (int64_t)UINT32_MAX : b;
      }
      if ((i & 1u) != 0u) {
        b = -b;
      }
      a = a >> (i % 8u);
      TEST_ASSERT_EQUAL_INT64(drdc_fx_mul_q5_58_unchecked(a, b),
                              drdc_fx_mul_q5_58_short(a, b));
    }
  }
  TEST_ASSERT_EQUAL_INT64(1, drdc_fx_mul_q5_58_short(INT64_C(1) << 57, 1));
  TEST_ASSERT_EQUAL_INT64(-1, drdc_fx_mul_q5_58_short(INT64_C(1) << 57, -1));
  TEST_ASSERT_EQUAL_INT64(0,
                          drdc_fx_mul_q5_58_short((INT64_C(1) << 57) - 1, 1));
}

static void test_drdc_fx_sincos_q5_58_errors(void)
{
  int64_t s = 77;
  int64_t c = 77;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_sincos_q5_58(1, NULL, &c));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_sincos_q5_58(1, &s, NULL));
  TEST_ASSERT_EQUAL_INT64(77, s);
  TEST_ASSERT_EQUAL_INT64(77, c);
}

static void test_drdc_fx_atan2_q5_58_errors(void)
{
  int64_t a = 77;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_atan2_q5_58(1, 1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_fx_atan2_q5_58(0, 0, &a));
  TEST_ASSERT_EQUAL_INT64(77, a);
}

static void test_drdc_fx_sqrt_q5_58_errors(void)
{
  int64_t r = 77;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_sqrt_q5_58(1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_fx_sqrt_q5_58(-1, &r));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_fx_sqrt_q5_58(INT64_MIN, &r));
  TEST_ASSERT_EQUAL_INT64(77, r);
}

static void test_drdc_fx_div_q5_58_errors(void)
{
  int64_t r = 77;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_div_q5_58(1, 1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DIVIDE_BY_ZERO, drdc_fx_div_q5_58(1, 0, &r));
  /* 32 = 2^63 raw does not fit */
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_OVERFLOW,
      drdc_fx_div_q5_58(32 * (INT64_C(1) << 52), INT64_C(1) << 52, &r));
  TEST_ASSERT_EQUAL_INT64(77, r);
}

void suite_fixed_q5_58(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_sincos_grid_and_symmetry);
  RUN_TEST(test_sincos_random_and_extremes);
  RUN_TEST(test_atan2_every_magnitude);
  RUN_TEST(test_sqrt_every_magnitude);
  RUN_TEST(test_mul_and_div_exact);
  RUN_TEST(test_mul_and_div_ties);
  RUN_TEST(test_mul_unchecked_exact);
  RUN_TEST(test_mul_short_exact);
  RUN_TEST(test_div_unchecked_exact);
  RUN_TEST(test_drdc_fx_sincos_q5_58_errors);
  RUN_TEST(test_drdc_fx_atan2_q5_58_errors);
  RUN_TEST(test_drdc_fx_sqrt_q5_58_errors);
  RUN_TEST(test_drdc_fx_div_q5_58_errors);
}
