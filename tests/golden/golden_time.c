/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Golden inputs and outputs of the time module.
 */
#include <drdc/time.h>

#include "golden.h"

void golden_time(golden_t *g)
{
  int i;

  for (i = 0; i < 4096; i++) {
    /* any 32-bit values: valid dates and every kind of bad one */
    int32_t year = (int32_t)(golden_next(g) % 10002u);
    int32_t month = (int32_t)(golden_next(g) % 14u);
    int32_t day = (int32_t)(golden_next(g) % 33u);
    int32_t days = 0;
    int32_t y = 0;
    int32_t m = 0;
    int32_t d = 0;
    int32_t count;

    golden_i32(g, (int32_t)drdc_time_days_from_civil(year, month, day, &days));
    golden_i32(g, days);
    /* day counts around the whole calendar and beyond both ends */
    count = (int32_t)(golden_next(g) % 8000001u) - 4000000;

    golden_i32(g, (int32_t)drdc_time_civil_from_days(count, &y, &m, &d));
    golden_i32(g, y);
    golden_i32(g, m);
    golden_i32(g, d);
  }
}
