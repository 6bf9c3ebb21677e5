/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Bad-input rows of orientation and transforms that the other
 *        suites do not name (docs/bad-input.md): NULL pointers, zero
 *        quaternions, vectors beyond DRDC_ORIENT_Q47_16_MAX and results
 *        beyond their format. Each status is matched exactly and every
 *        output, pre-filled with a sentinel, is checked unchanged.
 *
 * The rotations below have exact rational matrices, so each overflow is
 * an exact statement about real numbers, not about rounding:
 * - q = [1, 0, 0, 0.5] is a yaw of 2 atan(0.5): with |q|^2 = 1.25,
 *   R11 = R22 = (1 - 0.25) / 1.25 = 0.6 and R21 = -R12 = 2 (0.5) / 1.25
 *   = 0.8;
 * - q = [1, 0, 0, 1] is a yaw of 90 degrees: R = [0 -1 0; 1 0 0; 0 0 1].
 * The yaw-45 matrix holds c = 759250125 = round(2^30 / sqrt(2))
 * (2^30 / sqrt(2) = 759250124.994), so 0.7 2^30 < c < 2^30.
 *
 * drdc_quat_difference() overflows when a vector part of `a` is INT32_MIN
 * (its conjugate, +2.0, does not fit Q1.30); its header said "a part"
 * until this suite found that the scalar part and the parts of b do not.
 */
#include <drdc/orient.h>
#include <drdc/orient_transform.h>

#include <stddef.h>

#include "orient_test_util.h"
#include "suites.h"
#include "unity.h"

#define ONE30 INT32_C(0x40000000) /* 1.0 in Q1.30 */
#define ONE16 INT32_C(0x10000)    /* 1 m in Q15.16 */
#define C45   INT32_C(759250125)  /* cos 45 deg in Q1.30, rounded */

/* Pre-filled into every output; an error must leave it there. Each is
 * the byte SENTINEL_BYTE repeated, so fill() and untouched() below serve
 * outputs of any type. */
#define SENTINEL_BYTE 0x5Au
#define SENTINEL32    INT32_C(0x5A5A5A5A)
#define SENTINEL64    INT64_C(0x5A5A5A5A5A5A5A5A)
#define SENTINEL_BAM  UINT32_C(0x5A5A5A5A)

static const drdc_quat_t zero_q = {0, 0, 0, 0};
static const drdc_quat_t identity_q = {ONE30, 0, 0, 0};
static const drdc_quat_t yaw90_q = {C45, 0, 0, C45};
static const drdc_quat_t roll90_q = {C45, C45, 0, 0};

static const drdc_dcm_t eye = {{{ONE30, 0, 0}, {0, ONE30, 0}, {0, 0, ONE30}}};
static const drdc_dcm_t yaw45 = {
    {{C45, -C45, 0}, {C45, C45, 0}, {0, 0, ONE30}}};

static const drdc_vec3_q15_16_t v_local = {ONE16, 2 * ONE16, 3 * ONE16};
static const drdc_vec3_q47_16_t v_global = {ONE16, 2 * ONE16, 3 * ONE16};
static const drdc_euler_t e_level = {0u, 0u, 0u};

static const drdc_transform_t t_local = {
    {{{ONE30, 0, 0}, {0, ONE30, 0}, {0, 0, ONE30}}}, {ONE16, 0, 0}};
static const drdc_transform_global_t t_global = {
    {{{ONE30, 0, 0}, {0, ONE30, 0}, {0, 0, ONE30}}}, {INT64_C(1) << 40, 0, 0}};

/* ------------------------------------------------ sentinel helpers */

/* Byte by byte, whatever the output's type: every part then holds its
 * sentinel (SENTINEL32, SENTINEL64 or SENTINEL_BAM). */
static void fill(void *out, size_t n)
{
  unsigned char *b = out;
  size_t k;

  for (k = 0u; k < n; k++) {
    b[k] = SENTINEL_BYTE;
  }
}

/* Every byte still SENTINEL_BYTE: every part still equals its sentinel,
 * and no padding byte was written either. */
static int untouched(const void *out, size_t n)
{
  const unsigned char *b = out;
  size_t k;

  for (k = 0u; k < n; k++) {
    if (b[k] != SENTINEL_BYTE) {
      return 0;
    }
  }
  return 1;
}

/* element by element: no struct copy (memcpy) on freestanding targets */
static void copy_dcm(const drdc_dcm_t *from, drdc_dcm_t *to)
{
  unsigned k;

  for (k = 0u; k < 9u; k++) {
    to->m[k / 3u][k % 3u] = from->m[k / 3u][k % 3u];
  }
}

static int dcm_equal(const drdc_dcm_t *a, const drdc_dcm_t *b)
{
  unsigned k;

  for (k = 0u; k < 9u; k++) {
    if (a->m[k / 3u][k % 3u] != b->m[k / 3u][k % 3u]) {
      return 0;
    }
  }
  return 1;
}

/* ------------------------------------------------ quaternion algebra */

static void test_quat_algebra_null_pointers_give_null(void)
{
  drdc_quat_t q;
  drdc_vec3_q15_16_t v;
  drdc_vec3_q47_16_t g;
  drdc_bam32_t angle = SENTINEL_BAM;

  fill(&q, sizeof q);
  fill(&v, sizeof v);
  fill(&g, sizeof g);
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_conj(NULL, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_conj(&identity_q, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_canonical(NULL, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_canonical(&identity_q, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_quat_rotate_q15_16(NULL, &v_local, &v));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_quat_rotate_q15_16(&identity_q, NULL, &v));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_quat_rotate_q15_16(&identity_q, &v_local, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_quat_rotate_q47_16(NULL, &v_global, &g));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_quat_rotate_q47_16(&identity_q, NULL, &g));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_quat_rotate_q47_16(&identity_q, &v_global, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_compose(NULL, &yaw90_q, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_compose(&yaw90_q, NULL, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_quat_compose(&yaw90_q, &yaw90_q, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_difference(NULL, &yaw90_q, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_difference(&yaw90_q, NULL, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_quat_difference(&yaw90_q, &yaw90_q, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_quat_angle_between(NULL, &yaw90_q, &angle));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_quat_angle_between(&yaw90_q, NULL, &angle));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_quat_angle_between(&yaw90_q, &yaw90_q, NULL));
  /* nothing was written */
  TEST_ASSERT_TRUE(untouched(&q, sizeof q));
  TEST_ASSERT_TRUE(untouched(&v, sizeof v));
  TEST_ASSERT_TRUE(untouched(&g, sizeof g));
  TEST_ASSERT_EQUAL_UINT32(SENTINEL_BAM, angle);
}

static void test_rotate_by_zero_quaternion_gives_domain(void)
{
  drdc_vec3_q15_16_t v;
  drdc_vec3_q47_16_t g;

  fill(&v, sizeof v);
  fill(&g, sizeof g);
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                        drdc_quat_rotate_q15_16(&zero_q, &v_local, &v));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                        drdc_quat_rotate_q47_16(&zero_q, &v_global, &g));
  TEST_ASSERT_TRUE(untouched(&v, sizeof v));
  TEST_ASSERT_TRUE(untouched(&g, sizeof g));
}

/* |v| > 32768 m turned so that a part leaves [-32768, 32768) m. */
static void test_rotate_q15_16_beyond_32768_gives_overflow(void)
{
  /* [1, 0, 0, 0.5]: x' = 0.6 x - 0.8 y = 0.6 (2^31 - 1) + 0.8 2^31 raw
   * = 1.4 2^31 - 0.6, far beyond INT32_MAX */
  static const drdc_quat_t q345 = {ONE30, 0, 0, ONE30 / 2};
  static const drdc_vec3_q15_16_t far = {INT32_MAX, INT32_MIN, 0};
  /* yaw 90: x' = -y = +2^31 raw = +32768 m, one LSB beyond INT32_MAX
   * (|v| = 32768 sqrt(2) m) */
  static const drdc_quat_t q90 = {ONE30, 0, 0, ONE30};
  static const drdc_vec3_q15_16_t edge = {0, INT32_MIN, INT32_MIN};
  drdc_vec3_q15_16_t v;

  fill(&v, sizeof v);
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_quat_rotate_q15_16(&q345, &far, &v));
  TEST_ASSERT_TRUE(untouched(&v, sizeof v));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_quat_rotate_q15_16(&q90, &edge, &v));
  TEST_ASSERT_TRUE(untouched(&v, sizeof v));
  /* in place (out == v): v stays as it was */
  v.x = INT32_MAX;
  v.y = INT32_MIN;
  v.z = 0;
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_quat_rotate_q15_16(&q345, &v, &v));
  TEST_ASSERT_EQUAL_INT32(INT32_MAX, v.x);
  TEST_ASSERT_EQUAL_INT32(INT32_MIN, v.y);
  TEST_ASSERT_EQUAL_INT32(0, v.z);
}

static void test_rotate_q47_16_beyond_max_gives_range(void)
{
  static const drdc_vec3_q47_16_t beyond[] = {
      {DRDC_ORIENT_Q47_16_MAX + 1, 0, 0},
      {0, -DRDC_ORIENT_Q47_16_MAX - 1, 0},
      {0, 0, INT64_MAX},
      {INT64_MIN, 0, 0},
  };
  static const drdc_vec3_q47_16_t at_max = {DRDC_ORIENT_Q47_16_MAX,
                                            -DRDC_ORIENT_Q47_16_MAX, 0};
  drdc_vec3_q47_16_t g;
  size_t i;

  for (i = 0; i < COUNT(beyond); i++) {
    fill(&g, sizeof g);
    TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                          drdc_quat_rotate_q47_16(&identity_q, &beyond[i], &g));
    TEST_ASSERT_TRUE(untouched(&g, sizeof g));
  }
  /* the limit itself is accepted; the identity rotation of it is exact
   * (within 0.53 LSB of an integer result means equal) */
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_quat_rotate_q47_16(&identity_q, &at_max, &g));
  TEST_ASSERT_EQUAL_INT64(DRDC_ORIENT_Q47_16_MAX, g.x);
  TEST_ASSERT_EQUAL_INT64(-DRDC_ORIENT_Q47_16_MAX, g.y);
  TEST_ASSERT_EQUAL_INT64(0, g.z);
}

static void test_compose_with_zero_gives_domain(void)
{
  drdc_quat_t q;

  fill(&q, sizeof q);
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                        drdc_quat_compose(&zero_q, &yaw90_q, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                        drdc_quat_compose(&yaw90_q, &zero_q, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_quat_compose(&zero_q, &zero_q, &q));
  TEST_ASSERT_TRUE(untouched(&q, sizeof q));
}

/* A part of a * b at 2.0 or beyond: |a| |b| >= 2. */
static void test_compose_product_beyond_2_gives_overflow(void)
{
  static const drdc_quat_t minus2 = {INT32_MIN, 0, 0, 0};    /* -2 */
  static const drdc_quat_t minus1 = {-ONE30, 0, 0, 0};       /* -1 */
  static const drdc_quat_t sx_plus = {ONE30, ONE30, 0, 0};   /* [1, 1] */
  static const drdc_quat_t sx_minus = {ONE30, -ONE30, 0, 0}; /* [1, -1] */
  drdc_quat_t q;

  fill(&q, sizeof q);
  /* -2 * -2 = 4 */
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_quat_compose(&minus2, &minus2, &q));
  /* -2 * -1 = 2 */
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_quat_compose(&minus2, &minus1, &q));
  /* [1, 1, 0, 0] [1, -1, 0, 0]: s = 1 - (1)(-1) = 2, x = -1 + 1 = 0 */
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_quat_compose(&sx_plus, &sx_minus, &q));
  TEST_ASSERT_TRUE(untouched(&q, sizeof q));
}

static void test_difference_with_zero_gives_domain(void)
{
  drdc_quat_t q;

  fill(&q, sizeof q);
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                        drdc_quat_difference(&zero_q, &yaw90_q, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                        drdc_quat_difference(&yaw90_q, &zero_q, &q));
  TEST_ASSERT_TRUE(untouched(&q, sizeof q));
}

static void test_angle_between_zero_gives_domain(void)
{
  drdc_bam32_t angle = SENTINEL_BAM;

  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                        drdc_quat_angle_between(&zero_q, &yaw90_q, &angle));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                        drdc_quat_angle_between(&yaw90_q, &zero_q, &angle));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                        drdc_quat_angle_between(&zero_q, &zero_q, &angle));
  TEST_ASSERT_EQUAL_UINT32(SENTINEL_BAM, angle);
}

/* ------------------------------------------------------ conversions */

static void test_matrix_null_pointers_give_null(void)
{
  drdc_dcm_t m;
  drdc_euler_t e;
  drdc_vec3_q15_16_t v;
  drdc_vec3_q47_16_t g;

  fill(&m, sizeof m);
  fill(&e, sizeof e);
  fill(&v, sizeof v);
  fill(&g, sizeof g);
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_dcm_from_euler(NULL, &m));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_dcm_from_euler(&e_level, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_euler_from_dcm(NULL, &e));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_euler_from_dcm(&eye, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_dcm_mul(NULL, &eye, &m));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_dcm_mul(&eye, NULL, &m));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_dcm_mul(&eye, &eye, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_dcm_transpose(NULL, &m));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_dcm_transpose(&eye, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_dcm_apply_q15_16(NULL, &v_local, &v));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_dcm_apply_q15_16(&eye, NULL, &v));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_dcm_apply_q15_16(&eye, &v_local, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_dcm_apply_q47_16(NULL, &v_global, &g));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_dcm_apply_q47_16(&eye, NULL, &g));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_dcm_apply_q47_16(&eye, &v_global, NULL));
  /* nothing was written */
  TEST_ASSERT_TRUE(untouched(&m, sizeof m));
  TEST_ASSERT_TRUE(untouched(&e, sizeof e));
  TEST_ASSERT_TRUE(untouched(&v, sizeof v));
  TEST_ASSERT_TRUE(untouched(&g, sizeof g));
}

/* The first column and the third row are zero: neither atan2(R21, R11)
 * nor atan2(-R31, hypot(R11, R21)) nor atan2(R32, R33) has a
 * direction. */
static void test_euler_from_dcm_zero_column_and_row_gives_domain(void)
{
  static const drdc_dcm_t zero_m = {{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}};
  /* the rest of the matrix is not zero */
  static const drdc_dcm_t hollow = {
      {{0, ONE30, ONE30}, {0, ONE30, -ONE30}, {0, 0, 0}}};
  drdc_euler_t e;

  fill(&e, sizeof e);
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_euler_from_dcm(&zero_m, &e));
  TEST_ASSERT_TRUE(untouched(&e, sizeof e));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_euler_from_dcm(&hollow, &e));
  TEST_ASSERT_TRUE(untouched(&e, sizeof e));
}

static void test_dcm_mul_beyond_2_gives_overflow(void)
{
  /* rows and columns [1, 1, 0]: element (1, 1) = 1 + 1 = 2.0 */
  static const drdc_dcm_t shear = {
      {{ONE30, ONE30, 0}, {ONE30, ONE30, 0}, {0, 0, ONE30}}};
  /* every element 1.0: each product element is 3.0 */
  static const drdc_dcm_t ones = {
      {{ONE30, ONE30, ONE30}, {ONE30, ONE30, ONE30}, {ONE30, ONE30, ONE30}}};
  /* every element -2.0: each product element is 12.0, whose Q60 sum
   * (3 2^62) is beyond int64 as well */
  static const drdc_dcm_t minus2 = {{{INT32_MIN, INT32_MIN, INT32_MIN},
                                     {INT32_MIN, INT32_MIN, INT32_MIN},
                                     {INT32_MIN, INT32_MIN, INT32_MIN}}};
  static const drdc_dcm_t late_a = {
      {{ONE30, 0, 0}, {0, ONE30, 0}, {ONE30, ONE30, 0}}};
  static const drdc_dcm_t late_b = {
      {{ONE30, 0, 0}, {ONE30, 0, 0}, {0, 0, ONE30}}};
  drdc_dcm_t m;

  fill(&m, sizeof m);
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_dcm_mul(&shear, &shear, &m));
  TEST_ASSERT_TRUE(untouched(&m, sizeof m));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_dcm_mul(&ones, &ones, &m));
  TEST_ASSERT_TRUE(untouched(&m, sizeof m));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_dcm_mul(&minus2, &minus2, &m));
  TEST_ASSERT_TRUE(untouched(&m, sizeof m));
  /* in place (out == a), with the first six elements of the product in
   * range ([1 0 0], [1 0 0]) and only element (3, 1) = 1 + 1 = 2.0
   * beyond: a stays as it was */
  copy_dcm(&late_a, &m);
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_dcm_mul(&m, &late_b, &m));
  TEST_ASSERT_TRUE(dcm_equal(&m, &late_a));
}

static void test_dcm_apply_q15_16_beyond_32768_gives_overflow(void)
{
  /* yaw 45: x' = c (x - y) / 2^30 = c (2^32 - 1) / 2^30 raw
   * > 0.7 (2^32 - 1), about 1.4 2^31: beyond INT32_MAX */
  static const drdc_vec3_q15_16_t far = {INT32_MAX, INT32_MIN, 0};
  drdc_vec3_q15_16_t v;

  fill(&v, sizeof v);
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_dcm_apply_q15_16(&yaw45, &far, &v));
  TEST_ASSERT_TRUE(untouched(&v, sizeof v));
  /* in place (out == v): v stays as it was */
  v.x = INT32_MAX;
  v.y = INT32_MIN;
  v.z = 0;
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_dcm_apply_q15_16(&yaw45, &v, &v));
  TEST_ASSERT_EQUAL_INT32(INT32_MAX, v.x);
  TEST_ASSERT_EQUAL_INT32(INT32_MIN, v.y);
  TEST_ASSERT_EQUAL_INT32(0, v.z);
}

static void test_dcm_apply_q47_16_beyond_max_gives_range(void)
{
  static const drdc_vec3_q47_16_t beyond[] = {
      {DRDC_ORIENT_Q47_16_MAX + 1, 0, 0},
      {0, -DRDC_ORIENT_Q47_16_MAX - 1, 0},
      {0, 0, INT64_MIN},
  };
  drdc_vec3_q47_16_t g;
  size_t i;

  for (i = 0; i < COUNT(beyond); i++) {
    fill(&g, sizeof g);
    TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                          drdc_dcm_apply_q47_16(&eye, &beyond[i], &g));
    TEST_ASSERT_TRUE(untouched(&g, sizeof g));
  }
}

/* Elements of -2.0 and parts at the accepted limit: each product
 * -2 * -2^55 raw = 2^56 raw, with the 6 guard bits 2^62, and the sum of
 * three, 3 2^62, does not fit int64. */
static void test_dcm_apply_q47_16_sum_beyond_int64_gives_overflow(void)
{
  static const drdc_dcm_t row_minus2 = {
      {{INT32_MIN, INT32_MIN, INT32_MIN}, {0, ONE30, 0}, {0, 0, ONE30}}};
  static const drdc_vec3_q47_16_t at_min = {-DRDC_ORIENT_Q47_16_MAX,
                                            -DRDC_ORIENT_Q47_16_MAX,
                                            -DRDC_ORIENT_Q47_16_MAX};
  static const drdc_vec3_q47_16_t at_max = {
      DRDC_ORIENT_Q47_16_MAX, DRDC_ORIENT_Q47_16_MAX, DRDC_ORIENT_Q47_16_MAX};
  drdc_vec3_q47_16_t g;

  fill(&g, sizeof g);
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_dcm_apply_q47_16(&row_minus2, &at_min, &g));
  TEST_ASSERT_TRUE(untouched(&g, sizeof g));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_dcm_apply_q47_16(&row_minus2, &at_max, &g));
  TEST_ASSERT_TRUE(untouched(&g, sizeof g));
}

/* ---------------------------------------------------- interpolation */

static void test_interpolation_null_pointers_give_null(void)
{
  const drdc_quat_t *a = &identity_q;
  const drdc_quat_t *b = &yaw90_q;
  const drdc_quat_t *c = &roll90_q;
  const drdc_q1_30_t half = ONE30 / 2;
  drdc_quat_t q;

  fill(&q, sizeof q);
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_nlerp(NULL, b, half, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_nlerp(a, NULL, half, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_nlerp(a, b, half, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_slerp(NULL, b, half, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_slerp(a, NULL, half, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_slerp(a, b, half, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_squad_control(NULL, b, c, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_squad_control(a, NULL, c, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_squad_control(a, b, NULL, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_squad_control(a, b, c, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_squad(NULL, b, a, b, half, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_squad(a, NULL, a, b, half, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_squad(a, b, NULL, b, half, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_squad(a, b, a, NULL, half, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_quat_squad(a, b, a, b, half, NULL));
  TEST_ASSERT_TRUE(untouched(&q, sizeof q));
}

/* (1 - t) a + t b' = 0: a zero key weighted alone. */
static void test_nlerp_to_zero_gives_domain(void)
{
  drdc_quat_t q;

  fill(&q, sizeof q);
  /* t = 0: 1 * 0 + 0 * b */
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                        drdc_quat_nlerp(&zero_q, &yaw90_q, 0, &q));
  /* t = 1: 0 * a + 1 * 0 */
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                        drdc_quat_nlerp(&yaw90_q, &zero_q, ONE30, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                        drdc_quat_nlerp(&zero_q, &zero_q, ONE30 / 2, &q));
  TEST_ASSERT_TRUE(untouched(&q, sizeof q));
}

static void test_slerp_of_zero_gives_domain(void)
{
  static const drdc_q1_30_t ts[] = {0, ONE30 / 2, ONE30};
  drdc_quat_t q;
  size_t i;

  fill(&q, sizeof q);
  for (i = 0; i < COUNT(ts); i++) {
    TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                          drdc_quat_slerp(&zero_q, &yaw90_q, ts[i], &q));
    TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                          drdc_quat_slerp(&yaw90_q, &zero_q, ts[i], &q));
  }
  TEST_ASSERT_TRUE(untouched(&q, sizeof q));
}

static void test_squad_control_zero_key_gives_domain(void)
{
  drdc_quat_t q;

  fill(&q, sizeof q);
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_quat_squad_control(
                                           &zero_q, &identity_q, &yaw90_q, &q));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_DOMAIN, drdc_quat_squad_control(&roll90_q, &zero_q, &yaw90_q, &q));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_DOMAIN,
      drdc_quat_squad_control(&roll90_q, &identity_q, &zero_q, &q));
  TEST_ASSERT_TRUE(untouched(&q, sizeof q));
}

static void test_squad_zero_quaternion_gives_domain(void)
{
  const drdc_quat_t *a = &identity_q;
  const drdc_quat_t *b = &yaw90_q;
  const drdc_quat_t *z = &zero_q;
  static const drdc_q1_30_t ts[] = {0, ONE30 / 2, ONE30};
  drdc_quat_t q;
  size_t i;

  fill(&q, sizeof q);
  for (i = 0; i < COUNT(ts); i++) {
    TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                          drdc_quat_squad(z, b, a, b, ts[i], &q));
    TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                          drdc_quat_squad(a, z, a, b, ts[i], &q));
    TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                          drdc_quat_squad(a, b, z, b, ts[i], &q));
    TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                          drdc_quat_squad(a, b, a, z, ts[i], &q));
  }
  TEST_ASSERT_TRUE(untouched(&q, sizeof q));
}

/* ----------------------------------------------------------- frames */

static void test_frame_null_pointers_give_null(void)
{
  drdc_vec3_q15_16_t v;
  drdc_vec3_q47_16_t g;
  drdc_quat_t q;

  fill(&v, sizeof v);
  fill(&g, sizeof g);
  fill(&q, sizeof q);
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_frame_frd_flu_q15_16(NULL, &v));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_frame_frd_flu_q15_16(&v_local, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_frame_ned_enu_q15_16(NULL, &v));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_frame_ned_enu_q15_16(&v_local, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_frame_frd_flu_q47_16(NULL, &g));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_frame_frd_flu_q47_16(&v_global, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_frame_ned_enu_q47_16(NULL, &g));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_frame_ned_enu_q47_16(&v_global, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_frame_frd_flu_quat(NULL, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_frame_frd_flu_quat(&yaw90_q, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_frame_ned_enu_quat(NULL, &q));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_frame_ned_enu_quat(&yaw90_q, NULL));
  TEST_ASSERT_TRUE(untouched(&v, sizeof v));
  TEST_ASSERT_TRUE(untouched(&g, sizeof g));
  TEST_ASSERT_TRUE(untouched(&q, sizeof q));
}

/* ------------------------------------------------------- transforms */

static void test_transform_null_pointers_give_null(void)
{
  drdc_transform_t t;
  drdc_transform_global_t tg;
  drdc_vec3_q15_16_t v;
  drdc_vec3_q47_16_t g;

  fill(&t, sizeof t);
  fill(&tg, sizeof tg);
  fill(&v, sizeof v);
  fill(&g, sizeof g);
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_transform_from_quat(NULL, &v_local, &t));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_transform_from_quat(&yaw90_q, NULL, &t));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_transform_from_quat(&yaw90_q, &v_local, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_transform_compose(NULL, &t_local, &t));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_transform_compose(&t_local, NULL, &t));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_transform_compose(&t_local, &t_local, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_transform_invert(NULL, &t));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_transform_invert(&t_local, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_transform_point(NULL, &v_local, &v));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_transform_point(&t_local, NULL, &v));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_transform_point(&t_local, &v_local, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_transform_direction(NULL, &v_local, &v));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_transform_direction(&t_local, NULL, &v));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_transform_direction(&t_local, &v_local, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_transform_global_compose(NULL, &t_local, &tg));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_transform_global_compose(&t_global, NULL, &tg));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_NULL, drdc_transform_global_compose(&t_global, &t_local, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_transform_global_to_world(NULL, &v_local, &g));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_transform_global_to_world(&t_global, NULL, &g));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_NULL, drdc_transform_global_to_world(&t_global, &v_local, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_transform_global_to_local(NULL, &v_global, &v));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_transform_global_to_local(&t_global, NULL, &v));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_NULL, drdc_transform_global_to_local(&t_global, &v_global, NULL));
  /* nothing was written */
  TEST_ASSERT_TRUE(untouched(&t, sizeof t));
  TEST_ASSERT_TRUE(untouched(&tg, sizeof tg));
  TEST_ASSERT_TRUE(untouched(&v, sizeof v));
  TEST_ASSERT_TRUE(untouched(&g, sizeof g));
}

static void test_transform_from_zero_quat_gives_domain(void)
{
  drdc_transform_t t;

  fill(&t, sizeof t);
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN,
                        drdc_transform_from_quat(&zero_q, &v_local, &t));
  TEST_ASSERT_TRUE(untouched(&t, sizeof t));
}

/* t = Ra tb + ta leaves [-32768, 32768) m. */
static void test_transform_compose_beyond_32768_gives_overflow(void)
{
  /* identity rotations: t = (2^31 - 1) + (2^31 - 1) raw in x */
  static const drdc_transform_t far_x = {
      {{{ONE30, 0, 0}, {0, ONE30, 0}, {0, 0, ONE30}}}, {INT32_MAX, 0, 0}};
  /* -2^31 + -1 raw in y */
  static const drdc_transform_t far_y = {
      {{{ONE30, 0, 0}, {0, ONE30, 0}, {0, 0, ONE30}}}, {0, INT32_MIN, 0}};
  static const drdc_transform_t minus_y = {
      {{{ONE30, 0, 0}, {0, ONE30, 0}, {0, 0, ONE30}}}, {0, -1, 0}};
  drdc_transform_t t;

  fill(&t, sizeof t);
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_transform_compose(&far_x, &far_x, &t));
  TEST_ASSERT_TRUE(untouched(&t, sizeof t));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_transform_compose(&far_y, &minus_y, &t));
  TEST_ASSERT_TRUE(untouched(&t, sizeof t));
  /* in place (out == a): a stays as it was */
  copy_dcm(&far_x.r, &t.r);
  t.t.x = INT32_MAX;
  t.t.y = 0;
  t.t.z = 0;
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_transform_compose(&t, &far_x, &t));
  TEST_ASSERT_TRUE(dcm_equal(&t.r, &eye));
  TEST_ASSERT_EQUAL_INT32(INT32_MAX, t.t.x);
  TEST_ASSERT_EQUAL_INT32(0, t.t.y);
  TEST_ASSERT_EQUAL_INT32(0, t.t.z);
}

/* -R^T t leaves [-32768, 32768) m: with R = yaw 45 and
 * t = (-2^31, 2^31 - 1) raw, (R^T t).y = c (-x + y) / 2^30
 * = c (2^32 - 1) / 2^30 > 0.7 (2^32 - 1), about 1.4 2^31. */
static void test_transform_invert_beyond_32768_gives_overflow(void)
{
  static const drdc_transform_t far = {
      {{{C45, -C45, 0}, {C45, C45, 0}, {0, 0, ONE30}}},
      {INT32_MIN, INT32_MAX, 0}};
  drdc_transform_t t;

  fill(&t, sizeof t);
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_transform_invert(&far, &t));
  TEST_ASSERT_TRUE(untouched(&t, sizeof t));
  /* in place (out == a): a stays as it was */
  copy_dcm(&far.r, &t.r);
  t.t.x = INT32_MIN;
  t.t.y = INT32_MAX;
  t.t.z = 0;
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_transform_invert(&t, &t));
  TEST_ASSERT_TRUE(dcm_equal(&t.r, &yaw45));
  TEST_ASSERT_EQUAL_INT32(INT32_MIN, t.t.x);
  TEST_ASSERT_EQUAL_INT32(INT32_MAX, t.t.y);
  TEST_ASSERT_EQUAL_INT32(0, t.t.z);
}

static void test_quat_difference_with_int32_min_vector_part_overflows(void)
{
  /* a = [0, -2, 0, 0]: conj(a) needs +2.0 in x, beyond Q1.30's [-2, 2) */
  const drdc_quat_t a = {0, INT32_MIN, 0, 0};
  const drdc_quat_t b = {ONE30, 0, 0, 0};
  drdc_quat_t out = {SENTINEL32, SENTINEL32, SENTINEL32, SENTINEL32};

  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_quat_difference(&a, &b, &out));
  TEST_ASSERT_EQUAL_INT32(SENTINEL32, out.s);
  TEST_ASSERT_EQUAL_INT32(SENTINEL32, out.x);
  TEST_ASSERT_EQUAL_INT32(SENTINEL32, out.y);
  TEST_ASSERT_EQUAL_INT32(SENTINEL32, out.z);
}

void suite_orient_bad_input(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_quat_algebra_null_pointers_give_null);
  RUN_TEST(test_quat_difference_with_int32_min_vector_part_overflows);
  RUN_TEST(test_rotate_by_zero_quaternion_gives_domain);
  RUN_TEST(test_rotate_q15_16_beyond_32768_gives_overflow);
  RUN_TEST(test_rotate_q47_16_beyond_max_gives_range);
  RUN_TEST(test_compose_with_zero_gives_domain);
  RUN_TEST(test_compose_product_beyond_2_gives_overflow);
  RUN_TEST(test_difference_with_zero_gives_domain);
  RUN_TEST(test_angle_between_zero_gives_domain);
  RUN_TEST(test_matrix_null_pointers_give_null);
  RUN_TEST(test_euler_from_dcm_zero_column_and_row_gives_domain);
  RUN_TEST(test_dcm_mul_beyond_2_gives_overflow);
  RUN_TEST(test_dcm_apply_q15_16_beyond_32768_gives_overflow);
  RUN_TEST(test_dcm_apply_q47_16_beyond_max_gives_range);
  RUN_TEST(test_dcm_apply_q47_16_sum_beyond_int64_gives_overflow);
  RUN_TEST(test_interpolation_null_pointers_give_null);
  RUN_TEST(test_nlerp_to_zero_gives_domain);
  RUN_TEST(test_slerp_of_zero_gives_domain);
  RUN_TEST(test_squad_control_zero_key_gives_domain);
  RUN_TEST(test_squad_zero_quaternion_gives_domain);
  RUN_TEST(test_frame_null_pointers_give_null);
  RUN_TEST(test_transform_null_pointers_give_null);
  RUN_TEST(test_transform_from_zero_quat_gives_domain);
  RUN_TEST(test_transform_compose_beyond_32768_gives_overflow);
  RUN_TEST(test_transform_invert_beyond_32768_gives_overflow);
}
