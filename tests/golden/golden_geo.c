/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Golden inputs and outputs of core/geo: latitudes and longitudes
 *        anywhere (and beyond the valid ranges) through UTM/UPS and back,
 *        MGRS text and ECEF.
 */
#include <stddef.h>

#include <drdc/geo.h>
#include <drdc/geo_ecef.h>
#include <drdc/geo_mgrs.h>

#include "golden.h"

void golden_geo(golden_t *g)
{
  int i;

  for (i = 0; i < 512; i++) {
    /* about +-95 degrees of latitude and +-597 of longitude, in nas */
    drdc_nas_t lat = ((int64_t)(int32_t)golden_next(g)) * 80000;
    drdc_nas_t lon = ((int64_t)(int32_t)golden_next(g)) * 500000;
    drdc_geo_utm_t utm = {0, false, 0, 0};
    drdc_nas_t convergence = 0;
    drdc_q5_58_t scale = 0;
    drdc_nas_t back_lat = 0;
    drdc_nas_t back_lon = 0;
    drdc_geo_point_t p;
    drdc_vec3_q47_16_t ecef = {0, 0, 0};
    char text[DRDC_GEO_MGRS_SIZE];
    size_t k;

    golden_i32(g, (int32_t)drdc_geo_to_utm(lat, lon, DRDC_GEO_ZONE_STANDARD,
                                           &utm, &convergence, &scale));
    golden_i32(g, utm.zone);
    golden_i32(g, utm.north ? 1 : 0);
    golden_i64(g, utm.easting);
    golden_i64(g, utm.northing);
    golden_i64(g, convergence);
    golden_i64(g, scale);
    golden_i32(
        g, (int32_t)drdc_geo_from_utm(&utm, &back_lat, &back_lon, NULL, NULL));
    golden_i64(g, back_lat);
    golden_i64(g, back_lon);
    for (k = 0u; k < sizeof text; k++) {
      text[k] = '\0';
    }
    golden_i32(g, (int32_t)drdc_geo_mgrs_encode(
                      lat, lon, (int32_t)(golden_next(g) % 13u) - 1, text,
                      sizeof text));
    for (k = 0u; k < sizeof text; k++) {
      golden_u32(g, (uint32_t)(unsigned char)text[k]);
    }
    p.lat = lat;
    p.lon = lon;
    p.height = (int64_t)(int32_t)golden_next(g) * 256;
    golden_i32(g, (int32_t)drdc_geo_to_ecef(&p, &ecef));
    golden_i64(g, ecef.x);
    golden_i64(g, ecef.y);
    golden_i64(g, ecef.z);
  }
}
