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

/* 1 makes a deliberately broken port for the conformance engine's own
 * test (python/tests/test_conformance.py): every UTM easting that
 * drdc_geo_to_utm computes comes out one LSB east. Only the host
 * variant's test-runner-broken sets it. */
#ifndef GOLDEN_BREAK_TO_UTM
#define GOLDEN_BREAK_TO_UTM 0
#endif

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

    drdc_status_t status;
    int32_t prec;

    golden_fn(g, "drdc_geo_to_utm");
    golden_in(g, "lat_nas", lat);
    golden_in(g, "lon_nas", lon);
    status = drdc_geo_to_utm(lat, lon, DRDC_GEO_ZONE_STANDARD, &utm,
                             &convergence, &scale);
#if GOLDEN_BREAK_TO_UTM
    if (status == DRDC_OK) {
      utm.easting += 1;
    }
#endif
    golden_i32(g, (int32_t)status);
    golden_i32(g, utm.zone);
    golden_i32(g, utm.north ? 1 : 0);
    golden_i64(g, utm.easting);
    golden_i64(g, utm.northing);
    golden_i64(g, convergence);
    golden_i64(g, scale);
    golden_fn(g, "drdc_geo_from_utm");
    golden_in(g, "zone", utm.zone);
    golden_in(g, "north", utm.north ? 1 : 0);
    golden_in(g, "easting_q47_16", utm.easting);
    golden_in(g, "northing_q47_16", utm.northing);
    golden_i32(
        g, (int32_t)drdc_geo_from_utm(&utm, &back_lat, &back_lon, NULL, NULL));
    golden_i64(g, back_lat);
    golden_i64(g, back_lon);
    for (k = 0u; k < sizeof text; k++) {
      text[k] = '\0';
    }
    prec = (int32_t)(golden_next(g) % 13u) - 1;
    golden_fn(g, "drdc_geo_mgrs_encode");
    golden_in(g, "lat_nas", lat);
    golden_in(g, "lon_nas", lon);
    golden_in(g, "prec", prec);
    golden_i32(
        g, (int32_t)drdc_geo_mgrs_encode(lat, lon, prec, text, sizeof text));
    for (k = 0u; k < sizeof text; k++) {
      golden_u32(g, (uint32_t)(unsigned char)text[k]);
    }
    p.lat = lat;
    p.lon = lon;
    p.height = (int64_t)(int32_t)golden_next(g) * 256;
    golden_fn(g, "drdc_geo_to_ecef");
    golden_in(g, "lat_nas", p.lat);
    golden_in(g, "lon_nas", p.lon);
    golden_in(g, "height_q47_16", p.height);
    golden_i32(g, (int32_t)drdc_geo_to_ecef(&p, &ecef));
    golden_i64(g, ecef.x);
    golden_i64(g, ecef.y);
    golden_i64(g, ecef.z);
  }
}
