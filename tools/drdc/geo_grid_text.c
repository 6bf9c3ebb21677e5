/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief UTM/UPS text of drdc geo and GeoConvert's range messages.
 */
#include <ctype.h>
#include <stdio.h>
#include <string.h>

#include "geo_grid_text.h"

/* One kilometre in Q47.16 metres. */
#define KM_Q16 (INT64_C(1000) * INT64_C(65536))

bool geo_grid_read_zone(const char *s, int *zone, bool *north, char *why,
                        size_t why_size)
{
  const char *p = s;
  bool sign = false;
  bool negative = false;
  size_t digits = 0;
  long z = 0;
  char lower[8];
  size_t i;

  if (strlen(s) > 7u) {
    snprintf(why, why_size, "More than 7 characters in zone specification %s",
             s);
    return false;
  }
  if ((*p == '+') || (*p == '-')) {
    sign = true;
    negative = (*p == '-');
    p++;
  }
  while (isdigit((unsigned char)p[digits])) {
    z = (z * 10) + (p[digits] - '0');
    digits++;
  }
  if (digits == 0u) {
    p = s; /* no number: the whole text is the hemisphere */
    sign = false;
  } else {
    z = negative ? -z : z;
    if (z == 0) {
      snprintf(why, why_size,
               "Illegal zone 0 in %s, use just the hemisphere for UPS", s);
      return false;
    }
    if ((z < 1) || (z > 60)) {
      snprintf(why, why_size, "Zone %ld not in range [1, 60]", z);
      return false;
    }
    if (sign) {
      snprintf(why, why_size, "Must use unsigned number for zone %ld", z);
      return false;
    }
    if (digits > 2u) {
      snprintf(why, why_size, "More than 2 digits use to specify zone %ld", z);
      return false;
    }
    p += digits;
  }
  for (i = 0; (p[i] != '\0') && (i < (sizeof lower - 1u)); i++) {
    lower[i] = (char)tolower((unsigned char)p[i]);
  }
  lower[i] = '\0';
  if ((strcmp(lower, "n") == 0) || (strcmp(lower, "north") == 0)) {
    *north = true;
  } else if ((strcmp(lower, "s") == 0) || (strcmp(lower, "south") == 0)) {
    *north = false;
  } else {
    /* GeoConvert quotes the hemisphere lower-cased */
    snprintf(why, why_size,
             "Illegal hemisphere %s in %s, specify north or south", lower, s);
    return false;
  }
  *zone = (int)z;
  return true;
}

bool geo_grid_read_metres(const char *text, int64_t *q16, int64_t *rest,
                          bool *exact, char *why, size_t why_size)
{
  const char *p = text;
  size_t digits = 0;

  /* the number GeoConvert's stream reads: [+-]digits[.digits], then an
   * exponent only with its digits */
  if ((*p == '+') || (*p == '-')) {
    p++;
  }
  for (; isdigit((unsigned char)*p); p++) {
    digits++;
  }
  if (*p == '.') {
    for (p++; isdigit((unsigned char)*p); p++) {
      digits++;
    }
  }
  if (digits == 0u) {
    snprintf(why, why_size, "Cannot decode %s", text);
    return false;
  }
  if ((*p == 'e') || (*p == 'E')) {
    const char *q = p + 1;

    if ((*q == '+') || (*q == '-')) {
      q++;
    }
    if (!isdigit((unsigned char)*q)) {
      snprintf(why, why_size, "Cannot decode %s", text);
      return false;
    }
    for (p = q; isdigit((unsigned char)*p); p++) {
    }
  }
  if (*p != '\0') {
    snprintf(why, why_size, "Extra text %s at end of %s", p, text);
    return false;
  }
  if (!geo_text_read_metres(text, q16, rest, exact)) {
    snprintf(why, why_size, "Cannot decode %s (beyond 1e12 m)", text);
    return false;
  }
  return true;
}

bool geo_grid_range_error(const drdc_geo_utm_t *u, drdc_status_t st, char *why,
                          size_t why_size)
{
  return geo_grid_range_error_at(
      u, st, (st == DRDC_E_EASTING) ? u->easting : u->northing, KM_Q16, false,
      why, why_size);
}

bool geo_grid_range_error_at(const drdc_geo_utm_t *u, drdc_status_t st,
                             int64_t value, int64_t unit, bool negative,
                             char *why, size_t why_size)
{
  bool ups = (u->zone == DRDC_GEO_ZONE_UPS);
  bool easting = (st == DRDC_E_EASTING);
  /* [min, max] km: UTM easting, northing north, northing south; UPS
   * south, north (easting and northing alike) */
  static const int utm_km[3][2] = {{0, 1000}, {-9100, 9600}, {900, 19600}};
  static const int ups_km[2][2] = {{700, 3300}, {1200, 2800}};
  const int *range =
      ups ? ups_km[u->north ? 1 : 0] : utm_km[easting ? 0 : (u->north ? 1 : 2)];
  char km[32];

  geo_text_put_general(km, sizeof km, value, unit, negative);
  snprintf(why, why_size,
           "%s %skm not in %s range for %c hemisphere [%dkm, %dkm]",
           easting ? "Easting" : "Northing", km, ups ? "UPS" : "UTM",
           u->north ? 'N' : 'S', range[0], range[1]);
  return false;
}

bool geo_grid_mgrs_range_error(const drdc_geo_utm_t *u, drdc_status_t st,
                               char *why, size_t why_size)
{
  bool ups = (u->zone == DRDC_GEO_ZONE_UPS);
  bool easting = (st == DRDC_E_EASTING);
  static const int utm_km[3][2] = {{100, 900}, {-9000, 9500}, {1000, 19500}};
  static const int ups_km[2][2] = {{800, 3200}, {1300, 2700}};
  const int *range =
      ups ? ups_km[u->north ? 1 : 0] : utm_km[easting ? 0 : (u->north ? 1 : 2)];
  int64_t v = easting ? u->easting : u->northing;
  /* rounded down */
  int64_t km = (v / KM_Q16) - (((v % KM_Q16) < 0) ? 1 : 0);

  snprintf(why, why_size,
           "%s %lldkm not in MGRS/%s range for %c hemisphere "
           "[%dkm, %dkm)",
           easting ? "Easting" : "Northing", (long long)km, ups ? "UPS" : "UTM",
           u->north ? 'N' : 'S', range[0], range[1]);
  return false;
}

bool geo_grid_zone_error(const geo_text_angle_t *lat_in,
                         const geo_text_angle_t *lon_in, int64_t east, int zone,
                         char *why, size_t why_size)
{
  char lat[32];
  char lon[32];

  geo_text_put_general(lat, sizeof lat, lat_in->nas, GEO_TEXT_NAS_PER_DEGREE,
                       lat_in->negative);
  geo_text_put_general(lon, sizeof lon, lon_in->nas, GEO_TEXT_NAS_PER_DEGREE,
                       lon_in->negative);
  if (zone != DRDC_GEO_ZONE_UPS) {
    /* GeoConvert first tests the longitude east of the central meridian */
    if (east > (60 * GEO_TEXT_NAS_PER_DEGREE)) {
      snprintf(why, why_size,
               "Longitude %sd more than 60d from center of UTM zone %d", lon,
               zone);
      return false;
    }
    snprintf(why, why_size,
             "Latitude %s, longitude %s out of legal range for UTM zone %d",
             lat, lon, zone);
    return false;
  }
  if ((lat_in->nas < (70 * GEO_TEXT_NAS_PER_DEGREE)) &&
      (lat_in->nas > -(70 * GEO_TEXT_NAS_PER_DEGREE))) {
    snprintf(why, why_size, "Latitude %sd more than 20d from %c pole", lat,
             lat_in->negative ? 'S' : 'N');
    return false;
  }
  snprintf(why, why_size,
           "Latitude %s, longitude %s out of legal range for UPS", lat, lon);
  return false;
}
