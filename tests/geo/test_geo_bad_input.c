/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Bad-input catalogue of core/geo (UTM, UPS, MGRS) and
 *        drdc_fx_mul_q5_58
 *        (docs/bad-input.md): each error status of each function, with
 *        the outputs left unchanged.
 */
#include <drdc/fixed_arith.h>
#include <drdc/geo.h>
#include <drdc/geo_ecef.h>
#include <drdc/geo_mgrs.h>

#include <stddef.h>
#include <string.h>

#include "suites.h"
#include "unity.h"

#define NAS_DEG    INT64_C(3600000000000)
#define SENTINEL64 INT64_C(0x5A5A5A5A5A5A5A5A)
#define M(v)       ((int64_t)(v)*INT64_C(65536))

static drdc_geo_utm_t sentinel_utm(void)
{
  drdc_geo_utm_t u = {77, true, SENTINEL64, SENTINEL64};

  return u;
}

static void assert_utm_unchanged(const drdc_geo_utm_t *u)
{
  TEST_ASSERT_EQUAL_INT32(77, u->zone);
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, u->easting);
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, u->northing);
}

static void test_drdc_geo_utm_zone_errors(void)
{
  int32_t z = 77;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_geo_utm_zone(0, 0, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_LATITUDE,
                        drdc_geo_utm_zone((90 * NAS_DEG) + 1, 0, &z));
  TEST_ASSERT_EQUAL_INT(DRDC_E_LATITUDE,
                        drdc_geo_utm_zone((-90 * NAS_DEG) - 1, 0, &z));
  TEST_ASSERT_EQUAL_INT(DRDC_E_LONGITUDE,
                        drdc_geo_utm_zone(0, 540 * NAS_DEG, &z));
  TEST_ASSERT_EQUAL_INT(DRDC_E_LONGITUDE,
                        drdc_geo_utm_zone(0, (-540 * NAS_DEG) - 1, &z));
  TEST_ASSERT_EQUAL_INT32(77, z);
}

static void test_drdc_geo_tm_forward_errors(void)
{
  drdc_q47_16_t x = SENTINEL64;
  drdc_q47_16_t y = SENTINEL64;
  drdc_nas_t g = SENTINEL64;
  drdc_q5_58_t k = SENTINEL64;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_geo_tm_forward(0, 0, NULL, &y, &g, &k));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_geo_tm_forward(0, 0, &x, NULL, &g, &k));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_LATITUDE,
      drdc_geo_tm_forward((90 * NAS_DEG) + 1, 0, &x, &y, &g, &k));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_LONGITUDE,
      drdc_geo_tm_forward(0, (90 * NAS_DEG) + 1, &x, &y, &g, &k));
  /* 25 degrees from the central meridian on the equator: 2 900 km */
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_geo_tm_forward(0, 25 * NAS_DEG, &x, &y, &g, &k));
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, x);
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, y);
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, g);
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, k);
}

static void test_drdc_geo_to_utm_errors(void)
{
  drdc_geo_utm_t u = sentinel_utm();
  drdc_nas_t g = SENTINEL64;

  TEST_ASSERT_EQUAL_INT(
      DRDC_E_NULL,
      drdc_geo_to_utm(0, 0, DRDC_GEO_ZONE_STANDARD, NULL, &g, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_LATITUDE,
                        drdc_geo_to_utm((90 * NAS_DEG) + 1, 0,
                                        DRDC_GEO_ZONE_STANDARD, &u, &g, NULL));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_LONGITUDE,
      drdc_geo_to_utm(0, 540 * NAS_DEG, DRDC_GEO_ZONE_STANDARD, &u, &g, NULL));
  /* zone 61 */
  TEST_ASSERT_EQUAL_INT(DRDC_E_ZONE, drdc_geo_to_utm(0, 0, 61, &u, &g, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_ZONE, drdc_geo_to_utm(0, 0, -2, &u, &g, NULL));
  /* forced UPS (zone 0) at 80 N: "out of legal range for UPS" */
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_geo_to_utm(80 * NAS_DEG, -30 * NAS_DEG,
                                        DRDC_GEO_ZONE_UPS, &u, &g, NULL));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE,
      drdc_geo_to_utm(-10 * NAS_DEG, 0, DRDC_GEO_ZONE_UPS, &u, &g, NULL));
  /* GeoConvert -z 31: "Latitude 0, longitude -5 out of legal range" */
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_geo_to_utm(0, -5 * NAS_DEG, 31, &u, &g, NULL));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE,
      drdc_geo_to_utm(10 * NAS_DEG, 10 * NAS_DEG, 28, &u, &g, NULL));
  assert_utm_unchanged(&u);
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, g);
}

static void test_drdc_geo_from_utm_errors(void)
{
  drdc_geo_utm_t in = {31, true, M(500000), M(0)};
  drdc_nas_t lat = SENTINEL64;
  drdc_nas_t lon = SENTINEL64;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_geo_from_utm(NULL, &lat, &lon, NULL, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_geo_from_utm(&in, NULL, &lon, NULL, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_geo_from_utm(&in, &lat, NULL, NULL, NULL));
  in.zone = -1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_ZONE,
                        drdc_geo_from_utm(&in, &lat, &lon, NULL, NULL));
  in.zone = 61;
  TEST_ASSERT_EQUAL_INT(DRDC_E_ZONE,
                        drdc_geo_from_utm(&in, &lat, &lon, NULL, NULL));
  in.zone = 31;
  in.easting = M(1000000) + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_EASTING,
                        drdc_geo_from_utm(&in, &lat, &lon, NULL, NULL));
  in.easting = -1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_EASTING,
                        drdc_geo_from_utm(&in, &lat, &lon, NULL, NULL));
  in.easting = M(500000);
  in.northing = M(9600000) + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NORTHING,
                        drdc_geo_from_utm(&in, &lat, &lon, NULL, NULL));
  in.north = false;
  in.northing = M(900000) - 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NORTHING,
                        drdc_geo_from_utm(&in, &lat, &lon, NULL, NULL));
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, lat);
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, lon);
  /* UPS: [1 200, 2 800] km north, [700, 3 300] km south */
  in.zone = DRDC_GEO_ZONE_UPS;
  in.north = true;
  in.easting = M(1200000) - 1;
  in.northing = M(2000000);
  TEST_ASSERT_EQUAL_INT(DRDC_E_EASTING,
                        drdc_geo_from_utm(&in, &lat, &lon, NULL, NULL));
  in.easting = M(2000000);
  in.northing = M(2800000) + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NORTHING,
                        drdc_geo_from_utm(&in, &lat, &lon, NULL, NULL));
  in.north = false;
  in.northing = M(3300000) + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NORTHING,
                        drdc_geo_from_utm(&in, &lat, &lon, NULL, NULL));
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, lat);
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, lon);
  in.zone = 31;
  in.north = false;
  in.easting = M(500000);
  /* the limits themselves are accepted (GeoConvert's are inclusive) */
  in.northing = M(900000);
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_geo_from_utm(&in, &lat, &lon, NULL, NULL));
}

static void test_drdc_geo_mgrs_encode_errors(void)
{
  char text[DRDC_GEO_MGRS_SIZE] = "unchanged";

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_geo_mgrs_encode(0, 0, 5, NULL, 28u));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_LATITUDE,
      drdc_geo_mgrs_encode((90 * NAS_DEG) + 1, 0, 5, text, sizeof text));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_LONGITUDE,
      drdc_geo_mgrs_encode(0, 540 * NAS_DEG, 5, text, sizeof text));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_geo_mgrs_encode(0, 0, 12, text, sizeof text));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_geo_mgrs_encode(0, 0, -2, text, sizeof text));
  /* "31NAA6602100000" needs 16 bytes */
  TEST_ASSERT_EQUAL_INT(DRDC_E_BUFFER,
                        drdc_geo_mgrs_encode(0, 0, 5, text, 15u));
  TEST_ASSERT_EQUAL_STRING("unchanged", text);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_geo_mgrs_encode(0, 0, 5, text, 16u));
  TEST_ASSERT_EQUAL_STRING("31NAA6602100000", text);
}

static void test_drdc_geo_mgrs_from_utm_errors(void)
{
  char text[DRDC_GEO_MGRS_SIZE] = "unchanged";
  drdc_geo_utm_t u = {31, true, M(99999), M(0)};

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_geo_mgrs_from_utm(NULL, 5, text, sizeof text));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_geo_mgrs_from_utm(&u, 5, NULL, 28u));
  /* inside the UTM range, outside the MGRS limits */
  TEST_ASSERT_EQUAL_INT(DRDC_E_EASTING,
                        drdc_geo_mgrs_from_utm(&u, 5, text, sizeof text));
  u.easting = M(1000001);
  TEST_ASSERT_EQUAL_INT(DRDC_E_EASTING,
                        drdc_geo_mgrs_from_utm(&u, 5, text, sizeof text));
  u.easting = M(500000);
  u.northing = M(9500000);
  TEST_ASSERT_EQUAL_INT(DRDC_E_NORTHING,
                        drdc_geo_mgrs_from_utm(&u, 5, text, sizeof text));
  u.zone = 61;
  TEST_ASSERT_EQUAL_INT(DRDC_E_ZONE,
                        drdc_geo_mgrs_from_utm(&u, 5, text, sizeof text));
  u.zone = 31;
  u.northing = M(0);
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_geo_mgrs_from_utm(&u, 12, text, sizeof text));
  TEST_ASSERT_EQUAL_INT(DRDC_E_BUFFER,
                        drdc_geo_mgrs_from_utm(&u, 5, text, 15u));
  TEST_ASSERT_EQUAL_STRING("unchanged", text);
  /* zone 31 kept for a point of zone 32 */
  u.easting = M(900000) - 1;
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_geo_mgrs_from_utm(&u, 0, text, 28u));
  TEST_ASSERT_EQUAL_STRING("31NHA", text);
}

static void test_drdc_geo_mgrs_decode_errors(void)
{
  drdc_geo_utm_t u = sentinel_utm();
  int32_t prec = 77;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_geo_mgrs_decode(NULL, &u, NULL, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_geo_mgrs_decode("38SMB", NULL, NULL, NULL));
  /* zone 0 and 61 */
  TEST_ASSERT_EQUAL_INT(DRDC_E_ZONE,
                        drdc_geo_mgrs_decode("00SMB", &u, &u, &prec));
  TEST_ASSERT_EQUAL_INT(DRDC_E_ZONE,
                        drdc_geo_mgrs_decode("61SMB", &u, &u, &prec));
  /* wrong letters, odd digit count, too many digits, too short */
  TEST_ASSERT_EQUAL_INT(DRDC_E_MGRS,
                        drdc_geo_mgrs_decode("38IMB", &u, &u, &prec));
  TEST_ASSERT_EQUAL_INT(DRDC_E_MGRS,
                        drdc_geo_mgrs_decode("38SAB", &u, &u, &prec));
  TEST_ASSERT_EQUAL_INT(DRDC_E_MGRS,
                        drdc_geo_mgrs_decode("38SMB448", &u, &u, &prec));
  TEST_ASSERT_EQUAL_INT(DRDC_E_MGRS,
                        drdc_geo_mgrs_decode("38SMB4a", &u, &u, &prec));
  TEST_ASSERT_EQUAL_INT(DRDC_E_MGRS,
                        drdc_geo_mgrs_decode("38SM", &u, &u, &prec));
  TEST_ASSERT_EQUAL_INT(DRDC_E_MGRS,
                        drdc_geo_mgrs_decode("001SMB", &u, &u, &prec));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_MGRS,
      drdc_geo_mgrs_decode("38SMB123456789012345678901", &u, &u, &prec));
  /* an illegal 100 km square: MT is not in band S of zone 38 */
  TEST_ASSERT_EQUAL_INT(DRDC_E_BAND,
                        drdc_geo_mgrs_decode("38SMT", &u, &u, &prec));
  assert_utm_unchanged(&u);
  TEST_ASSERT_EQUAL_INT32(77, prec);
}

static void test_drdc_geo_to_ecef_errors(void)
{
  drdc_geo_point_t p = {0, 0, 0};
  drdc_vec3_q47_16_t e = {SENTINEL64, SENTINEL64, SENTINEL64};

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_geo_to_ecef(NULL, &e));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_geo_to_ecef(&p, NULL));
  p.lat = (90 * NAS_DEG) + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LATITUDE, drdc_geo_to_ecef(&p, &e));
  p.lat = 0;
  p.lon = 540 * NAS_DEG;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LONGITUDE, drdc_geo_to_ecef(&p, &e));
  p.lon = 0;
  p.height = DRDC_GEO_HEIGHT_MAX + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT, drdc_geo_to_ecef(&p, &e));
  p.height = -DRDC_GEO_HEIGHT_MAX - 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT, drdc_geo_to_ecef(&p, &e));
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, e.x);
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, e.z);
}

static void test_from_ecef_int64_min_does_not_overflow(void)
{
  /* Regression: a coordinate of INT64_MIN was negated in int64_t by the
   * range check of drdc_geo_from_ecef() (undefined behaviour, caught by
   * UBSan: the magnitude in ecef.c). Each coordinate at INT64_MIN,
   * INT64_MIN + 1 and INT64_MAX, the others on the equator's surface or
   * also extreme: DRDC_E_HEIGHT, p unchanged. */
  static const int64_t far[] = {INT64_MIN, INT64_MIN + 1, INT64_MAX};
  size_t i;
  size_t axis;

  for (i = 0; i < (sizeof far / sizeof far[0]); i++) {
    for (axis = 0; axis < 4u; axis++) {
      drdc_vec3_q47_16_t e = {M(6378137), 0, 0};
      drdc_geo_point_t p;

      if (axis == 0u) {
        e.x = far[i];
      } else if (axis == 1u) {
        e.y = far[i];
      } else if (axis == 2u) {
        e.z = far[i];
      } else {
        e.x = far[i];
        e.y = far[i];
        e.z = far[i];
      }
      memset(&p, 0x5A, sizeof p);
      TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT, drdc_geo_from_ecef(&e, &p));
      TEST_ASSERT_EACH_EQUAL_HEX8(0x5A, &p, sizeof p);
    }
  }
}

static void test_drdc_geo_from_ecef_errors(void)
{
  drdc_geo_point_t p = {SENTINEL64, SENTINEL64, SENTINEL64};
  drdc_vec3_q47_16_t e = {M(6378137), 0, 0};

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_geo_from_ecef(NULL, &p));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_geo_from_ecef(&e, NULL));
  /* 16 378 137 m from the centre on the equator: 10 000 km high + 1 */
  e.x = M(16378138);
  TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT, drdc_geo_from_ecef(&e, &p));
  e.x = INT64_MAX;
  TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT, drdc_geo_from_ecef(&e, &p));
  /* the Earth's core */
  e.x = M(1000);
  TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT, drdc_geo_from_ecef(&e, &p));
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, p.lat);
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, p.height);
  e.x = M(16378137);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_geo_from_ecef(&e, &p));
  TEST_ASSERT_EQUAL_INT64(DRDC_GEO_HEIGHT_MAX, p.height);
}

/* the errors of drdc_geo_to_enu (ned: 0) or drdc_geo_to_ned (ned: 1) */
static void local_errors(int ned)
{
  drdc_geo_point_t ref = {0, 0, 0};
  drdc_geo_point_t p = {0, 0, 0};
  drdc_vec3_q15_16_t v = {77, 77, 77};
  drdc_status_t (*f)(const drdc_geo_point_t *, const drdc_geo_point_t *,
                     drdc_vec3_q15_16_t *) =
      (ned != 0) ? drdc_geo_to_ned : drdc_geo_to_enu;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, f(NULL, &p, &v));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, f(&ref, NULL, &v));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, f(&ref, &p, NULL));
  p.lat = (-90 * NAS_DEG) - 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LATITUDE, f(&ref, &p, &v));
  p.lat = 0;
  ref.lon = -540 * NAS_DEG - 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LONGITUDE, f(&ref, &p, &v));
  ref.lon = 0;
  p.height = DRDC_GEO_HEIGHT_MAX + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT, f(&ref, &p, &v));
  /* 33 km up does not fit Q15.16 */
  p.height = M(33000);
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, f(&ref, &p, &v));
  TEST_ASSERT_EQUAL_INT32(77, v.x);
  TEST_ASSERT_EQUAL_INT32(77, v.z);
}

static void test_drdc_geo_to_enu_errors(void)
{
  /* drdc_geo_to_enu: DRDC_E_NULL, DRDC_E_LATITUDE, DRDC_E_LONGITUDE,
   * DRDC_E_HEIGHT, DRDC_E_OVERFLOW */
  local_errors(0);
}

static void test_drdc_geo_to_ned_errors(void)
{
  /* drdc_geo_to_ned: DRDC_E_NULL, DRDC_E_LATITUDE, DRDC_E_LONGITUDE,
   * DRDC_E_HEIGHT, DRDC_E_OVERFLOW */
  local_errors(1);
}

/* the errors of drdc_geo_from_enu (ned: 0) or drdc_geo_from_ned (1) */
static void from_local_errors(int ned)
{
  drdc_geo_point_t ref = {0, 0, 0};
  drdc_geo_point_t p = {SENTINEL64, SENTINEL64, SENTINEL64};
  drdc_vec3_q15_16_t v = {0, 0, 0};
  drdc_status_t (*f)(const drdc_geo_point_t *, const drdc_vec3_q15_16_t *,
                     drdc_geo_point_t *) =
      (ned != 0) ? drdc_geo_from_ned : drdc_geo_from_enu;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, f(NULL, &v, &p));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, f(&ref, NULL, &p));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, f(&ref, &v, NULL));
  ref.lat = (90 * NAS_DEG) + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LATITUDE, f(&ref, &v, &p));
  ref.lat = 0;
  ref.lon = 540 * NAS_DEG;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LONGITUDE, f(&ref, &v, &p));
  ref.lon = 0;
  ref.height = -DRDC_GEO_HEIGHT_MAX - 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT, f(&ref, &v, &p));
  /* the point (not the ref) beyond 10 000 km: ref at the limit, 1 km up */
  ref.height = DRDC_GEO_HEIGHT_MAX;
  v.z = (ned != 0) ? -M(1000) : M(1000);
  TEST_ASSERT_EQUAL_INT(DRDC_E_HEIGHT, f(&ref, &v, &p));
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, p.lat);
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, p.height);
}

static void test_drdc_geo_from_enu_errors(void)
{
  /* drdc_geo_from_enu: DRDC_E_NULL, DRDC_E_LATITUDE, DRDC_E_LONGITUDE,
   * DRDC_E_HEIGHT */
  from_local_errors(0);
}

static void test_drdc_geo_from_ned_errors(void)
{
  /* drdc_geo_from_ned: DRDC_E_NULL, DRDC_E_LATITUDE, DRDC_E_LONGITUDE,
   * DRDC_E_HEIGHT */
  from_local_errors(1);
}

static void test_drdc_fx_mul_q5_58_errors(void)
{
  int64_t r = SENTINEL64;
  int64_t one = INT64_C(288230376151711744);

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_fx_mul_q5_58(one, one, NULL));
  /* 8 x 4 = 32 is just out of range; 8 x -4 = -32 just in */
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        drdc_fx_mul_q5_58(8 * one, 4 * one, &r));
  TEST_ASSERT_EQUAL_INT64(SENTINEL64, r);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_mul_q5_58(8 * one, -4 * one, &r));
  TEST_ASSERT_EQUAL_INT64(INT64_MIN, r);
  /* rounding: ties away from zero */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_mul_q5_58(1, INT64_C(1) << 57, &r));
  TEST_ASSERT_EQUAL_INT64(1, r);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_fx_mul_q5_58(-1, INT64_C(1) << 57, &r));
  TEST_ASSERT_EQUAL_INT64(-1, r);
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_fx_mul_q5_58(3, (INT64_C(1) << 57) - 1, &r));
  TEST_ASSERT_EQUAL_INT64(1, r);
}

void suite_geo_bad_input(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_drdc_geo_utm_zone_errors);
  RUN_TEST(test_drdc_geo_tm_forward_errors);
  RUN_TEST(test_drdc_geo_to_utm_errors);
  RUN_TEST(test_drdc_geo_from_utm_errors);
  RUN_TEST(test_drdc_geo_mgrs_encode_errors);
  RUN_TEST(test_drdc_geo_mgrs_from_utm_errors);
  RUN_TEST(test_drdc_geo_mgrs_decode_errors);
  RUN_TEST(test_drdc_geo_to_ecef_errors);
  RUN_TEST(test_drdc_geo_from_ecef_errors);
  RUN_TEST(test_from_ecef_int64_min_does_not_overflow);
  RUN_TEST(test_drdc_geo_to_enu_errors);
  RUN_TEST(test_drdc_geo_to_ned_errors);
  RUN_TEST(test_drdc_geo_from_enu_errors);
  RUN_TEST(test_drdc_geo_from_ned_errors);
  RUN_TEST(test_drdc_fx_mul_q5_58_errors);
}
