/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief `drdc units`: convert one `VALUE FROM TO` per line between units
 *        named as GNU units names them, with the library's unit table
 *        (dimension check, exact factors) and host long double text.
 */
#include <ctype.h>
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <drdc/units.h>

#include "commands.h"
#include "lines.h"

static const char usage[] =
    "usage: drdc units [--list]\n"
    "\n"
    "Reads one conversion per line on standard input, 'VALUE FROM TO'\n"
    "(for example '3.5 ft m', '100 km/h m/s', '1 N*m ft*lbf', '100 tempC\n"
    "tempF'), and writes the converted value alone with 15 significant\n"
    "digits, as GNU units -t does. FROM and TO are unit expressions:\n"
    "\n"
    "  expression := term (('*' | '/') term)*\n"
    "  term       := factor (' ' factor)*      (only inside parentheses:\n"
    "                                           a blank outside them ends\n"
    "                                           FROM)\n"
    "  factor     := (name | number | '(' expression ')') power?\n"
    "  power      := '^' ['-'] digits | digits  (s2 = s^2; -9..9)\n"
    "  name       := a unit, or SI prefix + SI unit (kN, mA, MPa, uT)\n"
    "\n"
    "A power binds tightest, then a blank, then '*' and '/' (left to\n"
    "right): 'kg/(m s)' = kg/m/s. An exact unit name wins over a prefix\n"
    "reading: 'min' is the minute, 'h' the hour (SI; GNU units' h is\n"
    "Planck's constant), 'kt' the knot, 'rad' the radian. Prefixes:\n"
    "Y Z E P T G M k h da d c m u (or the micro sign) n p f a z y, and\n"
    "the words kilo, milli, micro, ...; on SI and SI-accepted units only\n"
    "(m g s A K N Pa J W Hz C V ohm F H Wb T S rad sr l L t eV bar Wh Ah\n"
    "gauss bit byte and their spelled names). Parentheses nest 4 deep.\n"
    "'dB' is not a unit (logarithmic).\n"
    "\n"
    "Temperatures K, degC, degF, degR (and GNU's tempC, tempF, tempR,\n"
    "tempK) are points on their scale: '0 degC K' gives 273.15; degC and\n"
    "degF stand alone only, never in a product. An unknown unit, units\n"
    "of different dimensions or a malformed line give 'ERROR: <reason>';\n"
    "the exit status is then 1. 'drdc units --list' lists every unit\n"
    "with its SI factor.\n";

/* Split the next word off *s: blanks end it only outside parentheses,
 * so '(kg m)' is one word. */
static const char *next_word(char **s, size_t *length)
{
  char *p = *s;
  char *start;
  int depth = 0;

  while ((*p == ' ') || (*p == '\t')) {
    p++;
  }
  start = p;
  while ((*p != '\0') && (depth > 0 || ((*p != ' ') && (*p != '\t')))) {
    if (*p == '(') {
      depth++;
    } else if ((*p == ')') && (depth > 0)) {
      depth--;
    }
    p++;
  }
  *length = (size_t)(p - start);
  *s = p;
  return start;
}

/* value in `from` -> value in `to`, through SI in long double (64-bit
 * mantissa: 3 more digits than printed). A result that is only the
 * rounding noise of two cancelling offsets (32 degF to degC) is 0. */
/* Neither infinite nor NaN. Not isfinite(): mingw-w64's macro converts
 * its argument to each floating type in turn, which -Wconversion rejects
 * in the Windows build. */
static int is_finite(long double v)
{
  return (v == v) && (fabsl(v) <= LDBL_MAX);
}

static long double convert(long double v, const drdc_units_expr_t *from,
                           const drdc_units_expr_t *to)
{
  long double si =
      (v + (long double)from->offset_num / (long double)from->offset_den) *
      (long double)from->factor_num / (long double)from->factor_den;
  long double scaled =
      si * (long double)to->factor_den / (long double)to->factor_num;
  long double offset =
      (long double)to->offset_num / (long double)to->offset_den;
  long double r = scaled - offset;
  long double noise = 1e-16L * (fabsl(scaled) + fabsl(offset));

  return (fabsl(r) <= noise) ? 0.0L : r;
}

static int list_units(void)
{
  size_t i;

  for (i = 0; i < drdc_units_count(); i++) {
    drdc_unit_info_t info;
    const drdc_unit_info_t *u = &info;

    (void)drdc_units_describe(drdc_units_at(i), &info);
    printf("%-18s %lld/%lld", u->name, (long long)u->factor_num,
           (long long)u->factor_den);
    if (u->offset_num != 0) {
      printf(" offset %lld/%lld", (long long)u->offset_num,
             (long long)u->offset_den);
    }
    printf("\n");
  }
  return 0;
}

/* Parse one unit expression word; an error line otherwise. */
static int parse_unit(const char *word, size_t n, drdc_units_expr_t *expr,
                      char *out, size_t size)
{
  drdc_status_t st = drdc_units_parse(word, n, expr);

  if (st != DRDC_OK) {
    const char *what = (st == DRDC_E_UNKNOWN_UNIT) ? "unknown unit"
                       : (st == DRDC_E_DOMAIN)
                           ? "a temperature scale inside an expression"
                           : "bad unit expression";

    snprintf(out, size, "ERROR: %s '%.*s' (%s)", what, (int)(n > 80 ? 80 : n),
             word, drdc_status_name(st));
    return 1;
  }
  return 0;
}

/* One line -> its output text; returns 0 or 1 (error line). */
static int convert_line(char *line, char *out, size_t size)
{
  drdc_units_expr_t from;
  drdc_units_expr_t to;
  const char *word;
  const char *from_word;
  const char *to_word;
  size_t from_n;
  size_t to_n;
  char *end;
  size_t n;
  long double v;
  size_t i;

  word = next_word(&line, &n);
  if (n == 0) {
    snprintf(out, size, "ERROR: expected 'VALUE FROM TO'");
    return 1;
  }
  errno = 0;
  v = strtold(word, &end);
  if ((end != word + n) || (errno != 0) || (*word == '\0') || !is_finite(v)) {
    snprintf(out, size, "ERROR: malformed value '%.*s'", (int)(n > 80 ? 80 : n),
             word);
    return 1;
  }
  from_word = next_word(&line, &from_n);
  if (parse_unit(from_word, from_n, &from, out, size) != 0) {
    return 1;
  }
  to_word = next_word(&line, &to_n);
  if (parse_unit(to_word, to_n, &to, out, size) != 0) {
    return 1;
  }
  word = next_word(&line, &n);
  if (n != 0) {
    snprintf(out, size, "ERROR: unexpected text after the units (%s)",
             drdc_status_name(DRDC_E_TRAILING));
    return 1;
  }
  for (i = 0; i < DRDC_UNITS_DIMENSIONS; i++) {
    if (from.dimension[i] != to.dimension[i]) {
      snprintf(out, size,
               "ERROR: %.*s and %.*s measure different quantities (%s)",
               (int)(from_n > 60 ? 60 : from_n), from_word,
               (int)(to_n > 60 ? 60 : to_n), to_word,
               drdc_status_name(DRDC_E_DIMENSION));
      return 1;
    }
  }
  snprintf(out, size, "%.15Lg", convert(v, &from, &to));
  return 0;
}

int drdc_cmd_units(int argc, char **argv)
{
  char *line = NULL;
  size_t cap = 0;
  size_t len = 0;
  int got;
  int failed = 0;

  if ((argc == 2) &&
      ((strcmp(argv[1], "--help") == 0) || (strcmp(argv[1], "-h") == 0))) {
    fputs(usage, stdout);
    return 0;
  }
  if ((argc == 2) && (strcmp(argv[1], "--list") == 0)) {
    return list_units();
  }
  if (argc != 1) {
    fprintf(stderr, "drdc units: unexpected argument '%s'\n", argv[1]);
    fputs(usage, stderr);
    return 2;
  }
  while ((got = drdc_tool_read_line(stdin, &line, &cap, &len)) !=
         DRDC_TOOL_LINE_EOF) {
    char out[160];
    const char *problem;

    if (got == DRDC_TOOL_LINE_ERROR) {
      fputs("drdc units: cannot read standard input\n", stderr);
      failed = 1;
      break;
    }
    problem = drdc_tool_line_problem(got, line, len);
    if (problem != NULL) {
      snprintf(out, sizeof out, "ERROR: %s", problem);
      failed = 1;
    } else if (convert_line(line, out, sizeof out) != 0) {
      failed = 1;
    }
    printf("%s\n", out);
  }
  free(line);
  return failed;
}
