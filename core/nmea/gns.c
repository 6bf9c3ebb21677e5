/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief GNS: multi-constellation fix with a mode letter per system.
 */
#include "nmea_impl.h"

/* $--GNS,hhmmss.ss,llll.ll,a,yyyyy.yy,a,c--c,xx,x.x,x.x,x.x,x.x,x.x(,s):
 * 12 fields (13 in 4.10); the satellites (field 7) are the last one
 * required. */
#define GNS_FIELDS          12u
#define GNS_FIELDS_REQUIRED 7u
/* mode letters kept (one per constellation: GPS, GLONASS, Galileo, BDS,
 * QZSS, NavIC) */
#define GNS_MODES_MAX 6u

drdc_status_t drdc__nmea_gns(const nmea_frame_t *fr, drdc_nmea_t *n)
{
  nmea_field_t mode = nmea_field(fr, 6u);
  drdc_status_t st;
  size_t i;
  int fix = 0;
  int32_t satellites = 0;

  if (nmea_has_fields(fr, GNS_FIELDS_REQUIRED, GNS_FIELDS) == 0) {
    return DRDC_E_MISSING_FIELD;
  }
  if (mode.n == 0u) {
    return DRDC_E_MISSING_FIELD;
  }
  if (mode.n > GNS_MODES_MAX) {
    return DRDC_E_SYNTAX;
  }
  for (i = 0u; i < mode.n; i++) {
    char c = mode.p[i];

    if (nmea_is_mode(c) == 0) {
      return DRDC_E_SYNTAX;
    }
    if (c != 'N') {
      fix = 1;
    }
  }
  if (fix == 0) {
    return DRDC_E_NO_FIX;
  }
  st = drdc__nmea_fix(fr, 1u, 2u, n);
  if (st == DRDC_OK) {
    st = drdc__nmea_uint(fr, 7u, 1u, 2u, &satellites);
  }
  if (st != DRDC_OK) {
    return st;
  }
  if (n != NULL) {
    for (i = 0u; i < mode.n; i++) {
      n->mode[i] = mode.p[i];
    }
    n->mode[mode.n] = '\0';
    n->satellites = satellites;
    n->has |= DRDC_NMEA_HAS_SATELLITES;
  }
  return DRDC_OK;
}
