/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief MGRS: encode from geographic or UTM/UPS (truncation), decode
 *        (validation, the row placed in its latitude band), over the grid
 *        of utm.c.
 *
 * Letter sets and the row placement follow the MGRS standard as
 * GeographicLib's MGRS class implements it (NGA.SIG.0012): UTM columns
 * A-H, J-R, S-Z by zone modulo 3, rows A-V (I and O skipped) shifted by 5
 * in even zones; UPS columns and rows from their own sets per polar half.
 * Coordinates are whole micrometres, truncated: of the Q28.36 metres of
 * the projection (from geographic) or of the Q47.16 input (from UTM).
 */
#include <drdc/geo_mgrs.h>

#include <stdbool.h>
#include <stddef.h>

#include <drdc/fixed_arith.h>

#include "geo_grid.h"

/** 100 km in micrometres. */
#define TILE_UM INT64_C(100000000000)
/** 100 km in Q47.16 metres. */
#define TILE_Q16 INT64_C(6553600000)
/** Rows of 100 km in the UTM letter cycle. */
#define ROW_PERIOD 20
/** Row shift of the even zones. */
#define EVEN_ROW_SHIFT 5
/** Rows from the equator to the southern false origin (10 000 km). */
#define SOUTH_ROWS 100
/** UPS: the 100 km index of the pole's easting and northing (2 000 km). */
#define UPS_POLE_INDEX 20
/** UPS: first 100 km index of each cap (north 1 300 km, south 800 km). */
#define UPS_NORTH_FIRST INT64_C(13)
#define UPS_SOUTH_FIRST INT64_C(8)

static const char digits[] = "0123456789";
static const char latband[] = "CDEFGHJKLMNPQRSTUVWX";
static const char upsband[] = "ABYZ";
static const char utmrow[] = "ABCDEFGHJKLMNPQRSTUV";
static const char *const utmcols[3] = {"ABCDEFGH", "JKLMNPQR", "STUVWXYZ"};
/* south-west (A), south-east (B), north-west (Y), north-east (Z) */
static const char *const upscols[4] = {"JKLPQRSTUXYZ", "ABCFGHJKLPQR",
                                       "RSTUXYZ", "ABCFGHJ"};
static const char *const upsrows[2] = {"ABCDEFGHJKLMNPQRSTUVWXYZ",
                                       "ABCDEFGHJKLMNP"};

/* index of c in set, letters in either case; -1 when absent */
static int32_t lookup(const char *set, char c)
{
  static const char upper[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZ";
  static const char lower[] = "abcdefghijklmnopqrstuvwxyz";
  char u = c;
  int32_t i;

  for (i = 0; lower[i] != '\0'; i++) {
    if (lower[i] == c) {
      u = upper[i];
    }
  }
  for (i = 0; set[i] != '\0'; i++) {
    if (set[i] == u) {
      return i;
    }
  }
  return -1;
}

static int64_t pow10_i64(int32_t n)
{
  int64_t p = 1;
  int32_t i;

  for (i = 0; i < n; i++) {
    p = p * 10;
  }
  return p;
}

/* whole micrometres of a coordinate v >= 0 with frac_bits fraction
 * bits, truncated: the whole metres times 10^6 plus the fraction's
 * micrometres (the fraction times 10^6 stays below 2^56); -1 when v < 0 */
static int64_t micrometres(int64_t v, unsigned frac_bits)
{
  uint64_t u = (uint64_t)v;
  uint64_t frac = u & ((UINT64_C(1) << frac_bits) - 1u);

  if (v < 0) {
    return -1;
  }
  /* shifts of the non-negative value: no 64-bit division */
  return (int64_t)(((u >> frac_bits) * UINT64_C(1000000)) +
                   ((frac * UINT64_C(1000000)) >> frac_bits));
}

drdc_status_t drdc__geo_mgrs_format(const drdc_geo_utm_t *u, unsigned frac_bits,
                                    drdc_nas_t lat, int32_t prec, char *text,
                                    size_t size)
{
  char *buf = text;
  size_t n = 0u;
  size_t need;
  int64_t x;
  int64_t y;
  int64_t ix;
  int64_t iy;
  int32_t d;
  bool eastp;

  if ((prec < DRDC_GEO_MGRS_PREC_MIN) || (prec > DRDC_GEO_MGRS_PREC_MAX)) {
    return DRDC_E_RANGE;
  }
  /* whole micrometres, truncated (-1 below zero: its tile index is -1) */
  x = micrometres(u->easting, frac_bits);
  y = micrometres(u->northing, frac_bits);
  ix = drdc__geo_floor_div(x, TILE_UM);
  iy = drdc__geo_floor_div(y, TILE_UM);
  eastp = (ix >= UPS_POLE_INDEX);
  /* the MGRS limits: UTM columns 1..8, rows 0..94 (north) or 10..99
   * (south); UPS 13..26 (north) or 8..31 (south) on both axes */
  if (u->zone != DRDC_GEO_ZONE_UPS) {
    if ((ix < 1) || (ix > 8)) {
      return DRDC_E_EASTING;
    }
    if (u->north && ((iy < 0) || (iy > 94))) {
      return DRDC_E_NORTHING;
    }
    if (!u->north && ((iy < 10) || (iy > 99))) {
      return DRDC_E_NORTHING;
    }
  } else {
    int64_t lo = u->north ? UPS_NORTH_FIRST : UPS_SOUTH_FIRST;
    int64_t hi = u->north ? INT64_C(26) : INT64_C(31);

    if ((ix < lo) || (ix > hi)) {
      return DRDC_E_EASTING;
    }
    if ((iy < lo) || (iy > hi)) {
      return DRDC_E_NORTHING;
    }
  }
  /* zone digits and band (UTM) or the UPS letter, two square letters,
   * the digits, the NUL */
  need = ((u->zone != DRDC_GEO_ZONE_UPS) ? 3u : 1u) +
         ((prec >= 0) ? (2u + (2u * (size_t)prec)) : 0u) + 1u;
  if (size < need) {
    return DRDC_E_BUFFER;
  }
  if (u->zone != DRDC_GEO_ZONE_UPS) {
    int64_t band = drdc__geo_floor_div(lat, 8 * GEO_NAS_DEG);

    if (band > 9) {
      band = 9;
    }
    if (band < -10) {
      band = -10;
    }
    buf[n] = digits[u->zone / 10];
    n++;
    buf[n] = digits[u->zone % 10];
    n++;
    buf[n] = latband[band + 10];
    n++;
    if (prec >= 0) {
      buf[n] = utmcols[(u->zone - 1) % 3][ix - 1];
      n++;
      buf[n] = utmrow[(iy + (((u->zone % 2) == 0) ? EVEN_ROW_SHIFT : 0)) %
                      ROW_PERIOD];
      n++;
    }
  } else {
    int32_t half = (u->north ? 2 : 0) + (eastp ? 1 : 0);
    int64_t first = u->north ? UPS_NORTH_FIRST : UPS_SOUTH_FIRST;

    buf[n] = upsband[half];
    n++;
    if (prec >= 0) {
      buf[n] = upscols[half][ix - (eastp ? UPS_POLE_INDEX : first)];
      n++;
      buf[n] = upsrows[u->north ? 1 : 0][iy - first];
      n++;
    }
  }
  /* prec digits of the easting's micrometres within the square, then
   * of the northing's: one loop, one copy of the digit code */
  for (d = 0; d < (2 * prec); d++) {
    int64_t v = (d < prec) ? x : y;
    int32_t place = (d < prec) ? d : (d - prec);

    buf[n] = digits[((v % TILE_UM) / pow10_i64(10 - place)) % 10];
    n++;
  }
  buf[n] = '\0';
  return DRDC_OK;
}

drdc_status_t drdc_geo_mgrs_encode(drdc_nas_t lat, drdc_nas_t lon, int32_t prec,
                                   char *text, size_t size)
{
  geo_grid_fwd_t g;
  drdc_status_t st;

  if (text == NULL) {
    return DRDC_E_NULL;
  }
  st = drdc__geo_grid_forward(lat, lon, DRDC_GEO_ZONE_STANDARD, &g);
  if (st != DRDC_OK) {
    return st;
  }
  /* the metres before their rounding to Q47.16 (2^-36 m), so that the
   * truncation falls on the side of a digit boundary that GeographicLib's
   * value falls on, but within nanometres of it */
  g.utm.easting = g.easting_q36;
  g.utm.northing = g.northing_q36;
  return drdc__geo_mgrs_format(&g.utm, 36u, lat, prec, text, size);
}

drdc_status_t drdc_geo_mgrs_from_utm(const drdc_geo_utm_t *u, int32_t prec,
                                     char *text, size_t size)
{
  geo_grid_rev_t g;
  drdc_status_t st;

  if ((u == NULL) || (text == NULL)) {
    return DRDC_E_NULL;
  }
  /* the position checked, and its latitude for the band letter */
  st = drdc__geo_grid_reverse(u, false, &g);
  if (st != DRDC_OK) {
    return st;
  }
  return drdc__geo_mgrs_format(u, 16u, g.lat, prec, text, size);
}

/* GeographicLib's placement of a UTM row letter (irow 0..19) in latitude
 * band iband (-10..9): the multiple of 20 rows nearest the band's centre,
 * then the band's extent with its overlaps; returns SOUTH_ROWS when the
 * square is not in the band. Rows count 100 km from the equator. */
static int32_t utm_row(int32_t iband, int32_t icol, int32_t irow_letter)
{
  /* int32_t: every value here is within +-8 000; 0.1 north in
   * ninetieths */
  int32_t north9 = (iband >= 0) ? (int32_t)9 : (int32_t)0;
  /* c = 100 (8 iband + 4) / 90 rows; min = floor(c - 4.3 - 0.1 north),
   * max = floor(c + 4.4 - 0.1 north), in ninetieths (never a tie) */
  int32_t low = ((800 * iband) + 13) - north9;
  int32_t high = ((800 * iband) + 796) - north9;
  int32_t minrow = (iband > -10) ? (int32_t)drdc__geo_floor_div(low, 90) : -90;
  int32_t maxrow = (iband < 9) ? (int32_t)drdc__geo_floor_div(high, 90) : 94;
  /* C's division truncates towards zero, as GeographicLib's does */
  int32_t baserow = ((minrow + maxrow) / 2) - (ROW_PERIOD / 2);
  int32_t irow =
      (((irow_letter - baserow) + SOUTH_ROWS) % ROW_PERIOD) + baserow;

  if ((irow < minrow) || (irow > maxrow)) {
    int32_t sband = (iband >= 0) ? iband : (-iband - 1);
    int32_t srow = (irow >= 0) ? irow : (-irow - 1);
    int32_t scol = (icol < 4) ? icol : (-icol + 7);

    /* the squares of 31X-37X and of band X above 80 degrees */
    if (!(((srow == 70) && (sband == 8) && (scol >= 2)) ||
          ((srow == 71) && (sband == 7) && (scol <= 2)) ||
          ((srow == 79) && (sband == 9) && (scol >= 1)) ||
          ((srow == 80) && (sband == 8) && (scol <= 1)))) {
      irow = SOUTH_ROWS;
    }
  }
  return irow;
}

/* metres (Q47.16) of v / 10^prec tiles, rounded */
static int64_t tiles_q16(int64_t v, int64_t den)
{
  int64_t r = 0;

  (void)drdc_fx_muldiv_s64(v, TILE_Q16, den, &r);
  return r;
}

/* A decoded MGRS text: its cell's south-west corner and centre (Q47.16
 * metres) in a zone and hemisphere, and its precision. */
typedef struct mgrs_cell {
  drdc_geo_utm_t corner;
  drdc_geo_utm_t centre;
  int32_t prec;
} mgrs_cell_t;

/* The cell of text into *cell, with drdc_geo_mgrs_decode()'s statuses
 * (*cell undefined on error). */
static drdc_status_t mgrs_decode(const char *text, mgrs_cell_t *cell)
{
  int32_t p = 0;
  int32_t len = 0;
  int32_t zone = 0;
  int32_t iband;
  int32_t ndig;
  int32_t k;
  int32_t icol;
  int32_t irow;
  int64_t x1;
  int64_t y1;
  int64_t unit;
  bool utmp;
  bool north;

  while ((len <= (int32_t)DRDC_GEO_MGRS_SIZE) && (text[len] != '\0')) {
    len++;
  }
  while ((p < len) && (lookup(digits, text[p]) >= 0)) {
    if (zone <= DRDC_GEO_ZONE_MAX) {
      zone = (zone * 10) + lookup(digits, text[p]);
    }
    p++;
  }
  /* GeographicLib checks the zone's value before its digit count */
  if ((p > 0) && ((zone == 0) || (zone > DRDC_GEO_ZONE_MAX))) {
    return DRDC_E_ZONE;
  }
  if (p > 2) {
    return DRDC_E_MGRS;
  }
  if ((len - p) < 1) {
    return DRDC_E_MGRS;
  }
  utmp = (zone != DRDC_GEO_ZONE_UPS);
  iband = lookup(utmp ? latband : upsband, text[p]);
  p++;
  if (iband < 0) {
    return DRDC_E_MGRS;
  }
  north = (iband >= (utmp ? 10 : 2));
  cell->corner.zone = zone;
  cell->corner.north = north;
  if (p == len) {
    /* the grid zone alone: GeographicLib's representative point, corner
     * and centre */
    if (utmp) {
      cell->corner.easting =
          (((zone == 31) && (iband == 17)) ? 4 : 5) * TILE_Q16;
      cell->corner.northing =
          (drdc__geo_floor_div((160 * (int64_t)iband) - 1511, 18) +
           (north ? 0 : SOUTH_ROWS)) *
          TILE_Q16;
    } else {
      cell->corner.easting =
          ((((iband % 2) == 1) ? 4 : -4) + UPS_POLE_INDEX) * TILE_Q16;
      cell->corner.northing = UPS_POLE_INDEX * TILE_Q16;
    }
    cell->centre = cell->corner;
    cell->prec = -1;
    return DRDC_OK;
  }
  if ((len - p) < 2) {
    return DRDC_E_MGRS;
  }
  icol = lookup(utmp ? utmcols[(zone - 1) % 3] : upscols[iband], text[p]);
  irow = lookup(utmp ? utmrow : upsrows[north ? 1 : 0], text[p + 1]);
  p += 2;
  if ((icol < 0) || (irow < 0)) {
    return DRDC_E_MGRS;
  }
  ndig = len - p;
  for (k = 0; k < ndig; k++) {
    if (lookup(digits, text[p + k]) < 0) {
      return DRDC_E_MGRS;
    }
  }
  if (((ndig % 2) != 0) || (ndig > (2 * DRDC_GEO_MGRS_PREC_MAX))) {
    return DRDC_E_MGRS;
  }
  if (utmp) {
    if ((zone % 2) == 0) {
      irow = (irow + ROW_PERIOD - EVEN_ROW_SHIFT) % ROW_PERIOD;
    }
    irow = utm_row(iband - 10, icol, irow);
    if (irow == SOUTH_ROWS) {
      return DRDC_E_BAND;
    }
    irow = north ? irow : (irow + SOUTH_ROWS);
    icol = icol + 1;
  } else {
    bool eastp = ((iband % 2) == 1);
    int32_t first = north ? (int32_t)UPS_NORTH_FIRST : (int32_t)UPS_SOUTH_FIRST;

    icol = icol + (eastp ? UPS_POLE_INDEX : first);
    irow = irow + first;
  }
  ndig = ndig / 2;
  x1 = icol;
  y1 = irow;
  unit = 1;
  for (k = 0; k < ndig; k++) {
    x1 = (x1 * 10) + lookup(digits, text[p + k]);
    y1 = (y1 * 10) + lookup(digits, text[p + ndig + k]);
    unit = unit * 10;
  }
  cell->corner.easting = tiles_q16(x1, unit);
  cell->corner.northing = tiles_q16(y1, unit);
  cell->centre = cell->corner;
  cell->centre.easting = tiles_q16((2 * x1) + 1, 2 * unit);
  cell->centre.northing = tiles_q16((2 * y1) + 1, 2 * unit);
  cell->prec = ndig;
  return DRDC_OK;
}

drdc_status_t drdc__geo_mgrs_centre(const char *text, drdc_geo_utm_t *centre)
{
  mgrs_cell_t cell;
  size_t n = 0u;
  drdc_status_t st;

  /* the decoder must not read beyond the array */
  while ((n < DRDC_GEO_MGRS_SIZE) && (text[n] != '\0')) {
    n++;
  }
  if (n == DRDC_GEO_MGRS_SIZE) {
    return DRDC_E_MGRS;
  }
  st = mgrs_decode(text, &cell);
  if (st == DRDC_OK) {
    *centre = cell.centre;
  }
  return st;
}

drdc_status_t drdc_geo_mgrs_decode(const char *text, drdc_geo_utm_t *corner,
                                   drdc_geo_utm_t *centre, int32_t *prec)
{
  mgrs_cell_t cell;
  drdc_status_t st;

  if ((text == NULL) || (corner == NULL)) {
    return DRDC_E_NULL;
  }
  st = mgrs_decode(text, &cell);
  if (st != DRDC_OK) {
    return st;
  }
  *corner = cell.corner;
  if (centre != NULL) {
    *centre = cell.centre;
  }
  if (prec != NULL) {
    *prec = cell.prec;
  }
  return DRDC_OK;
}
