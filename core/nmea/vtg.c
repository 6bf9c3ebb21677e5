/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief VTG: course over ground (true and magnetic) and speed.
 */
#include "nmea_impl.h"

/* $--VTG,x.x,T,x.x,M,x.x,N,x.x,K(,m): 8 fields, 9 from NMEA 2.3 with the
 * mode. Only the true course is required to be there (a receiver may end
 * the sentence after it); the sentence must carry the true course or a
 * speed. The unit letters name each value's field: the NMEA 1.5 layout
 * without them (`$GPVTG,054.7,034.4,005.5,010.2`) reads as a bad letter
 * in field 2 and is refused. */
#define VTG_FIELDS          8u
#define VTG_FIELDS_REQUIRED 1u

drdc_status_t drdc__nmea_vtg(const nmea_frame_t *fr, drdc_nmea_t *n)
{
  static const char letters[4] = {'T', 'M', 'N', 'K'};
  nmea_field_t mode = nmea_field(fr, 9u);
  char m = '\0';
  drdc_status_t st = DRDC_OK;
  int64_t v = 0;
  size_t i;

  if (nmea_has_fields(fr, VTG_FIELDS_REQUIRED, VTG_FIELDS) == 0) {
    return DRDC_E_MISSING_FIELD;
  }
  if (mode.n != 0u) {
    m = mode.p[0];
    if ((mode.n != 1u) || (nmea_is_mode(m) == 0)) {
      return DRDC_E_SYNTAX;
    }
  }
  if (m == 'N') {
    return DRDC_E_NO_FIX;
  }
  if ((nmea_field(fr, 1u).n == 0u) && (nmea_field(fr, 5u).n == 0u) &&
      (nmea_field(fr, 7u).n == 0u)) {
    return DRDC_E_MISSING_FIELD;
  }
  for (i = 0u; (i < 4u) && (st == DRDC_OK); i++) {
    st = drdc__nmea_letter(fr, (2u * i) + 2u, letters[i]);
  }
  if ((st == DRDC_OK) && (nmea_field(fr, 1u).n != 0u)) {
    st = drdc__nmea_fixed(fr, 1u, NMEA_DEGREES_BAM32, &v);
    if ((st == DRDC_OK) && (n != NULL)) {
      n->course = (drdc_bam32_t)(uint64_t)v;
      n->has |= DRDC_NMEA_HAS_COURSE;
    }
  }
  if ((st == DRDC_OK) && (nmea_field(fr, 3u).n != 0u)) {
    st = drdc__nmea_fixed(fr, 3u, NMEA_DEGREES_BAM32, &v);
    if ((st == DRDC_OK) && (n != NULL)) {
      n->course_magnetic = (drdc_bam32_t)(uint64_t)v;
      n->has |= DRDC_NMEA_HAS_COURSE_MAGNETIC;
    }
  }
  /* the speed in knots, or in km/h when the knots are empty */
  if ((st == DRDC_OK) && (nmea_field(fr, 5u).n != 0u)) {
    st = drdc__nmea_q15_16(fr, 5u, NMEA_KNOTS_Q15_16, n,
                           (n != NULL) ? &n->speed : NULL, DRDC_NMEA_HAS_SPEED,
                           DRDC_NMEA_BEYOND_SPEED);
  } else if ((st == DRDC_OK) && (nmea_field(fr, 7u).n != 0u)) {
    st = drdc__nmea_q15_16(fr, 7u, NMEA_KMH_Q15_16, n,
                           (n != NULL) ? &n->speed : NULL, DRDC_NMEA_HAS_SPEED,
                           DRDC_NMEA_BEYOND_SPEED);
  } else {
    /* no speed */
  }
  if ((st == DRDC_OK) && (n != NULL)) {
    n->mode[0] = m;
    n->mode[1] = '\0';
  }
  return st;
}
