/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Fuzzer of the MGRS decoder: any bytes as NUL-terminated text in a
 *        heap block of exactly that size (ASan reports any read past it).
 *        A rejected string leaves the outputs alone; an accepted one names
 *        a cell whose corner converts back to geographic coordinates and,
 *        for cells of 1 m and larger (exact Q47.16 corners), re-encodes at
 *        the decoded precision to a string that decodes to the same
 *        corner. Host only.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <drdc/geo.h>
#include <drdc/geo_mgrs.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  char *text = malloc(size + 1u);
  drdc_geo_utm_t corner = {77, false, 7, 7};
  drdc_geo_utm_t centre = {77, false, 7, 7};
  drdc_geo_utm_t again = {0, false, 0, 0};
  drdc_nas_t lat = 0;
  drdc_nas_t lon = 0;
  int32_t prec = 99;
  char out[DRDC_GEO_MGRS_SIZE];
  drdc_status_t st;

  if (text == NULL) {
    return 0;
  }
  memcpy(text, data, size);
  text[size] = '\0';
  st = drdc_geo_mgrs_decode(text, &corner, &centre, &prec);
  if (drdc_status_is_error(st)) {
    if ((corner.zone != 77) || (centre.easting != 7) || (prec != 99)) {
      abort(); /* an error must leave the outputs alone */
    }
  } else {
    if ((prec < -1) || (prec > 11)) {
      abort();
    }
    if (drdc_status_is_error(
            drdc_geo_from_utm(&corner, &lat, &lon, NULL, NULL))) {
      abort(); /* a decoded corner is a valid UTM/UPS point */
    }
    if ((prec >= 0) && (prec <= 5) &&
        ((drdc_geo_mgrs_from_utm(&corner, prec, out, sizeof out) != DRDC_OK) ||
         drdc_status_is_error(drdc_geo_mgrs_decode(out, &again, NULL, NULL)) ||
         (again.zone != corner.zone) || (again.easting != corner.easting) ||
         (again.northing != corner.northing))) {
      abort(); /* the cell re-encodes to itself */
    }
  }
  free(text);
  return 0;
}
