/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The bad-input rows of geo_pose.h, and {W-MGRS}, {We-MGRS} and
 *        {le} <-> {We} against GeoConvert, CartConvert and SciPy
 *        (vectors_pose.h; the {W-UTM} and {l} conversions are checked in
 *        test_geo_utm.c and test_geo_ecef.c, next to their vectors).
 */
#include <drdc/geo_pose.h>

#include <stddef.h>
#include <string.h>

#include "suites.h"
#include "unity.h"
#include "vectors_pose.h"

#define NAS_DEG    INT64_C(3600000000000)
#define M(v)       ((int64_t)(v)*INT64_C(65536))
#define SENTINEL64 INT64_C(0x5A5A5A5A5A5A5A5A)
#define COUNT(a)   (sizeof(a) / sizeof((a)[0]))

static void test_drdc_pose_grid_and_true_errors(void)
{
  drdc_quat_t q = {1073741824, 0, 0, 0};
  drdc_quat_t big = {INT32_MAX, 0, 0, INT32_MAX};
  drdc_quat_t out = {77, 77, 77, 77};

  /* drdc_pose_grid_from_true and drdc_pose_true_from_grid */
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_grid_from_true(NULL, 0, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_grid_from_true(&q, 0, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_true_from_grid(NULL, 0, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_true_from_grid(&q, 0, NULL));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE, drdc_pose_grid_from_true(&q, (180 * NAS_DEG) + 1, &out));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE, drdc_pose_true_from_grid(&q, (-180 * NAS_DEG) - 1, &out));
  /* a non-unit quaternion of parts near 2 turned by 90 degrees */
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_pose_grid_from_true(&big, 90 * NAS_DEG, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_pose_true_from_grid(&big, -90 * NAS_DEG, &out));
  TEST_ASSERT_EQUAL_INT32(77, out.s);
}

static void test_drdc_pose_wutm_from_w_errors(void)
{
  drdc_WPose_t w = {0, 0, 0, {INT32_MAX, 0, 0, INT32_MAX}};
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

/* The position and convergence now wait in the function's scratch until
 * the attitude is in: every byte of out stays as it was when the last
 * step (the attitude) fails after a projection that succeeded, UTM and
 * UPS, and when the metres are out of the forced zone's range; then the
 * same call with a unit quaternion gives drdc_geo_to_utm()'s position. */
static void test_drdc_pose_wutm_from_w_unchanged_on_error(void)
{
  static const struct {
    drdc_nas_t lat;
    drdc_nas_t lon;
    int32_t zone;
    drdc_status_t st;
  } rows[] = {
      /* UTM zone 2, 45 N: convergence about -2.1 degrees */
      {45 * NAS_DEG, -170 * NAS_DEG, 2, DRDC_E_OVERFLOW},
      /* UPS north, 85 N 45 E: convergence 45 degrees */
      {85 * NAS_DEG, 45 * NAS_DEG, DRDC_GEO_ZONE_STANDARD, DRDC_E_OVERFLOW},
      /* UPS south, 85 S 100 W */
      {-85 * NAS_DEG, -100 * NAS_DEG, DRDC_GEO_ZONE_UPS, DRDC_E_OVERFLOW},
      /* zone 31 forced 88 degrees east of its meridian: out of its range */
      {10 * NAS_DEG, 91 * NAS_DEG, 31, DRDC_E_RANGE},
      /* UPS forced at 10 N: out of the UPS range */
      {10 * NAS_DEG, 0, DRDC_GEO_ZONE_UPS, DRDC_E_RANGE},
  };
  size_t i;

  for (i = 0; i < (sizeof rows / sizeof rows[0]); i++) {
    drdc_WPose_t w = {
        rows[i].lon, rows[i].lat, M(12), {INT32_MAX, 0, 0, INT32_MIN}};
    drdc_WUTMPose_t out;
    drdc_WUTMPose_t before;
    drdc_geo_utm_t pos;

    memset(&out, 0x5A, sizeof out);
    memcpy(&before, &out, sizeof out);
    TEST_ASSERT_EQUAL_INT(rows[i].st,
                          drdc_pose_wutm_from_w(&w, rows[i].zone, &out));
    TEST_ASSERT_EQUAL_MEMORY(&before, &out, sizeof out);
    if (rows[i].st == DRDC_E_OVERFLOW) {
      w.q.s = 1073741824;
      w.q.z = 0;
      TEST_ASSERT_EQUAL_INT(DRDC_OK,
                            drdc_pose_wutm_from_w(&w, rows[i].zone, &out));
      TEST_ASSERT_EQUAL_INT(DRDC_OK,
                            drdc_geo_to_utm(rows[i].lat, rows[i].lon,
                                            rows[i].zone, &pos, NULL, NULL));
      TEST_ASSERT_EQUAL_INT32(pos.zone, out.utm.zone);
      TEST_ASSERT_TRUE(pos.north == out.utm.north);
      TEST_ASSERT_EQUAL_INT64(pos.easting, out.utm.easting);
      TEST_ASSERT_EQUAL_INT64(pos.northing, out.utm.northing);
      TEST_ASSERT_EQUAL_INT64(M(12), out.height);
    }
  }
}

static void test_drdc_pose_w_from_wutm_errors(void)
{
  drdc_WUTMPose_t u = {
      {31, true, M(500000), M(0)}, 0, {INT32_MAX, 0, 0, INT32_MIN}};
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
  drdc_WPose_t ref = {0, 0, 0, {1073741824, 0, 0, 0}};
  drdc_lPose_t l = {{0, 0, 0}, {1073741824, 0, 0, 0}};
  drdc_WPose_t out;

  out.height = SENTINEL64;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_w_from_l(NULL, 0, &l, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_w_from_l(&ref, 0, NULL, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_w_from_l(&ref, 0, &l, NULL));
  ref.latitude = (90 * NAS_DEG) + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LATITUDE, drdc_pose_w_from_l(&ref, 0, &l, &out));
  ref.latitude = 0;
  ref.longitude = 540 * NAS_DEG;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LONGITUDE,
                        drdc_pose_w_from_l(&ref, 0, &l, &out));
  ref.longitude = 0;
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_HEIGHT,
      drdc_pose_w_from_l(&ref, DRDC_GEO_HEIGHT_MAX + 1, &l, &out));
  ref.q.s = 0;
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_pose_w_from_l(&ref, 0, &l, &out));
  /* (30, 30, 30) km turned 45 degrees to the right: 42 km north */
  ref.q.s = 992008094;
  ref.q.z = 410903207;
  l.p.x = M(30000);
  l.p.y = M(30000);
  l.p.z = M(30000);
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_pose_w_from_l(&ref, 0, &l, &out));
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, out.height);
}

static void test_drdc_pose_l_from_w_errors(void)
{
  drdc_WPose_t ref = {0, 0, 0, {1073741824, 0, 0, 0}};
  drdc_WPose_t w = {0, 0, 0, {1073741824, 0, 0, 0}};
  drdc_lPose_t out;

  out.p.x = 77;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_l_from_w(NULL, 0, &w, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_l_from_w(&ref, 0, NULL, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_l_from_w(&ref, 0, &w, NULL));
  w.latitude = (-90 * NAS_DEG) - 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LATITUDE, drdc_pose_l_from_w(&ref, 0, &w, &out));
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
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_pose_l_from_w(&ref, 0, &w, &out));
  TEST_ASSERT_EQUAL_INT32(77, out.p.x);
}

static void test_drdc_pose_weutm_from_we_errors(void)
{
  drdc_WePose_t w = {0, 0, 0, {0u, 0u, 0u}};
  drdc_WeUTMPose_t u;

  u.height = SENTINEL64;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_weutm_from_we(NULL, -1, &u));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_weutm_from_we(&w, -1, NULL));
  w.latitude = (90 * NAS_DEG) + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LATITUDE, drdc_pose_weutm_from_we(&w, -1, &u));
  w.latitude = 0;
  w.longitude = 540 * NAS_DEG;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LONGITUDE, drdc_pose_weutm_from_we(&w, -1, &u));
  w.longitude = 0;
  TEST_ASSERT_EQUAL_INT(DRDC_E_ZONE, drdc_pose_weutm_from_we(&w, 61, &u));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_pose_weutm_from_we(&w, 28, &u));
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, u.height);
}

static void test_drdc_pose_we_from_weutm_errors(void)
{
  drdc_WeUTMPose_t u = {{31, true, M(500000), M(0)}, 0, {0u, 0u, 0u}};
  drdc_WePose_t w;

  /* the position and the convergence (parked in the height) are written
   * straight into out, so each must stay as it was on error */
  w.latitude = SENTINEL64;
  w.longitude = SENTINEL64;
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
  u.utm.zone = 0;
  u.utm.northing = M(2000000);
  u.utm.easting = M(2800000) + 1; /* beyond UPS north */
  TEST_ASSERT_EQUAL_INT(DRDC_E_EASTING, drdc_pose_we_from_weutm(&u, &w));
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, w.latitude);
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, w.longitude);
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, w.height);
}

/* {We} -> {We-UTM} -> {We} at 45 N, 1 degree east of zone 31's meridian:
 * GeoConvert -c gives gamma 0.70714304552 degree; the yaw turns by it. */
static void test_we_round_trip_turns_the_yaw(void)
{
  drdc_WePose_t w = {
      4 * NAS_DEG, 45 * NAS_DEG, M(10), {536870912u, 12345u, 4000000000u}};
  drdc_WeUTMPose_t u;
  drdc_WePose_t back;
  drdc_nas_t gamma = 0;
  drdc_geo_utm_t g;

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_geo_to_utm(w.latitude, w.longitude,
                                                 DRDC_GEO_ZONE_STANDARD, &g,
                                                 &gamma, NULL));
  TEST_ASSERT_EQUAL_INT(
      DRDC_OK, drdc_pose_weutm_from_we(&w, DRDC_GEO_ZONE_STANDARD, &u));
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

/* geo_pose.h bounds, the maxima measured on vectors_pose.h */
#define MGRS_Q_TOL   2    /* LSB of Q1.30 per quaternion part */
#define MGRS_YAW_TOL 1    /* binary-angle LSB */
#define CENTRE_TOL   1    /* nas: drdc_geo_from_utm()'s bound */
#define LE_NAS_TOL   2000 /* nas of arc: 62 um */
#define LE_H_TOL     2    /* LSB of Q47.16 */
#define LE_ANG_TOL   8    /* binary-angle LSB */
#define LE_P_TOL     4    /* LSB of Q15.16 */

static int64_t dist64(int64_t a, int64_t b)
{
  return (a > b) ? (a - b) : (b - a);
}

static int64_t bam_dist(drdc_bam32_t a, drdc_bam32_t b)
{
  uint32_t d = a - b;

  return (d > 0x80000000u) ? (int64_t)(0u - d) : (int64_t)d;
}

static int64_t quat_dist(const drdc_quat_t *q, const int32_t *v)
{
  int64_t d = dist64(q->s, v[0]);

  d = (dist64(q->x, v[1]) > d) ? dist64(q->x, v[1]) : d;
  d = (dist64(q->y, v[2]) > d) ? dist64(q->y, v[2]) : d;
  return (dist64(q->z, v[3]) > d) ? dist64(q->z, v[3]) : d;
}

static int64_t euler_dist(const drdc_euler_t *e, const uint32_t *v)
{
  int64_t d = bam_dist(e->yaw, v[0]);

  d = (bam_dist(e->pitch, v[1]) > d) ? bam_dist(e->pitch, v[1]) : d;
  return (bam_dist(e->roll, v[2]) > d) ? bam_dist(e->roll, v[2]) : d;
}

/* GeoConvert -m text, GeoConvert -c convergence, SciPy turns */
static void test_wmgrs_against_geoconvert(void)
{
  int64_t w_q = 0;
  int64_t w_yaw = 0;
  int64_t w_pos = 0;
  size_t i;

  for (i = 0; i < COUNT(pose_mgrs_vectors); i++) {
    const struct pose_mgrs_vector *v = &pose_mgrs_vectors[i];
    drdc_WPose_t w = {
        v->lon, v->lat, M(7), {v->q[0], v->q[1], v->q[2], v->q[3]}};
    drdc_WePose_t we = {v->lon, v->lat, M(7), {v->yaw, 11u, 22u}};
    drdc_WMGRSPose_t m;
    drdc_WeMGRSPose_t me;

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_wmgrs_from_w(&w, v->prec, &m));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_wemgrs_from_we(&we, v->prec, &me));
    TEST_ASSERT_EQUAL_STRING(m.mgrs, me.mgrs);
    /* every precision to 1 um: the digits truncate the coordinates
     * before their rounding to Q47.16 */
    TEST_ASSERT_EQUAL_STRING(v->mgrs, m.mgrs);
    w_pos += (v->prec > 8) ? 1 : 0;
    TEST_ASSERT_EQUAL_INT64(M(7), m.height);
    TEST_ASSERT_EQUAL_INT64(M(7), me.height);
    w_q = (quat_dist(&m.q, v->q_grid) > w_q) ? quat_dist(&m.q, v->q_grid) : w_q;
    w_yaw = (bam_dist(me.e.yaw, v->yaw_grid) > w_yaw)
                ? bam_dist(me.e.yaw, v->yaw_grid)
                : w_yaw;
    TEST_ASSERT_EQUAL_UINT32(11u, me.e.pitch);
    TEST_ASSERT_EQUAL_UINT32(22u, me.e.roll);
  }
  TEST_ASSERT_LESS_OR_EQUAL_INT64(MGRS_Q_TOL, w_q);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(MGRS_YAW_TOL, w_yaw);
  /* the vectors hold the precisions finer than 1 mm too */
  TEST_ASSERT_GREATER_THAN_INT64(0, w_pos);
}

/* GeoConvert's text and the attitude as grid north: the cell's centre,
 * the convergence there */
static void test_w_from_wmgrs_against_geoconvert(void)
{
  int64_t w_q = 0;
  int64_t w_yaw = 0;
  int64_t w_pos = 0;
  size_t i;

  for (i = 0; i < COUNT(pose_mgrs_vectors); i++) {
    const struct pose_mgrs_vector *v = &pose_mgrs_vectors[i];
    drdc_WMGRSPose_t m;
    drdc_WeMGRSPose_t me;
    drdc_WPose_t w;
    drdc_WePose_t we;

    (void)memcpy(m.mgrs, v->mgrs, sizeof m.mgrs);
    (void)memcpy(me.mgrs, v->mgrs, sizeof me.mgrs);
    m.height = M(-3);
    me.height = M(-3);
    m.q.s = v->q[0];
    m.q.x = v->q[1];
    m.q.y = v->q[2];
    m.q.z = v->q[3];
    me.e.yaw = v->yaw;
    me.e.pitch = 33u;
    me.e.roll = 44u;
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_w_from_wmgrs(&m, &w));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_we_from_wemgrs(&me, &we));
    w_pos = (dist64(w.latitude, v->centre_lat) > w_pos)
                ? dist64(w.latitude, v->centre_lat)
                : w_pos;
    w_pos = (dist64(w.longitude, v->centre_lon) > w_pos)
                ? dist64(w.longitude, v->centre_lon)
                : w_pos;
    TEST_ASSERT_EQUAL_INT64(w.latitude, we.latitude);
    TEST_ASSERT_EQUAL_INT64(w.longitude, we.longitude);
    TEST_ASSERT_EQUAL_INT64(M(-3), w.height);
    TEST_ASSERT_EQUAL_INT64(M(-3), we.height);
    w_q = (quat_dist(&w.q, v->q_true) > w_q) ? quat_dist(&w.q, v->q_true) : w_q;
    w_yaw = (bam_dist(we.e.yaw, v->yaw_true) > w_yaw)
                ? bam_dist(we.e.yaw, v->yaw_true)
                : w_yaw;
    TEST_ASSERT_EQUAL_UINT32(33u, we.e.pitch);
    TEST_ASSERT_EQUAL_UINT32(44u, we.e.roll);
  }
  TEST_ASSERT_LESS_OR_EQUAL_INT64(CENTRE_TOL, w_pos);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(MGRS_Q_TOL, w_q);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(MGRS_YAW_TOL, w_yaw);
}

/* CartConvert's local frame and SciPy's rotations, both ways */
static void test_le_and_we_against_cartconvert(void)
{
  int64_t w_lat = 0;
  int64_t w_lon = 0;
  int64_t w_h = 0;
  int64_t w_ang = 0;
  int64_t w_p = 0;
  int64_t w_back = 0;
  size_t i;

  for (i = 0; i < COUNT(pose_local_vectors); i++) {
    const struct pose_local_vector *v = &pose_local_vectors[i];
    drdc_WePose_t ref = {v->ref[1],
                         v->ref[0],
                         v->ref[2],
                         {v->ref_e[0], v->ref_e[1], v->ref_e[2]}};
    drdc_lePose_t le = {{v->p[0], v->p[1], v->p[2]},
                        {v->e[0], v->e[1], v->e[2]}};
    drdc_WePose_t w = {
        v->lon, v->lat, v->height, {v->out_e[0], v->out_e[1], v->out_e[2]}};
    drdc_WePose_t out;
    drdc_lePose_t back;
    int64_t d;

    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_pose_we_from_le(&ref, v->sep, &le, &out));
    w_lat = (dist64(out.latitude, v->lat) > w_lat)
                ? dist64(out.latitude, v->lat)
                : w_lat;
    /* longitude error as arc length: times cos(latitude) */
    d = (dist64(out.longitude, v->lon) * v->cos_lat) >> 30;
    w_lon = (d > w_lon) ? d : w_lon;
    w_h = (dist64(out.height, v->height) > w_h) ? dist64(out.height, v->height)
                                                : w_h;
    w_ang = (euler_dist(&out.e, v->out_e) > w_ang)
                ? euler_dist(&out.e, v->out_e)
                : w_ang;
    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_pose_le_from_we(&ref, v->sep, &w, &back));
    d = dist64(back.p.x, v->p[0]);
    d = (dist64(back.p.y, v->p[1]) > d) ? dist64(back.p.y, v->p[1]) : d;
    d = (dist64(back.p.z, v->p[2]) > d) ? dist64(back.p.z, v->p[2]) : d;
    w_p = (d > w_p) ? d : w_p;
    w_back = (euler_dist(&back.e, v->e) > w_back) ? euler_dist(&back.e, v->e)
                                                  : w_back;
  }
  TEST_ASSERT_LESS_OR_EQUAL_INT64(LE_NAS_TOL, w_lat);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(LE_NAS_TOL, w_lon);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(LE_H_TOL, w_h);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(LE_ANG_TOL, w_ang);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(LE_P_TOL, w_p);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(LE_ANG_TOL, w_back);
}

/* {le} <-> {l}: the position copied, the angles through the quaternion
 * (yaw 90 degrees is SciPy's { cos 45, 0, 0, sin 45 }, 759250125) */
static void test_le_and_l(void)
{
  drdc_lePose_t le = {{1, -2, 3}, {1u << 30, 0u, 0u}};
  drdc_lPose_t l;
  drdc_lePose_t back;

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_l_from_le(&le, &l));
  TEST_ASSERT_EQUAL_INT32(1, l.p.x);
  TEST_ASSERT_EQUAL_INT32(-2, l.p.y);
  TEST_ASSERT_EQUAL_INT32(3, l.p.z);
  TEST_ASSERT_INT32_WITHIN(2, 759250125, l.q.s);
  TEST_ASSERT_INT32_WITHIN(2, 759250125, l.q.z);
  TEST_ASSERT_EQUAL_INT32(0, l.q.x);
  TEST_ASSERT_EQUAL_INT32(0, l.q.y);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_le_from_l(&l, &back));
  TEST_ASSERT_EQUAL_INT32(3, back.p.z);
  TEST_ASSERT_UINT32_WITHIN(1u, 1u << 30, back.e.yaw);
  TEST_ASSERT_EQUAL_UINT32(0u, back.e.pitch);
}

/* the header's example: 33.3 N 44.4 E at 1 m is GeoConvert's
 * 38SMB4414084706 */
static void test_wmgrs_header_example(void)
{
  drdc_WPose_t w = {INT64_C(159840000000000),
                    INT64_C(119880000000000),
                    0,
                    {1073741824, 0, 0, 0}};
  drdc_WMGRSPose_t m;

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_wmgrs_from_w(&w, 5, &m));
  TEST_ASSERT_EQUAL_STRING("38SMB4414084706", m.mgrs);
}

static void test_drdc_pose_wmgrs_from_w_errors(void)
{
  drdc_WPose_t w = {0, 0, 0, {INT32_MAX, 0, 0, INT32_MAX}};
  drdc_WMGRSPose_t m;

  m.height = SENTINEL64;
  m.mgrs[0] = 'x';
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_wmgrs_from_w(NULL, 5, &m));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_wmgrs_from_w(&w, 5, NULL));
  w.latitude = (90 * NAS_DEG) + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LATITUDE, drdc_pose_wmgrs_from_w(&w, 5, &m));
  w.latitude = 0;
  w.longitude = 540 * NAS_DEG;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LONGITUDE, drdc_pose_wmgrs_from_w(&w, 5, &m));
  w.longitude = 0;
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_pose_wmgrs_from_w(&w, 12, &m));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_pose_wmgrs_from_w(&w, -2, &m));
  /* 45 N 10 E: 1 degree east of zone 32's meridian, a turn that
   * overflows the oversized quaternion */
  w.latitude = 45 * NAS_DEG;
  w.longitude = 10 * NAS_DEG;
  w.q.z = INT32_MIN;
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_pose_wmgrs_from_w(&w, 5, &m));
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, m.height);
  TEST_ASSERT_EQUAL_INT('x', m.mgrs[0]);
}

static void test_drdc_pose_w_from_wmgrs_errors(void)
{
  drdc_WMGRSPose_t m = {"38SMB4414084706", 0, {INT32_MAX, 0, 0, INT32_MIN}};
  drdc_WPose_t w;
  size_t i;

  w.height = SENTINEL64;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_w_from_wmgrs(NULL, &w));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_w_from_wmgrs(&m, NULL));
  /* 33 N: convergence about -0.33 degree turns the oversized q out of
   * Q1.30 */
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_pose_w_from_wmgrs(&m, &w));
  (void)memcpy(m.mgrs, "61SMB4414084706", 16);
  TEST_ASSERT_EQUAL_INT(DRDC_E_ZONE, drdc_pose_w_from_wmgrs(&m, &w));
  (void)memcpy(m.mgrs, "38SMB441408470", 15);
  TEST_ASSERT_EQUAL_INT(DRDC_E_MGRS, drdc_pose_w_from_wmgrs(&m, &w));
  /* GeoConvert: "Block MN not in zone/band 38S" */
  (void)memcpy(m.mgrs, "38SMN4414084706", 16);
  TEST_ASSERT_EQUAL_INT(DRDC_E_BAND, drdc_pose_w_from_wmgrs(&m, &w));
  /* no NUL in the array */
  for (i = 0; i < sizeof m.mgrs; i++) {
    m.mgrs[i] = '1';
  }
  TEST_ASSERT_EQUAL_INT(DRDC_E_MGRS, drdc_pose_w_from_wmgrs(&m, &w));
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, w.height);
}

static void test_drdc_pose_wemgrs_from_we_errors(void)
{
  drdc_WePose_t w = {0, 0, 0, {0u, 0u, 0u}};
  drdc_WeMGRSPose_t m;

  m.height = SENTINEL64;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_wemgrs_from_we(NULL, 5, &m));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_wemgrs_from_we(&w, 5, NULL));
  w.latitude = (-90 * NAS_DEG) - 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LATITUDE, drdc_pose_wemgrs_from_we(&w, 5, &m));
  w.latitude = 0;
  w.longitude = (-540 * NAS_DEG) - 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LONGITUDE, drdc_pose_wemgrs_from_we(&w, 5, &m));
  w.longitude = 0;
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_pose_wemgrs_from_we(&w, 12, &m));
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, m.height);
}

static void test_drdc_pose_we_from_wemgrs_errors(void)
{
  drdc_WeMGRSPose_t m = {"0SMB4414084706", 0, {0u, 0u, 0u}};
  drdc_WePose_t w;
  size_t i;

  w.height = SENTINEL64;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_we_from_wemgrs(NULL, &w));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_we_from_wemgrs(&m, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_ZONE, drdc_pose_we_from_wemgrs(&m, &w));
  (void)memcpy(m.mgrs, "38IMB4414084706", 16);
  TEST_ASSERT_EQUAL_INT(DRDC_E_MGRS, drdc_pose_we_from_wemgrs(&m, &w));
  (void)memcpy(m.mgrs, "38SMN4414084706", 16);
  TEST_ASSERT_EQUAL_INT(DRDC_E_BAND, drdc_pose_we_from_wemgrs(&m, &w));
  for (i = 0; i < sizeof m.mgrs; i++) {
    m.mgrs[i] = 'A';
  }
  TEST_ASSERT_EQUAL_INT(DRDC_E_MGRS, drdc_pose_we_from_wemgrs(&m, &w));
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, w.height);
}

static void test_drdc_pose_l_from_le_and_le_from_l_errors(void)
{
  drdc_lePose_t le = {{0, 0, 0}, {0u, 0u, 0u}};
  drdc_lPose_t l = {{5, 0, 0}, {0, 0, 0, 0}};
  drdc_lePose_t out;

  out.p.x = 77;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_l_from_le(NULL, &l));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_l_from_le(&le, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_le_from_l(NULL, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_le_from_l(&l, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_pose_le_from_l(&l, &out));
  TEST_ASSERT_EQUAL_INT32(77, out.p.x);
}

static void test_drdc_pose_we_from_le_errors(void)
{
  drdc_WePose_t ref = {0, 0, 0, {0u, 0u, 0u}};
  drdc_lePose_t le = {{0, 0, 0}, {0u, 0u, 0u}};
  drdc_WePose_t out;

  out.height = SENTINEL64;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_we_from_le(NULL, 0, &le, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_we_from_le(&ref, 0, NULL, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_we_from_le(&ref, 0, &le, NULL));
  ref.latitude = (90 * NAS_DEG) + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LATITUDE,
                        drdc_pose_we_from_le(&ref, 0, &le, &out));
  ref.latitude = 0;
  ref.longitude = 540 * NAS_DEG;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LONGITUDE,
                        drdc_pose_we_from_le(&ref, 0, &le, &out));
  ref.longitude = 0;
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_HEIGHT,
      drdc_pose_we_from_le(&ref, DRDC_GEO_HEIGHT_MAX + 1, &le, &out));
  /* (30, 30, 30) km turned 45 degrees to the right: 42 km north */
  ref.e.yaw = 1u << 29;
  le.p.x = M(30000);
  le.p.y = M(30000);
  le.p.z = M(30000);
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_pose_we_from_le(&ref, 0, &le, &out));
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, out.height);
}

/* Regression: a height near the ends of Q47.16 plus the geoid separation
 * overflowed int64_t (undefined behaviour, caught by UBSan) before the
 * point's check could refuse it. Each local pose conversion now gives
 * DRDC_E_HEIGHT for such a reference or pose height with either extreme
 * separation, and leaves out unchanged. */
static void test_local_poses_far_heights_do_not_overflow(void)
{
  static const int64_t heights[] = {INT64_MAX, INT64_MIN, INT64_MAX - M(1),
                                    INT64_MIN + M(1)};
  static const int64_t separations[] = {DRDC_GEO_HEIGHT_MAX,
                                        -DRDC_GEO_HEIGHT_MAX};
  const drdc_WPose_t w0 = {
      45 * NAS_DEG, 10 * NAS_DEG, 0, {1073741824, 0, 0, 0}};
  const drdc_WePose_t we0 = {45 * NAS_DEG, 10 * NAS_DEG, 0, {0u, 0u, 0u}};
  const drdc_lPose_t l = {{M(10), M(20), M(-3)}, {1073741824, 0, 0, 0}};
  const drdc_lePose_t le = {{M(10), M(20), M(-3)}, {0u, 0u, 0u}};
  size_t i;
  size_t j;

  for (i = 0; i < COUNT(heights); i++) {
    for (j = 0; j < COUNT(separations); j++) {
      const int64_t n = separations[j];
      drdc_WPose_t w = w0;
      drdc_WPose_t far = w0;
      drdc_WePose_t we = we0;
      drdc_WePose_t we_far = we0;
      drdc_WPose_t w_out;
      drdc_WePose_t we_out;
      drdc_lPose_t l_out;
      drdc_lePose_t le_out;

      far.height = heights[i];
      we_far.height = heights[i];
      memset(&w_out, 0x5A, sizeof w_out);
      memset(&we_out, 0x5A, sizeof we_out);
      memset(&l_out, 0x5A, sizeof l_out);
      memset(&le_out, 0x5A, sizeof le_out);
      /* the far height as the reference's */
      TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT,
                            drdc_pose_w_from_l(&far, n, &l, &w_out));
      TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT,
                            drdc_pose_l_from_w(&far, n, &w, &l_out));
      TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT,
                            drdc_pose_we_from_le(&we_far, n, &le, &we_out));
      TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT,
                            drdc_pose_le_from_we(&we_far, n, &we, &le_out));
      /* and as the pose's, at a good reference */
      TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT,
                            drdc_pose_l_from_w(&w, n, &far, &l_out));
      TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT,
                            drdc_pose_le_from_we(&we, n, &we_far, &le_out));
      TEST_ASSERT_EACH_EQUAL_HEX8(0x5A, &w_out, sizeof w_out);
      TEST_ASSERT_EACH_EQUAL_HEX8(0x5A, &we_out, sizeof we_out);
      TEST_ASSERT_EACH_EQUAL_HEX8(0x5A, &l_out, sizeof l_out);
      TEST_ASSERT_EACH_EQUAL_HEX8(0x5A, &le_out, sizeof le_out);
    }
  }
}

static void test_drdc_pose_le_from_we_errors(void)
{
  drdc_WePose_t ref = {0, 0, 0, {0u, 0u, 0u}};
  drdc_WePose_t w = {0, 0, 0, {0u, 0u, 0u}};
  drdc_lePose_t out;

  out.p.x = 77;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_le_from_we(NULL, 0, &w, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_le_from_we(&ref, 0, NULL, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_pose_le_from_we(&ref, 0, &w, NULL));
  w.latitude = (-90 * NAS_DEG) - 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LATITUDE,
                        drdc_pose_le_from_we(&ref, 0, &w, &out));
  w.latitude = 0;
  w.longitude = (-540 * NAS_DEG) - 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LONGITUDE,
                        drdc_pose_le_from_we(&ref, 0, &w, &out));
  w.longitude = 0;
  w.height = DRDC_GEO_HEIGHT_MAX + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT, drdc_pose_le_from_we(&ref, 0, &w, &out));
  w.height = M(40000);
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_pose_le_from_we(&ref, 0, &w, &out));
  TEST_ASSERT_EQUAL_INT32(77, out.p.x);
}

/* Points for the grid poses step by step: UTM north and south (off the
 * central meridian, a convergence of degrees), UPS north and south, and
 * a point on a central meridian (convergence 0). */
static const struct {
  drdc_nas_t lat;
  drdc_nas_t lon;
} grid_points[] = {
    {45 * NAS_DEG, -170 * NAS_DEG},
    {INT64_C(-119880000000000), INT64_C(544320000000000)},
    {85 * NAS_DEG, 45 * NAS_DEG},
    {-85 * NAS_DEG, -100 * NAS_DEG},
    {10 * NAS_DEG, 3 * NAS_DEG},
};

/* Attitudes: inside [-1, 1] (one pass), beyond it with a turn that fits
 * Q1.30, and beyond it with one that overflows wherever the convergence
 * is not 0. */
static const drdc_quat_t grid_attitudes[] = {
    {1073741824, 0, 0, 0},
    {-601295421, 536870912, -644245094, 268435456},
    {1610612736, -107374182, 214748364, 268435456},
    {INT32_MAX, 0, 0, INT32_MIN},
};

/* {W-UTM} and {W-MGRS} -> {W} against the public building blocks step by
 * step (drdc_geo_from_utm(), drdc_geo_mgrs_decode(),
 * drdc_pose_true_from_grid()): the same status, the same result, and out
 * unchanged byte for byte on error, for attitudes inside and beyond
 * [-1, 1] (the second pass of the wide attitude). */
static void test_w_from_grid_step_by_step(void)
{
  size_t i;
  size_t j;
  unsigned overflows = 0u;

  for (i = 0; i < COUNT(grid_points); i++) {
    for (j = 0; j < COUNT(grid_attitudes); j++) {
      drdc_WUTMPose_t u;
      drdc_WMGRSPose_t m;
      drdc_geo_utm_t corner;
      drdc_geo_utm_t centre;
      drdc_WPose_t out;
      drdc_WPose_t before;
      drdc_nas_t lat = 0;
      drdc_nas_t lon = 0;
      drdc_nas_t gamma = 0;
      drdc_quat_t q = {0, 0, 0, 0};
      drdc_status_t st;

      u.height = M(123);
      u.q = grid_attitudes[j];
      TEST_ASSERT_EQUAL_INT(
          DRDC_OK, drdc_geo_to_utm(grid_points[i].lat, grid_points[i].lon,
                                   DRDC_GEO_ZONE_STANDARD, &u.utm, NULL, NULL));
      TEST_ASSERT_EQUAL_INT(
          DRDC_OK, drdc_geo_from_utm(&u.utm, &lat, &lon, &gamma, NULL));
      st = drdc_pose_true_from_grid(&u.q, gamma, &q);
      memset(&out, 0x5A, sizeof out);
      memcpy(&before, &out, sizeof out);
      TEST_ASSERT_EQUAL_INT(st, drdc_pose_w_from_wutm(&u, &out));
      if (st == DRDC_OK) {
        TEST_ASSERT_EQUAL_INT64(lat, out.latitude);
        TEST_ASSERT_EQUAL_INT64(lon, out.longitude);
        TEST_ASSERT_EQUAL_INT64(M(123), out.height);
        TEST_ASSERT_EQUAL_MEMORY(&q, &out.q, sizeof q);
      } else {
        TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, st);
        TEST_ASSERT_EQUAL_MEMORY(&before, &out, sizeof out);
        overflows++;
      }

      /* the same through MGRS text at 1 m: the cell's centre */
      memset(&m, 0, sizeof m);
      m.height = M(-45);
      m.q = grid_attitudes[j];
      TEST_ASSERT_EQUAL_INT(
          DRDC_OK, drdc_geo_mgrs_encode(grid_points[i].lat, grid_points[i].lon,
                                        5, m.mgrs, sizeof m.mgrs));
      TEST_ASSERT_EQUAL_INT(
          DRDC_OK, drdc_geo_mgrs_decode(m.mgrs, &corner, &centre, NULL));
      TEST_ASSERT_EQUAL_INT(
          DRDC_OK, drdc_geo_from_utm(&centre, &lat, &lon, &gamma, NULL));
      st = drdc_pose_true_from_grid(&m.q, gamma, &q);
      memset(&out, 0xA5, sizeof out);
      memcpy(&before, &out, sizeof out);
      TEST_ASSERT_EQUAL_INT(st, drdc_pose_w_from_wmgrs(&m, &out));
      if (st == DRDC_OK) {
        TEST_ASSERT_EQUAL_INT64(lat, out.latitude);
        TEST_ASSERT_EQUAL_INT64(lon, out.longitude);
        TEST_ASSERT_EQUAL_INT64(M(-45), out.height);
        TEST_ASSERT_EQUAL_MEMORY(&q, &out.q, sizeof q);
      } else {
        TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, st);
        TEST_ASSERT_EQUAL_MEMORY(&before, &out, sizeof out);
      }
    }
  }
  /* the overflowing attitude at the four points off a meridian */
  TEST_ASSERT_EQUAL_UINT(4u, overflows);
}

/* {W} -> {W-MGRS} and {We} -> {We-MGRS} against drdc_geo_mgrs_encode(),
 * drdc_geo_to_utm()'s convergence and drdc_pose_grid_from_true() or
 * drdc_pose_bam_from_convergence(), as the test above */
static void test_mgrs_from_w_step_by_step(void)
{
  size_t i;
  size_t j;

  for (i = 0; i < COUNT(grid_points); i++) {
    drdc_geo_utm_t g;
    drdc_nas_t gamma = 0;
    char text[DRDC_GEO_MGRS_SIZE];
    drdc_WePose_t we = {grid_points[i].lon,
                        grid_points[i].lat,
                        M(7),
                        {4000000000u, 12345u, 99u}};
    drdc_WeMGRSPose_t me;

    TEST_ASSERT_EQUAL_INT(
        DRDC_OK, drdc_geo_to_utm(grid_points[i].lat, grid_points[i].lon,
                                 DRDC_GEO_ZONE_STANDARD, &g, &gamma, NULL));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_geo_mgrs_encode(grid_points[i].lat,
                                                        grid_points[i].lon, 11,
                                                        text, sizeof text));
    for (j = 0; j < COUNT(grid_attitudes); j++) {
      drdc_WPose_t w = {grid_points[i].lon, grid_points[i].lat, M(7),
                        grid_attitudes[j]};
      drdc_WMGRSPose_t out;
      drdc_WMGRSPose_t before;
      drdc_quat_t q = {0, 0, 0, 0};
      drdc_status_t st = drdc_pose_grid_from_true(&w.q, gamma, &q);

      memset(&out, 0x5A, sizeof out);
      memcpy(&before, &out, sizeof out);
      TEST_ASSERT_EQUAL_INT(st, drdc_pose_wmgrs_from_w(&w, 11, &out));
      if (st == DRDC_OK) {
        TEST_ASSERT_EQUAL_STRING(text, out.mgrs);
        TEST_ASSERT_EQUAL_INT64(M(7), out.height);
        TEST_ASSERT_EQUAL_MEMORY(&q, &out.q, sizeof q);
      } else {
        TEST_ASSERT_EQUAL_MEMORY(&before, &out, sizeof out);
      }
    }
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_wemgrs_from_we(&we, 11, &me));
    TEST_ASSERT_EQUAL_STRING(text, me.mgrs);
    TEST_ASSERT_EQUAL_INT64(M(7), me.height);
    TEST_ASSERT_EQUAL_UINT32(
        4000000000u - drdc_pose_bam_from_convergence(gamma), me.e.yaw);
    TEST_ASSERT_EQUAL_UINT32(12345u, me.e.pitch);
    TEST_ASSERT_EQUAL_UINT32(99u, me.e.roll);
  }
}

/* drdc_pose_wmgrs_from_w() and drdc_pose_wemgrs_from_we() write the text
 * last and take it as never failing: a standard zone's position is inside
 * the MGRS limits, and DRDC_GEO_MGRS_SIZE holds the longest text. The
 * encoder's status (the same projection and text) at the edges of the
 * zones and bands, Norway's and Svalbard's, and the UTM/UPS limits, at
 * the finest and the coarsest precision. */
static void test_mgrs_text_of_a_pose_cannot_fail(void)
{
  static const drdc_nas_t lats[] = {
      -90 * NAS_DEG, (-80 * NAS_DEG) - 1, -80 * NAS_DEG, 0,
      56 * NAS_DEG,  (64 * NAS_DEG) - 1,  72 * NAS_DEG,  (84 * NAS_DEG) - 1,
      84 * NAS_DEG,  90 * NAS_DEG,
  };
  static const drdc_nas_t lons[] = {
      -180 * NAS_DEG,      (-177 * NAS_DEG) - 1,
      -177 * NAS_DEG,      0,
      (3 * NAS_DEG) - 1,   3 * NAS_DEG,
      (9 * NAS_DEG) - 1,   9 * NAS_DEG,
      (12 * NAS_DEG) - 1,  12 * NAS_DEG,
      (21 * NAS_DEG) - 1,  21 * NAS_DEG,
      (33 * NAS_DEG) - 1,  33 * NAS_DEG,
      (42 * NAS_DEG) - 1,  42 * NAS_DEG,
      (180 * NAS_DEG) - 1,
  };
  char text[DRDC_GEO_MGRS_SIZE];
  size_t i;
  size_t j;

  for (i = 0; i < COUNT(lats); i++) {
    for (j = 0; j < COUNT(lons); j++) {
      TEST_ASSERT_EQUAL_INT(DRDC_OK,
                            drdc_geo_mgrs_encode(lats[i], lons[j],
                                                 DRDC_GEO_MGRS_PREC_MAX, text,
                                                 sizeof text));
      TEST_ASSERT_EQUAL_INT(DRDC_OK,
                            drdc_geo_mgrs_encode(lats[i], lons[j],
                                                 DRDC_GEO_MGRS_PREC_MIN, text,
                                                 sizeof text));
    }
  }
}

/* {We-MGRS} -> {We} against drdc_geo_mgrs_decode(), drdc_geo_from_utm()
 * and drdc_pose_bam_from_convergence() */
static void test_we_from_wemgrs_step_by_step(void)
{
  size_t i;

  for (i = 0; i < COUNT(grid_points); i++) {
    drdc_WeMGRSPose_t m;
    drdc_WePose_t out;
    drdc_geo_utm_t corner;
    drdc_geo_utm_t centre;
    drdc_nas_t lat = 0;
    drdc_nas_t lon = 0;
    drdc_nas_t gamma = 0;

    memset(&m, 0, sizeof m);
    m.height = M(3);
    m.e.yaw = 123456789u;
    m.e.pitch = 5u;
    m.e.roll = 6u;
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_geo_mgrs_encode(grid_points[i].lat,
                                                        grid_points[i].lon, 3,
                                                        m.mgrs, sizeof m.mgrs));
    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_geo_mgrs_decode(m.mgrs, &corner, &centre, NULL));
    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_geo_from_utm(&centre, &lat, &lon, &gamma, NULL));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_we_from_wemgrs(&m, &out));
    TEST_ASSERT_EQUAL_INT64(lat, out.latitude);
    TEST_ASSERT_EQUAL_INT64(lon, out.longitude);
    TEST_ASSERT_EQUAL_INT64(M(3), out.height);
    TEST_ASSERT_EQUAL_UINT32(123456789u + drdc_pose_bam_from_convergence(gamma),
                             out.e.yaw);
    TEST_ASSERT_EQUAL_UINT32(5u, out.e.pitch);
    TEST_ASSERT_EQUAL_UINT32(6u, out.e.roll);
  }
}

/* The position's errors before the wide attitude's first pass: out
 * unchanged byte for byte, the statuses as drdc_geo_from_utm()'s */
static void test_w_from_wutm_wide_position_errors(void)
{
  static const struct {
    drdc_geo_utm_t utm;
    drdc_status_t st;
  } rows[] = {
      {{61, true, M(500000), M(0)}, DRDC_E_ZONE},
      {{31, true, M(1000000) + 1, M(0)}, DRDC_E_EASTING},
      {{31, false, M(500000), M(900000) - 1}, DRDC_E_NORTHING},
      {{0, true, M(2800000) + 1, M(2000000)}, DRDC_E_EASTING},
      {{0, false, M(2000000), M(700000) - 1}, DRDC_E_NORTHING},
  };
  size_t i;
  size_t j;

  for (i = 0; i < COUNT(rows); i++) {
    for (j = 0; j < COUNT(grid_attitudes); j++) {
      drdc_WUTMPose_t u = {rows[i].utm, M(1), grid_attitudes[j]};
      drdc_WPose_t out;
      drdc_WPose_t before;

      memset(&out, 0x5A, sizeof out);
      memcpy(&before, &out, sizeof out);
      TEST_ASSERT_EQUAL_INT(rows[i].st, drdc_pose_w_from_wutm(&u, &out));
      TEST_ASSERT_EQUAL_MEMORY(&before, &out, sizeof out);
    }
  }
}

/* out unchanged, byte for byte, when the attitude fails after a valid
 * position (the last step), and the result's height status before the
 * attitude's when both fail; out may be ref */
static void test_drdc_pose_w_from_l_unchanged_on_error(void)
{
  static const drdc_quat_t zero = {0, 0, 0, 0};
  static const drdc_quat_t big = {INT32_MAX, INT32_MAX, INT32_MAX, INT32_MAX};
  drdc_WPose_t ref = {10 * NAS_DEG, 45 * NAS_DEG, M(100), {INT32_MAX, 0, 0, 0}};
  drdc_lPose_t l = {{M(1), 0, 0}, {0, 0, 0, 0}};
  drdc_WPose_t out;
  drdc_WPose_t before;
  drdc_WPose_t alias;

  memset(&out, 0x5A, sizeof out);
  memcpy(&before, &out, sizeof out);
  /* a zero relative attitude: the composed product is zero */
  l.q = zero;
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, drdc_pose_w_from_l(&ref, 0, &l, &out));
  TEST_ASSERT_EQUAL_MEMORY(&before, &out, sizeof out);
  /* parts near 2 times near 2: the product's scalar part near 4 */
  l.q = big;
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, drdc_pose_w_from_l(&ref, 0, &l, &out));
  TEST_ASSERT_EQUAL_MEMORY(&before, &out, sizeof out);
  /* 1 km above the highest reference: the result's height first */
  ref.height = DRDC_GEO_HEIGHT_MAX;
  l.p.z = -M(1000);
  TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT, drdc_pose_w_from_l(&ref, 0, &l, &out));
  TEST_ASSERT_EQUAL_MEMORY(&before, &out, sizeof out);
  l.q = zero;
  TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT, drdc_pose_w_from_l(&ref, 0, &l, &out));
  TEST_ASSERT_EQUAL_MEMORY(&before, &out, sizeof out);
  /* in place: the same pose as into another object */
  ref.height = M(100);
  ref.q.s = 992008094;
  ref.q.z = 410903207;
  l.p.x = M(1200);
  l.p.y = -M(300);
  l.p.z = M(20);
  l.q.s = 1073741824;
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_w_from_l(&ref, M(30), &l, &out));
  alias = ref;
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_w_from_l(&alias, M(30), &l, &alias));
  TEST_ASSERT_EQUAL_MEMORY(&out, &alias, sizeof out);
}

/* out unchanged, byte for byte, when the result's height fails (the
 * position is no longer the last step); out may be ref */
static void test_drdc_pose_we_from_le_unchanged_on_error(void)
{
  drdc_WePose_t ref = {
      10 * NAS_DEG, 45 * NAS_DEG, DRDC_GEO_HEIGHT_MAX, {1u << 29, 0u, 0u}};
  drdc_lePose_t le = {{0, 0, -M(1000)}, {1u << 28, 1u << 27, 0u}};
  drdc_WePose_t out;
  drdc_WePose_t before;
  drdc_WePose_t alias;

  memset(&out, 0x5A, sizeof out);
  memcpy(&before, &out, sizeof out);
  /* 1 km above the highest reference */
  TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT,
                        drdc_pose_we_from_le(&ref, 0, &le, &out));
  TEST_ASSERT_EQUAL_MEMORY(&before, &out, sizeof out);
  /* in place: the same pose as into another object */
  ref.height = M(100);
  le.p.x = M(1200);
  le.p.y = -M(300);
  le.p.z = M(20);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_we_from_le(&ref, M(30), &le, &out));
  alias = ref;
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_pose_we_from_le(&alias, M(30), &le, &alias));
  /* field by field: the struct's tail padding is not a value */
  TEST_ASSERT_EQUAL_INT64(out.longitude, alias.longitude);
  TEST_ASSERT_EQUAL_INT64(out.latitude, alias.latitude);
  TEST_ASSERT_EQUAL_INT64(out.height, alias.height);
  TEST_ASSERT_EQUAL_UINT32(out.e.yaw, alias.e.yaw);
  TEST_ASSERT_EQUAL_UINT32(out.e.pitch, alias.e.pitch);
  TEST_ASSERT_EQUAL_UINT32(out.e.roll, alias.e.roll);
}

void suite_geo_pose(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_drdc_pose_grid_and_true_errors);
  RUN_TEST(test_drdc_pose_wutm_from_w_errors);
  RUN_TEST(test_drdc_pose_wutm_from_w_unchanged_on_error);
  RUN_TEST(test_drdc_pose_w_from_wutm_errors);
  RUN_TEST(test_w_from_grid_step_by_step);
  RUN_TEST(test_mgrs_from_w_step_by_step);
  RUN_TEST(test_mgrs_text_of_a_pose_cannot_fail);
  RUN_TEST(test_we_from_wemgrs_step_by_step);
  RUN_TEST(test_w_from_wutm_wide_position_errors);
  RUN_TEST(test_drdc_pose_w_from_l_errors);
  RUN_TEST(test_drdc_pose_w_from_l_unchanged_on_error);
  RUN_TEST(test_drdc_pose_l_from_w_errors);
  RUN_TEST(test_drdc_pose_weutm_from_we_errors);
  RUN_TEST(test_drdc_pose_we_from_weutm_errors);
  RUN_TEST(test_we_round_trip_turns_the_yaw);
  RUN_TEST(test_wmgrs_against_geoconvert);
  RUN_TEST(test_w_from_wmgrs_against_geoconvert);
  RUN_TEST(test_le_and_we_against_cartconvert);
  RUN_TEST(test_le_and_l);
  RUN_TEST(test_wmgrs_header_example);
  RUN_TEST(test_drdc_pose_wmgrs_from_w_errors);
  RUN_TEST(test_drdc_pose_w_from_wmgrs_errors);
  RUN_TEST(test_drdc_pose_wemgrs_from_we_errors);
  RUN_TEST(test_drdc_pose_we_from_wemgrs_errors);
  RUN_TEST(test_drdc_pose_l_from_le_and_le_from_l_errors);
  RUN_TEST(test_drdc_pose_we_from_le_errors);
  RUN_TEST(test_drdc_pose_we_from_le_unchanged_on_error);
  RUN_TEST(test_drdc_pose_le_from_we_errors);
  RUN_TEST(test_local_poses_far_heights_do_not_overflow);
}
