/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief ZDA: time, date with a four-digit year, local zone.
 */
#include "nmea_impl.h"

/* $--ZDA,hhmmss.ss,xx,xx,xxxx,xx,xx */
#define ZDA_FIELDS 6u
#define ZONE_HOURS_MAX 13

drdc_status_t nmea_zda(const nmea_frame_t *fr, drdc_nmea_t *n)
{
  nmea_field_t zone = nmea_field(fr, 5u);
  drdc_status_t st;

  if (fr->count < ZDA_FIELDS) {
    return DRDC_E_MISSING_FIELD;
  }
  st = nmea_tod(nmea_field(fr, 1u), &n->time);
  if (st == DRDC_OK) {
    st = nmea_uint(nmea_field(fr, 2u), 2u, 2u, &n->day);
  }
  if (st == DRDC_OK) {
    st = nmea_uint(nmea_field(fr, 3u), 2u, 2u, &n->month);
  }
  if (st == DRDC_OK) {
    st = nmea_uint(nmea_field(fr, 4u), 4u, 4u, &n->year);
  }
  if (st != DRDC_OK) {
    return st;
  }
  if ((n->day < 1) || (n->day > 31)) {
    return DRDC_E_DAY;
  }
  if ((n->month < 1) || (n->month > 12)) {
    return DRDC_E_MONTH;
  }
  if (n->year < DRDC_YEAR_MIN) {
    return DRDC_E_YEAR;
  }
  n->has |= DRDC_NMEA_HAS_DATE;
  if (zone.n != 0u) {
    nmea_field_t digits = zone;
    char sign = zone.p[0];

    if ((sign == '-') || (sign == '+')) {
      digits.p = &zone.p[1];
      digits.n = zone.n - 1u;
    }
    st = nmea_uint(digits, 1u, 2u, &n->zone_hours);
    if (st == DRDC_OK) {
      st = nmea_uint(nmea_field(fr, 6u), 2u, 2u, &n->zone_minutes);
    }
    if (st != DRDC_OK) {
      return st;
    }
    if (n->zone_hours > ZONE_HOURS_MAX) {
      return DRDC_E_RANGE;
    }
    if (n->zone_minutes > 59) {
      return DRDC_E_MINUTE;
    }
    if (sign == '-') {
      n->zone_hours = -n->zone_hours;
    }
    n->has |= DRDC_NMEA_HAS_ZONE;
  }
  return DRDC_OK;
}
