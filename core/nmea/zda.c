/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief ZDA: time, date with a four-digit year, local zone.
 */
#include "nmea_impl.h"

/* $--ZDA,hhmmss.ss,xx,xx,xxxx,xx,xx: 6 fields; the year (field 4) is the
 * last one required, the local zone is optional. */
#define ZDA_FIELDS          6u
#define ZDA_FIELDS_REQUIRED 4u
#define ZONE_HOURS_MAX      13

drdc_status_t drdc__nmea_zda(const nmea_frame_t *fr, drdc_nmea_t *n)
{
  nmea_field_t zone = nmea_field(fr, 5u);
  drdc_status_t st;
  int32_t day = 0;
  int32_t month = 0;
  int32_t year = 0;
  int32_t zone_hours = 0;
  int32_t zone_minutes = 0;

  if (nmea_has_fields(fr, ZDA_FIELDS_REQUIRED, ZDA_FIELDS) == 0) {
    return DRDC_E_MISSING_FIELD;
  }
  st = drdc__nmea_tod(fr, 1u, (n != NULL) ? &n->time : NULL);
  if (st == DRDC_OK) {
    st = drdc__nmea_uint(fr, 2u, 2u, 2u, &day);
  }
  if (st == DRDC_OK) {
    st = drdc__nmea_uint(fr, 3u, 2u, 2u, &month);
  }
  if (st == DRDC_OK) {
    st = drdc__nmea_uint(fr, 4u, 4u, 4u, &year);
  }
  if (st != DRDC_OK) {
    return st;
  }
  if ((day < 1) || (day > 31)) {
    return DRDC_E_DAY;
  }
  if ((month < 1) || (month > 12)) {
    return DRDC_E_MONTH;
  }
  if (year < DRDC_YEAR_MIN) {
    return DRDC_E_YEAR;
  }
  if (n != NULL) {
    n->day = day;
    n->month = month;
    n->year = year;
    n->has |= DRDC_NMEA_HAS_TIME | DRDC_NMEA_HAS_DATE;
  }
  if (zone.n != 0u) {
    nmea_field_t digits = zone;
    char sign = zone.p[0];

    if ((sign == '-') || (sign == '+')) {
      digits.p = &zone.p[1];
      digits.n = zone.n - 1u;
    }
    st = drdc__nmea_digits(digits.p, digits.n, 1u, 2u, &zone_hours);
    if (st == DRDC_OK) {
      st = drdc__nmea_uint(fr, 6u, 2u, 2u, &zone_minutes);
    }
    if (st != DRDC_OK) {
      return st;
    }
    if (zone_hours > ZONE_HOURS_MAX) {
      return DRDC_E_RANGE;
    }
    if (zone_minutes > 59) {
      return DRDC_E_MINUTE;
    }
    if (n != NULL) {
      n->zone_hours = (sign == '-') ? -zone_hours : zone_hours;
      n->zone_minutes = zone_minutes;
      n->has |= DRDC_NMEA_HAS_ZONE;
    }
  }
  return DRDC_OK;
}
