/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Unit expressions: random expressions against GNU units 2.22 and
 *        pint 0.25.3 vectors (1e-12 relative), the grammar's precedence
 *        and name rules matched exactly, and the bad-input catalogue.
 */
#include <stddef.h>
#include <stdint.h>

#include <drdc/units.h>

#include "suites.h"
#include "unity.h"
#include "vectors_units_expr.h"

#define N_EXPR_VECTORS                                                         \
  (sizeof units_expr_vectors / sizeof units_expr_vectors[0])

static size_t length_of(const char *s)
{
  size_t n = 0u;

  while (s[n] != '\0') {
    n++;
  }
  return n;
}

static drdc_units_expr_t parse(const char *text)
{
  drdc_units_expr_t e = {{0}, 0, 0, 0, 0, 0u};

  TEST_ASSERT_EQUAL_INT_MESSAGE(
      DRDC_OK, drdc_units_parse(text, length_of(text), &e), text);
  return e;
}

static drdc_status_t parse_status(const char *text)
{
  drdc_units_expr_t e = {{0}, 7, 7, 7, 7, 7u};
  drdc_status_t st = drdc_units_parse(text, length_of(text), &e);

  if (st != DRDC_OK) {
    /* unchanged on error */
    TEST_ASSERT_EQUAL_INT64_MESSAGE(7, e.factor_num, text);
    TEST_ASSERT_EQUAL_INT_MESSAGE(7, e.rounded, text);
  }
  return st;
}

static int64_t convert(int64_t raw, unsigned from_frac, const char *from,
                       unsigned to_frac, const char *to)
{
  drdc_units_expr_t a = parse(from);
  drdc_units_expr_t b = parse(to);
  int64_t out = 0;

  TEST_ASSERT_EQUAL_INT_MESSAGE(
      DRDC_OK, drdc_units_convert_expr(raw, from_frac, &a, to_frac, &b, &out),
      from);
  return out;
}

/* The same dimension and factor (exact rationals in lowest terms). */
static void assert_same(const char *a, const char *b)
{
  drdc_units_expr_t x = parse(a);
  drdc_units_expr_t y = parse(b);
  size_t i;

  for (i = 0u; i < (size_t)DRDC_UNITS_DIMENSIONS; i++) {
    TEST_ASSERT_EQUAL_INT_MESSAGE(y.dimension[i], x.dimension[i], a);
  }
  TEST_ASSERT_EQUAL_INT64_MESSAGE(y.factor_num, x.factor_num, a);
  TEST_ASSERT_EQUAL_INT64_MESSAGE(y.factor_den, x.factor_den, a);
  TEST_ASSERT_EQUAL_INT64_MESSAGE(y.offset_num, x.offset_num, a);
}

/* Every vector within 1e-12 relative (plus 1 LSB) of the oracles'
 * factor; the largest error in 1e-15 units is reported. */
static void test_random_expressions_match_gnu_units_and_pint(void)
{
  size_t i;
  int64_t worst = 0; /* relative error x 10^15, rounded up */

  for (i = 0u; i < N_EXPR_VECTORS; i++) {
    const struct units_expr_vector *v = &units_expr_vectors[i];
    int64_t got = convert(v->raw, v->from_frac, v->from, v->to_frac, v->to);
    int64_t diff = (got > v->expect) ? (got - v->expect) : (v->expect - got);
    int64_t mag = (v->expect < 0) ? -v->expect : v->expect;

    /* mag >= 2^40 > 10^12: diff <= 1 + mag / 10^12 */
    TEST_ASSERT_TRUE_MESSAGE(diff <= (1 + (mag / INT64_C(1000000000000))),
                             v->from);
    if (diff > 1) {
      int64_t rel = ((diff - 1) * INT64_C(1000000000000000)) / mag + 1;

      if (rel > worst) {
        worst = rel;
      }
    }
  }
  TEST_ASSERT_TRUE(worst <= 1000);
}

/* The worked examples of unit expressions, exactly: 100 km/h = 250/9
 * m/s; 1 N m = 0.737562149277265 ft lbf; 2 kWh = 7 200 000 J. */
static void test_examples(void)
{
  /* 250/9 x 2^32 = 119304647111.1 */
  TEST_ASSERT_EQUAL_INT64(INT64_C(119304647111),
                          convert(100, 0, "km/h", 32, "m/s"));
  /* 2^40 x 2500000000000000 / 3389544870828501 = 810958159337.8 */
  TEST_ASSERT_EQUAL_INT64(INT64_C(810958159338),
                          convert(INT64_C(1) << 40, 40, "N*m", 40, "ft*lbf"));
  TEST_ASSERT_EQUAL_INT64(7200000, convert(2, 0, "kWh", 0, "J"));
  TEST_ASSERT_EQUAL_INT64(7200000, convert(2, 0, "kW h", 0, "J"));
  assert_same("ft*lbf", "lbf*ft");
  assert_same("lbf ft", "lbf*ft");
}

/* A power binds tightest, then a blank, then * and / left to right. */
static void test_precedence(void)
{
  assert_same("kg m/s^2", "N");
  assert_same("kg*m/s2", "N");
  assert_same("m/s s", "m/s^2");
  assert_same("m/s*s", "m");
  assert_same("kg/m s", "kg/(m s)");
  assert_same("kg/m/s", "kg/(m*s)");
  assert_same("(m/s)2", "m^2/s^2");
  assert_same("(m/s)^-1", "s/m");
  assert_same("m^+2", "m2");
  assert_same("s^-1", "Hz");
  assert_same("1/s", "Hz");
  assert_same("3600 s", "h");
  assert_same("  N \t*\tm  ", "J");
  assert_same("((m))", "m");
  assert_same("(((kg m)/s)/s)", "N");
  assert_same("kg/m^3", "g/L");
  assert_same("rad/s", "Hz");
}

/* Exact names win over prefix readings; prefixes on SI units only. */
static void test_names_and_prefixes(void)
{
  assert_same("min", "60 s");
  assert_same("h", "60 min");
  assert_same("hr", "h");
  assert_same("hm", "100 m");
  assert_same("dam", "10 m");
  assert_same("Pa", "N/m^2");
  assert_same("nm", "m/1000000000");
  assert_same("kt", "knot");
  assert_same("kt", "nmi/h");
  assert_same("mAh", "18 C/5");
  assert_same("mA", "A/1000");
  assert_same("kN", "1000 N");
  assert_same("MPa", "1000000 Pa");
  assert_same("uT", "T/1000000");
  assert_same("\xC2\xB5T", "uT");
  assert_same("\xCE\xBCs", "us");
  assert_same("kilometer", "km");
  assert_same("milliampere", "mA");
  assert_same("GHz", "1000000000 Hz");
  assert_same("mrad", "rad/1000");
  assert_same("mgauss", "T/10000000");
  assert_same("kWh", "kW h");
  assert_same("MeV", "1000000 eV");
  assert_same("rad", "radian");
  assert_same("sr", "rad^2");
  assert_same("ha", "hectare");
  assert_same("V A", "W");
  assert_same("ohm", "V/A");
  assert_same("S", "1/ohm");
  assert_same("F", "C/V");
  assert_same("H", "Wb/A");
  assert_same("T", "Wb/m^2");
  assert_same("gauss", "T/10000");
  TEST_ASSERT_EQUAL_INT(DRDC_E_UNKNOWN_UNIT, parse_status("kft"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_UNKNOWN_UNIT, parse_status("mdegC"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_UNKNOWN_UNIT, parse_status("dB"));
}

/* GNU units' abbreviations of the table's units are names (their factors
 * against GNU units: tests/units/vectors_units.h); an exact name wins
 * over a prefix reading (pt, ct), and where the SI reads a GNU
 * abbreviation otherwise the SI wins (Gs, nt) or the name stays
 * unknown (b, a, smi). The byte's B takes no prefix: dB stays no
 * unit. */
static void test_gnu_abbreviations(void)
{
  assert_same("mi", "mile");
  assert_same("mi/hr", "mph");
  assert_same("nmile", "nmi");
  assert_same("ly", "lightyear");
  assert_same("ch", "chain");
  assert_same("cc", "cm^3");
  assert_same("qt", "quart");
  assert_same("pt", "pint");
  assert_same("tbsp", "tablespoon");
  assert_same("Tb", "tablespoon");
  assert_same("tsp", "teaspoon");
  assert_same("gm", "g");
  assert_same("lbm", "lb");
  assert_same("ct", "carat");
  assert_same("d", "day");
  assert_same("da", "24 h");
  assert_same("wk", "week");
  assert_same("yr", "year");
  assert_same("rev", "turn");
  assert_same("dyn", "dyne");
  assert_same("pa", "Pa");
  assert_same("psia", "psi");
  assert_same("ev", "eV");
  assert_same("coul", "A s");
  assert_same("hz", "Hz");
  assert_same("degK", "K");
  assert_same("lfm", "ft/min");
  assert_same("B", "8 bit");
  assert_same("Gs", "1000000000 s");
  assert_same("nt", "mg");
  TEST_ASSERT_EQUAL_INT(DRDC_E_UNKNOWN_UNIT, parse_status("kB"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_UNKNOWN_UNIT, parse_status("b"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_UNKNOWN_UNIT, parse_status("a"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_UNKNOWN_UNIT, parse_status("smi"));
}

/* A temperature with an offset only alone; K and degR anywhere. */
static void test_temperatures(void)
{
  const int64_t one = INT64_C(1) << 32;
  drdc_units_expr_t c = parse(" degC ");

  TEST_ASSERT_EQUAL_INT64(5463, c.offset_num);
  TEST_ASSERT_EQUAL_INT64(20, c.offset_den);
  TEST_ASSERT_EQUAL_INT64(212 * one,
                          convert(100 * one, 32, "degC", 32, "degF"));
  assert_same("K/s", "degR/s*9/5");
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, parse_status("degC/s"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, parse_status("degF^2"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, parse_status("(degC)"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, parse_status("degC degC"));
}

/* Products that do not fit 63 bits are rounded (and say so) or refused,
 * never wrapped. */
static void test_factor_overflow(void)
{
  drdc_units_expr_t e = parse("lbf^3/lbf^2");
  drdc_units_expr_t lbf = parse("lbf");
  int64_t out = 0;

  /* (8896443230521 / 2 10^12)^3 has no 63-bit form: rounded */
  TEST_ASSERT_EQUAL_INT(1, e.rounded);
  TEST_ASSERT_EQUAL_INT(0, lbf.rounded);
  /* and still within 1e-15 of lbf: 2^50 lbf^3/lbf^2 in lbf */
  TEST_ASSERT_EQUAL_INT(
      DRDC_OK, drdc_units_convert_expr(INT64_C(1) << 50, 0, &e, 0, &lbf, &out));
  TEST_ASSERT_INT64_WITHIN(2, INT64_C(1) << 50, out);
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, parse_status("lightyear^3/nm^3"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, parse_status("Ym"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, parse_status("ym"));
}

/* A running product beyond 2^+-61 whose final factor fits: the parse
 * carries the magnitude in a binary scale, so only the result's range
 * matters. */
static void test_running_product_beyond_range(void)
{
  drdc_units_expr_t ratio = parse("parsec^2/lightyear^2");
  drdc_units_expr_t giga = parse("Ym/Gm");

  /* (au / (tan(pi / 648000) ly))^2, the parsec of GNU units and pint,
   * with au = 149597870700 m and ly = 9460730472580800 m exactly:
   * 10.637798272364005951289 (mpmath, 40 digits), times 2^40 rounded */
  TEST_ASSERT_EQUAL_INT(1, ratio.rounded);
  TEST_ASSERT_INT64_WITHIN(
      1, INT64_C(11696382894400),
      convert(INT64_C(1) << 40, 0, "parsec^2/lightyear^2", 0, "1"));
  /* 10^24 / 10^9, exact after its one rounding */
  TEST_ASSERT_EQUAL_INT64(INT64_C(1000000000000000),
                          convert(1, 0, "Ym/Gm", 0, "1"));
  TEST_ASSERT_EQUAL_INT64(INT64_C(1000000000000000),
                          giga.factor_num / giga.factor_den);
  /* the scale's own limit, 2^+-4064, far beyond any unit: Ym^9/ym^9
   * is 10^432 = 2^1435.1, its square fits, its cube does not */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, parse_status("(Ym^9/ym^9)^2/(Ym^9/ym^9)^2"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW,
                        parse_status("(Ym^9/ym^9)^3/(Ym^9/ym^9)^3"));
}

static void test_drdc_units_parse_bad_input(void)
{
  static char longest[DRDC_UNITS_EXPR_LENGTH_MAX + 2u];
  drdc_units_expr_t e = {{0}, 7, 7, 7, 7, 7u};
  size_t i;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_units_parse(NULL, 1, &e));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_units_parse("m", 1, NULL));
  /* DRDC_UNITS_EXPR_LENGTH_MAX characters are read, one more is not */
  for (i = 0u; i < (sizeof longest - 1u); i++) {
    longest[i] = ((i % 2u) == 0u) ? 'm' : ' ';
  }
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE,
      drdc_units_parse(longest, DRDC_UNITS_EXPR_LENGTH_MAX, &e)); /* m^128 */
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERLONG,
                        drdc_units_parse(longest, sizeof longest - 1u, &e));
  TEST_ASSERT_EQUAL_INT64(7, e.factor_num);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_units_parse("m/sXYZ", 3, &e));
  /* malformed */
  TEST_ASSERT_EQUAL_INT(DRDC_E_SYNTAX, drdc_units_parse("m", 0, &e));
  TEST_ASSERT_EQUAL_INT(DRDC_E_SYNTAX, parse_status("  "));
  TEST_ASSERT_EQUAL_INT(DRDC_E_SYNTAX, parse_status("m/"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_SYNTAX, parse_status("*m"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_SYNTAX, parse_status("m//s"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_SYNTAX, parse_status("(m"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_SYNTAX, parse_status("m)"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_SYNTAX, parse_status("()"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_SYNTAX, parse_status("m^"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_SYNTAX, parse_status("m^-"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_SYNTAX, parse_status("m^x"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_SYNTAX, parse_status("m+s"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_SYNTAX, parse_status("m.s"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_SYNTAX, parse_status("0 m"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_SYNTAX, parse_status("1000000001 m"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_SYNTAX, parse_status("m\ns"));
  /* limits */
  TEST_ASSERT_EQUAL_INT(DRDC_OK, parse_status("((((m))))"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, parse_status("(((((m)))))"));
  TEST_ASSERT_EQUAL_INT(DRDC_OK, parse_status("m^9/s^-9"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, parse_status("m^10"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, parse_status("m^-10"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, parse_status("s12"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, parse_status("((m^9)^9)^2"));
  /* names */
  TEST_ASSERT_EQUAL_INT(DRDC_E_UNKNOWN_UNIT, parse_status("furlongs"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_UNKNOWN_UNIT, parse_status("m/FT"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_UNKNOWN_UNIT, parse_status("\xC2"));
  /* temperatures and factors */
  TEST_ASSERT_EQUAL_INT(DRDC_E_DOMAIN, parse_status("tempF*s"));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, parse_status("angstrom^9/au^9"));
}

static void test_drdc_units_convert_expr_bad_input(void)
{
  drdc_units_expr_t m = parse("m");
  drdc_units_expr_t ft = parse("ft");
  drdc_units_expr_t kg = parse("kg");
  drdc_units_expr_t zero = m;
  drdc_units_expr_t ly = parse("lightyear");
  drdc_units_expr_t nm = parse("nm");
  int64_t out = 7;

  zero.factor_num = 0;
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_units_convert_expr(1, 0, NULL, 0, &m, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_units_convert_expr(1, 0, &m, 0, NULL, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_units_convert_expr(1, 0, &m, 0, &ft, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DIMENSION,
                        drdc_units_convert_expr(1, 0, &m, 0, &kg, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_units_convert_expr(1, 63, &m, 0, &ft, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_units_convert_expr(1, 0, &m, 63, &ft, &out));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_units_convert_expr(1, 0, &zero, 0, &ft, &out));
  /* 9.5e24: no 63-bit factor, even rounded */
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_units_convert_expr(1, 0, &ly, 0, &nm, &out));
  /* 3.28 x 2^62 */
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_OVERFLOW,
      drdc_units_convert_expr(INT64_MAX / 2, 0, &m, 0, &ft, &out));
  TEST_ASSERT_EQUAL_INT64(7, out);
}

void suite_units_expr(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_random_expressions_match_gnu_units_and_pint);
  RUN_TEST(test_examples);
  RUN_TEST(test_precedence);
  RUN_TEST(test_names_and_prefixes);
  RUN_TEST(test_gnu_abbreviations);
  RUN_TEST(test_temperatures);
  RUN_TEST(test_factor_overflow);
  RUN_TEST(test_running_product_beyond_range);
  RUN_TEST(test_drdc_units_parse_bad_input);
  RUN_TEST(test_drdc_units_convert_expr_bad_input);
}
