/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief RMC: time, status, position, speed, course and date; and its
 *        time and date alone, whatever its status, for dating.
 */
#include "nmea_impl.h"

/* $--RMC,hhmmss.ss,A,llll.ll,a,yyyyy.yy,a,x.x,x.x,ddmmyy,x.x,a(,m(,s)):
 * 11 fields before NMEA 2.3, 12 with the mode, 13 in 4.10; the date
 * (field 9) is the last one required. */
#define RMC_FIELDS          11u
#define RMC_FIELDS_REQUIRED 9u
/* Two-digit years: 80..99 are 1980..1999 (the GPS epoch), 00..79 are
 * 2000..2079. */
#define RMC_PIVOT 80

/* The status letter (field 2): A valid, V not valid. */
static drdc_status_t rmc_status(const nmea_frame_t *fr, char *status)
{
  nmea_field_t f = nmea_field(fr, 2u);
  char s;

  if (f.n == 0u) {
    return DRDC_E_MISSING_FIELD;
  }
  s = f.p[0];
  if ((f.n != 1u) || ((s != 'A') && (s != 'V'))) {
    return DRDC_E_SYNTAX;
  }
  *status = s;
  return DRDC_OK;
}

/* The date (field 9, ddmmyy): day and month checked, the two-digit year
 * widened around RMC_PIVOT. The outputs are written on success only. */
static drdc_status_t rmc_date(const nmea_frame_t *fr, int32_t *day,
                              int32_t *month, int32_t *year)
{
  int32_t ddmmyy = 0;
  int32_t d;
  int32_t m;
  int32_t y;
  drdc_status_t st = drdc__nmea_uint(fr, 9u, 6u, 6u, &ddmmyy);

  if (st != DRDC_OK) {
    return st;
  }
  d = ddmmyy / 10000;
  m = (ddmmyy / 100) % 100;
  y = ddmmyy % 100;
  y += (y < RMC_PIVOT) ? 2000 : 1900;
  if ((d < 1) || (d > 31)) {
    return DRDC_E_DAY;
  }
  if ((m < 1) || (m > 12)) {
    return DRDC_E_MONTH;
  }
  *day = d;
  *month = m;
  *year = y;
  return DRDC_OK;
}

drdc_status_t drdc__nmea_rmc(const nmea_frame_t *fr, drdc_nmea_t *n)
{
  nmea_field_t mode = nmea_field(fr, 12u);
  drdc_status_t st;
  int32_t day = 0;
  int32_t month = 0;
  int32_t year = 0;
  char s = '\0';
  char m = '\0';
  int64_t v = 0;

  if (nmea_has_fields(fr, RMC_FIELDS_REQUIRED, RMC_FIELDS) == 0) {
    return DRDC_E_MISSING_FIELD;
  }
  st = rmc_status(fr, &s);
  if (st != DRDC_OK) {
    return st;
  }
  if (mode.n == 1u) {
    m = mode.p[0];
  }
  if ((s == 'V') || (m == 'N')) {
    return DRDC_E_NO_FIX;
  }
  st = drdc__nmea_fix(fr, 1u, 3u, n);
  if (st == DRDC_OK) {
    st = rmc_date(fr, &day, &month, &year);
  }
  if (st != DRDC_OK) {
    return st;
  }
  if (n != NULL) {
    n->mode[0] = m;
    n->mode[1] = '\0';
    n->day = day;
    n->month = month;
    n->year = year;
    n->has |= DRDC_NMEA_HAS_DATE;
  }
  if (nmea_field(fr, 7u).n != 0u) {
    st = drdc__nmea_q15_16(fr, 7u, NMEA_KNOTS_Q15_16, n,
                           (n != NULL) ? &n->speed : NULL, DRDC_NMEA_HAS_SPEED,
                           DRDC_NMEA_BEYOND_SPEED);
    if (st != DRDC_OK) {
      return st;
    }
  }
  if (nmea_field(fr, 8u).n != 0u) {
    /* course in degrees -> binary angle, 2^32 per turn, wrapping */
    st = drdc__nmea_fixed(fr, 8u, NMEA_DEGREES_BAM32, &v);
    if (st != DRDC_OK) {
      return st;
    }
    if (n != NULL) {
      n->course = (drdc_bam32_t)(uint64_t)v;
      n->has |= DRDC_NMEA_HAS_COURSE;
    }
  }
  return DRDC_OK;
}

drdc_status_t drdc__nmea_rmc_date(const nmea_frame_t *fr, drdc_nmea_t *n)
{
  drdc_status_t st;
  int32_t day = 0;
  int32_t month = 0;
  int32_t year = 0;
  char s = '\0';

  if (nmea_has_fields(fr, RMC_FIELDS_REQUIRED, RMC_FIELDS) == 0) {
    return DRDC_E_MISSING_FIELD;
  }
  /* the status is read for its syntax only: V keeps the date */
  st = rmc_status(fr, &s);
  if (st == DRDC_OK) {
    st = drdc__nmea_tod(fr, 1u, (n != NULL) ? &n->time : NULL);
  }
  if (st == DRDC_OK) {
    st = rmc_date(fr, &day, &month, &year);
  }
  if ((st == DRDC_OK) && (n != NULL)) {
    n->day = day;
    n->month = month;
    n->year = year;
    n->has |= DRDC_NMEA_HAS_TIME | DRDC_NMEA_HAS_DATE;
  }
  return st;
}
