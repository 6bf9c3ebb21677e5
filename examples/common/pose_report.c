/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The example application, the same on every platform: one GNSS
 *        epoch (NMEA GGA and RMC) in; UTC, GPS time, UTM, MGRS and a JAUS
 *        Report Global Pose body out, as text through example_write().
 *
 * It uses only the installed headers and library (pkg-config drdc-<target>)
 * and prints every 64-bit and fixed-point value with drdc_fx_format(), so
 * it needs no printf at all.
 */
#include <drdc/fixed_format.h>
#include <drdc/geo.h>
#include <drdc/geo_mgrs.h>
#include <drdc/jaus_pose.h>
#include <drdc/nmea.h>
#include <drdc/time_iso8601.h>
#include <drdc/time_jaus.h>
#include <drdc/time_scales.h>

#include "example.h"

/* One epoch of an RTK receiver near DRDC Suffield: 50.27 N, 111.17 W. */
static const char gga_text[] =
    "$GNGGA,170000.00,5016.20000,N,11110.20000,W,4,12,0.7,754.3,M,-16.2,M,"
    "1.0,0001*66\r\n";
static const char rmc_text[] =
    "$GNRMC,170000.00,A,5016.20000,N,11110.20000,W,2.57,045.00,221126,,,R*40"
    "\r\n";

static size_t length_of(const char *s)
{
  size_t n = 0u;

  while (s[n] != '\0') {
    n++;
  }
  return n;
}

/* value / 2^frac_bits to `decimals` places, then a separator */
static void write_fixed(int64_t value, uint32_t frac_bits, uint32_t decimals,
                        const char *after)
{
  char text[DRDC_FX_FORMAT_MAX];

  if (drdc_fx_format(value, frac_bits, decimals, text, sizeof text, NULL) ==
      DRDC_OK) {
    example_write(text);
  }
  example_write(after);
}

static void write_hex(const uint8_t *bytes, size_t n)
{
  static const char hex[] = "0123456789abcdef";
  char pair[3] = {'\0', '\0', '\0'};
  size_t i;

  for (i = 0u; i < n; i++) {
    pair[0] = hex[bytes[i] >> 4];
    pair[1] = hex[bytes[i] & 0x0Fu];
    example_write(pair);
  }
}

/* The body of Report Global Pose: position and time stamp. Fields by
 * name: the pose structures put longitude first, the geodesy functions
 * take latitude first (docs/conventions.md, section 9). */
static drdc_status_t pose_body(const drdc_nmea_t *gga, const drdc_time_t *utc,
                               uint8_t *wire, size_t size, size_t *length)
{
  drdc_jaus_global_pose_t body = {
      .presence = DRDC_JAUS_PV_LATITUDE | DRDC_JAUS_PV_LONGITUDE |
                  DRDC_JAUS_PV_ALTITUDE | DRDC_JAUS_PV_TIME_STAMP,
      .pose = {.latitude = gga->latitude,
               .longitude = gga->longitude,
               .height = gga->altitude},
  };
  drdc_status_t st = drdc_time_jaus_pack(NULL, utc, &body.time_stamp);

  if (st == DRDC_OK) {
    st = drdc_jaus_global_pose_pack(&body, DRDC_JAUS_FORM_AS6009, wire, size,
                                    length);
  }
  return st;
}

static int fail(const char *what, drdc_status_t st)
{
  example_write("ERROR ");
  example_write(what);
  example_write(": ");
  example_write(drdc_status_name(st));
  example_write("\n");
  return 1;
}

int example_run(void)
{
  drdc_nmea_t gga;
  drdc_nmea_t rmc;
  drdc_time_t utc;
  drdc_time_gps_t gps;
  drdc_geo_utm_t utm;
  char iso[DRDC_TIME_ISO8601_SIZE];
  char mgrs[DRDC_GEO_MGRS_SIZE];
  uint8_t wire[DRDC_JAUS_POSE_BODY_MAX];
  size_t wire_length = 0u;
  drdc_status_t st;

  st = drdc_nmea_parse(gga_text, length_of(gga_text), &gga);
  if (st != DRDC_OK) {
    return fail("GGA", st);
  }
  st = drdc_nmea_parse(rmc_text, length_of(rmc_text), &rmc);
  if (st != DRDC_OK) {
    return fail("RMC", st);
  }
  /* the date of the RMC, the time of the GGA */
  st = drdc_nmea_utc(NULL, &rmc, &gga, &utc);
  if (st == DRDC_OK) {
    st = drdc_time_iso8601_format(NULL, &utc, 3, iso, sizeof iso);
  }
  if (st == DRDC_OK) {
    st = drdc_time_utc_to_gps(NULL, &utc, &gps);
  }
  if (st != DRDC_OK) {
    return fail("time", st);
  }
  st = drdc_geo_to_utm(gga.latitude, gga.longitude, DRDC_GEO_ZONE_STANDARD,
                       &utm, NULL, NULL);
  if (st == DRDC_OK) {
    st =
        drdc_geo_mgrs_encode(gga.latitude, gga.longitude, 5, mgrs, sizeof mgrs);
  }
  if (st != DRDC_OK) {
    return fail("geodesy", st);
  }
  st = pose_body(&gga, &utc, wire, sizeof wire, &wire_length);
  if (st != DRDC_OK) {
    return fail("JAUS", st);
  }

  example_write("UTC ");
  example_write(iso);
  example_write("\nGPS ");
  write_fixed(gps.week, 0u, 0u, " ");
  write_fixed(gps.tow, 0u, 0u, "\nlatitude nas ");
  write_fixed(gga.latitude, 0u, 0u, " longitude nas ");
  write_fixed(gga.longitude, 0u, 0u, " height m ");
  write_fixed(gga.altitude, 16u, 3u, "\nUTM ");
  write_fixed(utm.zone, 0u, 0u, utm.north ? "n " : "s ");
  write_fixed(utm.easting, 16u, 3u, " ");
  write_fixed(utm.northing, 16u, 3u, "\nMGRS ");
  example_write(mgrs);
  example_write("\nJAUS Report Global Pose body ");
  write_hex(wire, wire_length);
  example_write("\n");
  return 0;
}
