/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Tests of core/geo UTM and transverse Mercator against
 *        GeographicLib 2.1.2: 20 000 random points, every zone and band
 *        edge, Norway and Svalbard, forced neighbouring zones, points up
 *        to 500 km outside a zone, and named zone-rule cases.
 */
#include <drdc/geo.h>
#include <drdc/geo_pose.h>

#include <stddef.h>

#include <drdc/fixed_wide.h>

#include "../../core/geo/geo_impl.h"
#include "suites.h"
#include "unity.h"
#include "vectors_geo.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

/* Documented bounds (geo.h), the maxima measured on these vectors. */
#define EN_TOL       1   /* easting, northing, x, y: LSB of Q47.16 (15 um) */
#define CONV_TOL     1   /* forward convergence: nas (2.8e-13 degree) */
#define SCALE_TOL    307 /* scale: LSB of Q5.58 (1.1e-15; oracle has 1e-16) */
#define TM_SCALE_TOL 262 /* the same, drdc_geo_tm_forward beyond the zones */
#define LATLON_TOL   1   /* reverse latitude and longitude: nas */
/* reverse convergence and scale, compared with the forward row's values
 * at the unrounded point (the UTM input was rounded to 15 um) */
#define REV_CONV_TOL  2079  /* nas = 5.8e-10 degree */
#define REV_SCALE_TOL 25141 /* LSB of Q5.58 = 8.7e-14 */

#define NAS_DEG INT64_C(3600000000000)

static int64_t dist(int64_t a, int64_t b)
{
  return (a > b) ? (a - b) : (b - a);
}

/* |a - b| of two longitudes, modulo 360 degrees */
static int64_t lon_dist(int64_t a, int64_t b)
{
  int64_t d = dist(a, b);

  return (d > (180 * NAS_DEG)) ? ((360 * NAS_DEG) - d) : d;
}

struct worst {
  int64_t en;
  int64_t conv;
  int64_t scale;
  int64_t latlon;
  int64_t rev_conv;
  int64_t rev_scale;
};

static void keep(int64_t *w, int64_t e)
{
  if (e > *w) {
    *w = e;
  }
}

/* forward and reverse of each row; with_scale: reverse convergence and
 * scale as well */
static void check_rows(const struct geo_fwd_vector *v,
                       const struct geo_rev_vector *rv, size_t n, int forced,
                       int with_scale, struct worst *w)
{
  size_t i;

  for (i = 0; i < n; i++) {
    drdc_geo_utm_t u = {0, false, 0, 0};
    drdc_nas_t conv = 0;
    drdc_q5_58_t k = 0;
    drdc_nas_t lat = 0;
    drdc_nas_t lon = 0;
    drdc_geo_utm_t in;

    TEST_ASSERT_EQUAL_INT(
        DRDC_OK, drdc_geo_to_utm(v[i].lat, v[i].lon,
                                 forced ? v[i].zone : DRDC_GEO_ZONE_STANDARD,
                                 &u, &conv, &k));
    TEST_ASSERT_EQUAL_INT32(v[i].zone, u.zone);
    TEST_ASSERT_EQUAL_INT(v[i].north != 0, u.north);
    keep(&w->en, dist(u.easting, v[i].easting));
    keep(&w->en, dist(u.northing, v[i].northing));
    keep(&w->conv, lon_dist(conv, v[i].convergence));
    keep(&w->scale, dist(k, v[i].scale));
    in.zone = v[i].zone;
    in.north = (v[i].north != 0);
    in.easting = v[i].easting;
    in.northing = v[i].northing;
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_geo_from_utm(&in, &lat, &lon,
                                                     with_scale ? &conv : NULL,
                                                     with_scale ? &k : NULL));
    keep(&w->latlon, dist(lat, rv[i].lat));
    keep(&w->latlon, lon_dist(lon, rv[i].lon));
    /* in UPS the convergence is the longitude, as ill-conditioned as
     * 1 / (distance to the pole) for the 15 um rounding of the input:
     * the reverse longitude is checked instead */
    if (with_scale && (v[i].zone != 0)) {
      /* at a pole the convergence is the longitude: +-180 are one */
      keep(&w->rev_conv, lon_dist(conv, v[i].convergence));
      keep(&w->rev_scale, dist(k, v[i].scale));
    }
  }
}

static void assert_worst(const struct worst *w)
{
  TEST_ASSERT_LESS_OR_EQUAL_INT64(EN_TOL, w->en);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(CONV_TOL, w->conv);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(SCALE_TOL, w->scale);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(LATLON_TOL, w->latlon);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(REV_CONV_TOL, w->rev_conv);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(REV_SCALE_TOL, w->rev_scale);
}

static void test_utm_random(void)
{
  struct worst w = {0, 0, 0, 0, 0, 0};

  check_rows(geo_random_vectors, geo_random_rev, COUNT(geo_random_vectors), 0,
             0, &w);
  assert_worst(&w);
}

static void test_utm_edges(void)
{
  struct worst w = {0, 0, 0, 0, 0, 0};

  check_rows(geo_edge_vectors, geo_edge_rev, COUNT(geo_edge_vectors), 0, 1, &w);
  assert_worst(&w);
}

static void test_utm_forced_zone(void)
{
  struct worst w = {0, 0, 0, 0, 0, 0};

  check_rows(geo_forced_vectors, geo_forced_rev, COUNT(geo_forced_vectors), 1,
             1, &w);
  assert_worst(&w);
}

static void test_tm_outside_zone(void)
{
  int64_t w_en = 0;
  int64_t w_conv = 0;
  int64_t w_scale = 0;
  size_t i;

  for (i = 0; i < COUNT(geo_tm_vectors); i++) {
    const struct geo_tm_vector *v = &geo_tm_vectors[i];
    drdc_q47_16_t x = 0;
    drdc_q47_16_t y = 0;
    drdc_nas_t conv = 0;
    drdc_q5_58_t k = 0;

    TEST_ASSERT_EQUAL_INT(
        DRDC_OK, drdc_geo_tm_forward(v->lat, v->dlon, &x, &y, &conv, &k));
    keep(&w_en, dist(x, v->x));
    keep(&w_en, dist(y, v->y));
    keep(&w_conv, dist(conv, v->convergence));
    keep(&w_scale, dist(k, v->scale));
  }
  TEST_ASSERT_LESS_OR_EQUAL_INT64(EN_TOL, w_en);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(CONV_TOL, w_conv);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(TM_SCALE_TOL, w_scale);
}

static int32_t zone_of(int64_t lat_deg, int64_t lon_nas)
{
  int32_t z = -7;

  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_geo_utm_zone(lat_deg * NAS_DEG, lon_nas, &z));
  return z;
}

/* Named zone-rule cases (GeoConvert -u): edges belong east and north. */
static void test_utm_zone_rules(void)
{
  TEST_ASSERT_EQUAL_INT32(31, zone_of(0, 0));
  TEST_ASSERT_EQUAL_INT32(30, zone_of(0, -1));
  TEST_ASSERT_EQUAL_INT32(1, zone_of(0, -180 * NAS_DEG));
  TEST_ASSERT_EQUAL_INT32(1, zone_of(0, 180 * NAS_DEG));
  TEST_ASSERT_EQUAL_INT32(60, zone_of(0, (180 * NAS_DEG) - 1));
  TEST_ASSERT_EQUAL_INT32(1, zone_of(0, -540 * NAS_DEG));
  /* Norway: 32V from 3 degrees east, 56 <= lat < 64 */
  TEST_ASSERT_EQUAL_INT32(32, zone_of(56, 3 * NAS_DEG));
  TEST_ASSERT_EQUAL_INT32(31, zone_of(56, (3 * NAS_DEG) - 1));
  TEST_ASSERT_EQUAL_INT32(31, zone_of(64, 3 * NAS_DEG));
  TEST_ASSERT_EQUAL_INT32(31, zone_of(55, 3 * NAS_DEG));
  /* Svalbard: 31X 33X 35X 37X, 72 <= lat < 84 */
  TEST_ASSERT_EQUAL_INT32(31, zone_of(72, 8 * NAS_DEG));
  TEST_ASSERT_EQUAL_INT32(33, zone_of(72, 9 * NAS_DEG));
  TEST_ASSERT_EQUAL_INT32(35, zone_of(83, 21 * NAS_DEG));
  TEST_ASSERT_EQUAL_INT32(37, zone_of(80, 33 * NAS_DEG));
  TEST_ASSERT_EQUAL_INT32(38, zone_of(80, 42 * NAS_DEG));
  TEST_ASSERT_EQUAL_INT32(32, zone_of(71, 9 * NAS_DEG));
  /* the UPS caps */
  TEST_ASSERT_EQUAL_INT32(0, zone_of(84, 0));
  TEST_ASSERT_EQUAL_INT32(31, zone_of(-80, 0));
  TEST_ASSERT_EQUAL_INT32(0, zone_of(-81, 0));
  TEST_ASSERT_EQUAL_INT32(0, zone_of(90, 0));
}

/* The example of geo.h: lat 10, lon 20 -> 34n 390399.2275 1105578.5892 */
static void test_utm_header_example(void)
{
  drdc_geo_utm_t u = {0, false, 0, 0};

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_geo_to_utm(10 * NAS_DEG, 20 * NAS_DEG,
                                                 DRDC_GEO_ZONE_STANDARD, &u,
                                                 NULL, NULL));
  TEST_ASSERT_EQUAL_INT32(34, u.zone);
  TEST_ASSERT_TRUE(u.north);
  /* 390399.2275 m and 1105578.5892 m in Q47.16, within 0.1 mm */
  TEST_ASSERT_LESS_OR_EQUAL_INT64(7, dist(u.easting, INT64_C(25585203773)));
  TEST_ASSERT_LESS_OR_EQUAL_INT64(7, dist(u.northing, INT64_C(72455198422)));
}

static int64_t bam_dist(drdc_bam32_t a, drdc_bam32_t b)
{
  uint32_t d = a - b;

  return (d > 0x80000000u) ? (int64_t)(0u - d) : (int64_t)d;
}

#define M(v) ((int64_t)(v)*INT64_C(65536))
/* geo_pose.h bounds, the maxima measured here */
#define YAW_TOL   4     /* binary-angle LSB (3.4e-7 degree) */
#define PR_TOL    3     /* pitch and roll, binary-angle LSB */
#define POSE_ROWS 2000u /* rows of the 22 000 used (QEMU time) */

static void test_grid_from_true_turns_the_yaw_by_gamma(void)
{
  int64_t w_yaw = 0;
  int64_t w_pr = 0;
  int64_t w_trip = 0;
  size_t i;

  for (i = 0; i < POSE_ROWS; i++) {
    const struct geo_fwd_vector *v = &geo_random_vectors[i];
    /* a different attitude per row, pitch within +-60 degrees */
    drdc_euler_t e = {(drdc_bam32_t)(i * 2654435761u),
                      (drdc_bam32_t)((i * 40503u) % 715827882u) - 357913941u,
                      (drdc_bam32_t)(i * 97u * 1000003u)};
    drdc_quat_t qt;
    drdc_quat_t qg;
    drdc_quat_t back;
    drdc_euler_t eg;
    drdc_bam32_t gamma = drdc_pose_bam_from_convergence(v->convergence);

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_quat_from_euler(&e, &qt));
    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_pose_grid_from_true(&qt, v->convergence, &qg));
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_euler_from_quat(&qg, &eg));
    w_yaw = (bam_dist(eg.yaw, e.yaw - gamma) > w_yaw)
                ? bam_dist(eg.yaw, e.yaw - gamma)
                : w_yaw;
    w_pr = (bam_dist(eg.pitch, e.pitch) > w_pr) ? bam_dist(eg.pitch, e.pitch)
                                                : w_pr;
    w_pr =
        (bam_dist(eg.roll, e.roll) > w_pr) ? bam_dist(eg.roll, e.roll) : w_pr;
    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_pose_true_from_grid(&qg, v->convergence, &back));
    w_trip = (dist(back.s, qt.s) > w_trip) ? dist(back.s, qt.s) : w_trip;
    w_trip = (dist(back.z, qt.z) > w_trip) ? dist(back.z, qt.z) : w_trip;
  }
  TEST_ASSERT_LESS_OR_EQUAL_INT64(YAW_TOL, w_yaw);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(PR_TOL, w_pr);
  TEST_ASSERT_LESS_OR_EQUAL_INT64(4, w_trip); /* Q1.30 LSB */
}

static void test_wutm_round_trip(void)
{
  size_t i;

  for (i = 0; i < POSE_ROWS; i += 4u) {
    const struct geo_fwd_vector *v = &geo_random_vectors[i];
    drdc_WPose_t w = {v->lon, v->lat, M(123), {759250125, 0, 0, 759250125}};
    drdc_WUTMPose_t u;
    drdc_WPose_t back;

    TEST_ASSERT_EQUAL_INT(
        DRDC_OK, drdc_pose_wutm_from_w(&w, DRDC_GEO_ZONE_STANDARD, &u));
    TEST_ASSERT_EQUAL_INT32(v->zone, u.utm.zone);
    TEST_ASSERT_INT64_WITHIN(1, v->easting, u.utm.easting);
    TEST_ASSERT_INT64_WITHIN(1, v->northing, u.utm.northing);
    TEST_ASSERT_EQUAL_INT64(M(123), u.height);
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_pose_w_from_wutm(&u, &back));
    /* the 7.6 um rounding of the Q47.16 easting and northing */
    TEST_ASSERT_INT64_WITHIN(400, w.latitude, back.latitude);
    TEST_ASSERT_INT32_WITHIN(4, w.q.s, back.q.s);
    TEST_ASSERT_INT32_WITHIN(4, w.q.z, back.q.z);
  }
}

/* drdc__geo_mul_shift(a, b, n) against drdc_fx_muldiv_s64(a, b, 2^n) (the
 * division it replaced in the Q28.36 metres of UTM and UPS), bit for bit:
 * both round the same rational a b / 2^n to nearest, ties away from
 * zero. Checked for both constants on random values of every magnitude
 * and sign, the largest |a| whose quotient fits int64_t, and the exact
 * ties: b odd, so a b / 2^n is a half exactly when a is an odd multiple
 * of 2^(n-1); +-2^(n-1) is the one in range, checked with its
 * neighbours. */
static void check_mul_shift(int64_t b, unsigned n)
{
  static const int64_t named[] = {0, 1, -1, INT64_C(0x1fffffffffffffff)};
  uint64_t seed = UINT64_C(0x9E3779B97F4A7C15);
  int64_t half = INT64_C(1) << (n - 1u);
  int64_t want;
  int64_t a;
  int k;
  unsigned i;

  TEST_ASSERT_TRUE(((uint64_t)b & 1u) == 1u);
  for (i = 0u; i < 4000u; i++) {
    seed =
        (seed * UINT64_C(6364136223846793005)) + UINT64_C(1442695040888963407);
    /* 61 bits down to 1: the quotient stays within int64_t for
     * b < 2^63 and n >= 61 */
    a = (int64_t)(seed >> (3u + (i % 61u)));
    a = ((i & 1u) != 0u) ? -a : a;
    want = 0;
    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_fx_muldiv_s64(a, b, INT64_C(1) << n, &want));
    TEST_ASSERT_EQUAL_INT64(want, drdc__geo_mul_shift(a, b, n));
  }
  for (k = -1; k <= 1; k++) {
    for (i = 0u; i < (2u * COUNT(named)); i++) {
      a = (i < COUNT(named)) ? (half + k) : named[i - COUNT(named)];
      a = ((i & 1u) != 0u) ? -a : a;
      want = 0;
      TEST_ASSERT_EQUAL_INT(DRDC_OK,
                            drdc_fx_muldiv_s64(a, b, INT64_C(1) << n, &want));
      TEST_ASSERT_EQUAL_INT64(want, drdc__geo_mul_shift(a, b, n));
    }
  }
}

static void test_geo_mul_shift_is_muldiv(void)
{
  check_mul_shift(GEO_K0A_Q40, 62u);
  check_mul_shift(GEO_UPS_K_Q39, 61u);
}

void suite_geo_utm(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_utm_random);
  RUN_TEST(test_utm_edges);
  RUN_TEST(test_utm_forced_zone);
  RUN_TEST(test_tm_outside_zone);
  RUN_TEST(test_geo_mul_shift_is_muldiv);
  RUN_TEST(test_utm_zone_rules);
  RUN_TEST(test_utm_header_example);
  RUN_TEST(test_grid_from_true_turns_the_yaw_by_gamma);
  RUN_TEST(test_wutm_round_trip);
}
