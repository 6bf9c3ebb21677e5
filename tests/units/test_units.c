/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Units of measure: every unit against GNU units 2.22 vectors
 *        (1 LSB, relative error below 1e-9), the table's own rules, named
 *        conversions matched exactly, and the bad-input catalogue.
 */
#include <stddef.h>
#include <stdint.h>

#include <drdc/units.h>

#include "suites.h"
#include "unity.h"
#include "vectors_units.h"

#define N_VECTORS (sizeof units_vectors / sizeof units_vectors[0])

static size_t length_of(const char *s)
{
  size_t n = 0u;

  while (s[n] != '\0') {
    n++;
  }
  return n;
}

static const drdc_unit_t *unit(const char *name)
{
  const drdc_unit_t *u = NULL;

  TEST_ASSERT_EQUAL_INT_MESSAGE(
      DRDC_OK, drdc_units_find(name, length_of(name), &u), name);
  return u;
}

static drdc_unit_info_t info_of(const drdc_unit_t *u)
{
  drdc_unit_info_t info;

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_units_describe(u, &info));
  return info;
}

static int64_t convert(int64_t raw, unsigned from_frac, const char *from,
                       unsigned to_frac, const char *to)
{
  int64_t out = 0;

  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_units_convert(raw, from_frac, unit(from),
                                                    to_frac, unit(to), &out));
  return out;
}

/* Every vector: within 1 LSB of GNU units' 15-digit value, and a
 * relative error below 1e-9 wherever the result has 2^32 LSB or more. */
static void test_every_unit_matches_gnu_units(void)
{
  size_t i;
  int64_t worst = 0;

  for (i = 0u; i < N_VECTORS; i++) {
    const struct units_vector *v = &units_vectors[i];
    int64_t got = convert(v->raw, v->from_frac, v->from, v->to_frac, v->to);
    int64_t diff = (got > v->expect) ? (got - v->expect) : (v->expect - got);
    int64_t mag = (v->expect < 0) ? -v->expect : v->expect;

    TEST_ASSERT_TRUE_MESSAGE(diff <= 1, v->from);
    if (mag >= (INT64_C(1) << 32)) {
      /* diff <= 1 and mag >= 2^32 > 1e9 */
      TEST_ASSERT_TRUE((diff * INT64_C(1000000000)) < mag);
    }
    if (diff > worst) {
      worst = diff;
    }
  }
  TEST_ASSERT_TRUE(worst <= 1);
}

/* Table index of a unit. */
static size_t index_of(const drdc_unit_t *u)
{
  size_t i = 0u;

  while ((i < drdc_units_count()) && (drdc_units_at(i) != u)) {
    i++;
  }
  return i;
}

/* Whether a unit is eV (or ev), the one factor below 2^-56
 * (documented). */
static int is_ev(const char *name)
{
  return (name[0] == 'e') && ((name[1] == 'V') || (name[1] == 'v')) &&
         (name[2] == '\0');
}

/* At least 80 units; names unique (find() gives back each row itself);
 * fractions positive, below 2^56 (eV: 2^63); every unit has GNU units
 * vectors. */
static void test_table_rules(void)
{
  static uint8_t covered[256];
  size_t n = drdc_units_count();
  size_t i;

  TEST_ASSERT_TRUE(n >= 80u);
  TEST_ASSERT_TRUE(n <= sizeof covered);
  TEST_ASSERT_NULL(drdc_units_at(n));
  for (i = 0u; i < N_VECTORS; i++) {
    covered[index_of(unit(units_vectors[i].from))] = 1u;
    covered[index_of(unit(units_vectors[i].to))] = 1u;
  }
  for (i = 0u; i < n; i++) {
    const drdc_unit_t *row = drdc_units_at(i);
    drdc_unit_info_t info;

    TEST_ASSERT_NOT_NULL(row);
    info = info_of(row);
    TEST_ASSERT_TRUE(info.factor_num > 0);
    TEST_ASSERT_TRUE(info.factor_den > 0);
    TEST_ASSERT_TRUE(info.offset_den > 0);
    TEST_ASSERT_TRUE(info.factor_num < (INT64_C(1) << 56));
    TEST_ASSERT_TRUE_MESSAGE(
        is_ev(info.name) || (info.factor_den < (INT64_C(1) << 56)), info.name);
    TEST_ASSERT_TRUE_MESSAGE(covered[i] != 0u, info.name);
    TEST_ASSERT_EQUAL_PTR(row, unit(info.name));
  }
}

static void test_named_conversions(void)
{
  /* the header's example: 10 ft in Q47.16 metres */
  TEST_ASSERT_EQUAL_INT64(199754,
                          convert(INT64_C(10) << 16, 16, "ft", 16, "m"));
  /* exact definitions */
  TEST_ASSERT_EQUAL_INT64(1852, convert(1, 0, "nmi", 0, "m"));
  TEST_ASSERT_EQUAL_INT64(INT64_C(45359237000),
                          convert(100000000, 0, "lb", 0, "g"));
  TEST_ASSERT_EQUAL_INT64(INT64_C(44482216152605),
                          convert(INT64_C(10000000000000), 0, "lbf", 0, "N"));
  TEST_ASSERT_EQUAL_INT64(4184, convert(1000, 0, "cal", 0, "J"));
  /* pi-based: 360 degree is one turn; 1 degree = 3600 arcsec exactly */
  TEST_ASSERT_EQUAL_INT64(
      INT64_C(1) << 40, convert(INT64_C(360) << 40, 40, "degree", 40, "turn"));
  TEST_ASSERT_EQUAL_INT64(3600, convert(1, 0, "degree", 0, "arcsec"));
  /* rpm and Hz share a dimension, as in GNU units: 60 rpm = 2 pi / s */
  TEST_ASSERT_EQUAL_INT64(6, convert(60, 0, "rpm", 0, "Hz"));
  TEST_ASSERT_EQUAL_INT64(INT64_C(6283185307), convert(INT64_C(60000000000), 0,
                                                       "rpm", 0, "radian/s"));
  /* data rate */
  TEST_ASSERT_EQUAL_INT64(125000, convert(1, 0, "Mbps", 0, "byte/s"));
}

/* Temperatures are points on a scale: offsets apply. */
static void test_temperatures_are_affine(void)
{
  const int64_t one = INT64_C(1) << 32;

  /* 273.15 x 2^32 = 1173170316902.4 */
  TEST_ASSERT_EQUAL_INT64(INT64_C(1173170316902),
                          convert(0, 32, "degC", 32, "K"));
  TEST_ASSERT_EQUAL_INT64(INT64_C(-1173170316902),
                          convert(0, 32, "K", 32, "degC"));
  TEST_ASSERT_EQUAL_INT64(0, convert(32 * one, 32, "degF", 32, "degC"));
  TEST_ASSERT_EQUAL_INT64(-40 * one,
                          convert(-40 * one, 32, "degC", 32, "degF"));
  TEST_ASSERT_EQUAL_INT64(212 * one,
                          convert(100 * one, 32, "tempC", 32, "tempF"));
  TEST_ASSERT_EQUAL_INT64(0, convert(0, 32, "K", 32, "degR"));
  /* -459.67 degF rounds to -460 */
  TEST_ASSERT_EQUAL_INT64(-460, convert(0, 0, "degR", 0, "degF"));
  /* (27315 + 273.15) x 9/5 = 49658.67 */
  TEST_ASSERT_EQUAL_INT64(49659, convert(27315, 0, "degC", 0, "degR"));
}

/* One rounding, ties away from zero, symmetric for negative values. */
static void test_rounding_is_symmetric(void)
{
  TEST_ASSERT_EQUAL_INT64(1, convert(5, 0, "mm", 0, "cm"));
  TEST_ASSERT_EQUAL_INT64(-1, convert(-5, 0, "mm", 0, "cm"));
  TEST_ASSERT_EQUAL_INT64(3, convert(25, 0, "mm", 0, "cm"));
  TEST_ASSERT_EQUAL_INT64(-3, convert(-25, 0, "mm", 0, "cm"));
  TEST_ASSERT_EQUAL_INT64(0, convert(4, 0, "mm", 0, "cm"));
  /* one rounding, not two: 1 ft in Q0 to Q16 metres */
  TEST_ASSERT_EQUAL_INT64(19975, convert(1, 0, "ft", 16, "m"));
}

/* The documented guarantee of no DRDC_E_RANGE: every unit to and from
 * its SI unit (found as the `to` of its vectors) with format changes up
 * to 7 bits; temperatures with from_frac <= 48 and |raw| <= 2^53. eV,
 * whose denominator takes 63 bits, is documented outside it. */
static void test_no_range_error_to_and_from_si(void)
{
  static const unsigned fracs[] = {0u, 7u, 16u, 32u, 48u, 55u, 62u};
  size_t i;

  for (i = 0u; i < N_VECTORS; i += 1u) {
    const drdc_unit_t *a = unit(units_vectors[i].from);
    const drdc_unit_t *b = unit(units_vectors[i].to);
    int affine = (info_of(a).offset_num != 0) || (info_of(b).offset_num != 0);
    size_t f;
    int d;

    if ((i > 0u) && (units_vectors[i - 1u].from == units_vectors[i].from) &&
        (units_vectors[i - 1u].to == units_vectors[i].to)) {
      continue; /* one pass per unit pair */
    }
    if (is_ev(units_vectors[i].from) || is_ev(units_vectors[i].to)) {
      continue;
    }
    for (f = 0u; f < sizeof fracs / sizeof fracs[0]; f++) {
      for (d = -7; d <= 7; d++) {
        int to = (int)fracs[f] + d;
        int64_t out = 0;
        drdc_status_t st;

        if ((to < 0) || (to > 62) || (affine && (fracs[f] > 48u))) {
          continue;
        }
        st = drdc_units_convert(affine ? (INT64_C(1) << 53) : INT64_C(1),
                                fracs[f], a, (unsigned)to, b, &out);
        TEST_ASSERT_TRUE_MESSAGE((st == DRDC_OK) || (st == DRDC_E_OVERFLOW),
                                 units_vectors[i].from);
        st = drdc_units_convert(-1, fracs[f], a, (unsigned)to, b, &out);
        TEST_ASSERT_TRUE_MESSAGE((st == DRDC_OK) || (st == DRDC_E_OVERFLOW),
                                 units_vectors[i].from);
      }
    }
  }
}

static void test_drdc_units_find_bad_input(void)
{
  const drdc_unit_t *u = NULL;
  const drdc_unit_t *keep = drdc_units_at(0);

  u = keep;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_units_find(NULL, 2, &u));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_units_find("ft", 2, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_UNKNOWN_UNIT,
                        drdc_units_find("furlongs", 8, &u));
  TEST_ASSERT_EQUAL_INT(DRDC_E_UNKNOWN_UNIT, drdc_units_find("ft", 0, &u));
  TEST_ASSERT_EQUAL_INT(DRDC_E_UNKNOWN_UNIT, drdc_units_find("FT", 2, &u));
  TEST_ASSERT_EQUAL_PTR(keep, u);
  /* exactly `length` characters are read: no NUL needed */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_units_find("ftXYZ", 2, &u));
  TEST_ASSERT_EQUAL_STRING("ft", info_of(u).name);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_units_find("m/s^2 rest", 5, &u));
  TEST_ASSERT_EQUAL_STRING("m/s^2", info_of(u).name);
}

/* The decoded rows of units with published exact definitions (the
 * compact table must give back the definitions' numbers), first and
 * last rows, and the bad input of drdc_units_describe. */
static void test_drdc_units_describe(void)
{
  static const int8_t force[DRDC_UNITS_DIMENSIONS] = {1, 1, -2, 0, 0};
  drdc_unit_info_t info = info_of(unit("ft"));
  drdc_unit_info_t keep;
  size_t i;

  /* 0.3048 m = 381 / 1250 */
  TEST_ASSERT_EQUAL_STRING("ft", info.name);
  TEST_ASSERT_EQUAL_INT64(381, info.factor_num);
  TEST_ASSERT_EQUAL_INT64(1250, info.factor_den);
  TEST_ASSERT_EQUAL_INT64(0, info.offset_num);
  TEST_ASSERT_EQUAL_INT64(1, info.offset_den);
  TEST_ASSERT_EQUAL_INT(1, info.dimension[DRDC_UNITS_DIM_METRE]);
  /* lbf = 0.45359237 kg x 9.80665 m/s^2 = 8896443230521 / 2 10^12 N */
  info = info_of(unit("lbf"));
  TEST_ASSERT_EQUAL_INT64(INT64_C(8896443230521), info.factor_num);
  TEST_ASSERT_EQUAL_INT64(INT64_C(2000000000000), info.factor_den);
  for (i = 0u; i < (size_t)DRDC_UNITS_DIMENSIONS; i++) {
    TEST_ASSERT_EQUAL_INT(force[i], info.dimension[i]);
  }
  /* degF: factor 5/9, zero at -459.67 degF (offset 45967 / 100) */
  info = info_of(unit("degF"));
  TEST_ASSERT_EQUAL_INT64(5, info.factor_num);
  TEST_ASSERT_EQUAL_INT64(9, info.factor_den);
  TEST_ASSERT_EQUAL_INT64(45967, info.offset_num);
  TEST_ASSERT_EQUAL_INT64(100, info.offset_den);
  TEST_ASSERT_EQUAL_INT(1, info.dimension[DRDC_UNITS_DIM_KELVIN]);
  /* lightyear: c x 365.25 d = 9460730472580800 m */
  TEST_ASSERT_EQUAL_INT64(INT64_C(9460730472580800),
                          info_of(unit("lightyear")).factor_num);
  /* first and last rows: gauss, 10^-4 T = 10^-4 kg s^-2 A^-1 */
  TEST_ASSERT_EQUAL_STRING("m", info_of(drdc_units_at(0)).name);
  info = info_of(drdc_units_at(drdc_units_count() - 1u));
  TEST_ASSERT_EQUAL_STRING("gauss", info.name);
  TEST_ASSERT_EQUAL_INT64(10000, info.factor_den);
  TEST_ASSERT_EQUAL_INT(-1, info.dimension[DRDC_UNITS_DIM_AMPERE]);
  /* bad input: outputs unchanged */
  keep = info;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_units_describe(NULL, &info));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_units_describe(unit("m"), NULL));
  /* a pointer that is no row of the table (compared, never read) */
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_UNKNOWN_UNIT,
      drdc_units_describe((const drdc_unit_t *)(const void *)&keep, &info));
  TEST_ASSERT_EQUAL_PTR(keep.name, info.name);
  TEST_ASSERT_EQUAL_INT64(keep.factor_num, info.factor_num);
}

static void test_drdc_units_convert_bad_input(void)
{
  int64_t out = 7;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_units_convert(1, 0, NULL, 0, unit("m"), &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_units_convert(1, 0, unit("m"), 0, NULL, &out));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_NULL, drdc_units_convert(1, 0, unit("m"), 0, unit("ft"), NULL));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_DIMENSION,
      drdc_units_convert(1, 0, unit("ft"), 0, unit("kg"), &out));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_DIMENSION,
      drdc_units_convert(1, 0, unit("degC"), 0, unit("Pa"), &out));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE, drdc_units_convert(1, 63, unit("m"), 0, unit("ft"), &out));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE, drdc_units_convert(1, 0, unit("m"), 63, unit("ft"), &out));
  /* 9.46e25: no 63-bit factor */
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE,
      drdc_units_convert(1, 0, unit("lightyear"), 0, unit("angstrom"), &out));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_OVERFLOW,
      drdc_units_convert(INT64_MAX / 100, 0, unit("km"), 0, unit("mm"), &out));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_OVERFLOW,
      drdc_units_convert(INT64_MIN, 0, unit("ft"), 0, unit("in"), &out));
  TEST_ASSERT_EQUAL_INT64(7, out);
}

static void test_drdc_units_compatible_bad_input(void)
{
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_units_compatible(unit("rpm"), unit("Hz")));
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_units_compatible(unit("degree"), unit("radian")));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_units_compatible(NULL, unit("m")));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_units_compatible(unit("m"), NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DIMENSION,
                        drdc_units_compatible(unit("bps"), unit("Hz")));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DIMENSION,
                        drdc_units_compatible(unit("J"), unit("W")));
}

void suite_units(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_every_unit_matches_gnu_units);
  RUN_TEST(test_table_rules);
  RUN_TEST(test_named_conversions);
  RUN_TEST(test_temperatures_are_affine);
  RUN_TEST(test_rounding_is_symmetric);
  RUN_TEST(test_no_range_error_to_and_from_si);
  RUN_TEST(test_drdc_units_find_bad_input);
  RUN_TEST(test_drdc_units_describe);
  RUN_TEST(test_drdc_units_convert_bad_input);
  RUN_TEST(test_drdc_units_compatible_bad_input);
}
