/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Tests of MGRS encode and decode against GeoConvert: every
 *        precision from the grid zone to 1 um cells (prec 11),
 *        decoded centres and the status of malformed strings.
 */
#include <drdc/geo_mgrs.h>

#include <stddef.h>

#include "suites.h"
#include "unity.h"
#include "vectors_mgrs.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

/* the digit value of c, or -1 */
static int32_t digit(char c)
{
  static const char d[] = "0123456789";
  int32_t i;

  for (i = 0; i < 10; i++) {
    if (d[i] == c) {
      return i;
    }
  }
  return -1;
}

/* 1 when a and b are the same MGRS but for one unit of the last digit of
 * the easting and/or the northing; 0 otherwise */
static int within_last_digit(const char *a, const char *b)
{
  size_t n = 0u;
  size_t start;
  size_t half;
  size_t i;
  int64_t ea = 0;
  int64_t eb = 0;
  int64_t na = 0;
  int64_t nb = 0;

  while ((a[n] != '\0') && (b[n] != '\0')) {
    n++;
  }
  if ((a[n] != '\0') || (b[n] != '\0')) {
    return 0;
  }
  start = 0u;
  while ((start < n) && ((digit(a[start]) < 0) || (start < 3u))) {
    if (a[start] != b[start]) {
      return 0;
    }
    start++;
  }
  half = (n - start) / 2u;
  for (i = 0u; i < half; i++) {
    ea = (ea * 10) + digit(a[start + i]);
    eb = (eb * 10) + digit(b[start + i]);
    na = (na * 10) + digit(a[start + half + i]);
    nb = (nb * 10) + digit(b[start + half + i]);
  }
  return ((ea - eb) <= 1) && ((eb - ea) <= 1) && ((na - nb) <= 1) &&
         ((nb - na) <= 1);
}

/* The measured disagreements with GeoConvert (tests/ref/gen_geo_mgrs.py
 * vectors, 6 063 points): none at precisions -1..10; at 11 (1 um) the 3
 * points whose GeographicLib coordinate GeoConvert -u -p 9 prints on a
 * 1 um boundary (near_nm 0: within 0.5 nm of it, far inside
 * GeographicLib's own 5 nm error), one in each part the tests below
 * take. Each is one unit of the last digit. */
#define MGRS_NEAR_NM 0
static const uint32_t mgrs_mismatches_per_part[MGRS_PRECS] = {
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1};

/* the text of GeoConvert at prec (MGRS_PREC_FIRST + p) from its text at
 * the finest precision: the head (zone, band, square) and the leading p
 * digits of each coordinate (GeoConvert truncates one value at every
 * precision; gen_geo_mgrs.py asserts this on the full table) */
static void coarser(const char *fine, int32_t p, char *out)
{
  size_t n = 0u;
  size_t head;
  size_t k = 0u;
  size_t i;
  size_t digits = (size_t)(MGRS_PRECS - 1 + MGRS_PREC_FIRST);
  size_t want = (size_t)(p + MGRS_PREC_FIRST);

  while ((n < DRDC_GEO_MGRS_SIZE) && (fine[n] != '\0')) {
    n++;
  }
  /* a UPS or UTM head of 3 or 5 characters (checked below) */
  head = (n > ((2u * digits) + 2u)) ? (n - (2u * digits)) : 3u;
  TEST_ASSERT_TRUE(n == (head + (2u * digits)));
  TEST_ASSERT_TRUE((head == 3u) || (head == 5u));
  if (p + MGRS_PREC_FIRST < 0) {
    head = head - 2u;
  }
  for (i = 0u; i < head; i++) {
    out[k] = fine[i];
    k++;
  }
  if (p + MGRS_PREC_FIRST >= 0) {
    for (i = 0u; i < want; i++) {
      out[k] = fine[head + i];
      k++;
    }
    for (i = 0u; i < want; i++) {
      out[k] = fine[head + digits + i];
      k++;
    }
  }
  out[k] = '\0';
}

/* encode lat, lon at every precision against want(p); a difference must
 * be within one unit of the last digit at a point whose GeographicLib
 * coordinate lies within MGRS_NEAR_NM of a 1 um boundary; counted */
static void check_point(int64_t lat, int64_t lon, int32_t near_nm,
                        const char *const *want, const char *fine,
                        uint32_t *mismatches)
{
  int32_t p;

  for (p = 0; p < MGRS_PRECS; p++) {
    char text[DRDC_GEO_MGRS_SIZE];
    char derived[DRDC_GEO_MGRS_SIZE];
    const char *w = derived;
    size_t k = 0u;

    if (want != NULL) {
      w = want[p];
    } else {
      coarser(fine, p, derived);
    }
    TEST_ASSERT_EQUAL_INT(
        DRDC_OK,
        drdc_geo_mgrs_encode(lat, lon, p + MGRS_PREC_FIRST, text, sizeof text));
    while ((text[k] == w[k]) && (text[k] != '\0')) {
      k++;
    }
    if (text[k] != w[k]) {
      TEST_ASSERT_TRUE_MESSAGE(near_nm <= MGRS_NEAR_NM, w);
      TEST_ASSERT_EQUAL_INT_MESSAGE(1, within_last_digit(text, w), w);
      mismatches[p]++;
    }
  }
}

static void assert_mismatches(const uint32_t *mismatches)
{
  int32_t p;

  for (p = 0; p < MGRS_PRECS; p++) {
    TEST_ASSERT_EQUAL_UINT32(mgrs_mismatches_per_part[p], mismatches[p]);
  }
}

/* The vectors in three tests of a few seconds each on the slowest image
 * (Cortex-M0, where every 64-bit product is a libgcc call), so that the
 * console reports progress well within the harness's hang limit. */
static void test_mgrs_encode_every_precision(void)
{
  uint32_t mismatches[MGRS_PRECS] = {0u};
  size_t i;

  for (i = 0; i < COUNT(mgrs_enc_vectors); i++) {
    const struct mgrs_enc_vector *v = &mgrs_enc_vectors[i];

    check_point(v->lat, v->lon, v->near_nm, v->text, NULL, mismatches);
  }
  assert_mismatches(mismatches);
}

static void check_fine(size_t first, size_t end)
{
  uint32_t mismatches[MGRS_PRECS] = {0u};
  size_t i;

  for (i = first; i < end; i++) {
    const struct mgrs_fine_vector *v = &mgrs_fine_vectors[i];

    check_point(v->lat, v->lon, v->near_nm, NULL, v->text, mismatches);
  }
  assert_mismatches(mismatches);
}

static void test_mgrs_encode_fine_first_half(void)
{
  check_fine(0u, COUNT(mgrs_fine_vectors) / 2u);
}

static void test_mgrs_encode_fine_second_half(void)
{
  check_fine(COUNT(mgrs_fine_vectors) / 2u, COUNT(mgrs_fine_vectors));
}

/* Regression: a northern UTM position south of the equator (negative
 * northing, which drdc_geo_from_utm() accepts) indexed the row letters
 * and digits below their arrays; it is outside the MGRS limits */
static void test_mgrs_from_utm_negative_northing(void)
{
  drdc_geo_utm_t u = {38, true, INT64_C(500000) * 65536, -50 * 65536};
  char text[DRDC_GEO_MGRS_SIZE] = "unchanged";

  TEST_ASSERT_EQUAL_INT(DRDC_E_NORTHING,
                        drdc_geo_mgrs_from_utm(&u, 5, text, sizeof text));
  u.northing = -1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NORTHING,
                        drdc_geo_mgrs_from_utm(&u, 11, text, sizeof text));
  TEST_ASSERT_EQUAL_STRING("unchanged", text);
  u.northing = 0;
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_geo_mgrs_from_utm(&u, 5, text, sizeof text));
  TEST_ASSERT_EQUAL_STRING("38NNF0000000000", text);
}

/* Regression: a point whose Q47.16 easting rounds up onto a
 * 1 m boundary GeographicLib's value lies below: the digits truncate the
 * coordinate before its rounding, as GeoConvert's do. GeoConvert -u -p 9
 * gives easting 660073.999993416 m, drdc_geo_to_utm() 660074 m exactly;
 * the truncated Q47.16 gave 45SXV6007466863 */
static void test_mgrs_truncates_before_rounding(void)
{
  const int64_t lat = INT64_C(128998398905204);
  const int64_t lon = INT64_C(319580136376372);
  drdc_geo_utm_t u;
  char text[DRDC_GEO_MGRS_SIZE];

  TEST_ASSERT_EQUAL_INT(
      DRDC_OK,
      drdc_geo_to_utm(lat, lon, DRDC_GEO_ZONE_STANDARD, &u, NULL, NULL));
  TEST_ASSERT_EQUAL_INT64(INT64_C(660074) * 65536, u.easting);
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_geo_mgrs_encode(lat, lon, 5, text, sizeof text));
  TEST_ASSERT_EQUAL_STRING("45SXV6007366863", text);
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_geo_mgrs_encode(lat, lon, 11, text, sizeof text));
  TEST_ASSERT_EQUAL_STRING("45SXV6007399999366863207264", text);
}

static void test_mgrs_decode(void)
{
  size_t i;

  for (i = 0; i < COUNT(mgrs_dec_vectors); i++) {
    const struct mgrs_dec_vector *v = &mgrs_dec_vectors[i];
    drdc_geo_utm_t corner = {99, false, 0, 0};
    drdc_geo_utm_t centre = {99, false, 0, 0};
    int32_t prec = -9;
    drdc_status_t st = drdc_geo_mgrs_decode(v->text, &corner, &centre, &prec);

    TEST_ASSERT_EQUAL_INT_MESSAGE(v->status, st, v->text);
    if (st == DRDC_OK) {
      TEST_ASSERT_EQUAL_INT32_MESSAGE(v->zone, centre.zone, v->text);
      TEST_ASSERT_EQUAL_INT_MESSAGE(v->north != 0, centre.north, v->text);
      TEST_ASSERT_INT64_WITHIN_MESSAGE(1, v->easting, centre.easting, v->text);
      TEST_ASSERT_INT64_WITHIN_MESSAGE(1, v->northing, centre.northing,
                                       v->text);
    } else {
      TEST_ASSERT_EQUAL_INT32(99, centre.zone);
      TEST_ASSERT_EQUAL_INT32(-9, prec);
    }
  }
}

/* Named cases: corner and centre of "38SMB4488" (1 km cell) */
static void test_mgrs_corner_and_centre(void)
{
  drdc_geo_utm_t corner;
  drdc_geo_utm_t centre;
  int32_t prec = 0;

  TEST_ASSERT_EQUAL_INT(
      DRDC_OK, drdc_geo_mgrs_decode("38SMB4488", &corner, &centre, &prec));
  TEST_ASSERT_EQUAL_INT32(2, prec);
  TEST_ASSERT_EQUAL_INT32(38, corner.zone);
  TEST_ASSERT_TRUE(corner.north);
  TEST_ASSERT_EQUAL_INT64(INT64_C(444000) * 65536, corner.easting);
  TEST_ASSERT_EQUAL_INT64(INT64_C(3688000) * 65536, corner.northing);
  TEST_ASSERT_EQUAL_INT64(INT64_C(444500) * 65536, centre.easting);
  TEST_ASSERT_EQUAL_INT64(INT64_C(3688500) * 65536, centre.northing);
}

void suite_geo_mgrs(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_mgrs_encode_every_precision);
  RUN_TEST(test_mgrs_encode_fine_first_half);
  RUN_TEST(test_mgrs_encode_fine_second_half);
  RUN_TEST(test_mgrs_truncates_before_rounding);
  RUN_TEST(test_mgrs_from_utm_negative_northing);
  RUN_TEST(test_mgrs_decode);
  RUN_TEST(test_mgrs_corner_and_centre);
}
