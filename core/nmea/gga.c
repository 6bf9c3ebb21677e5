/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief GGA: time, position, fix quality, satellites, HDOP, altitude and
 *        geoid separation.
 */
#include "nmea_impl.h"

/* $--GGA,hhmmss.ss,llll.ll,a,yyyyy.yy,a,x,xx,x.x,x.x,M,x.x,M,x.x,xxxx:
 * 14 fields; the quality (field 6) is the last one required. Receivers
 * that send no corrections often end the sentence at the geoid
 * separation's unit or leave off the station id. */
#define GGA_FIELDS          14u
#define GGA_FIELDS_REQUIRED 6u
/* Fix quality 1..8 in NMEA 0183 v4.10 (8: simulator) */
#define GGA_QUALITY_MAX 8

drdc_status_t drdc__nmea_gga(const nmea_frame_t *fr, drdc_nmea_t *n)
{
  drdc_status_t st;
  int32_t quality = 0;
  int32_t satellites = 0;
  int has_quality = 1;
  int has_satellites = 0;

  if (nmea_has_fields(fr, GGA_FIELDS_REQUIRED, GGA_FIELDS) == 0) {
    return DRDC_E_MISSING_FIELD;
  }
  /* an empty quality beside a position: a fix of unknown quality; beside
   * no position: no fix (strict mode: a missing field) */
  if ((nmea_field(fr, 6u).n == 0u) && (fr->strict == 0u)) {
    has_quality = 0;
    if (nmea_field(fr, 2u).n == 0u) {
      return DRDC_E_NO_FIX;
    }
  } else {
    st = drdc__nmea_uint(fr, 6u, 1u, 1u, &quality);
    if (st != DRDC_OK) {
      return st;
    }
    if (quality == 0) {
      return DRDC_E_NO_FIX;
    }
    if (quality > GGA_QUALITY_MAX) {
      return DRDC_E_RANGE;
    }
  }
  st = drdc__nmea_fix(fr, 1u, 2u, n);
  if (st != DRDC_OK) {
    return st;
  }
  if (nmea_field(fr, 7u).n != 0u) {
    st = drdc__nmea_uint(fr, 7u, 1u, 2u, &satellites);
    if (st != DRDC_OK) {
      return st;
    }
    has_satellites = 1;
  }
  if (n != NULL) {
    if (has_quality != 0) {
      n->quality = quality;
      n->has |= DRDC_NMEA_HAS_QUALITY;
    }
    if (has_satellites != 0) {
      n->satellites = satellites;
      n->has |= DRDC_NMEA_HAS_SATELLITES;
    }
  }
  return DRDC_OK;
}
