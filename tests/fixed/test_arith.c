/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Tests of fixed/ conversions, rounding shifts, multiply, divide and
 *        multiply-divide: exact rational reference table (0 LSB tolerance),
 *        both overflow forms, named boundaries and bad inputs.
 */
#include <drdc/fixed_arith.h>

#include <stddef.h>

#include "suites.h"
#include "unity.h"
#include "vectors_arith.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

static drdc_status_t call32(int op, int sat, int32_t a, int32_t b, int32_t c,
                            int32_t *out)
{
  switch (op) {
  case FX_MUL_Q1_30:
    return sat ? drdc_fx_mul_q1_30_sat(a, b, out)
               : drdc_fx_mul_q1_30(a, b, out);
  case FX_MUL_Q15_16:
    return sat ? drdc_fx_mul_q15_16_sat(a, b, out)
               : drdc_fx_mul_q15_16(a, b, out);
  case FX_DIV_Q1_30:
    return sat ? drdc_fx_div_q1_30_sat(a, b, out)
               : drdc_fx_div_q1_30(a, b, out);
  case FX_DIV_Q15_16:
    return sat ? drdc_fx_div_q15_16_sat(a, b, out)
               : drdc_fx_div_q15_16(a, b, out);
  default:
    return sat ? drdc_fx_muldiv_s32_sat(a, b, c, out)
               : drdc_fx_muldiv_s32(a, b, c, out);
  }
}

static drdc_status_t call64(int op, int sat, int64_t a, int64_t b, int64_t c,
                            int64_t *out)
{
  switch (op) {
  case FX_MUL_Q47_16:
    return sat ? drdc_fx_mul_q47_16_sat(a, b, out)
               : drdc_fx_mul_q47_16(a, b, out);
  case FX_DIV_Q47_16:
    return sat ? drdc_fx_div_q47_16_sat(a, b, out)
               : drdc_fx_div_q47_16(a, b, out);
  default:
    return sat ? drdc_fx_muldiv_s64_sat(a, b, c, out)
               : drdc_fx_muldiv_s64(a, b, c, out);
  }
}

/* Each row: the plain form gives the exact rounded result or overflow with
 * the output unchanged; the _sat form gives the same or the clamp. */
static void test_arith32_matches_fractions(void)
{
  size_t i;

  for (i = 0; i < COUNT(arith32_vectors); i++) {
    const struct arith32_vector *v = &arith32_vectors[i];
    int32_t out = 0x5A5A5A5A;

    if (v->over) {
      TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                            call32(v->op, 0, v->a, v->b, v->c, &out));
      TEST_ASSERT_EQUAL_INT32(0x5A5A5A5A, out);
      TEST_ASSERT_EQUAL_INT(DRDC_W_SATURATED,
                            call32(v->op, 1, v->a, v->b, v->c, &out));
    } else {
      TEST_ASSERT_EQUAL_INT(DRDC_OK, call32(v->op, 0, v->a, v->b, v->c, &out));
      TEST_ASSERT_EQUAL_INT32(v->result, out);
      out = 0;
      TEST_ASSERT_EQUAL_INT(DRDC_OK, call32(v->op, 1, v->a, v->b, v->c, &out));
    }
    TEST_ASSERT_EQUAL_INT32(v->result, out);
  }
}

static void test_arith64_matches_fractions(void)
{
  size_t i;

  for (i = 0; i < COUNT(arith64_vectors); i++) {
    const struct arith64_vector *v = &arith64_vectors[i];
    int64_t out = 0x5A5A5A5A;

    if (v->over) {
      TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                            call64(v->op, 0, v->a, v->b, v->c, &out));
      TEST_ASSERT_EQUAL_INT64(0x5A5A5A5A, out);
      TEST_ASSERT_EQUAL_INT(DRDC_W_SATURATED,
                            call64(v->op, 1, v->a, v->b, v->c, &out));
    } else {
      TEST_ASSERT_EQUAL_INT(DRDC_OK, call64(v->op, 0, v->a, v->b, v->c, &out));
      TEST_ASSERT_EQUAL_INT64(v->result, out);
      out = 0;
      TEST_ASSERT_EQUAL_INT(DRDC_OK, call64(v->op, 1, v->a, v->b, v->c, &out));
    }
    TEST_ASSERT_EQUAL_INT64(v->result, out);
  }
}

/* Rounding shift against its definition: r is the rounded quotient iff
 * |2x - r 2^(n+1)| <= 2^n, with ties (equality) resolved away from zero.
 * Every x of a 16-bit window around 0 and INT32 extremes, every n. */
static void test_rshift_round_definition(void)
{
  int32_t x;
  unsigned n;
  int32_t first_bad = 0;

  for (n = 1u; n <= 31u; n++) {
    for (x = -40000; x <= 40000; x += 7) {
      int64_t r = drdc_fx_rshift_round_s32(x, n);
      int64_t twice_err = (2 * (int64_t)x) - (r * ((int64_t)1 << (n + 1u)));
      int64_t half = (int64_t)1 << n;
      int64_t r64 = drdc_fx_rshift_round_s64(x, n);

      if ((twice_err > half) || (twice_err < -half) ||
          ((twice_err == half) && (x > 0)) ||
          ((twice_err == -half) && (x < 0)) || (r64 != r)) {
        first_bad = x;
      }
    }
  }
  TEST_ASSERT_EQUAL_INT32(0, first_bad);
  TEST_ASSERT_EQUAL_INT32(3, drdc_fx_rshift_round_s32(5, 1u));
  TEST_ASSERT_EQUAL_INT32(-3, drdc_fx_rshift_round_s32(-5, 1u));
  TEST_ASSERT_EQUAL_INT32(2, drdc_fx_rshift_round_s32(7, 2u));
  TEST_ASSERT_EQUAL_INT32(-1, drdc_fx_rshift_round_s32(INT32_MIN, 32u));
  TEST_ASSERT_EQUAL_INT32(0, drdc_fx_rshift_round_s32(INT32_MAX, 32u));
  TEST_ASSERT_EQUAL_INT32(0, drdc_fx_rshift_round_s32(INT32_MIN, 33u));
  TEST_ASSERT_EQUAL_INT32(-(1 << 30), drdc_fx_rshift_round_s32(INT32_MIN, 1u));
  TEST_ASSERT_EQUAL_INT32(1 << 30, drdc_fx_rshift_round_s32(INT32_MAX, 1u));
  TEST_ASSERT_EQUAL_INT32(-1, drdc_fx_rshift_round_s32(INT32_MIN, 31u));
  TEST_ASSERT_EQUAL_INT32(INT32_MIN, drdc_fx_rshift_round_s32(INT32_MIN, 0u));
  TEST_ASSERT_EQUAL_INT64(-1, drdc_fx_rshift_round_s64(INT64_MIN, 64u));
  TEST_ASSERT_EQUAL_INT64(-1, drdc_fx_rshift_round_s64(INT64_MIN, 63u));
  TEST_ASSERT_EQUAL_INT64(INT64_C(1) << 62,
                          drdc_fx_rshift_round_s64(INT64_MAX, 1u));
  TEST_ASSERT_EQUAL_INT64(0, drdc_fx_rshift_round_s64(INT64_MAX, 65u));
}

static void test_conversions_at_their_limits(void)
{
  drdc_q15_16_t q = 7;
  drdc_q47_16_t g = 7;
  drdc_q1_30_t u = 7;

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_q15_16_from_int(32767, &q));
  TEST_ASSERT_EQUAL_INT32(INT32_C(32767) << 16, q);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_q15_16_from_int(-32768, &q));
  TEST_ASSERT_EQUAL_INT32(INT32_MIN, q);
  q = 7;
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_fx_q15_16_from_int(32768, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_fx_q15_16_from_int(INT32_MIN, &q));
  TEST_ASSERT_EQUAL_INT32(7, q);
  TEST_ASSERT_EQUAL_INT(DRDC_W_SATURATED,
                        drdc_fx_q15_16_from_int_sat(32768, &q));
  TEST_ASSERT_EQUAL_INT32(INT32_MAX, q);
  TEST_ASSERT_EQUAL_INT(DRDC_W_SATURATED,
                        drdc_fx_q15_16_from_int_sat(-32769, &q));
  TEST_ASSERT_EQUAL_INT32(INT32_MIN, q);

  TEST_ASSERT_EQUAL_INT32(32768, drdc_fx_int_from_q15_16(INT32_MAX));
  TEST_ASSERT_EQUAL_INT32(-32768, drdc_fx_int_from_q15_16(INT32_MIN));
  TEST_ASSERT_EQUAL_INT32(1, drdc_fx_int_from_q15_16(0x8000));
  TEST_ASSERT_EQUAL_INT32(-1, drdc_fx_int_from_q15_16(-0x8000));
  TEST_ASSERT_EQUAL_INT32(0, drdc_fx_int_from_q15_16(0x7FFF));

  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_fx_q47_16_from_int((INT64_C(1) << 47) - 1, &g));
  TEST_ASSERT_EQUAL_INT64(INT64_MAX - 0xFFFF, g);
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_fx_q47_16_from_int(-(INT64_C(1) << 47), &g));
  TEST_ASSERT_EQUAL_INT64(INT64_MIN, g);
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_fx_q47_16_from_int(INT64_C(1) << 47, &g));
  TEST_ASSERT_EQUAL_INT64(INT64_MIN, g);
  TEST_ASSERT_EQUAL_INT(DRDC_W_SATURATED,
                        drdc_fx_q47_16_from_int_sat(INT64_MIN, &g));
  TEST_ASSERT_EQUAL_INT64(INT64_MIN, g);
  TEST_ASSERT_EQUAL_INT(DRDC_W_SATURATED,
                        drdc_fx_q47_16_from_int_sat(INT64_MAX, &g));
  TEST_ASSERT_EQUAL_INT64(INT64_MAX, g);
  TEST_ASSERT_EQUAL_INT64(INT64_C(1) << 47, drdc_fx_int_from_q47_16(INT64_MAX));
  TEST_ASSERT_EQUAL_INT64(-(INT64_C(1) << 47),
                          drdc_fx_int_from_q47_16(INT64_MIN));
  TEST_ASSERT_EQUAL_INT64(-2, drdc_fx_int_from_q47_16(-0x18000));

  TEST_ASSERT_EQUAL_INT64(INT32_MIN, drdc_fx_q47_16_from_q15_16(INT32_MIN));
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_q15_16_from_q47_16(INT32_MIN, &q));
  TEST_ASSERT_EQUAL_INT32(INT32_MIN, q);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_q15_16_from_q47_16(INT32_MAX, &q));
  TEST_ASSERT_EQUAL_INT32(INT32_MAX, q);
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_fx_q15_16_from_q47_16((int64_t)INT32_MAX + 1, &q));
  TEST_ASSERT_EQUAL_INT32(INT32_MAX, q);
  TEST_ASSERT_EQUAL_INT(DRDC_W_SATURATED, drdc_fx_q15_16_from_q47_16_sat(
                                              (int64_t)INT32_MIN - 1, &q));
  TEST_ASSERT_EQUAL_INT32(INT32_MIN, q);

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_q1_30_from_q15_16(-(2 << 16), &u));
  TEST_ASSERT_EQUAL_INT32(INT32_MIN, u);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_q1_30_from_q15_16((2 << 16) - 1, &u));
  TEST_ASSERT_EQUAL_INT32(INT32_MAX - 0x3FFF, u);
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_fx_q1_30_from_q15_16(2 << 16, &u));
  TEST_ASSERT_EQUAL_INT32(INT32_MAX - 0x3FFF, u);
  TEST_ASSERT_EQUAL_INT(DRDC_W_SATURATED,
                        drdc_fx_q1_30_from_q15_16_sat(2 << 16, &u));
  TEST_ASSERT_EQUAL_INT32(INT32_MAX, u);
  TEST_ASSERT_EQUAL_INT32(1 << 16, drdc_fx_q15_16_from_q1_30(1 << 30));
  TEST_ASSERT_EQUAL_INT32(1, drdc_fx_q15_16_from_q1_30(0x2000));
  TEST_ASSERT_EQUAL_INT32(-1, drdc_fx_q15_16_from_q1_30(-0x2000));
  TEST_ASSERT_EQUAL_INT32(0, drdc_fx_q15_16_from_q1_30(0x1FFF));
  TEST_ASSERT_EQUAL_INT32(1 << 17, drdc_fx_q15_16_from_q1_30(INT32_MAX));
  TEST_ASSERT_EQUAL_INT32(-(1 << 17), drdc_fx_q15_16_from_q1_30(INT32_MIN));
}

/* Named bad inputs: NULL outputs and zero divisors, outputs unchanged. */
static void test_bad_inputs_leave_outputs(void)
{
  int32_t o32 = 99;
  int64_t o64 = 99;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_q15_16_from_int(1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_q15_16_from_int_sat(1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_q47_16_from_int(1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_q15_16_from_q47_16(1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_q1_30_from_q15_16(1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_mul_q1_30(1, 1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_mul_q15_16_sat(1, 1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_mul_q47_16(1, 1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_div_q15_16(1, 1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_div_q47_16_sat(1, 1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_muldiv_s32(1, 1, 1, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_muldiv_s64(1, 1, 1, NULL));

  TEST_ASSERT_EQUAL_INT(DRDC_E_DIVIDE_BY_ZERO, drdc_fx_div_q1_30(1, 0, &o32));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DIVIDE_BY_ZERO,
                        drdc_fx_div_q1_30_sat(1, 0, &o32));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DIVIDE_BY_ZERO, drdc_fx_div_q15_16(0, 0, &o32));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DIVIDE_BY_ZERO,
                        drdc_fx_div_q15_16_sat(1, 0, &o32));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DIVIDE_BY_ZERO,
                        drdc_fx_muldiv_s32(1, 1, 0, &o32));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DIVIDE_BY_ZERO,
                        drdc_fx_muldiv_s32_sat(1, 1, 0, &o32));
  TEST_ASSERT_EQUAL_INT32(99, o32);
  TEST_ASSERT_EQUAL_INT(DRDC_E_DIVIDE_BY_ZERO, drdc_fx_div_q47_16(1, 0, &o64));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DIVIDE_BY_ZERO,
                        drdc_fx_div_q47_16_sat(1, 0, &o64));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DIVIDE_BY_ZERO,
                        drdc_fx_muldiv_s64(1, 1, 0, &o64));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DIVIDE_BY_ZERO,
                        drdc_fx_muldiv_s64_sat(1, 1, 0, &o64));
  TEST_ASSERT_EQUAL_INT64(99, o64);
}

/* muldiv_s64 against the 64-bit muldiv_s32 on every product of a grid:
 * int32 inputs make both exact, so they must agree bit for bit. */
static void test_muldiv_s64_agrees_with_s32(void)
{
  int64_t i;
  int64_t j;
  int32_t bad = 0;

  for (i = -2147000000; i < 2147000000; i += 123456789) {
    for (j = -2100000000; j < 2100000000; j += 98765431) {
      int32_t a = (int32_t)i;
      int32_t c = (int32_t)j;
      int32_t r32 = 0;
      int64_t r64 = 0;
      drdc_status_t s32 = drdc_fx_muldiv_s32(a, 1234567, c, &r32);
      drdc_status_t s64 = drdc_fx_muldiv_s64(a, 1234567, c, &r64);

      if ((s64 != DRDC_OK) || ((s32 == DRDC_OK) && (r64 != r32)) ||
          ((s32 != DRDC_OK) && (r64 >= INT32_MIN) && (r64 <= INT32_MAX))) {
        bad = a;
      }
    }
  }
  TEST_ASSERT_EQUAL_INT32(0, bad);
}

void suite_fixed_arith(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_arith32_matches_fractions);
  RUN_TEST(test_arith64_matches_fractions);
  RUN_TEST(test_rshift_round_definition);
  RUN_TEST(test_conversions_at_their_limits);
  RUN_TEST(test_bad_inputs_leave_outputs);
  RUN_TEST(test_muldiv_s64_agrees_with_s32);
}
