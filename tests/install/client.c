/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief A host program outside the tree: built by
 * tests/integration/test_install.py from an installed prefix alone (pkg-config
 * drdc-host), it prints the UTM position of each "LAT LON" line (whole
 * nanoarcseconds) in millimetres, for comparison with the drdc tool's output.
 */
#include <inttypes.h>
#include <stdio.h>

#include <drdc/geo.h>

int main(void)
{
  int64_t lat;
  int64_t lon;
  int failed = 0;

  while (scanf("%" SCNd64 " %" SCNd64, &lat, &lon) == 2) {
    drdc_geo_utm_t utm;
    drdc_status_t st =
        drdc_geo_to_utm(lat, lon, DRDC_GEO_ZONE_STANDARD, &utm, NULL, NULL);

    if (drdc_status_is_error(st)) {
      printf("ERROR: %s\n", drdc_status_name(st));
      failed = 1;
      continue;
    }
    /* Q47.16 metres to millimetres, rounded half away from zero */
    printf("%d%c %" PRId64 " %" PRId64 "\n", (int)utm.zone,
           utm.north ? 'n' : 's', (utm.easting * 1000 + (1 << 15)) >> 16,
           (utm.northing * 1000 + (1 << 15)) >> 16);
  }
  return failed;
}
