/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief HDT and THS: true heading (from a gyrocompass, a dual-antenna
 *        receiver or an INS).
 */
#include "nmea_impl.h"

/* $--HDT,x.x,T: 2 fields; the heading is required, the letter may be
 * left off. */
#define HDT_FIELDS          2u
#define HDT_FIELDS_REQUIRED 1u
/* $--THS,x.x,a: 2 fields, both required: the mode says whether the
 * heading is valid. */
#define THS_FIELDS 2u

/* Mode letters of THS (NMEA 0183 v4.10): A autonomous, E estimated (dead
 * reckoning), M manual input, S simulator, V not valid. */
static int is_ths_mode(char c)
{
  return ((c == 'A') || (c == 'E') || (c == 'M') || (c == 'S') || (c == 'V'))
             ? 1
             : 0;
}

/* Field 1, degrees from true north, into n->heading (wrapped to a turn). */
static drdc_status_t heading(const nmea_frame_t *fr, drdc_nmea_t *n)
{
  int64_t v = 0;
  drdc_status_t st = drdc__nmea_fixed(fr, 1u, NMEA_DEGREES_BAM32, &v);

  if ((st == DRDC_OK) && (n != NULL)) {
    n->heading = (drdc_bam32_t)(uint64_t)v;
    n->has |= DRDC_NMEA_HAS_HEADING;
  }
  return st;
}

drdc_status_t drdc__nmea_hdt(const nmea_frame_t *fr, drdc_nmea_t *n)
{
  drdc_status_t st;

  if (nmea_has_fields(fr, HDT_FIELDS_REQUIRED, HDT_FIELDS) == 0) {
    return DRDC_E_MISSING_FIELD;
  }
  st = drdc__nmea_letter(fr, 2u, 'T');
  if (st == DRDC_OK) {
    st = heading(fr, n);
  }
  return st;
}

drdc_status_t drdc__nmea_ths(const nmea_frame_t *fr, drdc_nmea_t *n)
{
  nmea_field_t mode = nmea_field(fr, 2u);
  char m = '\0';
  drdc_status_t st;

  if ((fr->count < THS_FIELDS) || (mode.n == 0u)) {
    return DRDC_E_MISSING_FIELD;
  }
  m = mode.p[0];
  if ((mode.n != 1u) || (is_ths_mode(m) == 0)) {
    return DRDC_E_SYNTAX;
  }
  if (m == 'V') {
    return DRDC_E_NO_FIX;
  }
  st = heading(fr, n);
  if ((st == DRDC_OK) && (n != NULL)) {
    n->mode[0] = m;
    n->mode[1] = '\0';
  }
  return st;
}
