/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time_jaus
 * @brief JAUS 32-bit time stamp <-> UTC.
 */
#include <drdc/time_jaus.h>

#include "time_impl.h"

#define MSEC_SHIFT   0
#define SECOND_SHIFT 10
#define MINUTE_SHIFT 16
#define HOUR_SHIFT   22
#define DAY_SHIFT    27
#define MSEC_MASK    UINT32_C(0x3FF)
#define SECOND_MASK  UINT32_C(0x3F)
#define MINUTE_MASK  UINT32_C(0x3F)
#define HOUR_MASK    UINT32_C(0x1F)
#define DAY_MASK     UINT32_C(0x1F)
#define NS_PER_MS    1000000

drdc_status_t drdc_time_jaus_pack(const drdc_time_leap_t *leap,
                                  const drdc_time_t *utc, uint32_t *stamp)
{
  drdc_time_civil_t c;
  int32_t msec;
  drdc_status_t st;

  if (stamp == NULL) {
    return DRDC_E_NULL;
  }
  st = drdc_time_to_civil(leap, utc, &c);
  if (st != DRDC_OK) {
    return st;
  }
  /* Every field is within its mask after the civil conversion. */
  msec = c.nsec / NS_PER_MS;
  *stamp = ((uint32_t)c.day << DAY_SHIFT) | ((uint32_t)c.hour << HOUR_SHIFT) |
           ((uint32_t)c.minute << MINUTE_SHIFT) |
           ((uint32_t)c.second << SECOND_SHIFT) |
           ((uint32_t)msec << MSEC_SHIFT);
  return DRDC_OK;
}

drdc_status_t drdc_time_jaus_unpack(uint32_t stamp,
                                    drdc_time_jaus_fields_t *fields)
{
  drdc_time_jaus_fields_t f;

  if (fields == NULL) {
    return DRDC_E_NULL;
  }
  f.day = (stamp >> DAY_SHIFT) & DAY_MASK;
  f.hour = (stamp >> HOUR_SHIFT) & HOUR_MASK;
  f.minute = (stamp >> MINUTE_SHIFT) & MINUTE_MASK;
  f.second = (stamp >> SECOND_SHIFT) & SECOND_MASK;
  f.msec = (stamp >> MSEC_SHIFT) & MSEC_MASK;
  if (f.day == 0u) {
    return DRDC_E_DAY;
  }
  if (f.hour > 23u) {
    return DRDC_E_HOUR;
  }
  if (f.minute > 59u) {
    return DRDC_E_MINUTE;
  }
  if (f.second > 60u) {
    return DRDC_E_SECOND;
  }
  if (f.msec > 999u) {
    return DRDC_E_NANOSECOND;
  }
  *fields = f;
  return DRDC_OK;
}

drdc_status_t drdc_time_jaus_to_utc(const drdc_time_leap_t *leap,
                                    uint32_t stamp, const drdc_time_t *ref,
                                    drdc_time_t *utc)
{
  /* The candidate date `c` (the reference's month stepped from the one
   * before to the one after, the stamp's day and time of day); the best
   * candidate is kept as a time and its distance recomputed. */
  drdc_time_civil_t c;
  int32_t ref_day;
  drdc_time_t t;
  drdc_time_t best;
  int found = 0;
  drdc_status_t st;
  drdc_status_t why = DRDC_E_RANGE;
  unsigned k;

  if ((ref == NULL) || (utc == NULL)) {
    return DRDC_E_NULL;
  }
  /* The stamp's fields must be valid; the candidate takes them from the
   * stamp's bits below. */
  {
    drdc_time_jaus_fields_t f;

    st = drdc_time_jaus_unpack(stamp, &f);
    if (st != DRDC_OK) {
      return st;
    }
  }
  /* the reference's year and month: drdc_time_to_civil() without the
   * fields not needed (the same check, the day of its UTC second) */
  if (drdc_time_check(leap, ref) != DRDC_OK) {
    return DRDC_E_RANGE;
  }
  (void)drdc_time_civil_from_days(
      (int32_t)drdc_time_floor_div(ref->sec, SECONDS_PER_DAY), &c.year,
      &c.month, &ref_day);
  c.day = (int32_t)((stamp >> DAY_SHIFT) & DAY_MASK);
  c.hour = (int32_t)((stamp >> HOUR_SHIFT) & HOUR_MASK);
  c.minute = (int32_t)((stamp >> MINUTE_SHIFT) & MINUTE_MASK);
  c.second = (int32_t)((stamp >> SECOND_SHIFT) & SECOND_MASK);
  c.nsec = (int32_t)((stamp >> MSEC_SHIFT) & MSEC_MASK) * NS_PER_MS;
  best.sec = 0;
  best.nsec = 0;
  /* The month before, of and after the reference, earliest first so the
   * earlier candidate wins a tie. */
  c.month--;
  if (c.month < 1) {
    c.month = 12;
    c.year--;
  }
  for (k = 0u; k < 3u; k++) {
    st = drdc_time_from_civil(leap, &c, &t);
    if (st == DRDC_OK) {
      /* Both instants are within the calendar: no overflow. */
      int64_t dist = t.sec - ref->sec;
      int64_t best_dist = best.sec - ref->sec;

      if (dist < 0) {
        dist = -dist;
      }
      if (best_dist < 0) {
        best_dist = -best_dist;
      }
      if ((found == 0) || (dist < best_dist)) {
        best = t;
        found = 1;
      }
    } else if (st == DRDC_E_SECOND) {
      why = st; /* remember: 23:59:60 on a day without a leap second */
    } else {
      /* not a date (day 31 of a short month, ...): no candidate */
    }
    c.month++;
    if (c.month > 12) {
      c.month = 1;
      c.year++;
    }
  }
  if (found == 0) {
    return why;
  }
  {
    int64_t best_dist = best.sec - ref->sec;

    if ((best_dist > DRDC_TIME_JAUS_WINDOW_SECONDS) ||
        (best_dist < -DRDC_TIME_JAUS_WINDOW_SECONDS)) {
      return DRDC_E_RANGE;
    }
  }
  *utc = best;
  return DRDC_OK;
}
