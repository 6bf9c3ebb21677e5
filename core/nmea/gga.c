/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief GGA: time, position, fix quality, satellites, HDOP, altitude and
 *        geoid separation.
 */
#include "nmea_impl.h"

/* $--GGA,hhmmss.ss,llll.ll,a,yyyyy.yy,a,x,xx,x.x,x.x,M,x.x,M,x.x,xxxx */
#define GGA_FIELDS 14u
/* Fix quality 1..8 in NMEA 0183 v4.10 (8: simulator) */
#define GGA_QUALITY_MAX 8

drdc_status_t nmea_gga(const nmea_frame_t *fr, drdc_nmea_t *n)
{
  drdc_status_t st;

  if (fr->count < GGA_FIELDS) {
    return DRDC_E_MISSING_FIELD;
  }
  st = nmea_uint(nmea_field(fr, 6u), 1u, 1u, &n->quality);
  if (st != DRDC_OK) {
    return st;
  }
  if (n->quality == 0) {
    return DRDC_E_NO_FIX;
  }
  if (n->quality > GGA_QUALITY_MAX) {
    return DRDC_E_RANGE;
  }
  st = nmea_tod(nmea_field(fr, 1u), &n->time);
  if (st == DRDC_OK) {
    st = nmea_angle(nmea_field(fr, 2u), nmea_field(fr, 3u), 1, &n->latitude);
  }
  if (st == DRDC_OK) {
    st = nmea_angle(nmea_field(fr, 4u), nmea_field(fr, 5u), 0, &n->longitude);
  }
  if (st != DRDC_OK) {
    return st;
  }
  n->has |= DRDC_NMEA_HAS_POSITION;
  if (nmea_field(fr, 7u).n != 0u) {
    st = nmea_uint(nmea_field(fr, 7u), 1u, 2u, &n->satellites);
    if (st != DRDC_OK) {
      return st;
    }
    n->has |= DRDC_NMEA_HAS_SATELLITES;
  }
  return nmea_precision(fr, 11u, n);
}
