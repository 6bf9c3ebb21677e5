/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Tests of ECEF and ENU/NED against GeographicLib CartConvert:
 *        2 009 points forward and reverse, 1 000 local points, round trips.
 */
#include <drdc/geo_ecef.h>
#include <drdc/geo_pose.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>

#include "suites.h"
#include "unity.h"
#include "vectors_ecef.h"
#include "../../core/geo/geo_impl.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

/* Documented bounds (geo_ecef.h), the maxima measured on these vectors. */
#define XYZ_TOL      1 /* LSB of Q47.16 */
#define LATLON_TOL   1 /* nas */
#define H_TOL        0 /* LSB of Q47.16 */
#define TRIP_XYZ_TOL 0 /* LSB of Q47.16: ECEF -> geodetic -> ECEF */
#define ENU_TOL      1 /* LSB of Q15.16 */

static int64_t dist(int64_t a, int64_t b)
{
  return (a > b) ? (a - b) : (b - a);
}

static void test_ecef_forward_and_reverse(void)
{
  int64_t w_xyz = 0;
  int64_t w_ll = 0;
  int64_t w_h = 0;
  int64_t w_trip = 0;
  size_t i;

  for (i = 0; i < COUNT(ecef_vectors); i++) {
    const struct ecef_vector *v = &ecef_vectors[i];
    drdc_geo_point_t p = {v->lat, v->lon, v->height};
    drdc_geo_point_t q = {0, 0, 0};
    drdc_vec3_q47_16_t e = {0, 0, 0};
    drdc_vec3_q47_16_t in = {v->x, v->y, v->z};
    drdc_vec3_q47_16_t back = {0, 0, 0};
    int64_t d;

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_geo_to_ecef(&p, &e));
    d = dist(e.x, v->x);
    d = (dist(e.y, v->y) > d) ? dist(e.y, v->y) : d;
    d = (dist(e.z, v->z) > d) ? dist(e.z, v->z) : d;
    w_xyz = (d > w_xyz) ? d : w_xyz;
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_geo_from_ecef(&in, &q));
    d = dist(q.lat, v->rev_lat);
    /* on the polar axis the longitude is 0 by convention */
    if ((dist(v->rev_lat, 0) != INT64_C(324000000000000)) &&
        (dist(v->rev_lon, q.lon) != INT64_C(1296000000000000))) {
      d = (dist(q.lon, v->rev_lon) > d) ? dist(q.lon, v->rev_lon) : d;
    }
    w_ll = (d > w_ll) ? d : w_ll;
    w_h = (dist(q.height, v->rev_height) > w_h) ? dist(q.height, v->rev_height)
                                                : w_h;
    /* round trip ECEF -> geodetic -> ECEF */
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_geo_to_ecef(&q, &back));
    d = dist(back.x, in.x);
    d = (dist(back.y, in.y) > d) ? dist(back.y, in.y) : d;
    d = (dist(back.z, in.z) > d) ? dist(back.z, in.z) : d;
    w_trip = (d > w_trip) ? d : w_trip;
  }
  TEST_ASSERT_LESS_OR_EQUAL_INT64(XYZ_TOL, w_xyz);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(LATLON_TOL, w_ll);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(H_TOL, w_h);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(TRIP_XYZ_TOL, w_trip);
}

static void test_enu_and_ned(void)
{
  int64_t w = 0;
  int64_t w_trip = 0;
  size_t i;

  for (i = 0; i < COUNT(enu_vectors); i++) {
    const struct enu_vector *v = &enu_vectors[i];
    drdc_geo_point_t ref = {v->lat0, v->lon0, v->h0};
    drdc_geo_point_t p = {v->lat, v->lon, v->height};
    drdc_geo_point_t q = {0, 0, 0};
    drdc_vec3_q15_16_t enu = {0, 0, 0};
    drdc_vec3_q15_16_t ned = {0, 0, 0};
    drdc_vec3_q15_16_t again = {0, 0, 0};
    int64_t d;

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_geo_to_enu(&ref, &p, &enu));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_geo_to_ned(&ref, &p, &ned));
    d = dist(enu.x, v->e);
    d = (dist(enu.y, v->n) > d) ? dist(enu.y, v->n) : d;
    d = (dist(enu.z, v->u) > d) ? dist(enu.z, v->u) : d;
    w = (d > w) ? d : w;
    TEST_ASSERT_EQUAL_INT32(enu.y, ned.x);
    TEST_ASSERT_EQUAL_INT32(enu.x, ned.y);
    TEST_ASSERT_EQUAL_INT32(-enu.z, ned.z);
    /* ENU -> geodetic -> ENU, and NED the same way */
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_geo_from_enu(&ref, &enu, &q));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_geo_to_enu(&ref, &q, &again));
    d = dist(again.x, enu.x);
    d = (dist(again.y, enu.y) > d) ? dist(again.y, enu.y) : d;
    d = (dist(again.z, enu.z) > d) ? dist(again.z, enu.z) : d;
    w_trip = (d > w_trip) ? d : w_trip;
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_geo_from_ned(&ref, &ned, &q));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_geo_to_ned(&ref, &q, &again));
    d = dist(again.x, ned.x);
    d = (dist(again.y, ned.y) > d) ? dist(again.y, ned.y) : d;
    d = (dist(again.z, ned.z) > d) ? dist(again.z, ned.z) : d;
    w_trip = (d > w_trip) ? d : w_trip;
  }
  TEST_ASSERT_LESS_OR_EQUAL_INT64(ENU_TOL, w);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(ENU_TOL, w_trip);
}

#define M(v)      ((int64_t)(v)*INT64_C(65536))
#define LOCAL_TOL 1 /* geo_pose.h: LSB of Q15.16 */
#define TRIP_TOL  2 /* geo_pose.h: LSB of Q47.16 height */

/* {l} at a reference facing north (q = 1) is NED; facing east (yaw 90)
 * x is east, y south. */
static void test_local_pose_against_cartconvert(void)
{
  static const drdc_quat_t facing_east = {759250125, 0, 0, 759250125};
  int64_t w_local = 0;
  int64_t w_trip = 0;
  size_t i;

  for (i = 0; i < COUNT(enu_vectors); i++) {
    const struct enu_vector *v = &enu_vectors[i];
    drdc_WPose_t ref = {v->lon0, v->lat0, v->h0 - M(30), {1073741824, 0, 0, 0}};
    drdc_WPose_t w = {v->lon, v->lat, v->height - M(30), {1073741824, 0, 0, 0}};
    drdc_lPose_t l;
    drdc_WPose_t back;
    int64_t d;

    /* geoid separation 30 m: MSL heights 30 m below the ellipsoidal */
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_l_from_w(&ref, M(30), &w, &l));
    d = dist(l.p.x, v->n);
    d = (dist(l.p.y, v->e) > d) ? dist(l.p.y, v->e) : d;
    d = (dist(l.p.z, -v->u) > d) ? dist(l.p.z, -v->u) : d;
    ref.q.s = facing_east.s;
    ref.q.z = facing_east.z;
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_l_from_w(&ref, M(30), &w, &l));
    d = (dist(l.p.x, v->e) > d) ? dist(l.p.x, v->e) : d;
    d = (dist(l.p.y, -v->n) > d) ? dist(l.p.y, -v->n) : d;
    d = (dist(l.p.z, -v->u) > d) ? dist(l.p.z, -v->u) : d;
    w_local = (d > w_local) ? d : w_local;
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_w_from_l(&ref, M(30), &l, &back));
    /* the 15 um of the Q15.16 local position: up to 245 nas */
    TEST_ASSERT_INT64_WITHIN(250, w.latitude, back.latitude);
    TEST_ASSERT_INT64_WITHIN(250 * 50, w.longitude, back.longitude);
    d = dist(back.height, w.height);
    w_trip = (d > w_trip) ? d : w_trip;
  }
  TEST_ASSERT_LESS_OR_EQUAL_INT64(LOCAL_TOL, w_local);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(TRIP_TOL, w_trip);
}

/* drdc__geo_nas_from_rad(r) against drdc_fx_muldiv_s64(r, GEO_NAS_180, GEO_PI)
 * (the 128-bit division it replaced), bit for bit, on both signs of: the
 * extremes of int64_t and of the angles (0, 1, pi, pi/2, INT64_MAX,
 * INT64_MIN), the radians nearest to a whole and to a half nas (where
 * the estimate's correction and the rounding decide: x = n pi 2^58 /
 * 648e12 and (n + 1/2) pi 2^58 / 648e12, rounded, and their neighbours,
 * for n of every magnitude), and random values of every magnitude. */
static void check_nas_from_rad(int64_t r)
{
  int64_t want = 0;

  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_fx_muldiv_s64(r, GEO_NAS_180, GEO_PI, &want));
  TEST_ASSERT_EQUAL_INT64(want, drdc__geo_nas_from_rad(r));
}

static void test_geo_nas_from_rad_is_muldiv(void)
{
  static const int64_t named[] = {
      0,          1,           2,          GEO_PI,    GEO_PI - 1,
      GEO_PI + 1, GEO_HALF_PI, GEO_TWO_PI, INT64_MAX, INT64_MAX - 1};
  uint64_t seed = UINT64_C(0x2545F4914F6CDD1D);
  int64_t n;
  int64_t x;
  int64_t k;
  unsigned i;

  for (i = 0u; i < COUNT(named); i++) {
    check_nas_from_rad(named[i]);
    check_nas_from_rad(-named[i]);
  }
  check_nas_from_rad(INT64_MIN);
  for (i = 0u; i < 3000u; i++) {
    seed =
        (seed * UINT64_C(6364136223846793005)) + UINT64_C(1442695040888963407);
    /* n up to 2^52 nas: x up to about 2^62.5 */
    n = (int64_t)(seed >> (12u + (i % 52u)));
    x = 0;
    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_fx_muldiv_s64((2 * n) + (int64_t)(i & 1u),
                                             GEO_PI, 2 * GEO_NAS_180, &x));
    for (k = -1; k <= 1; k++) {
      check_nas_from_rad(x + k);
      check_nas_from_rad(-(x + k));
    }
    x = (int64_t)(seed >> (1u + (i % 63u)));
    check_nas_from_rad(((i & 2u) != 0u) ? -x : x);
  }
}

void suite_geo_ecef(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_ecef_forward_and_reverse);
  RUN_TEST(test_enu_and_ned);
  RUN_TEST(test_local_pose_against_cartconvert);
  RUN_TEST(test_geo_nas_from_rad_is_muldiv);
}
