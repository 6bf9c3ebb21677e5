/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief `drdc units`: convert one `VALUE FROM TO` per line between units
 *        named as GNU units names them, with the library's unit table
 *        (dimension check, exact factors) and host long double text.
 */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <drdc/units.h>

#include "commands.h"
#include "lines.h"

static const char usage[] =
    "usage: drdc units\n"
    "\n"
    "Reads one conversion per line on standard input, 'VALUE FROM TO'\n"
    "(for example '3.5 ft m', '100 tempC tempF', '60 rpm Hz'), unit names\n"
    "as GNU units spells them, and writes the converted value alone with\n"
    "15 significant digits. Temperatures K, degC, degF, degR (and GNU's\n"
    "tempC, tempF, tempR, tempK) are points on their scale: '0 degC K'\n"
    "gives 273.15. An unknown unit, units of different dimensions or a\n"
    "malformed line give 'ERROR: <reason>'; the exit status is then 1.\n"
    "'drdc units --list' lists every unit with its SI factor.\n";

/* Split the next blank-separated word off *s. */
static const char *next_word(char **s, size_t *length)
{
  char *p = *s;
  char *start;

  while ((*p == ' ') || (*p == '\t')) {
    p++;
  }
  start = p;
  while ((*p != '\0') && (*p != ' ') && (*p != '\t')) {
    p++;
  }
  *length = (size_t)(p - start);
  *s = p;
  return start;
}

/* value in `from` -> value in `to`, through SI in long double (64-bit
 * mantissa: 3 more digits than printed). A result that is only the
 * rounding noise of two cancelling offsets (32 degF to degC) is 0. */
static long double convert(long double v, const drdc_unit_t *from_unit,
                           const drdc_unit_t *to_unit)
{
  drdc_unit_info_t from_info;
  drdc_unit_info_t to_info;
  const drdc_unit_info_t *from = &from_info;
  const drdc_unit_info_t *to = &to_info;

  (void)drdc_units_describe(from_unit, &from_info);
  (void)drdc_units_describe(to_unit, &to_info);
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

/* One line -> its output text; returns 0 or 1 (error line). */
static int convert_line(char *line, char *out, size_t size)
{
  const drdc_unit_t *from;
  const drdc_unit_t *to;
  const char *word;
  char *end;
  size_t n;
  long double v;
  drdc_status_t st;

  word = next_word(&line, &n);
  if (n == 0) {
    snprintf(out, size, "ERROR: expected 'VALUE FROM TO'");
    return 1;
  }
  errno = 0;
  v = strtold(word, &end);
  if ((end != word + n) || (errno != 0) || (*word == '\0') || !isfinite(v)) {
    snprintf(out, size, "ERROR: malformed value '%.*s'", (int)n, word);
    return 1;
  }
  word = next_word(&line, &n);
  st = drdc_units_find(word, n, &from);
  if (st != DRDC_OK) {
    snprintf(out, size, "ERROR: unknown unit '%.*s' (%s)", (int)n, word,
             drdc_status_name(st));
    return 1;
  }
  word = next_word(&line, &n);
  st = drdc_units_find(word, n, &to);
  if (st != DRDC_OK) {
    snprintf(out, size, "ERROR: unknown unit '%.*s' (%s)", (int)n, word,
             drdc_status_name(st));
    return 1;
  }
  word = next_word(&line, &n);
  if (n != 0) {
    snprintf(out, size, "ERROR: unexpected text after the units (%s)",
             drdc_status_name(DRDC_E_TRAILING));
    return 1;
  }
  st = drdc_units_compatible(from, to);
  if (st != DRDC_OK) {
    drdc_unit_info_t a;
    drdc_unit_info_t b;

    (void)drdc_units_describe(from, &a);
    (void)drdc_units_describe(to, &b);
    snprintf(out, size,
             "ERROR: %s and %s measure different quantities "
             "(%s)",
             a.name, b.name, drdc_status_name(st));
    return 1;
  }
  snprintf(out, size, "%.15Lg", convert(v, from, to));
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
