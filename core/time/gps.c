/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time_scales
 * @brief UTC <-> GPS week and time of week (10-bit week resolution in
 *        gps_week.c).
 */
#include <drdc/time_scales.h>

#include "time_impl.h"

/* TAI seconds since 1958 at the GPS epoch 1980-01-06T00:00:00 GPS time,
 * which is TAI - 19 s: (4383 + 3657) days plus 19 s. */
#define GPS_EPOCH_TAI                                                          \
  ((((int64_t)DAYS_1958_TO_1970 + DAYS_1970_TO_GPS) * SECONDS_PER_DAY) +       \
   TAI_MINUS_GPS)

drdc_status_t drdc_time_utc_to_gps(const drdc_time_leap_t *leap,
                                   const drdc_time_t *utc, drdc_time_gps_t *gps)
{
  drdc_time_count_t tai;
  int64_t g;
  int64_t week;
  drdc_status_t st;

  if (gps == NULL) {
    return DRDC_E_NULL;
  }
  st = drdc_time_utc_to_tai(leap, utc, &tai);
  if (drdc_status_is_error(st)) {
    return st;
  }
  g = tai.sec - GPS_EPOCH_TAI;
  if (g < 0) {
    return DRDC_E_RANGE;
  }
  week = g / SECONDS_PER_WEEK;
  if (week > DRDC_TIME_GPS_WEEK_MAX) {
    return DRDC_E_RANGE;
  }
  gps->week = (int32_t)week;
  gps->tow = (int32_t)(g - (week * SECONDS_PER_WEEK));
  gps->nsec = tai.nsec;
  return st;
}

drdc_status_t drdc_time_gps_to_utc(const drdc_time_leap_t *leap,
                                   const drdc_time_gps_t *gps, drdc_time_t *utc)
{
  drdc_time_count_t tai;

  if ((gps == NULL) || (utc == NULL)) {
    return DRDC_E_NULL;
  }
  if ((gps->week < 0) || (gps->week > DRDC_TIME_GPS_WEEK_MAX)) {
    return DRDC_E_WEEK;
  }
  if ((gps->tow < 0) || (gps->tow >= SECONDS_PER_WEEK)) {
    return DRDC_E_TIME_OF_WEEK;
  }
  if ((gps->nsec < 0) || (gps->nsec >= DRDC_NS_PER_SECOND)) {
    return DRDC_E_NANOSECOND;
  }
  tai.sec = GPS_EPOCH_TAI + ((int64_t)gps->week * SECONDS_PER_WEEK) + gps->tow;
  tai.nsec = gps->nsec;
  return drdc_time_tai_to_utc(leap, &tai, utc);
}
