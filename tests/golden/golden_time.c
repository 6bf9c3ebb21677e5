/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Golden inputs and outputs of the time module.
 */
#include <drdc/time.h>
#include <drdc/time_iso8601.h>
#include <drdc/time_scales.h>

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

    golden_fn(g, "drdc_time_days_from_civil");
    golden_in(g, "year", year);
    golden_in(g, "month", month);
    golden_in(g, "day", day);
    golden_i32(g, (int32_t)drdc_time_days_from_civil(year, month, day, &days));
    golden_i32(g, days);
    /* day counts around the whole calendar and beyond both ends */
    count = (int32_t)(golden_next(g) % 8000001u) - 4000000;
    golden_fn(g, "drdc_time_civil_from_days");
    golden_in(g, "days", count);
    golden_i32(g, (int32_t)drdc_time_civil_from_days(count, &y, &m, &d));
    golden_i32(g, y);
    golden_i32(g, m);
    golden_i32(g, d);
  }
}

#if GOLDEN_TRACE
static void golden_utc(golden_t *g, const drdc_time_t *utc)
{
  golden_in(g, "sec", utc->sec);
  golden_in(g, "nsec", utc->nsec);
}
#else
#define golden_utc(g, utc) ((void)(g))
#endif

/* Instants from 1970 to 2106 with any nanoseconds, through every time
 * scale and the ISO 8601 text (its characters fold into the digest). */
void golden_time_scales(golden_t *g)
{
  int i;

  for (i = 0; i < 2048; i++) {
    drdc_time_t utc;
    drdc_time_t back = {0, 0};
    drdc_time_count_t count = {0, 0};
    drdc_time_gps_t gps = {0, 0, 0};
    drdc_time_civil_t civil = {0, 0, 0, 0, 0, 0, 0};
    char text[40];
    size_t k;

    utc.sec = (int64_t)golden_next(g);
    utc.nsec = (int32_t)(golden_next(g) % 1000000000u);
    golden_fn(g, "drdc_time_utc_to_tai");
    golden_utc(g, &utc);
    golden_i32(g, (int32_t)drdc_time_utc_to_tai(NULL, &utc, &count));
    golden_i64(g, count.sec);
    golden_i32(g, count.nsec);
    golden_fn(g, "drdc_time_utc_to_gps");
    golden_utc(g, &utc);
    golden_i32(g, (int32_t)drdc_time_utc_to_gps(NULL, &utc, &gps));
    golden_i32(g, gps.week);
    golden_i32(g, gps.tow);
    golden_i32(g, gps.nsec);
    golden_fn(g, "drdc_time_gps_to_utc");
    golden_in(g, "week", gps.week);
    golden_in(g, "tow", gps.tow);
    golden_in(g, "nsec", gps.nsec);
    golden_i32(g, (int32_t)drdc_time_gps_to_utc(NULL, &gps, &back));
    golden_i64(g, back.sec);
    golden_i32(g, back.nsec);
    golden_fn(g, "drdc_time_utc_to_unix");
    golden_utc(g, &utc);
    golden_i32(g, (int32_t)drdc_time_utc_to_unix(NULL, &utc, &count));
    golden_i64(g, count.sec);
    golden_fn(g, "drdc_time_utc_to_rtems");
    golden_utc(g, &utc);
    golden_i32(g, (int32_t)drdc_time_utc_to_rtems(NULL, &utc, &count));
    golden_i64(g, count.sec);
    golden_fn(g, "drdc_time_to_civil");
    golden_utc(g, &utc);
    golden_i32(g, (int32_t)drdc_time_to_civil(NULL, &utc, &civil));
    golden_i32(g, civil.year);
    golden_i32(g, civil.second);
    for (k = 0; k < sizeof text; k++) {
      text[k] = '\0';
    }
    golden_fn(g, "drdc_time_iso8601_format");
    golden_utc(g, &utc);
    golden_i32(
        g, (int32_t)drdc_time_iso8601_format(NULL, &utc, 9, text, sizeof text));
    for (k = 0; k < sizeof text; k++) {
      golden_u32(g, (uint32_t)(unsigned char)text[k]);
    }
  }
}
