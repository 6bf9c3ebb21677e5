/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief GLL: position, time of day and status.
 */
#include "nmea_impl.h"

/* $--GLL,llll.ll,a,yyyyy.yy,a,hhmmss.ss,A(,m): 6 fields, 7 from NMEA 2.3
 * with the mode. Every field up to the status is required: without the
 * status nothing says whether the position is a fix. */
#define GLL_FIELDS 6u

drdc_status_t drdc__nmea_gll(const nmea_frame_t *fr, drdc_nmea_t *n)
{
  nmea_field_t status = nmea_field(fr, 6u);
  nmea_field_t mode = nmea_field(fr, 7u);
  char m = '\0';
  char s = '\0';
  drdc_status_t st;

  if (fr->count < GLL_FIELDS) {
    return DRDC_E_MISSING_FIELD;
  }
  if (status.n == 0u) {
    return DRDC_E_MISSING_FIELD;
  }
  s = status.p[0];
  if ((status.n != 1u) || ((s != 'A') && (s != 'V'))) {
    return DRDC_E_SYNTAX;
  }
  if (mode.n != 0u) {
    m = mode.p[0];
    if ((mode.n != 1u) || (nmea_is_mode(m) == 0)) {
      return DRDC_E_SYNTAX;
    }
  }
  if ((s == 'V') || (m == 'N')) {
    return DRDC_E_NO_FIX;
  }
  st = drdc__nmea_fix(fr, 5u, 1u, n);
  if ((st == DRDC_OK) && (n != NULL)) {
    n->mode[0] = m;
    n->mode[1] = '\0';
  }
  return st;
}
