/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief `drdc time --from F --to T`: convert one time per line between
 *        UTC text, GPS week and time of week, and Unix, RTEMS and TAI
 *        seconds, through the library's UTC hub.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <drdc/time_iso8601.h>
#include <drdc/time_scales.h>

#include "commands.h"
#include "lines.h"
#include "reasons.h"

enum scale { SCALE_UTC, SCALE_GPS, SCALE_UNIX, SCALE_RTEMS, SCALE_TAI };

static const char *const scale_names[] = {"utc", "gps", "unix", "rtems", "tai"};

static const char usage[] =
    "usage: drdc time --from F --to T\n"
    "\n"
    "Reads one time per line on standard input and writes one line per\n"
    "input line. F and T are one of:\n"
    "  utc    YYYY-MM-DDTHH:MM:SS[.fffffffff]Z (written with 9 decimals;\n"
    "         second 60 only in a leap second)\n"
    "  gps    WEEK TOW: full GPS week and seconds of week, up to 9 decimals\n"
    "  unix   seconds since 1970-01-01T00:00:00Z, 86 400 a day\n"
    "  rtems  seconds since 1988-01-01T00:00:00Z, 86 400 a day\n"
    "  tai    seconds since 1958-01-01T00:00:00 TAI\n"
    "Seconds are signed decimals with up to 9 decimals; output has 9.\n"
    "A leap second has no Unix or RTEMS value of its own: it is written as\n"
    "the next midnight. A line that cannot be converted gives\n"
    "'ERROR: <reason>'; the exit status is then 1. Instants past the\n"
    "built-in leap-second table's expiry are converted with the last known\n"
    "offset and a warning on standard error.\n";

static int scale_of(const char *name)
{
  size_t i;

  for (i = 0; i < sizeof scale_names / sizeof scale_names[0]; i++) {
    if (strcmp(name, scale_names[i]) == 0) {
      return (int)i;
    }
  }
  return -1;
}

/* Signed decimal seconds with up to 9 decimals -> floor seconds and
 * nanoseconds in [0, 1e9). Reads up to the first character that cannot
 * continue the number; *end points there. */
static drdc_status_t parse_seconds(const char *s, const char **end,
                                   drdc_time_count_t *out)
{
  int neg = 0;
  int64_t sec = 0;
  int32_t nsec = 0;
  int digits = 0;
  int frac = 0;

  if ((*s == '-') || (*s == '+')) {
    neg = (*s == '-');
    s++;
  }
  while ((*s >= '0') && (*s <= '9')) {
    if (sec > (INT64_MAX - 9) / 10) {
      return DRDC_E_RANGE;
    }
    sec = (sec * 10) + (*s - '0');
    s++;
    digits++;
  }
  if (digits == 0) {
    return DRDC_E_SYNTAX;
  }
  if (*s == '.') {
    s++;
    while ((*s >= '0') && (*s <= '9')) {
      if (frac == 9) {
        return DRDC_E_SYNTAX;
      }
      nsec = (nsec * 10) + (*s - '0');
      s++;
      frac++;
    }
    if (frac == 0) {
      return DRDC_E_SYNTAX;
    }
    for (; frac < 9; frac++) {
      nsec *= 10;
    }
  }
  if (neg) {
    sec = -sec;
    if (nsec > 0) { /* -1.5 = -2 + 0.5 */
      sec -= 1;
      nsec = DRDC_NS_PER_SECOND - nsec;
    }
  }
  out->sec = sec;
  out->nsec = nsec;
  *end = s;
  return DRDC_OK;
}

static const char *skip_blanks(const char *s)
{
  while ((*s == ' ') || (*s == '\t')) {
    s++;
  }
  return s;
}

/* One input line (no newline) -> UTC. */
static drdc_status_t read_time(int from, const char *line, drdc_time_t *utc)
{
  drdc_time_count_t k;
  const char *end;
  drdc_status_t st;

  line = skip_blanks(line);
  if (from == SCALE_UTC) {
    return drdc_time_iso8601_parse(NULL, line, utc);
  }
  if (from == SCALE_GPS) {
    drdc_time_count_t week;
    drdc_time_gps_t g;

    st = parse_seconds(line, &end, &week);
    if ((st == DRDC_OK) && (week.nsec != 0)) {
      st = DRDC_E_SYNTAX; /* a week number is an integer */
    }
    if ((st == DRDC_OK) && ((*end != ' ') && (*end != '\t'))) {
      st = DRDC_E_SYNTAX;
    }
    if (st != DRDC_OK) {
      return st;
    }
    st = parse_seconds(skip_blanks(end), &end, &k);
    if (st != DRDC_OK) {
      return st;
    }
    if (*skip_blanks(end) != '\0') {
      return DRDC_E_TRAILING;
    }
    if ((week.sec < 0) || (week.sec > DRDC_TIME_GPS_WEEK_MAX)) {
      return DRDC_E_WEEK;
    }
    if ((k.sec < 0) || (k.sec >= DRDC_TIME_GPS_SECONDS_PER_WEEK)) {
      return DRDC_E_TIME_OF_WEEK;
    }
    g.week = (int32_t)week.sec;
    g.tow = (int32_t)k.sec;
    g.nsec = k.nsec;
    return drdc_time_gps_to_utc(NULL, &g, utc);
  }
  st = parse_seconds(line, &end, &k);
  if (st != DRDC_OK) {
    return st;
  }
  if (*skip_blanks(end) != '\0') {
    return DRDC_E_TRAILING;
  }
  if (from == SCALE_UNIX) {
    return drdc_time_unix_to_utc(&k, utc);
  }
  if (from == SCALE_RTEMS) {
    return drdc_time_rtems_to_utc(&k, utc);
  }
  return drdc_time_tai_to_utc(NULL, &k, utc);
}

static void put_seconds(char *out, size_t size, const drdc_time_count_t *k)
{
  if ((k->sec < 0) && (k->nsec > 0)) { /* {-2, 5e8} is -1.5 */
    snprintf(out, size, "-%lld.%09ld", (long long)(-(k->sec + 1)),
             (long)(DRDC_NS_PER_SECOND - k->nsec));
  } else {
    snprintf(out, size, "%lld.%09ld", (long long)k->sec, (long)k->nsec);
  }
}

/* UTC -> the output text of scale `to`. */
static drdc_status_t write_time(int to, const drdc_time_t *utc, char *out,
                                size_t size)
{
  drdc_time_count_t k;
  drdc_status_t st;

  switch (to) {
  case SCALE_UTC:
    return drdc_time_iso8601_format(NULL, utc, 9, out, size);
  case SCALE_GPS: {
    drdc_time_gps_t g;

    st = drdc_time_utc_to_gps(NULL, utc, &g);
    if (!drdc_status_is_error(st)) {
      snprintf(out, size, "%ld %ld.%09ld", (long)g.week, (long)g.tow,
               (long)g.nsec);
    }
    return st;
  }
  case SCALE_UNIX:
    st = drdc_time_utc_to_unix(NULL, utc, &k);
    break;
  case SCALE_RTEMS:
    st = drdc_time_utc_to_rtems(NULL, utc, &k);
    break;
  default:
    st = drdc_time_utc_to_tai(NULL, utc, &k);
    break;
  }
  if (!drdc_status_is_error(st)) {
    put_seconds(out, size, &k);
  }
  return st;
}

int drdc_cmd_time(int argc, char **argv)
{
  int from = -1;
  int to = -1;
  int i;
  int failed = 0;
  long line_no = 0;
  char *line = NULL;
  size_t cap = 0;
  size_t len = 0;
  int got;

  for (i = 1; i < argc; i++) {
    if ((strcmp(argv[i], "--help") == 0) || (strcmp(argv[i], "-h") == 0)) {
      fputs(usage, stdout);
      return 0;
    }
    if (((strcmp(argv[i], "--from") == 0) || (strcmp(argv[i], "--to") == 0)) &&
        (i + 1 < argc)) {
      int s = scale_of(argv[i + 1]);

      if (s < 0) {
        fprintf(stderr,
                "drdc time: unknown time scale '%s' (utc, gps, "
                "unix, rtems, tai)\n",
                argv[i + 1]);
        return 2;
      }
      if (argv[i][2] == 'f') {
        from = s;
      } else {
        to = s;
      }
      i++;
      continue;
    }
    fprintf(stderr, "drdc time: unexpected argument '%s'\n", argv[i]);
    fputs(usage, stderr);
    return 2;
  }
  if ((from < 0) || (to < 0)) {
    fputs("drdc time: --from and --to are required\n", stderr);
    fputs(usage, stderr);
    return 2;
  }

  while ((got = drdc_tool_read_line(stdin, &line, &cap, &len)) !=
         DRDC_TOOL_LINE_EOF) {
    char out[64];
    drdc_time_t utc;
    drdc_status_t st;
    const char *problem;

    if (got == DRDC_TOOL_LINE_ERROR) {
      fputs("drdc time: cannot read standard input\n", stderr);
      failed = 1;
      break;
    }
    line_no++;
    problem = drdc_tool_line_problem(got, line, len);
    if (problem != NULL) {
      printf("ERROR: %s\n", problem);
      failed = 1;
      continue;
    }
    /* blanks around a time are no part of it in any format: the UTC
     * parser reads the bare ISO 8601 text, so they go here */
    while ((len > 0u) &&
           ((line[len - 1u] == ' ') || (line[len - 1u] == '\t'))) {
      line[--len] = '\0';
    }
    st = read_time(from, line, &utc);
    if (!drdc_status_is_error(st)) {
      drdc_status_t st2 = write_time(to, &utc, out, sizeof out);

      if (st2 != DRDC_OK) {
        st = st2;
      }
    }
    if (drdc_status_is_error(st)) {
      printf("ERROR: %s (%s)\n", drdc_tool_time_reason(st),
             drdc_status_name(st));
      failed = 1;
      continue;
    }
    printf("%s\n", out);
    if (st == DRDC_W_LEAP_EXPIRED) {
      fprintf(stderr,
              "drdc time: warning: line %ld: past the leap-second "
              "table's expiry; the last known offset was used\n",
              line_no);
    }
  }
  free(line);
  return failed;
}
