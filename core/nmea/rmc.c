/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief RMC: time, status, position, speed, course and date.
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

drdc_status_t drdc__nmea_rmc(const nmea_frame_t *fr, drdc_nmea_t *n)
{
  nmea_field_t status = nmea_field(fr, 2u);
  nmea_field_t mode = nmea_field(fr, 12u);
  drdc_status_t st;
  int32_t ddmmyy = 0;
  int32_t day;
  int32_t month;
  int32_t year;
  char s;
  char m = '\0';
  int64_t v = 0;

  if (nmea_has_fields(fr, RMC_FIELDS_REQUIRED, RMC_FIELDS) == 0) {
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
  st = drdc__nmea_fix(fr, 1u, 3u, n);
  if (st == DRDC_OK) {
    st = drdc__nmea_uint(fr, 9u, 6u, 6u, &ddmmyy);
  }
  if (st != DRDC_OK) {
    return st;
  }
  day = ddmmyy / 10000;
  month = (ddmmyy / 100) % 100;
  year = ddmmyy % 100;
  year += (year < RMC_PIVOT) ? 2000 : 1900;
  if ((day < 1) || (day > 31)) {
    return DRDC_E_DAY;
  }
  if ((month < 1) || (month > 12)) {
    return DRDC_E_MONTH;
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
