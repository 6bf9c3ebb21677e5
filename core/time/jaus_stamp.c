/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time_jaus
 * @brief JAUS 32-bit time stamp <-> UTC.
 */
#include <drdc/time_jaus.h>

#include "time_impl.h"

#define MSEC_SHIFT 0
#define SECOND_SHIFT 10
#define MINUTE_SHIFT 16
#define HOUR_SHIFT 22
#define DAY_SHIFT 27
#define MSEC_MASK UINT32_C(0x3FF)
#define SECOND_MASK UINT32_C(0x3F)
#define MINUTE_MASK UINT32_C(0x3F)
#define HOUR_MASK UINT32_C(0x1F)
#define DAY_MASK UINT32_C(0x1F)
#define NS_PER_MS 1000000

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
  *stamp = ((uint32_t)c.day << DAY_SHIFT) | ((uint32_t)c.hour << HOUR_SHIFT)
           | ((uint32_t)c.minute << MINUTE_SHIFT)
           | ((uint32_t)c.second << SECOND_SHIFT)
           | ((uint32_t)msec << MSEC_SHIFT);
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
  drdc_time_civil_t c;
  int64_t best_sec = 0;
  int32_t best_nsec = 0;
  int64_t best_dist = -1;
  drdc_status_t st;
  drdc_status_t why = DRDC_E_RANGE;
  int32_t ref_year;
  int32_t ref_month;
  int32_t k;

  if ((ref == NULL) || (utc == NULL)) {
    return DRDC_E_NULL;
  }
  /* The stamp's fields live in a block of their own, so that their stack
   * slots can be reused (issue 8: stack depth). */
  {
    drdc_time_jaus_fields_t f;

    st = drdc_time_jaus_unpack(stamp, &f);
    if (st != DRDC_OK) {
      return st;
    }
    c.day = (int32_t)f.day;
    c.hour = (int32_t)f.hour;
    c.minute = (int32_t)f.minute;
    c.second = (int32_t)f.second;
    c.nsec = (int32_t)f.msec * NS_PER_MS;
  }
  /* the reference's year and month: drdc_time_to_civil() without the
   * fields not needed (the same check, the day of its UTC second), one
   * call level less */
  if (drdc_time_check(leap, ref) != DRDC_OK) {
    return DRDC_E_RANGE;
  }
  {
    int32_t ref_day;

    (void)drdc_time_civil_from_days(
        (int32_t)drdc_time_floor_div(ref->sec, SECONDS_PER_DAY), &ref_year,
        &ref_month, &ref_day);
  }
  /* The month before, of and after the reference, earliest first so the
   * earlier candidate wins a tie. */
  for (k = -1; k <= 1; k++) {
    drdc_time_t t;
    int64_t dist;

    c.year = ref_year;
    c.month = ref_month + k;
    if (c.month < 1) {
      c.month = 12;
      c.year--;
    } else if (c.month > 12) {
      c.month = 1;
      c.year++;
    } else {
      /* 1..12 already: the year stays */
    }
    st = drdc_time_from_civil(leap, &c, &t);
    if (st != DRDC_OK) {
      if (st == DRDC_E_SECOND) {
        why = st; /* remember: 23:59:60 on a day without a leap second */
      }
      continue;
    }
    /* Both instants are within the calendar: no overflow. */
    dist = t.sec - ref->sec;
    if (dist < 0) {
      dist = -dist;
    }
    if ((best_dist < 0) || (dist < best_dist)) {
      best_sec = t.sec;
      best_nsec = t.nsec;
      best_dist = dist;
    }
  }
  if ((best_dist < 0) || (best_dist > DRDC_TIME_JAUS_WINDOW_SECONDS)) {
    return (best_dist < 0) ? why : DRDC_E_RANGE;
  }
  utc->sec = best_sec;
  utc->nsec = best_nsec;
  return DRDC_OK;
}
