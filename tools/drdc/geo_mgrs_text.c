/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief GeoConvert's messages for MGRS strings: the library's decoder
 *        says only which kind of error it found; GeoConvert's message
 *        names the part of the string, so the string is read again here
 *        in GeoConvert's order of checks.
 */
#include <ctype.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <drdc/geo_mgrs.h>

#include "geo_mgrs_text.h"

/* Letters GeoConvert accepts at each place, in its messages' order. */
static const char utm_bands[] = "CDEFGHJKLMNPQRSTUVWX";
static const char ups_bands[] = "ABYZ";
static const char utm_rows[] = "ABCDEFGHJKLMNPQRSTUV";
static const char ups_north_rows[] = "ABCDEFGHJKLMNP";
static const char ups_south_rows[] = "ABCDEFGHJKLMNPQRSTUVWXYZ";
/* UTM columns by zone modulo 3: zones 3, 6, ... then 1, 4, ... then 2 */
static const char *const utm_columns[3] = {"STUVWXYZ", "ABCDEFGH", "JKLMNPQR"};
/* UPS columns by band A, B, Y, Z */
static const char *const ups_columns[4] = {"JKLPQRSTUXYZ", "ABCFGHJKLPQR",
                                           "RSTUXYZ", "ABCFGHJ"};
/* Most digits GeoConvert reads: 11 per coordinate. */
#define MGRS_DIGITS_MAX 22

static bool in_set(char c, const char *set)
{
  return (c != '\0') && (strchr(set, toupper((unsigned char)c)) != NULL);
}

/* Whether the library finds the first `letters` characters of text (zone,
 * band, column and row) to be a 100 km square outside its band. */
static bool block_outside_band(const char *text, size_t letters)
{
  char square[8];
  drdc_geo_utm_t corner;
  drdc_geo_utm_t centre;
  int32_t prec;

  snprintf(square, sizeof square, "%.*s", (int)letters, text);
  return drdc_geo_mgrs_decode(square, &corner, &centre, &prec) == DRDC_E_BAND;
}

bool geo_mgrs_error(const char *text, drdc_status_t st, char *why,
                    size_t why_size)
{
  size_t len = strlen(text);
  size_t p = 0;
  uint32_t digits_value = 0;
  int32_t zone;
  const char *rest;
  size_t digits = 0;
  size_t i;
  bool ups;

  /* GeoConvert reads the zone into a 32-bit int, which wraps */
  while (isdigit((unsigned char)text[p])) {
    digits_value = (digits_value * 10u) + (uint32_t)(text[p] - '0');
    p++;
  }
  zone = (digits_value > (uint32_t)INT32_MAX)
             ? (-(int32_t)(UINT32_MAX - digits_value) - 1)
             : (int32_t)digits_value;
  ups = (p == 0u);
  if (!ups && ((zone < 1) || (zone > 60))) {
    snprintf(why, why_size, "Zone %ld not in [1,60]", (long)zone);
    return false;
  }
  if (p > 2u) {
    snprintf(why, why_size, "More than 2 digits at start of MGRS %.*s", (int)p,
             text);
    return false;
  }
  if (len <= p) {
    snprintf(why, why_size, "MGRS string too short %s", text);
    return false;
  }
  if (!in_set(text[p], ups ? ups_bands : utm_bands)) {
    snprintf(why, why_size, "Band letter %c not in %s set %s", text[p],
             ups ? "UPS" : "UTM", ups ? ups_bands : utm_bands);
    return false;
  }
  if (len == (p + 2u)) {
    snprintf(why, why_size, "Missing row letter in %s", text);
    return false;
  }
  if (len > (p + 2u)) {
    char band = (char)toupper((unsigned char)text[p]);
    const char *columns = ups ? ups_columns[strchr(ups_bands, band) - ups_bands]
                              : utm_columns[zone % 3];
    const char *rows = !ups                               ? utm_rows
                       : ((band == 'Y') || (band == 'Z')) ? ups_north_rows
                                                          : ups_south_rows;

    if (!in_set(text[p + 1u], columns)) {
      if (ups) {
        snprintf(why, why_size, "Column letter %c not in UPS band %c set %s",
                 text[p + 1u], text[p], columns);
      } else {
        snprintf(why, why_size, "Column letter %c not in zone %.*s set %s",
                 text[p + 1u], (int)p, text, columns);
      }
      return false;
    }
    if (!in_set(text[p + 2u], rows)) {
      snprintf(why, why_size, "Row letter %c not in %s set %s", text[p + 2u],
               !ups                       ? "UTM"
               : (rows == ups_north_rows) ? "UPS N"
                                          : "UPS S",
               rows);
      return false;
    }
    /* GeoConvert checks the 100 km square before the digits */
    if (block_outside_band(text, p + 3u)) {
      snprintf(why, why_size, "Block %.2s not in zone/band %.*s", text + p + 1u,
               (int)(p + 1u), text);
      return false;
    }
    rest = text + p + 3u;
    for (i = 0; rest[i] != '\0'; i++) {
      if (!isdigit((unsigned char)rest[i])) {
        snprintf(why, why_size, "Encountered a non-digit in %s", rest);
        return false;
      }
      digits++;
    }
    /* GeoConvert names an odd count before too many */
    if ((digits % 2u) != 0u) {
      snprintf(why, why_size, "Not an even number of digits in %s", rest);
      return false;
    }
    if (digits > MGRS_DIGITS_MAX) {
      snprintf(why, why_size, "More than %d digits in %s", MGRS_DIGITS_MAX,
               rest);
      return false;
    }
  }
  /* a string GeoConvert reads that the library refuses */
  snprintf(why, why_size, "MGRS %s: %s", text, drdc_status_name(st));
  return false;
}
