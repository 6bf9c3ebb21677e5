/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The bad-input rows of pose.h (the conversions are checked
 *        against GeoConvert in test_geo_utm.c and CartConvert in
 *        test_geo_ecef.c, next to their vectors).
 */
#include <drdc/pose.h>

#include <stddef.h>

#include "suites.h"
#include "unity.h"

#define NAS_DEG INT64_C(3600000000000)
#define M(v) ((int64_t)(v) * INT64_C(65536))
#define SENTINEL64 INT64_C(0x5A5A5A5A5A5A5A5A)

static void test_drdc_pose_grid_and_true_errors(void)
{
  drdc_quat_t q = { 1073741824, 0, 0, 0 };
  drdc_quat_t big = { INT32_MAX, 0, 0, INT32_MAX };
  drdc_quat_t out = { 77, 77, 77, 77 };

  /* drdc_pose_grid_from_true and drdc_pose_true_from_grid */
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_grid_from_true(NULL, 0, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_grid_from_true(&q, 0, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_true_from_grid(NULL, 0, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_true_from_grid(&q, 0, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_pose_grid_from_true(&q, (180 * NAS_DEG) + 1,
                                                 &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_pose_true_from_grid(&q, (-180 * NAS_DEG) - 1,
                                                 &out));
  /* a non-unit quaternion of parts near 2 turned by 90 degrees */
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_pose_grid_from_true(&big, 90 * NAS_DEG, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_pose_true_from_grid(&big, -90 * NAS_DEG, &out));
  TEST_ASSERT_EQUAL_INT32(77, out.s);
}

static void test_drdc_pose_wutm_from_w_errors(void)
{
  drdc_WPose_t w = { 0, 0, 0, { INT32_MAX, 0, 0, INT32_MAX } };
  drdc_WUTMPose_t u;

  u.height = SENTINEL64;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_wutm_from_w(NULL, -1, &u));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_wutm_from_w(&w, -1, NULL));
  w.latitude = (90 * NAS_DEG) + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LATITUDE, drdc_pose_wutm_from_w(&w, -1, &u));
  w.latitude = 0;
  w.longitude = 540 * NAS_DEG;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LONGITUDE, drdc_pose_wutm_from_w(&w, -1, &u));
  w.longitude = 0;
  TEST_ASSERT_EQUAL_INT(DRDC_E_ZONE, drdc_pose_wutm_from_w(&w, 61, &u));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_pose_wutm_from_w(&w, 28, &u));
  /* 3 degrees west of zone 31's meridian: convergence 0 at the equator,
   * so use 45 N for a turn that overflows the oversized quaternion */
  w.latitude = 45 * NAS_DEG;
  w.longitude = -170 * NAS_DEG;
  w.q.z = INT32_MIN;
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_pose_wutm_from_w(&w, 2, &u));
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, u.height);
}

static void test_drdc_pose_w_from_wutm_errors(void)
{
  drdc_WUTMPose_t u = { { 31, true, M(500000), M(0) }, 0,
                        { INT32_MAX, 0, 0, INT32_MIN } };
  drdc_WPose_t w;

  w.height = SENTINEL64;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_w_from_wutm(NULL, &w));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_w_from_wutm(&u, NULL));
  u.utm.zone = 61;
  TEST_ASSERT_EQUAL_INT(DRDC_E_ZONE, drdc_pose_w_from_wutm(&u, &w));
  u.utm.zone = 31;
  u.utm.easting = -1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_EASTING, drdc_pose_w_from_wutm(&u, &w));
  u.utm.easting = M(500000);
  u.utm.northing = M(9600001);
  TEST_ASSERT_EQUAL_INT(DRDC_E_NORTHING, drdc_pose_w_from_wutm(&u, &w));
  /* zone 1, 45 N, 300 km west: convergence about -2 degrees */
  u.utm.zone = 1;
  u.utm.easting = M(200000);
  u.utm.northing = M(5000000);
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_pose_w_from_wutm(&u, &w));
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, w.height);
}

static void test_drdc_pose_w_from_l_errors(void)
{
  drdc_WPose_t ref = { 0, 0, 0, { 1073741824, 0, 0, 0 } };
  drdc_lPose_t l = { { 0, 0, 0 }, { 1073741824, 0, 0, 0 } };
  drdc_WPose_t out;

  out.height = SENTINEL64;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_w_from_l(NULL, 0, &l, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_w_from_l(&ref, 0, NULL, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_w_from_l(&ref, 0, &l, NULL));
  ref.latitude = (90 * NAS_DEG) + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LATITUDE,
                        drdc_pose_w_from_l(&ref, 0, &l, &out));
  ref.latitude = 0;
  ref.longitude = 540 * NAS_DEG;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LONGITUDE,
                        drdc_pose_w_from_l(&ref, 0, &l, &out));
  ref.longitude = 0;
  TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT,
                        drdc_pose_w_from_l(&ref, DRDC_GEO_HEIGHT_MAX + 1, &l,
                                           &out));
  ref.q.s = 0;
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_pose_w_from_l(&ref, 0, &l, &out));
  /* (30, 30, 30) km turned 45 degrees to the right: 42 km north */
  ref.q.s = 992008094;
  ref.q.z = 410903207;
  l.p.x = M(30000);
  l.p.y = M(30000);
  l.p.z = M(30000);
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_pose_w_from_l(&ref, 0, &l, &out));
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, out.height);
}

static void test_drdc_pose_l_from_w_errors(void)
{
  drdc_WPose_t ref = { 0, 0, 0, { 1073741824, 0, 0, 0 } };
  drdc_WPose_t w = { 0, 0, 0, { 1073741824, 0, 0, 0 } };
  drdc_lPose_t out;

  out.p.x = 77;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_l_from_w(NULL, 0, &w, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_l_from_w(&ref, 0, NULL, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_l_from_w(&ref, 0, &w, NULL));
  w.latitude = (-90 * NAS_DEG) - 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LATITUDE,
                        drdc_pose_l_from_w(&ref, 0, &w, &out));
  w.latitude = 0;
  w.longitude = -540 * NAS_DEG - 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LONGITUDE,
                        drdc_pose_l_from_w(&ref, 0, &w, &out));
  w.longitude = 0;
  w.height = DRDC_GEO_HEIGHT_MAX + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT, drdc_pose_l_from_w(&ref, 0, &w, &out));
  w.height = 0;
  ref.q.s = 0;
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_pose_l_from_w(&ref, 0, &w, &out));
  ref.q.s = 1073741824;
  w.height = M(40000);
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_pose_l_from_w(&ref, 0, &w, &out));
  TEST_ASSERT_EQUAL_INT32(77, out.p.x);
}

static void test_drdc_pose_weutm_from_we_errors(void)
{
  drdc_WePose_t w = { 0, 0, 0, { 0u, 0u, 0u } };
  drdc_WeUTMPose_t u;

  u.height = SENTINEL64;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_weutm_from_we(NULL, -1, &u));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_weutm_from_we(&w, -1, NULL));
  w.latitude = (90 * NAS_DEG) + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LATITUDE,
                        drdc_pose_weutm_from_we(&w, -1, &u));
  w.latitude = 0;
  w.longitude = 540 * NAS_DEG;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LONGITUDE,
                        drdc_pose_weutm_from_we(&w, -1, &u));
  w.longitude = 0;
  TEST_ASSERT_EQUAL_INT(DRDC_E_ZONE, drdc_pose_weutm_from_we(&w, 61, &u));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_pose_weutm_from_we(&w, 28, &u));
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, u.height);
}

static void test_drdc_pose_we_from_weutm_errors(void)
{
  drdc_WeUTMPose_t u = { { 31, true, M(500000), M(0) }, 0,
                         { 0u, 0u, 0u } };
  drdc_WePose_t w;

  w.height = SENTINEL64;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_we_from_weutm(NULL, &w));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_we_from_weutm(&u, NULL));
  u.utm.zone = 61;
  TEST_ASSERT_EQUAL_INT(DRDC_E_ZONE, drdc_pose_we_from_weutm(&u, &w));
  u.utm.zone = 31;
  u.utm.easting = M(1000000) + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_EASTING, drdc_pose_we_from_weutm(&u, &w));
  u.utm.easting = M(500000);
  u.utm.northing = M(-9100000) - 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NORTHING, drdc_pose_we_from_weutm(&u, &w));
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, w.height);
}

/* {We} -> {We-UTM} -> {We} at 45 N, 1 degree east of zone 31's meridian:
 * GeoConvert -c gives gamma 0.70714304552 degree; the yaw turns by it. */
static void test_we_round_trip_turns_the_yaw(void)
{
  drdc_WePose_t w = { 4 * NAS_DEG, 45 * NAS_DEG, M(10),
                      { 536870912u, 12345u, 4000000000u } };
  drdc_WeUTMPose_t u;
  drdc_WePose_t back;
  drdc_nas_t gamma = 0;
  drdc_geo_utm_t g;

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_geo_to_utm(w.latitude, w.longitude,
                                                 DRDC_GEO_ZONE_STANDARD, &g,
                                                 &gamma, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_pose_weutm_from_we(&w, DRDC_GEO_ZONE_STANDARD,
                                                &u));
  TEST_ASSERT_EQUAL_UINT32(w.e.yaw - drdc_pose_bam_from_convergence(gamma),
                           u.e.yaw);
  TEST_ASSERT_EQUAL_UINT32(12345u, u.e.pitch);
  TEST_ASSERT_EQUAL_UINT32(4000000000u, u.e.roll);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_we_from_weutm(&u, &back));
  /* the convergence at the 15 um-rounded point: within 1 LSB */
  TEST_ASSERT_UINT32_WITHIN(1u, w.e.yaw, back.e.yaw);
  TEST_ASSERT_INT64_WITHIN(300, w.latitude, back.latitude);
  /* 0.70714304552 degree is 8 436 545 binary-angle units */
  TEST_ASSERT_UINT32_WITHIN(1u, 8436545u,
                            drdc_pose_bam_from_convergence(gamma));
}

void suite_geo_pose(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_drdc_pose_grid_and_true_errors);
  RUN_TEST(test_drdc_pose_wutm_from_w_errors);
  RUN_TEST(test_drdc_pose_w_from_wutm_errors);
  RUN_TEST(test_drdc_pose_w_from_l_errors);
  RUN_TEST(test_drdc_pose_l_from_w_errors);
  RUN_TEST(test_drdc_pose_weutm_from_we_errors);
  RUN_TEST(test_drdc_pose_we_from_weutm_errors);
  RUN_TEST(test_we_round_trip_turns_the_yaw);
}
