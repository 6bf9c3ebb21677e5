/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Array loops of the geodesy functions beyond batch.c's: the UTM
 *        zone, the transverse Mercator projection and MGRS text both
 *        ways, one public function call per element.
 *
 * Only python/build_backend.py compiles this file; drdc/_lib.py declares
 * the prototypes. Text travels in fixed-width rows: `width` bytes each,
 * NUL-padded (numpy's "S" arrays). Outputs of an element whose status is
 * an error are 0 (text: all NUL).
 */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <drdc/geo.h>
#include <drdc/geo_mgrs.h>

void drdc_batch_geo_utm_zone(size_t n, const int64_t *lat, const int64_t *lon,
                             int32_t *zone, int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    int32_t z = 0;

    status[i] = (int32_t)drdc_geo_utm_zone(lat[i], lon[i], &z);
    zone[i] = z;
  }
}

void drdc_batch_geo_tm_forward(size_t n, const int64_t *lat,
                               const int64_t *dlon, int64_t *x, int64_t *y,
                               int64_t *convergence, int64_t *scale,
                               int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    drdc_q47_16_t xi = 0;
    drdc_q47_16_t yi = 0;
    drdc_nas_t c = 0;
    drdc_q5_58_t k = 0;

    status[i] = (int32_t)drdc_geo_tm_forward(lat[i], dlon[i], &xi, &yi, &c, &k);
    x[i] = xi;
    y[i] = yi;
    convergence[i] = c;
    scale[i] = k;
  }
}

/* `text` is DRDC_GEO_MGRS_SIZE bytes a row: the library's text and its
 * NUL, zero-padded; all zero where the status is an error. */
static void put_text(char *row, drdc_status_t st, const char *text)
{
  if (drdc_status_is_error(st)) {
    memset(row, 0, DRDC_GEO_MGRS_SIZE);
  } else {
    strncpy(row, text, DRDC_GEO_MGRS_SIZE);
  }
}

void drdc_batch_geo_mgrs_encode(size_t n, const int64_t *lat,
                                const int64_t *lon, const int32_t *prec,
                                char *text, int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    char buf[DRDC_GEO_MGRS_SIZE] = {0};
    drdc_status_t st =
        drdc_geo_mgrs_encode(lat[i], lon[i], prec[i], buf, sizeof buf);

    status[i] = (int32_t)st;
    put_text(&text[i * DRDC_GEO_MGRS_SIZE], st, buf);
  }
}

void drdc_batch_geo_mgrs_from_utm(size_t n, const int32_t *zone,
                                  const int32_t *north, const int64_t *easting,
                                  const int64_t *northing, const int32_t *prec,
                                  char *text, int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    char buf[DRDC_GEO_MGRS_SIZE] = {0};
    drdc_geo_utm_t u;
    drdc_status_t st;

    u.zone = zone[i];
    u.north = (north[i] != 0);
    u.easting = easting[i];
    u.northing = northing[i];
    st = drdc_geo_mgrs_from_utm(&u, prec[i], buf, sizeof buf);
    status[i] = (int32_t)st;
    put_text(&text[i * DRDC_GEO_MGRS_SIZE], st, buf);
  }
}

/* MGRS text of `width` bytes a row (NUL-padded) -> the centre of its cell
 * and its precision; `scratch` holds width + 1 bytes, the row with its
 * NUL (the library reads a NUL-terminated string). */
void drdc_batch_geo_mgrs_decode(size_t n, const char *text, size_t width,
                                char *scratch, int32_t *zone, uint8_t *north,
                                int64_t *easting, int64_t *northing,
                                int32_t *prec, int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    drdc_geo_utm_t corner;
    drdc_geo_utm_t centre = {0, false, 0, 0};
    int32_t p = 0;

    memcpy(scratch, &text[i * width], width);
    scratch[width] = '\0';
    status[i] = (int32_t)drdc_geo_mgrs_decode(scratch, &corner, &centre, &p);
    if (drdc_status_is_error((drdc_status_t)status[i])) {
      centre.zone = 0;
      centre.north = false;
      centre.easting = 0;
      centre.northing = 0;
      p = 0;
    }
    zone[i] = centre.zone;
    north[i] = centre.north ? 1u : 0u;
    easting[i] = centre.easting;
    northing[i] = centre.northing;
    prec[i] = p;
  }
}
