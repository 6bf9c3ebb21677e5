/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief `drdc nmea`: decode one NMEA 0183 sentence per line with the
 *        library's parser and print its fields as `key=value` pairs.
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <drdc/nmea.h>

#include "commands.h"
#include "lines.h"
#include "reasons.h"

static const char usage[] =
    "usage: drdc nmea [--strict] [--raw] [--keep-going]\n"
    "\n"
    "Reads one NMEA 0183 sentence per line on standard input (GGA, RMC,\n"
    "GNS, GLL, VTG, HDT, THS, GSA, ZDA, GST from any talker) and writes one\n"
    "line per input line: the decoded fields as space-separated key=value\n"
    "pairs, or 'ERROR: <reason> (<status>)'.\n"
    "\n"
    "Exit status: 0 every line decoded (with --keep-going: every line\n"
    "read, whether it decoded or gave ERROR); 1 a line gave ERROR, or\n"
    "standard input could not be read; 2 a usage error.\n"
    "\n"
    "Keys, in this order, each only when the sentence carries it:\n"
    "  type talker time date zone lat lon quality mode fix satellites ids\n"
    "  system hdop pdop vdop altitude separation speed course\n"
    "  course_magnetic heading rms sigma_lat sigma_lon sigma_alt\n"
    "  sigma_major sigma_minor orientation beyond\n"
    "Values: time hh:mm:ss.nnnnnnnnn (UTC), date yyyy-mm-dd, zone +hh:mm,\n"
    "lat and lon degrees with 12 decimals (north and east positive),\n"
    "altitude, separation and the GST deviations in metres and the\n"
    "dilutions of precision with 4 decimals, speed m/s with 4 decimals,\n"
    "course, heading and orientation degrees [0, 360) with 8 decimals,\n"
    "ids comma-separated, beyond the comma-separated names of the values\n"
    "beyond their format (written as the format's limit). Decimals are the\n"
    "library's integers rounded to nearest, ties away from zero.\n"
    "\n"
    "Options:\n"
    "  --strict  NMEA 0183 to the letter: 82 characters, every field of\n"
    "            the layout, GGA quality required\n"
    "  --raw     the library's integers instead of decimals: lat and lon\n"
    "            in nano-arcseconds, metres, speed and DOPs in Q15.16 or\n"
    "            Q47.16, angles as 2^32 per turn, time's fraction in ns\n"
    "  --keep-going\n"
    "            a line that gives ERROR does not make the exit status 1:\n"
    "            real receiver logs hold sentences without a fix and\n"
    "            sentences not decoded here on every other line\n";

typedef struct nmea_options {
  uint32_t flags; /* of drdc_nmea_parse_with() */
  int raw;
  int keep_going; /* lines that give ERROR leave the exit status 0 */
} nmea_options_t;

static const char *type_name(drdc_nmea_type_t t)
{
  static const char *const names[] = {"GGA", "RMC", "GNS", "ZDA", "GST",
                                      "GLL", "VTG", "HDT", "THS", "GSA"};

  return ((unsigned)t < (sizeof names / sizeof names[0])) ? names[t] : "?";
}

/* a / b rounded to nearest, ties away from zero (b > 0) */
static __int128 div_round(__int128 a, __int128 b)
{
  return (a >= 0) ? (a + (b / 2)) / b : -((-a + (b / 2)) / b);
}

/* " key=" and the value v / den with `decimals` decimals (or v, raw) */
static void put_fixed(const nmea_options_t *o, const char *key, int64_t v,
                      int64_t den, unsigned decimals)
{
  __int128 scale = 1;
  __int128 q;
  unsigned k;

  printf(" %s=", key);
  if (o->raw) {
    printf("%" PRId64, v);
    return;
  }
  for (k = 0; k < decimals; k++) {
    scale *= 10;
  }
  q = div_round((__int128)v * scale, den);
  printf("%s%" PRId64 ".%0*" PRId64, (q < 0) ? "-" : "",
         (int64_t)((q < 0 ? -q : q) / scale), (int)decimals,
         (int64_t)((q < 0 ? -q : q) % scale));
}

/* a binary angle as degrees in [0, 360) with 8 decimals: a x 360 / 2^32 */
static void put_angle(const nmea_options_t *o, const char *key, drdc_bam32_t a)
{
  if (o->raw) {
    printf(" %s=%" PRIu32, key, a);
    return;
  }
  put_fixed(o, key, (int64_t)a * 360, INT64_C(4294967296), 8u);
}

static void put_q16(const nmea_options_t *o, const char *key, int64_t v)
{
  put_fixed(o, key, v, 65536, 4u);
}

static void put_beyond(uint32_t beyond)
{
  static const char *const names[] = {
      "hdop",      "speed",     "rms",       "sigma_major", "sigma_minor",
      "sigma_lat", "sigma_lon", "sigma_alt", "pdop",        "vdop"};
  const char *sep = " beyond=";
  unsigned k;

  for (k = 0; k < sizeof names / sizeof names[0]; k++) {
    if (beyond & (UINT32_C(1) << k)) {
      printf("%s%s", sep, names[k]);
      sep = ",";
    }
  }
}

static void put_record(const nmea_options_t *o, const drdc_nmea_t *n)
{
  uint32_t has = n->has;
  int32_t k;

  printf("type=%s talker=%s", type_name(n->type), n->talker);
  if (has & DRDC_NMEA_HAS_TIME) {
    printf(" time=%02" PRId32 ":%02" PRId32 ":%02" PRId32 ".%09" PRId32,
           n->time.hour, n->time.minute, n->time.second, n->time.nsec);
  }
  if (has & DRDC_NMEA_HAS_DATE) {
    printf(" date=%04" PRId32 "-%02" PRId32 "-%02" PRId32, n->year, n->month,
           n->day);
  }
  if (has & DRDC_NMEA_HAS_ZONE) {
    printf(" zone=%c%02" PRId32 ":%02" PRId32, (n->zone_hours < 0) ? '-' : '+',
           (n->zone_hours < 0) ? -n->zone_hours : n->zone_hours,
           n->zone_minutes);
  }
  if (has & DRDC_NMEA_HAS_POSITION) {
    /* nas / 3.6e12 = degrees; 12 decimals: nas x 10 / 36 */
    put_fixed(o, "lat", n->latitude, INT64_C(3600000000000), 12u);
    put_fixed(o, "lon", n->longitude, INT64_C(3600000000000), 12u);
  }
  if (has & DRDC_NMEA_HAS_QUALITY) {
    printf(" quality=%" PRId32, n->quality);
  }
  if (n->mode[0] != '\0') {
    printf(" mode=%s", n->mode);
  }
  if (has & DRDC_NMEA_HAS_FIX_TYPE) {
    printf(" fix=%" PRId32, n->fix_type);
  }
  if (has & DRDC_NMEA_HAS_SATELLITES) {
    printf(" satellites=%" PRId32, n->satellites);
  }
  if ((n->type == DRDC_NMEA_GSA) && (n->satellites > 0)) {
    printf(" ids=");
    for (k = 0; k < n->satellites; k++) {
      printf("%s%u", (k > 0) ? "," : "", (unsigned)n->satellite_ids[k]);
    }
  }
  if (has & DRDC_NMEA_HAS_SYSTEM) {
    printf(" system=%" PRId32, n->system_id);
  }
  if (has & DRDC_NMEA_HAS_HDOP) {
    put_q16(o, "hdop", n->hdop);
  }
  if (has & DRDC_NMEA_HAS_PDOP) {
    put_q16(o, "pdop", n->pdop);
  }
  if (has & DRDC_NMEA_HAS_VDOP) {
    put_q16(o, "vdop", n->vdop);
  }
  if (has & DRDC_NMEA_HAS_ALTITUDE) {
    put_q16(o, "altitude", n->altitude);
  }
  if (has & DRDC_NMEA_HAS_SEPARATION) {
    put_q16(o, "separation", n->separation);
  }
  if (has & DRDC_NMEA_HAS_SPEED) {
    put_q16(o, "speed", n->speed);
  }
  if (has & DRDC_NMEA_HAS_COURSE) {
    put_angle(o, "course", n->course);
  }
  if (has & DRDC_NMEA_HAS_COURSE_MAGNETIC) {
    put_angle(o, "course_magnetic", n->course_magnetic);
  }
  if (has & DRDC_NMEA_HAS_HEADING) {
    put_angle(o, "heading", n->heading);
  }
  if (has & DRDC_NMEA_HAS_GST) {
    put_q16(o, "rms", n->rms);
    put_q16(o, "sigma_lat", n->sigma_latitude);
    put_q16(o, "sigma_lon", n->sigma_longitude);
    put_q16(o, "sigma_alt", n->sigma_altitude);
  }
  if (has & DRDC_NMEA_HAS_ELLIPSE) {
    put_q16(o, "sigma_major", n->sigma_major);
    put_q16(o, "sigma_minor", n->sigma_minor);
    put_angle(o, "orientation", n->orientation);
  }
  if (n->beyond != 0u) {
    put_beyond(n->beyond);
  }
  putchar('\n');
}

int drdc_cmd_nmea(int argc, char **argv)
{
  nmea_options_t o = {0u, 0, 0};
  char *line = NULL;
  size_t cap = 0;
  size_t len = 0;
  int got;
  int failed = 0;
  int i;

  for (i = 1; i < argc; i++) {
    if ((strcmp(argv[i], "--help") == 0) || (strcmp(argv[i], "-h") == 0)) {
      fputs(usage, stdout);
      return 0;
    } else if (strcmp(argv[i], "--strict") == 0) {
      o.flags = DRDC_NMEA_STRICT;
    } else if (strcmp(argv[i], "--raw") == 0) {
      o.raw = 1;
    } else if (strcmp(argv[i], "--keep-going") == 0) {
      o.keep_going = 1;
    } else {
      fprintf(stderr, "drdc nmea: unexpected argument '%s'\n", argv[i]);
      fputs(usage, stderr);
      return 2;
    }
  }
  while ((got = drdc_tool_read_line(stdin, &line, &cap, &len)) !=
         DRDC_TOOL_LINE_EOF) {
    drdc_nmea_t n;
    drdc_status_t st;

    if (got == DRDC_TOOL_LINE_ERROR) {
      fputs("drdc nmea: cannot read standard input\n", stderr);
      failed = 1;
      break;
    }
    /* too long or a NUL inside: the tool's one wording for every
     * command */
    if (drdc_tool_line_problem(got, line, len) != NULL) {
      printf("ERROR: %s\n", drdc_tool_line_problem(got, line, len));
      failed |= !o.keep_going;
      continue;
    }
    /* the reader took the line end off (LF or CR LF); any other byte
     * inside the line is the parser's to judge */
    st = drdc_nmea_parse_with(line, len, o.flags, &n);
    if (st != DRDC_OK) {
      printf("ERROR: %s (%s)\n", drdc_tool_nmea_reason(st),
             drdc_status_name(st));
      failed |= !o.keep_going;
      continue;
    }
    put_record(&o, &n);
  }
  free(line);
  return failed;
}
