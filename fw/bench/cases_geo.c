/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Benchmark case of core/geo: geographic -> UTM (standard zone,
 *        convergence and scale), against the same algorithm in double
 *        (cases_double.c, "utm_forward").
 */
#include <drdc/geo.h>

#include "bench.h"

/* latitude +-80 and longitude +-180 degrees from the 32-bit input */
static uint32_t utm_case(uint32_t x)
{
  drdc_geo_utm_t u = { 0, false, 0, 0 };
  drdc_nas_t g = 0;
  drdc_q5_58_t k = 0;

  (void)drdc_geo_to_utm(((int64_t)(x & 0xFFFFu) - 32768) * INT64_C(8800000000),
                        ((int64_t)(x >> 16) - 32768) * INT64_C(19700000000),
                        DRDC_GEO_ZONE_STANDARD, &u, &g, &k);
  return (uint32_t)u.easting ^ (uint32_t)u.northing ^ (uint32_t)g;
}

BENCH_LOOP(run_utm_forward, utm_case(x))

const bench_case_t bench_cases_geo[] = {
  { "utm_forward", "drdc", "drdc_geo_to_utm", run_utm_forward },
  { 0, 0, 0, 0 },
};
