/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief RMC: time, status, position, speed, course and date.
 */
#include "nmea_impl.h"

/* $--RMC,hhmmss.ss,A,llll.ll,a,yyyyy.yy,a,x.x,x.x,ddmmyy,x.x,a(,m(,s)):
 * 11 fields before NMEA 2.3, 12 with the mode, 13 in 4.10 */
#define RMC_FIELDS 11u
/* Two-digit years: 80..99 are 1980..1999 (the GPS epoch), 00..79 are
 * 2000..2079. */
#define RMC_PIVOT 80
/* knots -> m/s: 1852 m / 3600 s */
#define KNOT_NUM INT64_C(1852)
#define KNOT_DEN INT64_C(3600)

/* Course in degrees -> binary angle, 2^32 per turn, wrapping. */
static drdc_status_t course(nmea_field_t f, drdc_bam32_t *out)
{
  int64_t v = 0;
  drdc_status_t st = nmea_fixed(f, 1, 360, 32u, &v);

  if (st == DRDC_OK) {
    *out = (drdc_bam32_t)(uint64_t)v;
  }
  return st;
}

drdc_status_t nmea_rmc(const nmea_frame_t *fr, drdc_nmea_t *n)
{
  nmea_field_t status = nmea_field(fr, 2u);
  nmea_field_t mode = nmea_field(fr, 12u);
  nmea_field_t date = nmea_field(fr, 9u);
  drdc_status_t st;
  int32_t ddmmyy = 0;
  char s;
  char m = '\0';
  int64_t v = 0;

  if (fr->count < RMC_FIELDS) {
    return DRDC_E_MISSING_FIELD;
  }
  if (status.n == 0u) {
    return DRDC_E_MISSING_FIELD;
  }
  s = status.p[0];
  if (mode.n == 1u) {
    m = mode.p[0];
  }
  if ((status.n != 1u) || ((s != 'A') && (s != 'V'))) {
    return DRDC_E_SYNTAX;
  }
  if ((s == 'V') || (m == 'N')) {
    return DRDC_E_NO_FIX;
  }
  n->mode[0] = m;
  n->mode[1] = '\0';
  st = nmea_tod(nmea_field(fr, 1u), &n->time);
  if (st == DRDC_OK) {
    st = nmea_angle(nmea_field(fr, 3u), nmea_field(fr, 4u), 1, &n->latitude);
  }
  if (st == DRDC_OK) {
    st = nmea_angle(nmea_field(fr, 5u), nmea_field(fr, 6u), 0, &n->longitude);
  }
  if (st == DRDC_OK) {
    n->has |= DRDC_NMEA_HAS_POSITION;
    st = nmea_uint(date, 6u, 6u, &ddmmyy);
  }
  if (st != DRDC_OK) {
    return st;
  }
  n->day = ddmmyy / 10000;
  n->month = (ddmmyy / 100) % 100;
  n->year = ddmmyy % 100;
  n->year += (n->year < RMC_PIVOT) ? 2000 : 1900;
  if ((n->day < 1) || (n->day > 31)) {
    return DRDC_E_DAY;
  }
  if ((n->month < 1) || (n->month > 12)) {
    return DRDC_E_MONTH;
  }
  n->has |= DRDC_NMEA_HAS_DATE;
  if (nmea_field(fr, 7u).n != 0u) {
    st = nmea_fixed(nmea_field(fr, 7u), KNOT_NUM, KNOT_DEN, 16u, &v);
    if ((st == DRDC_OK) && ((v > INT32_MAX) || (v < INT32_MIN))) {
      st = DRDC_E_RANGE;
    }
    if (st != DRDC_OK) {
      return st;
    }
    n->speed = (drdc_q15_16_t)v;
    n->has |= DRDC_NMEA_HAS_SPEED;
  }
  if (nmea_field(fr, 8u).n != 0u) {
    st = course(nmea_field(fr, 8u), &n->course);
    if (st != DRDC_OK) {
      return st;
    }
    n->has |= DRDC_NMEA_HAS_COURSE;
  }
  return DRDC_OK;
}
