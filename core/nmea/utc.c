/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief A sentence's time of day on the date of an RMC or ZDA sentence,
 *        across midnight, as a UTC instant.
 */
#include "nmea_impl.h"

#define SECONDS_PER_HALF_DAY 43200u
/* 2^31: the bias that maps int32_t order onto uint32_t order */
#define BIAS 0x80000000u

/* The seconds of the day modulo 2^32: exact for the times
 * drdc_nmea_parse() writes (below 86 401); hand-filled fields of any int32
 * value wrap instead of overflowing (drdc_time_from_civil() then refuses
 * them). */
static uint32_t seconds_of_day(const drdc_nmea_tod_t *t)
{
  return ((((uint32_t)t->hour * 60u) + (uint32_t)t->minute) * 60u) +
         (uint32_t)t->second;
}

/* A time of day in the ranges drdc_time_from_civil() accepts, with its
 * statuses in its order (second 60 is left to it: whether the day has a
 * leap second is its question). */
static drdc_status_t tod_check(const drdc_nmea_tod_t *t)
{
  if ((t->hour < 0) || (t->hour > 23)) {
    return DRDC_E_HOUR;
  }
  if ((t->minute < 0) || (t->minute > 59)) {
    return DRDC_E_MINUTE;
  }
  if ((t->second < 0) || (t->second > 60)) {
    return DRDC_E_SECOND;
  }
  if ((t->nsec < 0) || (t->nsec >= DRDC_NS_PER_SECOND)) {
    return DRDC_E_NANOSECOND;
  }
  return DRDC_OK;
}

drdc_status_t drdc_nmea_utc(const drdc_time_leap_t *leap,
                            const drdc_nmea_t *dated, const drdc_nmea_t *s,
                            drdc_time_t *utc)
{
  int32_t days = 0;
  uint32_t shift;
  drdc_time_civil_t c;
  drdc_status_t st;

  if ((dated == NULL) || (s == NULL) || (utc == NULL)) {
    return DRDC_E_NULL;
  }
  if (((dated->has & DRDC_NMEA_HAS_DATE) == 0u) ||
      ((dated->has & DRDC_NMEA_HAS_TIME) == 0u) ||
      ((s->has & DRDC_NMEA_HAS_TIME) == 0u)) {
    return DRDC_E_MISSING_FIELD;
  }
  st = drdc_time_days_from_civil(dated->year, dated->month, dated->day, &days);
  if (st != DRDC_OK) {
    return st;
  }
  /* dated's time of day only chooses the day of s's: checked here, as
   * drdc_time_from_civil() checks s's below, so that a hand-filled one
   * out of range is refused instead of moving the day */
  st = tod_check(&dated->time);
  if (st != DRDC_OK) {
    return st;
  }
  /* the day of `s`: the one nearest to the dated time of day. shift is
   * the signed difference d of the two times of day plus 2^31, modulo
   * 2^32 (d itself in int32_t could overflow for hand-filled fields):
   * d < -half a day below BIAS - half a day, d > half a day above
   * BIAS + half a day, the same days as the signed comparisons of d */
  shift = (seconds_of_day(&s->time) - seconds_of_day(&dated->time)) ^ BIAS;
  if (shift < (BIAS - SECONDS_PER_HALF_DAY)) {
    days += 1;
  } else if (shift > (BIAS + SECONDS_PER_HALF_DAY)) {
    days -= 1;
  } else {
    /* same day */
  }
  st = drdc_time_civil_from_days(days, &c.year, &c.month, &c.day);
  if (st != DRDC_OK) {
    return DRDC_E_RANGE;
  }
  c.hour = s->time.hour;
  c.minute = s->time.minute;
  c.second = s->time.second;
  c.nsec = s->time.nsec;
  return drdc_time_from_civil(leap, &c, utc);
}
