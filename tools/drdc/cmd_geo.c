/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief `drdc geo`: GeoConvert's conversions and options with the
 *        library's integer geodesy; text in and out exact (decimal digits
 *        <-> nas and Q47.16 metres, printed decimals rounded half to even
 *        from the exact fixed-point value).
 */
#include <ctype.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <drdc/geo.h>
#include <drdc/fixed_sqrt.h>
#include <drdc/geo_mgrs.h>
#include <drdc/version.h>

#include "commands.h"
#include "geo_grid_text.h"
#include "geo_mgrs_text.h"
#include "geo_text.h"
#include "lines.h"

__extension__ typedef __int128 i128;

static const char usage[] =
    "usage: drdc geo [-g | -d | -: | -u | -m | -c] [-z ZONE | -s | -t | -S | "
    "-T]\n"
    "                [-n] [-w] [-p PREC] [-l | -a] [--comment-delimiter "
    "DELIM]\n"
    "                [--version | -h | --help]\n"
    "                [--input-file FILE | --input-string STRING]\n"
    "                [--line-separator CHAR] [--output-file FILE]\n"
    "\n"
    "Reads one position per line and writes it as GeographicLib's\n"
    "GeoConvert 2.1.2 does, from the library's integer geodesy:\n"
    "  input   'LAT LON' in decimal degrees or degrees, minutes, seconds\n"
    "          (33.3, 33d18'N, 33:18:00N, N33d18; a hemisphere letter\n"
    "          may swap the order); 'ZONE{n|s} EASTING NORTHING' or\n"
    "          'EASTING NORTHING ZONE{n|s}' (UTM, metres; UPS with the\n"
    "          hemisphere alone); or MGRS (the centre of its cell)\n"
    "  -g      output 'LAT LON' in decimal degrees, PREC + 5 decimals\n"
    "          (the default)\n"
    "  -d, -:  output degrees, minutes and seconds, PREC + 1 decimals of\n"
    "          a second (minutes at PREC -2, -3; degrees below); -: uses\n"
    "          ':' between the parts\n"
    "  -u      output UTM/UPS 'ZONE{n|s} EASTING NORTHING', PREC decimals\n"
    "          of a metre\n"
    "  -m      output MGRS, PREC + 5 digits per coordinate (truncated)\n"
    "  -c      output the meridian convergence (PREC + 5 decimals of a\n"
    "          degree) and the point scale (PREC + 7 decimals)\n"
    "  -z ZONE output in UTM zone ZONE (1..60, 0 for UPS, or with its\n"
    "          hemisphere, 38n); -s the standard zone; -t the standard UTM\n"
    "          zone also in the polar caps; -S, -T as -s, -t until a line\n"
    "          converts, then that line's zone and hemisphere for the rest.\n"
    "          Default: geographic input in its standard zone, UTM/UPS and\n"
    "          MGRS input in its own\n"
    "  -n      MGRS input means the south-west corner of its cell\n"
    "  -w      longitude first, on input and output\n"
    "  -l, -a  hemisphere written north/south, or n/s (the default)\n"
    "  -p PREC precision, -5..10 (-6 for MGRS), default 0\n"
    "  --comment-delimiter DELIM  cut DELIM and the rest of a line off\n"
    "          before reading it, and write them after its output\n"
    "  --input-file FILE, --output-file FILE  read or write FILE instead\n"
    "          of standard input or output ('-': those)\n"
    "  --input-string STRING  read STRING, its lines separated by CHAR\n"
    "          (--line-separator, default ';')\n"
    "  --version  the library version; -h, --help this text\n"
    "Printed decimals are the library's fixed-point values rounded half to\n"
    "even, never more digits than those values resolve: a value that is\n"
    "not exactly the input is written with at most 12 decimals of a degree\n"
    "(-g, -c: PREC 7; the library's unit is 1 nas, 2.8e-13 degree), 9 of\n"
    "a second (-d: PREC 8) and 4 of a metre (-u: PREC 4; 1/65536 m), and\n"
    "MGRS computed from such metres with at most 9 digits (PREC 4).\n"
    "UTM/UPS and MGRS input keeps all its decimals: the library converts\n"
    "the nearest 1/65536 m and the digits below move its results by their\n"
    "derivatives there (within 1.5 nas of the exact input's values); -u\n"
    "and -m write such input in its own zone with its own digits, exactly.\n"
    "Latitude -0 (or 0S) is just south of the equator, as in GeoConvert.\n"
    "A line that cannot be converted gives GeoConvert's 'ERROR: <message>'\n"
    "(nan, inf, metres beyond 1e12 and angles beyond 1000000 degrees are\n"
    "errors here); the others go on and the exit status is 1 at the end;\n"
    "bad options exit with status 2.\n";

#define Q16_PER_M   INT64_C(65536)
#define Q58_ONE     INT64_C(288230376151711744)
#define NAS_PER_DEG GEO_TEXT_NAS_PER_DEGREE
/* False northing of the southern UTM hemisphere, metres and Q47.16. */
#define SOUTH_METRES INT64_C(10000000)
#define SOUTH_SHIFT  (SOUTH_METRES * Q16_PER_M)

/* Most decimals the library's values resolve (see the usage text). */
#define DEGREE_DECIMALS_MAX         12
#define SECOND_DECIMALS_MAX         9
#define METRE_DECIMALS_MAX          4
#define MGRS_DIGITS_FROM_METRES_MAX 9

/* -z/-s/-t, beside DRDC_GEO_ZONE_STANDARD (-s), UPS (0) and 1..60 */
#define ZONE_MATCH (-3) /* none given: the input's own zone */
#define ZONE_UTM   (-2) /* -t */

enum mode { MODE_GEO, MODE_DMS, MODE_UTM, MODE_MGRS, MODE_CONV };

struct options {
  enum mode mode;
  int prec;
  int zone;               /* ZONE_MATCH, ZONE_UTM, standard, UPS or 1..60 */
  bool set_hemisphere;    /* -z with a hemisphere: -u writes in it */
  bool north;             /* that hemisphere */
  bool corner;            /* -n */
  bool lon_first;         /* -w */
  bool long_names;        /* -l */
  char sep;               /* -: */
  bool sticky;            /* -S, -T: the first conversion's zone from then on */
  const char *comment;    /* --comment-delimiter, or NULL */
  const char *input_file; /* --input-file, or NULL for standard input */
  const char *input_string; /* --input-string, or NULL */
  char line_separator;      /* --line-separator, in the input string */
  const char *output_file;  /* --output-file, or NULL for standard output */
};

/* One converted line. */
struct position {
  geo_text_angle_t lat;
  geo_text_angle_t lon; /* as read or computed, not reduced */
  drdc_nas_t lon_calc;  /* lon within the library's [-540, 540) */
  bool geographic;      /* the input was 'LAT LON' */
  drdc_geo_utm_t u;     /* the output zone's coordinates */
  bool u_input;         /* u is the input's own grid position */
  /* While u_input: the exact decimal text of the easting and northing
   * (NULL where u holds the input exactly: MGRS cells of 1 m and more),
   * whole metres added to the northing text since it was read (moves
   * between the hemispheres), and what u's Q47.16 values lack of the
   * text, 2^-48 m. */
  const char *text[2];
  int64_t text_add;
  int64_t rest[2];
  char cell[2][48]; /* MGRS input: its cell's easting and northing text */
  bool rezoned;     /* u was computed again for -z, -s or -t */
  drdc_nas_t conv;
  drdc_q5_58_t k;
  char why[200]; /* the ERROR line's message when a step fails */
};

/* The ERROR message of pos; false, for `return fail(...)`. */
static bool fail(struct position *pos, const char *format, ...)
{
  va_list args;

  va_start(args, format);
  vsnprintf(pos->why, sizeof pos->why, format, args);
  va_end(args);
  return false;
}

static int imin(int a, int b)
{
  return (a < b) ? a : b;
}

static int imax(int a, int b)
{
  return (a > b) ? a : b;
}

static int64_t pow10_i64(int n)
{
  int64_t p = 1;
  int i;

  for (i = 0; i < n; i++) {
    p *= 10;
  }
  return p;
}

static int64_t floor_div(int64_t a, int64_t b)
{
  int64_t q = a / b;

  return (((a % b) != 0) && ((a < 0) != (b < 0))) ? (q - 1) : q;
}

/* Longitude into [-180, 180) degrees, exact. */
static drdc_nas_t reduce_longitude(drdc_nas_t lon)
{
  int64_t turn = 360 * NAS_PER_DEG;

  return lon - (floor_div(lon + (180 * NAS_PER_DEG), turn) * turn);
}

/* GeoConvert's zone for -t: the standard UTM zone, the Norway and
 * Svalbard exceptions by the latitude band, in the polar caps too. */
static int utm_only_zone(drdc_nas_t lat, drdc_nas_t lon)
{
  int64_t ilon = floor_div(reduce_longitude(lon), NAS_PER_DEG);
  int64_t ilat = floor_div(lat, NAS_PER_DEG);
  int64_t band = ((ilat + 80) / 8) - 10;
  int zone = (int)((ilon + 186) / 6);

  band = (band < -10) ? -10 : ((band > 9) ? 9 : band);
  if ((band == 7) && (zone == 31) && (ilon >= 3)) {
    zone = 32; /* Norway */
  } else if ((band == 9) && (ilon >= 0) && (ilon < 42)) {
    zone = (int)((2 * ((ilon + 183) / 12)) + 1); /* Svalbard */
  }
  return zone;
}

/* Split on GeoConvert's separators: blanks and commas. */
static int split(char *line, char **words, int max)
{
  int n = 0;
  char *p = line;

  for (;;) {
    while ((*p != '\0') && (strchr(" \t\n\v\f\r,", *p) != NULL)) {
      p++;
    }
    if (*p == '\0') {
      return n;
    }
    if (n == max) {
      return max + 1;
    }
    words[n++] = p;
    while ((*p != '\0') && (strchr(" \t\n\v\f\r,", *p) == NULL)) {
      p++;
    }
    if (*p != '\0') {
      *p++ = '\0';
    }
  }
}

/* GeoConvert's message for a point that zone cannot hold. */
static bool zone_range_error(struct position *pos, int zone)
{
  /* east of the central meridian, reduced to [-180, 180) */
  drdc_nas_t east =
      reduce_longitude(pos->lon_calc - (((6 * zone) - 183) * NAS_PER_DEG));

  return geo_grid_zone_error(&pos->lat, &pos->lon, east, zone, pos->why,
                             sizeof pos->why);
}

static void set_computed_angle(geo_text_angle_t *a, drdc_nas_t nas,
                               bool negative)
{
  a->nas = nas;
  a->negative = negative;
  a->exact = false;
  a->hemisphere = GEO_TEXT_NONE;
  a->too_large = false;
}

/* What the library gives at a grid point, in this order: latitude,
 * longitude and convergence (nas), point scale (Q5.58). */
enum { AT_LAT, AT_LON, AT_CONV, AT_SCALE, AT_COUNT };

/* Half the span of the finite differences below, Q47.16 LSB (0.98 mm). */
#define STEP 64
/* 2^32: the fine values below carry 32 bits below their unit, the rests
 * 32 bits below the Q47.16 LSB (2^-48 m). */
#define FINE_ONE ((i128)1 << 32)
/* UPS false easting and northing (the pole), Q47.16. */
#define UPS_POLE (INT64_C(2000000) * Q16_PER_M)
/* UPS points within 2^30 LSB (16 km) of the pole along both axes take
 * the polar treatment of polar_values(), which evaluates the direction
 * 2^64 x 2^-48 m (65 km) out. */
#define POLAR_NEAR (INT64_C(1) << 30)
#define POLAR_OUT  ((i128)1 << 64)

/* The library's values at u moved by `by` LSB along axis (0 easting, 1
 * northing). */
static drdc_status_t values_at(const drdc_geo_utm_t *u, int axis, int64_t by,
                               int64_t v[AT_COUNT])
{
  drdc_geo_utm_t p = *u;

  if (axis == 0) {
    p.easting += by;
  } else {
    p.northing += by;
  }
  return drdc_geo_from_utm(&p, &v[AT_LAT], &v[AT_LON], &v[AT_CONV],
                           &v[AT_SCALE]);
}

/* GeoConvert's message for the input refused with st (the coordinate of
 * u that st names): it quotes the input's own value, which is the text's
 * where pos has it. */
static bool range_error(struct position *pos, const drdc_geo_utm_t *u,
                        drdc_status_t st)
{
  int axis = (st == DRDC_E_EASTING) ? 0 : 1;
  int decimals;

  if (pos->u_input && (pos->text[axis] != NULL)) {
    /* the most decimals of a metre that int64 holds for this value */
    for (decimals = 15; decimals >= 0; decimals--) {
      int64_t v = 0;
      bool negative = false;

      if (geo_text_metres_scaled(pos->text[axis],
                                 (axis == 1) ? pos->text_add : 0, decimals,
                                 false, &v, &negative)) {
        return geo_grid_range_error_at(u, st, v, pow10_i64(decimals + 3),
                                       negative, pos->why, sizeof pos->why);
      }
    }
  }
  return geo_grid_range_error(u, st, pos->why, sizeof pos->why);
}

/* The library's values at the exact point u + rest (rest: 2^-48 m along
 * the easting and the northing) into fine[], in 2^-32 of their units:
 * the values at u plus, along each axis, the derivative times the rest.
 * The derivative is the central difference of the library's values 2
 * STEP apart: its ends' roundings (1 nas, 334 LSB of Q5.58 at most)
 * scaled by |rest| / (2 STEP) <= 1/256 add below 0.004 nas and 2 LSB; the
 * neglected second-order term (rest^2 f''/2) is below 1e-6 nas in UTM,
 * and 6e3 nas / d^2 in UPS d metres from a pole (1.4e-5 nas beyond
 * POLAR_NEAR, which polar_values() keeps to). One-sided within STEP of
 * the range's edge, and east of east_min (a pole's cusp). Fails, with
 * GeoConvert's message, for a point beyond the range of its zone, also
 * where u (rounded to a limit) is not. */
static bool fine_values(struct position *pos, const drdc_geo_utm_t *u,
                        const int64_t rest[2], int64_t east_min,
                        i128 fine[AT_COUNT])
{
  int64_t at[AT_COUNT];
  drdc_status_t st = values_at(u, 0, 0, at);
  int axis;
  int i;

  if ((st == DRDC_E_EASTING) || (st == DRDC_E_NORTHING)) {
    return range_error(pos, u, st);
  }
  if (st != DRDC_OK) {
    return fail(pos, "%s", drdc_status_name(st));
  }
  for (i = 0; i < AT_COUNT; i++) {
    fine[i] = (i128)at[i] * FINE_ONE;
  }
  for (axis = 0; axis < 2; axis++) {
    int64_t ahead[AT_COUNT];
    int64_t behind[AT_COUNT];
    const int64_t *hi = ahead;
    const int64_t *lo = behind;
    int64_t span = 2 * STEP;
    drdc_status_t st_ahead;
    drdc_status_t st_behind;

    if (rest[axis] == 0) {
      continue;
    }
    st_ahead = values_at(u, axis, STEP, ahead);
    st_behind = ((axis == 0) && ((u->easting - STEP) < east_min))
                    ? DRDC_E_RANGE
                    : values_at(u, axis, -STEP, behind);
    st = (rest[axis] > 0) ? st_ahead : st_behind;
    if ((st == DRDC_E_EASTING) || (st == DRDC_E_NORTHING)) {
      /* the range's limits are whole kilometres, multiples of the LSB: the
       * point lies beyond one exactly when u one LSB towards it does */
      int64_t by = (rest[axis] > 0) ? 1 : -1;
      int64_t edge[AT_COUNT];
      drdc_geo_utm_t past = *u;

      st = values_at(u, axis, by, edge);
      if ((st == DRDC_E_EASTING) || (st == DRDC_E_NORTHING)) {
        if (axis == 0) {
          past.easting += by;
        } else {
          past.northing += by;
        }
        return range_error(pos, &past, st);
      }
    }
    if (st_ahead != DRDC_OK) {
      hi = at;
      span = STEP;
    }
    if (st_behind != DRDC_OK) {
      lo = at;
      span = (hi == at) ? 0 : STEP;
    }
    for (i = 0; (i < AT_COUNT) && (span != 0); i++) {
      /* longitude and convergence may wrap at +-180 degrees */
      int64_t d = ((i == AT_LON) || (i == AT_CONV))
                      ? reduce_longitude(hi[i] - lo[i])
                      : (hi[i] - lo[i]);

      fine[i] += ((i128)d * rest[axis]) / span;
    }
  }
  return true;
}

/* A fine value (2^-32 units) rounded to its unit, halves up. */
static int64_t round_fine(i128 v)
{
  i128 q = v / FINE_ONE;
  i128 r = v % FINE_ONE;

  if (r < 0) {
    r += FINE_ONE;
    q--;
  }
  return (int64_t)(q + (((2 * r) >= FINE_ONE) ? 1 : 0));
}

/* A point of UPS zone `pole` (hemisphere of pole->north) at the exact
 * offsets (x, y) from the pole, 2^-48 m, as the nearest Q47.16 point and
 * its rests; |x|, |y| < 2^96. */
static void polar_point(const drdc_geo_utm_t *pole, i128 x, i128 y,
                        drdc_geo_utm_t *u, int64_t rest[2])
{
  i128 off[2];
  int axis;

  off[0] = x;
  off[1] = y;
  *u = *pole;
  for (axis = 0; axis < 2; axis++) {
    i128 q = round_fine(off[axis]);

    rest[axis] = (int64_t)(off[axis] - (q * FINE_ONE));
    if (axis == 0) {
      u->easting = UPS_POLE + (int64_t)q;
    } else {
      u->northing = UPS_POLE + (int64_t)q;
    }
  }
}

/* The input's exact offsets from the UPS pole as integers of one unit,
 * off[], and that unit in 2^-48 m, *num / *den: 10^-D m with D as large
 * as int64 allows (at most 18), from the text; or 2^-16 m, from u when
 * it is the input exactly. False where the text's value is not held. */
static bool polar_offsets(const struct position *pos, int64_t off[2], i128 *num,
                          i128 *den)
{
  int decimals;
  int axis;

  if (pos->text[0] == NULL) {
    off[0] = pos->u.easting - UPS_POLE;
    off[1] = pos->u.northing - UPS_POLE;
    *num = FINE_ONE;
    *den = 1;
    return true;
  }
  for (decimals = 18; decimals >= 0; decimals--) {
    bool negative = false;

    for (axis = 0; axis < 2; axis++) {
      int64_t add = ((axis == 1) ? pos->text_add : 0) - (UPS_POLE / Q16_PER_M);

      if (!geo_text_metres_scaled(pos->text[axis], add, decimals, false,
                                  &off[axis], &negative)) {
        break;
      }
    }
    if (axis == 2) {
      *num = (i128)1 << 48;
      *den = (i128)pow10_i64(decimals);
      return true;
    }
  }
  return false;
}

/* UPS within POLAR_NEAR of a pole: the latitude and the scale depend
 * only on the distance from the pole, the longitude and the convergence
 * only on the direction, and differences at u would bend with the pole
 * (or straddle it). So the first two are taken on the easting axis at
 * the exact distance (correctly rounded from the input's own decimals;
 * differences only east of the pole), the others 65 km out in the
 * exact direction (the input's offsets from the pole scaled, a relative
 * error of 2^-63 at most). fine[] stays as it is elsewhere and at the
 * pole itself. */
static bool polar_values(struct position *pos, i128 fine[AT_COUNT])
{
  int64_t off[2];
  i128 num = 1;
  i128 den = 1;
  i128 big;
  i128 radial[AT_COUNT];
  i128 direction[AT_COUNT];
  drdc_geo_utm_t pole = pos->u;
  drdc_geo_utm_t u;
  int64_t rest[2];
  int axis;

  for (axis = 0; axis < 2; axis++) {
    int64_t q = ((axis == 0) ? pos->u.easting : pos->u.northing) - UPS_POLE;

    if ((q >= POLAR_NEAR) || (q <= -POLAR_NEAR)) {
      return true;
    }
  }
  if (!polar_offsets(pos, off, &num, &den) ||
      ((off[0] == 0) && (off[1] == 0))) {
    return true;
  }
  pole.easting = UPS_POLE;
  pole.northing = UPS_POLE;
  polar_point(&pole, ((i128)drdc_fx_hypot_s64(off[0], off[1]) * num) / den, 0,
              &u, rest);
  if (!fine_values(pos, &u, rest, UPS_POLE, radial)) {
    return false;
  }
  /* |off| < 2^63: the products stay below 2^127 */
  big = (off[0] < 0) ? -(i128)off[0] : (i128)off[0];
  big = ((off[1] < 0) ? -(i128)off[1] : (i128)off[1]) > big
            ? ((off[1] < 0) ? -(i128)off[1] : (i128)off[1])
            : big;
  polar_point(&pole, ((i128)off[0] * POLAR_OUT) / big,
              ((i128)off[1] * POLAR_OUT) / big, &u, rest);
  if (!fine_values(pos, &u, rest, INT64_MIN, direction)) {
    return false;
  }
  fine[AT_LAT] = radial[AT_LAT];
  fine[AT_SCALE] = radial[AT_SCALE];
  fine[AT_LON] = direction[AT_LON];
  fine[AT_CONV] = direction[AT_CONV];
  return true;
}

/* Whether coordinate `axis` of the input is a negative zero ("-0"). */
static bool text_negative_zero(const struct position *pos, int axis)
{
  int64_t v = 0;
  bool negative = false;

  return (pos->text[axis] != NULL) &&
         geo_text_metres_scaled(pos->text[axis],
                                (axis == 1) ? pos->text_add : 0, 0, false, &v,
                                &negative) &&
         negative && (v == 0) && (pos->rest[axis] == 0) &&
         ((axis == 0) ? pos->u.easting : pos->u.northing) == 0;
}

/* UTM/UPS -> geographic, then GeoConvert's FixHemisphere: a UTM northing
 * given in the other hemisphere is moved to the latitude's own. The
 * input's digits below Q47.16 (pos->rest) move every value by the
 * library's derivatives (fine_values(), polar_values()). */
static bool from_grid(struct position *pos)
{
  i128 fine[AT_COUNT];
  i128 half_turn = (i128)(180 * NAS_PER_DEG) * FINE_ONE;

  if (!fine_values(pos, &pos->u, pos->rest, INT64_MIN, fine)) {
    return false;
  }
  if ((pos->u.zone == DRDC_GEO_ZONE_UPS) && !polar_values(pos, fine)) {
    return false;
  }
  /* GeoConvert's longitude is in [-180, 180] */
  if (fine[AT_LON] > half_turn) {
    fine[AT_LON] -= 2 * half_turn;
  } else if (fine[AT_LON] < -half_turn) {
    fine[AT_LON] += 2 * half_turn;
  }
  /* a northing of -0 in the north gives GeoConvert a latitude of -0 */
  set_computed_angle(
      &pos->lat, round_fine(fine[AT_LAT]),
      (fine[AT_LAT] < 0) ||
          ((fine[AT_LAT] == 0) && pos->u.north && text_negative_zero(pos, 1)));
  set_computed_angle(&pos->lon, round_fine(fine[AT_LON]), fine[AT_LON] < 0);
  pos->lon_calc = pos->lon.nas;
  pos->conv = round_fine(fine[AT_CONV]);
  pos->k = round_fine(fine[AT_SCALE]);
  if ((fine[AT_LAT] != 0) && (pos->u.north != (fine[AT_LAT] > 0))) {
    if (pos->u.zone == DRDC_GEO_ZONE_UPS) {
      return fail(pos, "UPS coordinates in the wrong hemisphere");
    }
    pos->u.northing += pos->u.north ? SOUTH_SHIFT : -SOUTH_SHIFT;
    pos->text_add += pos->u.north ? SOUTH_METRES : -SOUTH_METRES;
    pos->u.north = !pos->u.north;
  }
  return true;
}

static bool read_geographic(char *a, char *b, const struct options *o,
                            struct position *pos)
{
  geo_text_angle_t x;
  geo_text_angle_t y;
  enum geo_text_hemisphere hx;
  enum geo_text_hemisphere hy;
  drdc_status_t st;

  if (!geo_text_read_angle(a, &x, pos->why, sizeof pos->why) ||
      !geo_text_read_angle(b, &y, pos->why, sizeof pos->why)) {
    return false;
  }
  hx = x.hemisphere;
  hy = y.hemisphere;
  if ((hx == GEO_TEXT_NONE) && (hy == GEO_TEXT_NONE)) {
    hx = o->lon_first ? GEO_TEXT_LONGITUDE : GEO_TEXT_LATITUDE;
    hy = o->lon_first ? GEO_TEXT_LATITUDE : GEO_TEXT_LONGITUDE;
  } else if (hx == GEO_TEXT_NONE) {
    hx = (hy == GEO_TEXT_LATITUDE) ? GEO_TEXT_LONGITUDE : GEO_TEXT_LATITUDE;
  } else if (hy == GEO_TEXT_NONE) {
    hy = (hx == GEO_TEXT_LATITUDE) ? GEO_TEXT_LONGITUDE : GEO_TEXT_LATITUDE;
  }
  if (hx == hy) {
    return fail(pos, "Both %s and %s interpreted as %s", a, b,
                (hx == GEO_TEXT_LATITUDE) ? "latitudes" : "longitudes");
  }
  pos->lat = (hx == GEO_TEXT_LATITUDE) ? x : y;
  pos->lon = (hx == GEO_TEXT_LATITUDE) ? y : x;
  if (pos->lat.too_large) {
    /* GeoConvert reads any angle; drdc holds up to GEO_TEXT_DEGREES_MAX */
    return fail(pos, "angle beyond %dd in %s", GEO_TEXT_DEGREES_MAX,
                (hx == GEO_TEXT_LATITUDE) ? a : b);
  }
  if ((pos->lat.nas > (90 * NAS_PER_DEG)) ||
      (pos->lat.nas < -(90 * NAS_PER_DEG))) {
    char lat[32];

    geo_text_put_general(lat, sizeof lat, pos->lat.nas, NAS_PER_DEG,
                         pos->lat.negative);
    return fail(pos, "Latitude %sd not in [-90d, 90d]", lat);
  }
  if (pos->lon.too_large) {
    return fail(pos, "angle beyond %dd in %s", GEO_TEXT_DEGREES_MAX,
                (hx == GEO_TEXT_LATITUDE) ? b : a);
  }
  /* GeoConvert takes any longitude; the library [-540, 540) */
  pos->lon_calc = pos->lon.nas;
  if ((pos->lon_calc < -(540 * NAS_PER_DEG)) ||
      (pos->lon_calc >= (540 * NAS_PER_DEG))) {
    pos->lon_calc = reduce_longitude(pos->lon_calc);
  }
  pos->geographic = true;
  st = drdc_geo_to_utm(pos->lat.nas, pos->lon_calc, DRDC_GEO_ZONE_STANDARD,
                       &pos->u, &pos->conv, &pos->k);
  if (st != DRDC_OK) {
    return fail(pos, "%s", drdc_status_name(st));
  }
  if ((pos->lat.nas == 0) && pos->lat.negative &&
      (pos->u.zone != DRDC_GEO_ZONE_UPS)) {
    /* GeoConvert's hemisphere is the sign bit: -0 is south */
    pos->u.north = false;
    pos->u.northing += SOUTH_SHIFT;
  }
  return true;
}

static bool read_utm(char **w, struct position *pos)
{
  char *zone_text;
  char *e;
  char *n;
  bool e_exact = false;
  bool n_exact = false;
  int zone = 0;
  bool north = true;

  if ((*w[0] != '\0') && isalpha((unsigned char)w[0][strlen(w[0]) - 1u])) {
    zone_text = w[0];
    e = w[1];
    n = w[2];
  } else if ((*w[2] != '\0') &&
             isalpha((unsigned char)w[2][strlen(w[2]) - 1u])) {
    zone_text = w[2];
    e = w[0];
    n = w[1];
  } else {
    return fail(pos,
                "Neither %s nor %s of the form UTM/UPS Zone + Hemisphere "
                "(ex: 38n, 09s, n)",
                w[0], w[2]);
  }
  if (!geo_grid_read_zone(zone_text, &zone, &north, pos->why,
                          sizeof pos->why)) {
    return false;
  }
  pos->u.zone = zone;
  pos->u.north = north;
  if (!geo_grid_read_metres(e, &pos->u.easting, &pos->rest[0], &e_exact,
                            pos->why, sizeof pos->why) ||
      !geo_grid_read_metres(n, &pos->u.northing, &pos->rest[1], &n_exact,
                            pos->why, sizeof pos->why)) {
    return false;
  }
  pos->u_input = true;
  pos->text[0] = e;
  pos->text[1] = n;
  return from_grid(pos);
}

/* The exact easting and northing of an MGRS cell finer than 1 m (prec
 * 6..11 digits per coordinate) as decimal text in pos->cell: the whole
 * metres of the 1 m cell that holds it (exact in Q47.16), then its
 * digits below the metre, then a 5 for the centre (half the cell). */
static bool mgrs_cell_text(const char *text, int32_t prec, bool centre,
                           struct position *pos)
{
  char square[DRDC_GEO_MGRS_SIZE];
  const char *digits = text;
  drdc_geo_utm_t metre;
  int axis;

  /* zone digits, then the band, column and row letters */
  while (isdigit((unsigned char)*digits)) {
    digits++;
  }
  digits += 3;
  snprintf(square, sizeof square, "%.*s%.5s%.5s", (int)(digits - text), text,
           digits, digits + prec);
  if (drdc_geo_mgrs_decode(square, &metre, NULL, NULL) != DRDC_OK) {
    return false;
  }
  for (axis = 0; axis < 2; axis++) {
    int64_t whole = ((axis == 0) ? metre.easting : metre.northing) / Q16_PER_M;
    bool exact = false;
    int64_t *q16 = (axis == 0) ? &pos->u.easting : &pos->u.northing;

    snprintf(pos->cell[axis], sizeof pos->cell[axis], "%lld.%.*s%s",
             (long long)whole, (int)(prec - 5), digits + (axis * prec) + 5,
             centre ? "5" : "");
    if (!geo_text_read_metres(pos->cell[axis], q16, &pos->rest[axis], &exact)) {
      return false;
    }
    pos->text[axis] = pos->cell[axis];
  }
  return true;
}

static bool read_mgrs(const char *text, const struct options *o,
                      struct position *pos)
{
  drdc_geo_utm_t corner;
  drdc_geo_utm_t centre;
  int32_t prec = 0;
  drdc_status_t st;

  st = drdc_geo_mgrs_decode(text, &corner, &centre, &prec);
  if (st != DRDC_OK) {
    return geo_mgrs_error(text, st, pos->why, sizeof pos->why);
  }
  pos->u = o->corner ? corner : centre;
  pos->u_input = true;
  /* corners are multiples of 10^(5 - prec) m, centres half a cell more:
   * exact in Q47.16 down to 1 m cells (0.5 m); finer ones are carried
   * as their decimal text */
  if ((prec > 5) && !mgrs_cell_text(text, prec, !o->corner, pos)) {
    return fail(pos, "MGRS %s: %s", text, drdc_status_name(DRDC_E_MGRS));
  }
  return from_grid(pos);
}

/* The output zone: GeoConvert's SetAltZone and, for -u with a
 * hemisphere, its Transfer. */
static bool output_zone(const struct options *o, struct position *pos)
{
  int zone;
  drdc_status_t st;

  if (o->zone != ZONE_MATCH) {
    if (o->zone >= DRDC_GEO_ZONE_UPS) {
      zone = o->zone;
    } else if (o->zone == ZONE_UTM) {
      zone = utm_only_zone(pos->lat.nas, pos->lon_calc);
    } else {
      int32_t z = 0;

      st = drdc_geo_utm_zone(pos->lat.nas, pos->lon_calc, &z);
      if (st != DRDC_OK) {
        return fail(pos, "%s", drdc_status_name(st));
      }
      zone = (int)z;
    }
    if (zone != pos->u.zone) {
      /* GeoConvert computes the new zone's coordinates in the hemisphere
       * of the latitude's sign bit and labels them with the input's */
      bool label = pos->u.north;

      st = drdc_geo_to_utm(pos->lat.nas, pos->lon_calc, zone, &pos->u,
                           &pos->conv, &pos->k);
      if (st == DRDC_E_RANGE) {
        return zone_range_error(pos, zone);
      }
      if (st != DRDC_OK) {
        return fail(pos, "%s", drdc_status_name(st));
      }
      if ((pos->lat.nas == 0) && pos->lat.negative &&
          (pos->u.zone != DRDC_GEO_ZONE_UPS)) {
        pos->u.northing += SOUTH_SHIFT;
      }
      pos->u.north = label;
      pos->u_input = false;
      pos->text[0] = NULL;
      pos->text[1] = NULL;
      pos->rest[0] = 0;
      pos->rest[1] = 0;
      pos->rezoned = true;
    }
  }
  if ((o->mode == MODE_UTM) && o->set_hemisphere &&
      (o->north != pos->u.north)) {
    if (pos->u.zone == DRDC_GEO_ZONE_UPS) {
      return fail(pos,
                  "Attempt to transfer UPS coordinates between hemispheres");
    }
    pos->u.northing += o->north ? -SOUTH_SHIFT : SOUTH_SHIFT;
    pos->text_add += o->north ? -SOUTH_METRES : SOUTH_METRES;
    pos->u.north = o->north;
  }
  return true;
}

/* A UTM coordinate as GeoConvert's UTMUPSString: PREC decimals, or for a
 * negative PREC the value in units of 10^-PREC m with -PREC zeros
 * appended when it is above half a unit. */
static void put_metres(char *out, size_t size, int64_t v, int prec)
{
  if (prec >= 0) {
    geo_text_put_fixed(out, size, v, Q16_PER_M, prec, false);
  } else {
    int64_t unit = Q16_PER_M;
    int64_t mag = (v < 0) ? -v : v;
    size_t n;
    int i;

    for (i = 0; i < -prec; i++) {
      unit *= 10;
    }
    geo_text_put_fixed(out, size, v, unit, 0, false);
    if ((2 * mag) > unit) {
      n = strlen(out);
      for (i = 0; (i < -prec) && ((n + 1u) < size); i++) {
        out[n++] = '0';
      }
      out[n] = '\0';
    }
  }
}

/* Coordinate `axis` (0 easting, 1 northing) of u as put_metres() writes
 * it; while u is the input, from its exact decimal text. */
static void put_grid_metres(char *out, size_t size, const struct position *pos,
                            int axis, int prec)
{
  int64_t v = 0;
  bool negative = false;
  const char *text = pos->text[axis];

  if ((text == NULL) ||
      !geo_text_metres_scaled(text, (axis == 1) ? pos->text_add : 0, prec,
                              false, &v, &negative)) {
    put_metres(out, size, (axis == 0) ? pos->u.easting : pos->u.northing, prec);
  } else if (prec >= 0) {
    geo_text_put_fixed(out, size, v, pow10_i64(prec), prec, negative);
  } else {
    size_t n;
    int i;

    geo_text_put_fixed(out, size, v, 1, 0, negative);
    if (v != 0) {
      n = strlen(out);
      for (i = 0; (i < -prec) && ((n + 1u) < size); i++) {
        out[n++] = '0';
      }
      out[n] = '\0';
    }
  }
}

static void put_degrees(char *out, size_t size, const geo_text_angle_t *a,
                        int decimals)
{
  geo_text_put_fixed(out, size, a->nas, NAS_PER_DEG,
                     a->exact ? decimals : imin(decimals, DEGREE_DECIMALS_MAX),
                     a->negative);
}

static void put_dms(char *out, size_t size, const geo_text_angle_t *a, int prec,
                    enum geo_text_hemisphere which, char sep)
{
  /* prec - 4 decimals of a second at most SECOND_DECIMALS_MAX */
  int most = 4 + SECOND_DECIMALS_MAX;

  geo_text_put_dms(out, size, a->nas, a->negative,
                   a->exact ? prec : imin(prec, most), which, sep);
}

/* The upper end of MGRS's range of coordinate `axis` (0 easting, 1
 * northing) of u, metres: 900 km for UTM eastings, 9 500 km and 10 000 km
 * for UTM northings (north, south), 2 700 km and 3 200 km for UPS. */
static int64_t mgrs_upper(const drdc_geo_utm_t *u, int axis)
{
  if (u->zone == DRDC_GEO_ZONE_UPS) {
    return u->north ? INT64_C(2700000) : INT64_C(3200000);
  }
  if (axis == 0) {
    return INT64_C(900000);
  }
  return u->north ? INT64_C(9500000) : SOUTH_METRES;
}

/* MGRS of the input's own exact position (pos->text), prec digits per
 * coordinate, truncated from its decimal digits: the library writes the
 * letters and the digits down to 1 m from *grid, the Q47.16 point
 * nearest the input within the same whole metres (so the band comes
 * from a latitude within 1 nas of the input's, and a refused point is
 * quoted in the input's whole kilometres), and the digits below the
 * metre come from the text. A coordinate exactly at the range's upper
 * end, which MGRS excludes, is taken a little below it, all nines, as
 * GeoConvert moves it down by 1.9e-9 m. */
static drdc_status_t mgrs_from_text(const struct position *pos, int32_t prec,
                                    drdc_geo_utm_t *grid, char *out,
                                    size_t size)
{
  int64_t *coord[2] = {&grid->easting, &grid->northing};
  int64_t below[2] = {0, 0}; /* digits below the metre */
  int32_t fine = (prec > 5) ? (prec - 5) : 0;
  char text[DRDC_GEO_MGRS_SIZE];
  drdc_status_t st;
  int axis;

  *grid = pos->u;
  for (axis = 0; axis < 2; axis++) {
    int64_t add = (axis == 1) ? pos->text_add : 0;
    int64_t whole = 0;
    int64_t scaled = 0;
    bool negative = false;

    if (!geo_text_metres_scaled(pos->text[axis], add, 0, true, &whole,
                                &negative) ||
        !geo_text_metres_scaled(pos->text[axis], add, fine, true, &scaled,
                                &negative)) {
      return DRDC_E_RANGE;
    }
    below[axis] = scaled - (whole * pow10_i64(fine));
    if ((*coord[axis] == (mgrs_upper(&pos->u, axis) * Q16_PER_M)) &&
        (pos->rest[axis] == 0)) {
      whole--;
      below[axis] = pow10_i64(fine) - 1;
    }
    if (*coord[axis] < (whole * Q16_PER_M)) {
      *coord[axis] = whole * Q16_PER_M;
    } else if (*coord[axis] >= ((whole + 1) * Q16_PER_M)) {
      *coord[axis] = ((whole + 1) * Q16_PER_M) - 1;
    }
  }
  st = drdc_geo_mgrs_from_utm(grid, (prec > 5) ? 5 : prec, text, sizeof text);
  if ((st != DRDC_OK) || (prec <= 5)) {
    if ((st == DRDC_OK) && (snprintf(out, size, "%s", text) >= (int)size)) {
      return DRDC_E_BUFFER;
    }
    return st;
  }
  {
    /* the 5 easting digits end 5 before the 5 northing digits */
    size_t n = strlen(text);

    if (snprintf(out, size, "%.*s%0*lld%s%0*lld", (int)(n - 5u), text,
                 (int)fine, (long long)below[0], text + (n - 5u), (int)fine,
                 (long long)below[1]) >= (int)size) {
      return DRDC_E_BUFFER;
    }
  }
  return DRDC_OK;
}

/* The output line of a converted position; false for an ERROR line
 * (its message in pos->why). */
static bool write_output(const struct options *o, struct position *pos,
                         char *out, size_t size)
{
  char a[64];
  char b[64];
  const geo_text_angle_t *first = o->lon_first ? &pos->lon : &pos->lat;
  const geo_text_angle_t *second = o->lon_first ? &pos->lat : &pos->lon;
  const drdc_geo_utm_t *u = &pos->u;
  int p = o->prec;

  switch (o->mode) {
  case MODE_GEO: {
    int decimals = imax(0, imin(9, p) + 5);

    put_degrees(a, sizeof a, first, decimals);
    put_degrees(b, sizeof b, second, decimals);
    break;
  }
  case MODE_DMS: {
    int prec = imax(0, imin(10, p) + 5);

    put_dms(a, sizeof a, first, prec,
            o->lon_first ? GEO_TEXT_LONGITUDE : GEO_TEXT_LATITUDE, o->sep);
    put_dms(b, sizeof b, second, prec,
            o->lon_first ? GEO_TEXT_LATITUDE : GEO_TEXT_LONGITUDE, o->sep);
    break;
  }
  case MODE_UTM: {
    int prec = imax(-5, imin(9, p));
    char zone[8];
    const char *h = u->north ? (o->long_names ? "north" : "n")
                             : (o->long_names ? "south" : "s");

    if (!pos->u_input) {
      prec = imin(prec, METRE_DECIMALS_MAX);
    }
    if (u->zone == DRDC_GEO_ZONE_UPS) {
      snprintf(zone, sizeof zone, "%s", h);
    } else {
      snprintf(zone, sizeof zone, "%02d%s", (int)u->zone, h);
    }
    put_grid_metres(a, sizeof a, pos, 0, prec);
    put_grid_metres(b, sizeof b, pos, 1, prec);
    snprintf(out, size, "%.8s %.60s %.60s", zone, a, b);
    return true;
  }
  case MODE_MGRS: {
    int32_t prec = imax(-1, imin(6, p) + 5);
    drdc_geo_utm_t refused = *u; /* what a range error quotes */
    drdc_status_t st;

    /* a northern label keeps its northing (grid input rezoned) */
    bool south_of_equator = (pos->lat.nas == 0) && pos->lat.negative &&
                            !u->north && (u->zone != DRDC_GEO_ZONE_UPS);

    if (pos->geographic && !pos->rezoned && !south_of_equator) {
      /* the library's own MGRS of a geographic point: its digits come
       * from 2^-36 m, not from the Q47.16 metres */
      st = drdc_geo_mgrs_encode(pos->lat.nas, pos->lon_calc, prec, out, size);
    } else {
      drdc_geo_utm_t grid = *u;

      if (!pos->u_input) {
        prec = imin(prec, MGRS_DIGITS_FROM_METRES_MAX);
      }
      if (south_of_equator) {
        /* a latitude of -0 (or negative, under half a nas) is a point
         * just south of the equator, as GeoConvert's sign bit makes it:
         * band M, the northing 10 000 000 m less than the last digit
         * resolves, which truncates to all nines */
        grid.north = false;
        grid.northing = SOUTH_SHIFT - 1;
      }
      if (pos->text[0] != NULL) {
        st = mgrs_from_text(pos, prec, &grid, out, size);
        refused = grid;
      } else {
        st = drdc_geo_mgrs_from_utm(&grid, prec, out, size);
      }
    }
    if ((st == DRDC_E_EASTING) || (st == DRDC_E_NORTHING)) {
      return geo_grid_mgrs_range_error(&refused, st, pos->why, sizeof pos->why);
    }
    return (st == DRDC_OK) ? true : fail(pos, "%s", drdc_status_name(st));
  }
  default: {
    int prec = imax(-5, imin(8, p));
    int64_t central = INT64_C(500000) * Q16_PER_M;
    bool west =
        (u->zone != DRDC_GEO_ZONE_UPS)
            ? ((u->easting < central) ||
               ((u->easting == central) && (pos->rest[0] < 0)))
            : (pos->geographic ? (pos->lon.nas < 0) : pos->lon.negative);
    geo_text_angle_t conv;

    /* GeoConvert's double convergence is a signed zero on the central
     * meridian and the equator: negative when exactly one of latitude and
     * longitude offset is negative */
    conv.nas = pos->conv;
    conv.negative = (pos->conv < 0) || (pos->lat.negative != west);
    conv.exact = false;
    conv.hemisphere = GEO_TEXT_NONE;
    conv.too_large = false;
    put_degrees(a, sizeof a, &conv, prec + 5);
    geo_text_put_fixed(b, sizeof b, pos->k, Q58_ONE, prec + 7, false);
    break;
  }
  }
  snprintf(out, size, "%.60s %.60s", a, b);
  return true;
}

/* One line -> its output text; returns false for an ERROR line. After
 * the first line that converts, -S and -T hold its zone and hemisphere,
 * as -z would. */
static bool convert_line(char *line, struct options *o, char *out, size_t size)
{
  char *w[4];
  int n = split(line, w, 3);
  struct position pos;
  bool ok;

  memset(&pos, 0, sizeof pos);
  if (n == 1) {
    ok = read_mgrs(w[0], o, &pos);
  } else if (n == 2) {
    ok = read_geographic(w[0], w[1], o, &pos);
  } else if (n == 3) {
    ok = read_utm(w, &pos);
  } else {
    ok = fail(&pos, "Coordinate requires 1, 2, or 3 elements");
  }
  ok = ok && output_zone(o, &pos) && write_output(o, &pos, out, size);
  if (!ok) {
    snprintf(out, size, "ERROR: %s", pos.why);
  } else if (o->sticky) {
    o->sticky = false;
    o->zone = (int)pos.u.zone;
    o->set_hemisphere = true;
    o->north = pos.u.north;
  }
  return ok;
}

/* -p's integer, as GeoConvert reads it. */
static bool read_int(const char *s, int *out)
{
  char *end = NULL;
  long v = strtol(s, &end, 10);
  bool digits = (end != s);

  /* blanks around the number, as GeoConvert's stream reads it */
  while (isspace((unsigned char)*end)) {
    end++;
  }
  if (!digits || (*end != '\0')) {
    return false;
  }
  *out = (v < -100) ? -100 : ((v > 100) ? 100 : (int)v);
  return true;
}

static int parse_options(int argc, char **argv, struct options *o)
{
  int i;

  for (i = 1; i < argc; i++) {
    const char *a = argv[i];
    bool has_value = (i + 1) < argc;

    if ((strcmp(a, "--help") == 0) || (strcmp(a, "-h") == 0)) {
      fputs(usage, stdout);
      return 0;
    } else if (strcmp(a, "--version") == 0) {
      printf("drdc geo: libdrdc-fx version %s\n", DRDC_VERSION_STRING);
      return 0;
    } else if ((strcmp(a, "-S") == 0) || (strcmp(a, "-T") == 0)) {
      o->zone = (a[1] == 'S') ? DRDC_GEO_ZONE_STANDARD : ZONE_UTM;
      o->set_hemisphere = false;
      o->sticky = true;
    } else if ((strcmp(a, "--comment-delimiter") == 0) && has_value) {
      o->comment = argv[++i];
    } else if ((strcmp(a, "--input-file") == 0) && has_value) {
      o->input_file = argv[++i];
    } else if ((strcmp(a, "--input-string") == 0) && has_value) {
      o->input_string = argv[++i];
    } else if ((strcmp(a, "--output-file") == 0) && has_value) {
      o->output_file = argv[++i];
    } else if ((strcmp(a, "--line-separator") == 0) && has_value) {
      i++;
      if (strlen(argv[i]) != 1u) {
        fputs("drdc geo: Line separator must be a single character\n", stderr);
        return 2;
      }
      o->line_separator = argv[i][0];
    } else if (strcmp(a, "-g") == 0) {
      o->mode = MODE_GEO;
    } else if (strcmp(a, "-d") == 0) {
      o->mode = MODE_DMS;
      o->sep = '\0';
    } else if (strcmp(a, "-:") == 0) {
      o->mode = MODE_DMS;
      o->sep = ':';
    } else if (strcmp(a, "-u") == 0) {
      o->mode = MODE_UTM;
    } else if (strcmp(a, "-m") == 0) {
      o->mode = MODE_MGRS;
    } else if (strcmp(a, "-c") == 0) {
      o->mode = MODE_CONV;
    } else if (strcmp(a, "-n") == 0) {
      o->corner = true;
    } else if (strcmp(a, "-w") == 0) {
      o->lon_first = !o->lon_first;
    } else if (strcmp(a, "-l") == 0) {
      o->long_names = true;
    } else if (strcmp(a, "-a") == 0) {
      o->long_names = false;
    } else if (strcmp(a, "-s") == 0) {
      o->zone = DRDC_GEO_ZONE_STANDARD;
      o->set_hemisphere = false;
      o->sticky = false;
    } else if (strcmp(a, "-t") == 0) {
      o->zone = ZONE_UTM;
      o->set_hemisphere = false;
      o->sticky = false;
    } else if ((strcmp(a, "-z") == 0) && has_value) {
      int z = 0;
      bool north = true;
      char why[120];

      i++;
      if (geo_grid_read_zone(argv[i], &z, &north, why, sizeof why)) {
        o->set_hemisphere = true;
        o->north = north;
      } else if (!read_int(argv[i], &z)) {
        fprintf(stderr,
                "drdc geo: Zone %s is not a number or zone+hemisphere\n",
                argv[i]);
        return 2;
      } else if ((z < 0) || (z > 60)) {
        fprintf(stderr, "drdc geo: Zone %s not in [0, 60]\n", argv[i]);
        return 2;
      } else {
        o->set_hemisphere = false;
      }
      o->zone = z;
      o->sticky = false;
    } else if ((strcmp(a, "-p") == 0) && has_value) {
      i++;
      if (!read_int(argv[i], &o->prec)) {
        fprintf(stderr, "drdc geo: Precision %s is not a number\n", argv[i]);
        return 2;
      }
    } else {
      fprintf(stderr, "drdc geo: unknown option '%s'\n%s", a, usage);
      return 2;
    }
  }
  if ((o->input_file != NULL) && (o->input_string != NULL)) {
    fputs("drdc geo: Cannot specify --input-string and --input-file "
          "together\n",
          stderr);
    return 2;
  }
  return -1;
}

/* Convert one input line and write its output line (with the comment
 * GeoConvert moves to its end); false for an ERROR line. */
static bool put_line(char *line, size_t len, int got, struct options *o,
                     FILE *out)
{
  const char *problem = drdc_tool_line_problem(got, line, len);
  char *comment = NULL;
  char text[240];
  bool ok = false;

  if (problem != NULL) {
    snprintf(text, sizeof text, "ERROR: %s", problem);
  } else {
    if ((o->comment != NULL) && (*o->comment != '\0')) {
      char *found = strstr(line, o->comment);

      if (found != NULL) {
        /* the line is converted without it; the delimiter and what
         * follows are written after the output, one blank between */
        size_t n = strlen(found) + 1u;

        comment = malloc(n);
        if (comment == NULL) {
          fputs("drdc geo: out of memory\n", stderr);
          exit(1);
        }
        memcpy(comment, found, n);
        *found = '\0';
      }
    }
    ok = convert_line(line, o, text, sizeof text);
  }
  if (comment != NULL) {
    fprintf(out, "%s %s\n", text, comment);
    free(comment);
  } else {
    fprintf(out, "%s\n", text);
  }
  fflush(out);
  return ok;
}

/* --input-string: GeoConvert's lines are the pieces between line
 * separators; nothing after the last separator is no line. */
static int convert_string(const char *s, struct options *o, FILE *out)
{
  int failed = 0;
  size_t n = strlen(s);
  char *copy = malloc(n + 2u);
  char *p;

  if (copy == NULL) {
    fputs("drdc geo: out of memory\n", stderr);
    return 1;
  }
  /* a line after the last separator, unless it is empty */
  memcpy(copy, s, n + 1u);
  if ((n > 0u) && (copy[n - 1u] != o->line_separator)) {
    copy[n] = o->line_separator;
    copy[n + 1u] = '\0';
  }
  for (p = copy; *p != '\0';) {
    char *end = strchr(p, o->line_separator);

    *end = '\0';
    if (!put_line(p, strlen(p), DRDC_TOOL_LINE_OK, o, out)) {
      failed = 1;
    }
    p = end + 1;
  }
  free(copy);
  return failed;
}

static int convert_stream(FILE *in, struct options *o, FILE *out)
{
  int failed = 0;
  char *line = NULL;
  size_t cap = 0;
  size_t len = 0;
  int got;

  while ((got = drdc_tool_read_line(in, &line, &cap, &len)) !=
         DRDC_TOOL_LINE_EOF) {
    if (got == DRDC_TOOL_LINE_ERROR) {
      fputs("drdc geo: cannot read the input\n", stderr);
      failed = 1;
      break;
    }
    if (!put_line(line, len, got, o, out)) {
      failed = 1;
    }
  }
  free(line);
  return failed;
}

int drdc_cmd_geo(int argc, char **argv)
{
  struct options o;
  int status;
  FILE *in = stdin;
  FILE *out = stdout;

  memset(&o, 0, sizeof o);
  o.mode = MODE_GEO;
  o.zone = ZONE_MATCH;
  o.north = true;
  o.line_separator = ';';
  status = parse_options(argc, argv, &o);
  if (status >= 0) {
    return status;
  }
  if ((o.input_file != NULL) && (strcmp(o.input_file, "-") != 0)) {
    in = fopen(o.input_file, "r");
    if (in == NULL) {
      fprintf(stderr, "drdc geo: Cannot open %s for reading\n", o.input_file);
      return 2;
    }
  }
  if ((o.output_file != NULL) && (strcmp(o.output_file, "-") != 0)) {
    out = fopen(o.output_file, "w");
    if (out == NULL) {
      fprintf(stderr, "drdc geo: Cannot open %s for writing\n", o.output_file);
      if (in != stdin) {
        fclose(in);
      }
      return 2;
    }
  }
  status = (o.input_string != NULL) ? convert_string(o.input_string, &o, out)
                                    : convert_stream(in, &o, out);
  if (in != stdin) {
    fclose(in);
  }
  if ((out != stdout) && (fclose(out) != 0)) {
    fprintf(stderr, "drdc geo: cannot write %s\n", o.output_file);
    status = 1;
  }
  return status;
}
