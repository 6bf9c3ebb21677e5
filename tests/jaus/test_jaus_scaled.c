/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief JAUS scaled integers: the exact Fraction model's vectors (every
 *        type and form, min, max, zero, negatives, ties, random, out of
 *        range), round trips, named cases, and the bad-input catalogue.
 */
#include <stddef.h>
#include <stdint.h>

#include <drdc/jaus_scaled.h>

#include "suites.h"
#include "unity.h"
#include "vectors_jaus.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

/* Encode or decode: the plain and the _sat form have the same type. */
typedef drdc_status_t (*scaled_fn)(int64_t in, int64_t min, int64_t max,
                                   drdc_jaus_type_t type, drdc_jaus_form_t form,
                                   int64_t *out);

/* Every vector through both forms. Clamped: the plain form gives
 * `range_status` and leaves its output, the _sat form `sat_status`; in
 * range both give DRDC_OK and the plain form the model's value, which
 * the _sat form writes either way. The tests pass the statuses so that
 * each names the function and status it tests (tools/gates/badinput.py). */
static void expect_model(const struct jaus_vector *vectors, size_t n,
                         scaled_fn plain, drdc_status_t range_status,
                         scaled_fn sat, drdc_status_t sat_status)
{
  size_t i;

  for (i = 0u; i < n; i++) {
    const struct jaus_vector *v = &vectors[i];
    int64_t out = 7;
    int64_t sat_out = 7;
    drdc_status_t st = plain(v->in, v->min, v->max, v->type, v->form, &out);
    drdc_status_t st_sat =
        sat(v->in, v->min, v->max, v->type, v->form, &sat_out);

    if (v->clamped != 0u) {
      TEST_ASSERT_EQUAL_INT(range_status, st);
      TEST_ASSERT_EQUAL_INT64(7, out);
      TEST_ASSERT_EQUAL_INT(sat_status, st_sat);
    } else {
      TEST_ASSERT_EQUAL_INT(DRDC_OK, st);
      TEST_ASSERT_EQUAL_INT64(v->out, out);
      TEST_ASSERT_EQUAL_INT(DRDC_OK, st_sat);
    }
    TEST_ASSERT_EQUAL_INT64(v->out, sat_out);
  }
}

static void test_encode_matches_the_model(void)
{
  expect_model(jaus_encode_vectors, COUNT(jaus_encode_vectors),
               drdc_jaus_scaled_encode, DRDC_E_RANGE,
               drdc_jaus_scaled_encode_sat, DRDC_W_SATURATED);
}

static void test_decode_matches_the_model(void)
{
  expect_model(jaus_decode_vectors, COUNT(jaus_decode_vectors),
               drdc_jaus_scaled_decode, DRDC_E_RANGE,
               drdc_jaus_scaled_decode_sat, DRDC_W_SATURATED);
}

/* integer -> real -> integer is exact when the real format resolves the
 * scale factor (max - min >= ihi - ilo raw LSB). */
static void test_round_trips_are_exact(void)
{
  size_t i;
  size_t checked = 0u;

  for (i = 0u; i < COUNT(jaus_decode_vectors); i++) {
    const struct jaus_vector *v = &jaus_decode_vectors[i];
    int64_t ilo = 0;
    int64_t ihi = 0;
    int64_t real = 0;
    int64_t back = 0;

    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_jaus_scaled_range(v->type, v->form, &ilo, &ihi));
    if ((v->clamped != 0u) || ((v->max - v->min) < (ihi - ilo))) {
      continue;
    }
    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_jaus_scaled_decode(v->in, v->min, v->max,
                                                  v->type, v->form, &real));
    TEST_ASSERT_EQUAL_INT(
        DRDC_OK,
        drdc_jaus_scaled_encode(real, v->min, v->max, v->type, v->form, &back));
    TEST_ASSERT_EQUAL_INT64(v->in, back);
    checked++;
  }
  TEST_ASSERT_TRUE(checked > 500u);
}

/* Named cases: the header's example, the RA midpoint, the AS6009 ends,
 * symmetric rounding of mirrored values. */
static void test_named_cases(void)
{
  const int64_t deg = INT64_C(1) << 16;
  int64_t i = 0;
  int64_t j = 0;
  int64_t ilo = 0;
  int64_t ihi = 0;

  /* 90 degrees in -180..180 -> 16383.5 -> 16384; -90 -> -16384 */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_jaus_scaled_encode(
                                     90 * deg, -180 * deg, 180 * deg,
                                     DRDC_JAUS_INT16, DRDC_JAUS_FORM_RA3, &i));
  TEST_ASSERT_EQUAL_INT64(16384, i);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_jaus_scaled_encode(
                                     -90 * deg, -180 * deg, 180 * deg,
                                     DRDC_JAUS_INT16, DRDC_JAUS_FORM_RA3, &j));
  TEST_ASSERT_EQUAL_INT64(-16384, j);
  /* RA: the midpoint is integer 0; AS6009: min is the type's minimum */
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_jaus_scaled_encode(5, 0, 10, DRDC_JAUS_INT8,
                                                DRDC_JAUS_FORM_RA3, &i));
  TEST_ASSERT_EQUAL_INT64(0, i);
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_jaus_scaled_encode(0, 0, 10, DRDC_JAUS_INT8,
                                                DRDC_JAUS_FORM_AS6009, &i));
  TEST_ASSERT_EQUAL_INT64(-128, i);
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_jaus_scaled_encode(0, 0, 10, DRDC_JAUS_INT8,
                                                DRDC_JAUS_FORM_RA3, &i));
  TEST_ASSERT_EQUAL_INT64(-127, i);
  TEST_ASSERT_EQUAL_INT(
      DRDC_OK,
      drdc_jaus_scaled_range(DRDC_JAUS_UINT32, DRDC_JAUS_FORM_RA3, &ilo, &ihi));
  TEST_ASSERT_EQUAL_INT64(0, ilo);
  TEST_ASSERT_EQUAL_INT64(INT64_C(4294967295), ihi);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_jaus_scaled_range(DRDC_JAUS_INT32,
                                                        DRDC_JAUS_FORM_AS6009,
                                                        &ilo, &ihi));
  TEST_ASSERT_EQUAL_INT64(INT64_C(-2147483648), ilo);
  TEST_ASSERT_EQUAL_INT64(INT64_C(2147483647), ihi);
}

static void test_drdc_jaus_scaled_range_bad_input(void)
{
  int64_t ilo = 7;
  int64_t ihi = 7;

  TEST_ASSERT_EQUAL_INT(
      DRDC_E_NULL,
      drdc_jaus_scaled_range(DRDC_JAUS_INT8, DRDC_JAUS_FORM_RA3, NULL, &ihi));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_NULL,
      drdc_jaus_scaled_range(DRDC_JAUS_INT8, DRDC_JAUS_FORM_RA3, &ilo, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_jaus_scaled_range((drdc_jaus_type_t)6,
                                               DRDC_JAUS_FORM_RA3, &ilo, &ihi));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE,
      drdc_jaus_scaled_range(DRDC_JAUS_INT8, (drdc_jaus_form_t)2, &ilo, &ihi));
  TEST_ASSERT_EQUAL_INT64(7, ilo);
  TEST_ASSERT_EQUAL_INT64(7, ihi);
}

static void test_drdc_jaus_scaled_encode_bad_input(void)
{
  int64_t i = 7;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_jaus_scaled_encode(0, -1, 1, DRDC_JAUS_INT8,
                                                DRDC_JAUS_FORM_RA3, NULL));
  /* a NULL output wins over an outside value (the plain form refuses an
   * outside value before it hands over to the saturating body) */
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_jaus_scaled_encode(5, -1, 1, DRDC_JAUS_INT8,
                                                DRDC_JAUS_FORM_RA3, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_jaus_scaled_encode(2, -1, 1, DRDC_JAUS_INT8,
                                                DRDC_JAUS_FORM_RA3, &i));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE,
      drdc_jaus_scaled_encode(1, 1, 1, DRDC_JAUS_INT8, DRDC_JAUS_FORM_RA3, &i));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_jaus_scaled_encode(0, INT64_MIN, INT64_MAX,
                                                DRDC_JAUS_INT8,
                                                DRDC_JAUS_FORM_RA3, &i));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_jaus_scaled_encode(0, -1, 1, (drdc_jaus_type_t)9,
                                                DRDC_JAUS_FORM_RA3, &i));
  TEST_ASSERT_EQUAL_INT64(7, i);
}

static void test_drdc_jaus_scaled_encode_sat_bad_input(void)
{
  int64_t i = 7;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_jaus_scaled_encode_sat(0, -1, 1, DRDC_JAUS_INT8,
                                                    DRDC_JAUS_FORM_RA3, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_jaus_scaled_encode_sat(0, 2, 1, DRDC_JAUS_INT8,
                                                    DRDC_JAUS_FORM_RA3, &i));
  TEST_ASSERT_EQUAL_INT64(7, i);
  TEST_ASSERT_EQUAL_INT(DRDC_W_SATURATED,
                        drdc_jaus_scaled_encode_sat(-5, -1, 1, DRDC_JAUS_INT8,
                                                    DRDC_JAUS_FORM_RA3, &i));
  TEST_ASSERT_EQUAL_INT64(-127, i);
  TEST_ASSERT_EQUAL_INT(DRDC_W_SATURATED,
                        drdc_jaus_scaled_encode_sat(-5, -1, 1, DRDC_JAUS_INT8,
                                                    DRDC_JAUS_FORM_AS6009, &i));
  TEST_ASSERT_EQUAL_INT64(-128, i);
}

static void test_drdc_jaus_scaled_decode_bad_input(void)
{
  int64_t v = 7;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_jaus_scaled_decode(0, -1, 1, DRDC_JAUS_INT8,
                                                DRDC_JAUS_FORM_RA3, NULL));
  /* and over an outside integer (200 > 127) */
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_jaus_scaled_decode(200, -1, 1, DRDC_JAUS_INT8,
                                                DRDC_JAUS_FORM_RA3, NULL));
  /* -32768 is outside the RA 3.x int16 range, inside the AS6009 one */
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_jaus_scaled_decode(
                                          -32768, -1000, 1000, DRDC_JAUS_INT16,
                                          DRDC_JAUS_FORM_RA3, &v));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE, drdc_jaus_scaled_decode(256, -1000, 1000, DRDC_JAUS_UINT8,
                                            DRDC_JAUS_FORM_AS6009, &v));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_jaus_scaled_decode(0, 1000, -1000, DRDC_JAUS_UINT8,
                                                DRDC_JAUS_FORM_AS6009, &v));
  TEST_ASSERT_EQUAL_INT64(7, v);
  TEST_ASSERT_EQUAL_INT(
      DRDC_OK, drdc_jaus_scaled_decode(-32768, -1000, 1000, DRDC_JAUS_INT16,
                                       DRDC_JAUS_FORM_AS6009, &v));
  TEST_ASSERT_EQUAL_INT64(-1000, v);
}

static void test_drdc_jaus_scaled_decode_sat_bad_input(void)
{
  int64_t v = 7;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_jaus_scaled_decode_sat(0, -1, 1, DRDC_JAUS_INT8,
                                                    DRDC_JAUS_FORM_RA3, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_jaus_scaled_decode_sat(0, 0, 0, DRDC_JAUS_INT8,
                                                    DRDC_JAUS_FORM_RA3, &v));
  TEST_ASSERT_EQUAL_INT64(7, v);
  TEST_ASSERT_EQUAL_INT(DRDC_W_SATURATED, drdc_jaus_scaled_decode_sat(
                                              -128, -1000, 1000, DRDC_JAUS_INT8,
                                              DRDC_JAUS_FORM_RA3, &v));
  TEST_ASSERT_EQUAL_INT64(-1000, v);
}

void suite_jaus_scaled(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_encode_matches_the_model);
  RUN_TEST(test_decode_matches_the_model);
  RUN_TEST(test_round_trips_are_exact);
  RUN_TEST(test_named_cases);
  RUN_TEST(test_drdc_jaus_scaled_range_bad_input);
  RUN_TEST(test_drdc_jaus_scaled_encode_bad_input);
  RUN_TEST(test_drdc_jaus_scaled_encode_sat_bad_input);
  RUN_TEST(test_drdc_jaus_scaled_decode_bad_input);
  RUN_TEST(test_drdc_jaus_scaled_decode_sat_bad_input);
}
