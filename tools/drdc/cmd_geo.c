/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief `drdc geo`: GeoConvert's -g, -u, -c and -p with the library's
 *        integer geodesy (text in and out exact: decimal digits <-> nas
 *        and Q47.16 metres through the library's rounding).
 */
#include <ctype.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <drdc/fixed_arith.h>
#include <drdc/geo.h>
#include <drdc/geo_mgrs.h>

#include "commands.h"
#include "lines.h"

static const char usage[] =
    "usage: drdc geo [-g | -u | -m | -c] [-p PREC]\n"
    "\n"
    "Reads one position per line on standard input and writes it like\n"
    "GeographicLib's GeoConvert:\n"
    "  input   'LAT LON' in decimal degrees, or 'ZONE{n|s} EASTING NORTHING'\n"
    "          (UTM, metres; UPS with the hemisphere alone, 'n E N'), or\n"
    "          MGRS (the centre of its cell)\n"
    "  -g      output 'LAT LON' in decimal degrees (PREC + 5 decimals;\n"
    "          the default)\n"
    "  -u      output UTM/UPS 'ZONE{n|s} EASTING NORTHING' (PREC decimals\n"
    "          of a metre; the standard zone)\n"
    "  -m      output MGRS with PREC + 5 digits per coordinate (truncated)\n"
    "  -c      output the meridian convergence in degrees (PREC + 5\n"
    "          decimals) and the point scale (PREC + 7 decimals)\n"
    "  -p PREC precision, -6..9 (default 0)\n"
    "A line that cannot be converted gives 'ERROR: <reason>'; the others go\n"
    "on and the exit status is 1 at the end.\n";

#define NAS_PER_DEG INT64_C(3600000000000)
#define Q16_PER_M   INT64_C(65536)
#define Q58_ONE     INT64_C(288230376151711744)

static int64_t pow10_i64(int n)
{
  int64_t p = 1;
  int i;

  for (i = 0; i < n; i++) {
    p *= 10;
  }
  return p;
}

/* Decimal text -> value * unit, rounded (ties away from zero). Accepts
 * [+-]digits[.digits]; at most 18 significant fraction digits used. */
static bool parse_decimal(const char *s, int64_t unit, int64_t *out)
{
  bool neg = false;
  int64_t ip = 0;
  int64_t fp = 0;
  int fd = 0;
  bool digits = false;
  int64_t v = 0;

  if ((*s == '+') || (*s == '-')) {
    neg = (*s == '-');
    s++;
  }
  while (isdigit((unsigned char)*s)) {
    if (ip > INT64_C(100000000000)) {
      return false;
    }
    ip = (ip * 10) + (*s - '0');
    s++;
    digits = true;
  }
  if (*s == '.') {
    s++;
    while (isdigit((unsigned char)*s)) {
      if (fd < 17) {
        fp = (fp * 10) + (*s - '0');
        fd++;
      }
      s++;
      digits = true;
    }
  }
  if ((*s != '\0') || !digits) {
    return false;
  }
  if (drdc_fx_muldiv_s64(fp, unit, pow10_i64(fd), &v) != DRDC_OK) {
    return false;
  }
  if (ip > (INT64_MAX / unit)) {
    return false;
  }
  v += ip * unit;
  *out = neg ? -v : v;
  return true;
}

/* Print value / unit with `decimals` decimals (negative: rounded to
 * 10^-decimals, printed without a point), as C++'s fixed does (a negative
 * value that rounds to zero keeps its sign). */
static void print_fixed_signed(int64_t value, int64_t unit, int decimals,
                               bool negative_zero)
{
  int64_t q = 0;
  uint64_t mag;
  int64_t p;

  if (decimals >= 0) {
    (void)drdc_fx_muldiv_s64(value, pow10_i64(decimals), unit, &q);
  } else {
    p = pow10_i64(-decimals);
    (void)drdc_fx_muldiv_s64(value, 1, unit * p, &q);
    q *= p;
  }
  mag = (q < 0) ? (0u - (uint64_t)q) : (uint64_t)q;
  if ((value < 0) || ((value == 0) && negative_zero)) {
    putchar('-');
  }
  if (decimals > 0) {
    p = pow10_i64(decimals);
    printf("%llu.%0*llu", (unsigned long long)(mag / (uint64_t)p), decimals,
           (unsigned long long)(mag % (uint64_t)p));
  } else {
    printf("%llu", (unsigned long long)mag);
  }
}

static void print_fixed(int64_t value, int64_t unit, int decimals)
{
  print_fixed_signed(value, unit, decimals, false);
}

enum mode { MODE_GEO, MODE_UTM, MODE_CONV, MODE_MGRS };

static char *next_word(char **s)
{
  char *p = *s;
  char *start;

  while ((*p == ' ') || (*p == '\t') || (*p == ',')) {
    p++;
  }
  start = p;
  while ((*p != '\0') && (*p != ' ') && (*p != '\t') && (*p != ',')) {
    p++;
  }
  if (*p != '\0') {
    *p = '\0';
    p++;
  }
  *s = p;
  return start;
}

static const char *status_reason(drdc_status_t st)
{
  switch (st) {
  case DRDC_E_LATITUDE:
    return "latitude not in [-90d, 90d]";
  case DRDC_E_LONGITUDE:
    return "longitude not in [-540d, 540d)";
  case DRDC_E_ZONE:
    return "zone not in [0, 60]";
  case DRDC_E_EASTING:
    return "easting not in the UTM/UPS range";
  case DRDC_E_NORTHING:
    return "northing not in the UTM/UPS range";
  case DRDC_E_MGRS:
    return "malformed MGRS";
  case DRDC_E_BAND:
    return "MGRS 100 km square not in its latitude band";
  case DRDC_E_RANGE:
    return "point out of legal range for the UTM zone or UPS";
  default:
    return drdc_status_name(st);
  }
}

/* One line; returns false after printing an ERROR line. */
static bool convert_line(char *line, enum mode mode, int prec)
{
  char *rest = line;
  char *w1 = next_word(&rest);
  char *w2 = next_word(&rest);
  char *w3 = next_word(&rest);
  char *w4 = next_word(&rest);
  drdc_nas_t lat = 0;
  drdc_nas_t lon = 0;
  drdc_status_t st = DRDC_OK;
  drdc_geo_utm_t u;
  drdc_nas_t conv = 0;
  drdc_q5_58_t k = 0;
  bool west = false;       /* the point is west of its central meridian */
  bool grid_input = false; /* UTM/UPS or MGRS input: -m keeps its zone */

  if (*w4 != '\0') {
    printf("ERROR: extra text on the line\n");
    return false;
  }
  if ((*w2 == '\0') && (*w1 != '\0')) {
    /* MGRS: the centre of its cell, as GeoConvert reads it */
    drdc_geo_utm_t corner;

    st = drdc_geo_mgrs_decode(w1, &corner, &u, NULL);
    grid_input = true;
    if (st == DRDC_OK) {
      st = drdc_geo_from_utm(&u, &lat, &lon, &conv, &k);
      west = (u.zone != 0) ? (u.easting < (INT64_C(500000) * Q16_PER_M))
                           : (lon < 0);
    }
  } else if (*w3 != '\0') {
    size_t n = strlen(w1);
    char h = (n > 0u) ? (char)tolower((unsigned char)w1[n - 1u]) : '\0';
    char *end = NULL;
    long z;

    if ((h != 'n') && (h != 's')) {
      printf("ERROR: illegal hemisphere in zone %s\n", w1);
      return false;
    }
    w1[n - 1u] = '\0';
    if (*w1 == '\0') {
      z = 0; /* UPS: the hemisphere alone */
    } else {
      z = strtol(w1, &end, 10);
      if (*end != '\0') {
        printf("ERROR: illegal zone %s\n", w1);
        return false;
      }
      if ((z < 1) || (z > 60)) {
        printf("ERROR: zone %ld not in range [1, 60]\n", z);
        return false;
      }
    }
    u.zone = (int32_t)z;
    u.north = (h == 'n');
    if (!parse_decimal(w2, Q16_PER_M, &u.easting) ||
        !parse_decimal(w3, Q16_PER_M, &u.northing)) {
      printf("ERROR: bad easting or northing\n");
      return false;
    }
    st = drdc_geo_from_utm(&u, &lat, &lon, &conv, &k);
    grid_input = true;
    west = (u.easting < (INT64_C(500000) * Q16_PER_M));
  } else {
    if ((*w2 == '\0') || !parse_decimal(w1, NAS_PER_DEG, &lat) ||
        !parse_decimal(w2, NAS_PER_DEG, &lon)) {
      printf("ERROR: expected 'LAT LON' or 'ZONE{n|s} EASTING NORTHING'\n");
      return false;
    }
    if (mode == MODE_GEO) {
      int32_t z = 0;

      st = drdc_geo_utm_zone(lat, lon, &z); /* range checks only */
    } else {
      st = drdc_geo_to_utm(lat, lon, DRDC_GEO_ZONE_STANDARD, &u, &conv, &k);
      west = (u.zone != 0) ? (u.easting < (INT64_C(500000) * Q16_PER_M))
                           : (lon < 0);
    }
  }
  if (st != DRDC_OK) {
    printf("ERROR: %s\n", status_reason(st));
    return false;
  }
  if (mode == MODE_GEO) {
    print_fixed(lat, NAS_PER_DEG, prec + 5);
    putchar(' ');
    print_fixed(lon, NAS_PER_DEG, prec + 5);
  } else if (mode == MODE_UTM) {
    /* UTM input comes back in its own zone (as GeoConvert keeps it) */
    if (u.zone == DRDC_GEO_ZONE_UPS) {
      printf("%c ", u.north ? 'n' : 's');
    } else {
      printf("%02d%c ", (int)u.zone, u.north ? 'n' : 's');
    }
    print_fixed(u.easting, Q16_PER_M, prec);
    putchar(' ');
    print_fixed(u.northing, Q16_PER_M, prec);
  } else if (mode == MODE_MGRS) {
    char text[DRDC_GEO_MGRS_SIZE];
    int32_t mp = ((prec + 5) > DRDC_GEO_MGRS_PREC_MAX) ? DRDC_GEO_MGRS_PREC_MAX
                                                       : (prec + 5);

    if (grid_input) {
      st = drdc_geo_mgrs_from_utm(&u, (mp < -1) ? -1 : mp, text, sizeof text);
    } else {
      st = drdc_geo_mgrs_encode(lat, lon, (mp < -1) ? -1 : mp, text,
                                sizeof text);
    }
    if (st != DRDC_OK) {
      printf("ERROR: %s\n", status_reason(st));
      return false;
    }
    fputs(text, stdout);
  } else {
    /* GeoConvert's double convergence is a signed zero on the central
     * meridian and the equator: negative when exactly one of latitude
     * and longitude offset is negative */
    print_fixed_signed(conv, NAS_PER_DEG, prec + 5, (lat < 0) != west);
    putchar(' ');
    print_fixed(k, Q58_ONE, prec + 7);
  }
  putchar('\n');
  return true;
}

int drdc_cmd_geo(int argc, char **argv)
{
  enum mode mode = MODE_GEO;
  int prec = 0;
  int i;
  char *line = NULL;
  size_t cap = 0;
  size_t len = 0;
  int got;
  int failed = 0;

  for (i = 1; i < argc; i++) {
    if (strcmp(argv[i], "--help") == 0) {
      fputs(usage, stdout);
      return 0;
    } else if (strcmp(argv[i], "-g") == 0) {
      mode = MODE_GEO;
    } else if (strcmp(argv[i], "-u") == 0) {
      mode = MODE_UTM;
    } else if (strcmp(argv[i], "-m") == 0) {
      mode = MODE_MGRS;
    } else if (strcmp(argv[i], "-c") == 0) {
      mode = MODE_CONV;
    } else if ((strcmp(argv[i], "-p") == 0) && ((i + 1) < argc)) {
      char *end = NULL;
      long p = strtol(argv[i + 1], &end, 10);

      if ((*argv[i + 1] == '\0') || (*end != '\0')) {
        fprintf(stderr, "drdc geo: -p needs an integer\n");
        return 2;
      }
      prec = (p < -6) ? -6 : ((p > 9) ? 9 : (int)p);
      i++;
    } else {
      fprintf(stderr, "drdc geo: unknown option '%s'\n%s", argv[i], usage);
      return 2;
    }
  }
  while ((got = drdc_tool_read_line(stdin, &line, &cap, &len)) !=
         DRDC_TOOL_LINE_EOF) {
    const char *problem;

    if (got == DRDC_TOOL_LINE_ERROR) {
      fputs("drdc geo: cannot read standard input\n", stderr);
      failed = 1;
      break;
    }
    problem = drdc_tool_line_problem(got, line, len);
    if (problem != NULL) {
      printf("ERROR: %s\n", problem);
      failed = 1;
    } else if (!convert_line(line, mode, prec)) {
      failed = 1;
    }
    fflush(stdout);
  }
  free(line);
  return failed;
}
