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
    "  term       := factor (' ' factor)*      (a product)\n"
    "  factor     := (name | number | '(' expression ')') power?\n"
    "  power      := '^' ['-'] digits | digits  (s2 = s^2; -9..9)\n"
    "  name       := a unit, or SI prefix + SI unit (kN, mA, MPa, uT)\n"
    "\n"
    "A power binds tightest, then a blank, then '*' and '/' (left to\n"
    "right): 'kg/(m s)' = kg/m/s. A blank outside parentheses may end\n"
    "FROM or join a product: of the cuts of the words after VALUE into\n"
    "FROM and TO, the one that gives two expressions of one dimension is\n"
    "taken ('1 N m ft lbf' is N m in ft lbf); where two do, the line is\n"
    "an error, and 'N*m' or '(N m)' says which is meant. GNU units'\n"
    "abbreviations are names too (mi, ly, qt, pt, gr, ct, d, wk, yr, B,\n"
    "...). An exact unit name wins over a prefix reading: 'min' is the\n"
    "minute, 'pt' the pint, 'h' the hour (SI; GNU units' h is Planck's\n"
    "constant), 'kt' the knot, 'rad' the radian; 'Gs' and 'nt' are the\n"
    "gigasecond and the nanotonne (SI; GNU units: gauss, newton).\n"
    "Prefixes: Y Z E P T G M k h da d c m u (or the micro sign) n p f a\n"
    "z y, and the words kilo, milli, micro, ...; on SI and SI-accepted\n"
    "units only (m g s A K N Pa J W Hz C V ohm F H Wb T S rad sr l L t\n"
    "eV bar Wh Ah gauss bit byte and their spelled names). Parentheses\n"
    "nest 4 deep.\n"
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
static const char *next_word(const char **s, size_t *length)
{
  const char *p = *s;
  const char *start;
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

/* FROM and TO of a line: where they lie in it and what they parse to. */
struct unit_pair {
  const char *from;
  size_t from_n;
  const char *to;
  size_t to_n;
  drdc_units_expr_t from_expr;
  drdc_units_expr_t to_expr;
};

static int same_dimension(const drdc_units_expr_t *a,
                          const drdc_units_expr_t *b)
{
  size_t i;

  for (i = 0; i < DRDC_UNITS_DIMENSIONS; i++) {
    if (a->dimension[i] != b->dimension[i]) {
      return 0;
    }
  }
  return 1;
}

/* The unit words of a line (after its value) cut into FROM and TO at
 * every blank between words, so that a product may be written with a
 * blank ('1 N m ft lbf'): the cuts that give two expressions of one
 * dimension are counted, 0, 1 or 2 (more than one), and the first is
 * written to *pair. Each try parses at most 255 characters a side
 * (longer is refused at once), so a long line costs one pass. */
static int split_units(const char *s, struct unit_pair *pair)
{
  const char *p = s;
  const char *first;
  const char *end;
  size_t n;
  int found = 0;

  first = next_word(&p, &n);
  if (n == 0u) {
    return 0;
  }
  end = first + strlen(first);
  while ((end > first) && ((end[-1] == ' ') || (end[-1] == '\t'))) {
    end--;
  }
  for (;;) {
    const char *cut = p; /* FROM ends here */
    const char *q = p;
    const char *to = next_word(&q, &n);
    drdc_units_expr_t from_expr;
    drdc_units_expr_t to_expr;

    if (n == 0u) {
      return found;
    }
    if ((drdc_units_parse(first, (size_t)(cut - first), &from_expr) ==
         DRDC_OK) &&
        (drdc_units_parse(to, (size_t)(end - to), &to_expr) == DRDC_OK) &&
        same_dimension(&from_expr, &to_expr)) {
      if (++found > 1) {
        return found;
      }
      pair->from = first;
      pair->from_n = (size_t)(cut - first);
      pair->to = to;
      pair->to_n = (size_t)(end - to);
      pair->from_expr = from_expr;
      pair->to_expr = to_expr;
    }
    p = to + n;
  }
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

/* One line -> its output text; returns 0 or 1 (error line). FROM and TO
 * are the one cut of the unit words that gives two expressions of one
 * dimension (split_units()); with none, the first two words, and their
 * own errors. */
static int convert_line(const char *line, char *out, size_t size)
{
  struct unit_pair pair;
  const char *word;
  char *end;
  size_t n;
  long double v;
  int splits;

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
  splits = split_units(line, &pair);
  if (splits > 1) {
    snprintf(out, size,
             "ERROR: the units split into FROM and TO in more than one way; "
             "write a product as N*m or (N m) (%s)",
             drdc_status_name(DRDC_E_SYNTAX));
    return 1;
  }
  if (splits == 0) {
    pair.from = next_word(&line, &pair.from_n);
    if (parse_unit(pair.from, pair.from_n, &pair.from_expr, out, size) != 0) {
      return 1;
    }
    pair.to = next_word(&line, &pair.to_n);
    if (parse_unit(pair.to, pair.to_n, &pair.to_expr, out, size) != 0) {
      return 1;
    }
    word = next_word(&line, &n);
    if (n != 0) {
      snprintf(out, size, "ERROR: unexpected text after the units (%s)",
               drdc_status_name(DRDC_E_TRAILING));
      return 1;
    }
    if (!same_dimension(&pair.from_expr, &pair.to_expr)) {
      snprintf(out, size,
               "ERROR: %.*s and %.*s measure different quantities (%s)",
               (int)(pair.from_n > 60 ? 60 : pair.from_n), pair.from,
               (int)(pair.to_n > 60 ? 60 : pair.to_n), pair.to,
               drdc_status_name(DRDC_E_DIMENSION));
      return 1;
    }
  }
  snprintf(out, size, "%.15Lg", convert(v, &pair.from_expr, &pair.to_expr));
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
