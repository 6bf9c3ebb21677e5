/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time_scales
 * @brief UTC <-> TAI seconds since 1958-01-01, through the leap state.
 */
#include <drdc/time_scales.h>

#include "time_impl.h"

/* No offset in a state can exceed this (19 + 127 from GPS, 37 built in):
 * a bound that rules out overflow before the segment search. */
#define TAI_UTC_BOUND 1000

drdc_status_t drdc_time_utc_to_tai(const drdc_time_leap_t *leap,
                                   const drdc_time_t *utc,
                                   drdc_time_count_t *tai)
{
  int32_t off;
  drdc_time_count_t r;
  drdc_status_t st;

  if (tai == NULL) {
    return DRDC_E_NULL;
  }
  st = drdc_time_leap_offset(leap, utc, &off);
  if (drdc_status_is_error(st)) {
    return st;
  }
  /* Valid UTC: |sec| < 2.6e11, far from int64 limits. */
  r.sec = utc->sec + off + DRDC_TIME_TAI_EPOCH_TO_UNIX;
  r.nsec = utc->nsec;
  if (r.nsec >= DRDC_NS_PER_SECOND) { /* 23:59:60: one second further */
    r.sec += 1;
    r.nsec -= DRDC_NS_PER_SECOND;
  }
  *tai = r;
  return st;
}

drdc_status_t drdc_time_tai_to_utc(const drdc_time_leap_t *leap,
                                   const drdc_time_count_t *tai,
                                   drdc_time_t *utc)
{
  const drdc_time_leap_t *l = drdc_time_leap_or_builtin(leap);
  drdc_time_leap_entry_t e;
  drdc_time_t r;
  int64_t t;
  int64_t u;
  int32_t i;
  int32_t day;

  if ((tai == NULL) || (utc == NULL)) {
    return DRDC_E_NULL;
  }
  if ((tai->nsec < 0) || (tai->nsec >= DRDC_NS_PER_SECOND)) {
    return DRDC_E_NANOSECOND;
  }
  if ((tai->sec < (UTC_SEC_MIN + DRDC_TIME_TAI_EPOCH_TO_UNIX)) ||
      (tai->sec >
       (UTC_SEC_END + DRDC_TIME_TAI_EPOCH_TO_UNIX + TAI_UTC_BOUND))) {
    return DRDC_E_RANGE;
  }
  t = tai->sec - DRDC_TIME_TAI_EPOCH_TO_UNIX; /* TAI on the Unix scale */
  /* Segment i runs from UTC midnight of entry i, at TAI t = day * 86400
   * + offset, to the start of entry i + 1. */
  i = drdc_time_leap_count(l) - 1;
  while (i >= 0) {
    e = drdc_time_leap_entry(l, i);
    if ((((int64_t)e.day * SECONDS_PER_DAY) + e.tai_utc) <= t) {
      break;
    }
    i--;
  }
  if (i < 0) {
    return DRDC_E_RANGE; /* before 1972-01-01T00:00:00 UTC */
  }
  u = t - e.tai_utc;
  r.nsec = tai->nsec;
  if ((i + 1) < drdc_time_leap_count(l)) {
    /* The last second of a segment that ends with a positive leap second
     * reaches the next midnight: it is 23:59:60. */
    int64_t next_midnight =
        (int64_t)drdc_time_leap_entry(l, i + 1).day * SECONDS_PER_DAY;

    if (u >= next_midnight) {
      u -= 1;
      r.nsec += DRDC_NS_PER_SECOND;
    }
  }
  if (u >= UTC_SEC_END) {
    return DRDC_E_RANGE;
  }
  r.sec = u;
  day = (int32_t)drdc_time_floor_div(u, SECONDS_PER_DAY);
  *utc = r;
  return (day >= l->expiry_day) ? DRDC_W_LEAP_EXPIRED : DRDC_OK;
}
