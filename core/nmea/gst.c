/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief GST: pseudorange residual RMS and error ellipse, 1-sigma errors.
 */
#include "nmea_impl.h"

/* $--GST,hhmmss.ss,x.x,x.x,x.x,x.x,x.x,x.x,x.x */
#define GST_FIELDS 8u
/* RMS, latitude, longitude, altitude deviations, ellipse semi-axes */
#define GST_DEVIATIONS 6u

/* Where deviation `i` (of GST_DEVIATIONS) goes. */
static drdc_q15_16_t *deviation(drdc_nmea_t *n, size_t i)
{
  drdc_q15_16_t *p;

  switch (i) {
  case 0u:
    p = &n->rms;
    break;
  case 1u:
    p = &n->sigma_latitude;
    break;
  case 2u:
    p = &n->sigma_longitude;
    break;
  case 3u:
    p = &n->sigma_altitude;
    break;
  case 4u:
    p = &n->sigma_major;
    break;
  default:
    p = &n->sigma_minor;
    break;
  }
  return p;
}

drdc_status_t drdc__nmea_gst(const nmea_frame_t *fr, drdc_nmea_t *n)
{
  /* the deviations in metres -> Q15.16: fields 2, 6, 7, 8 (always) and
   * 3, 4 (the error ellipse) */
  static const uint8_t fields[GST_DEVIATIONS] = {2u, 6u, 7u, 8u, 3u, 4u};
  drdc_status_t st;
  int64_t v = 0;
  size_t i;
  size_t count = 4u;

  if (fr->count < GST_FIELDS) {
    return DRDC_E_MISSING_FIELD;
  }
  st = drdc__nmea_tod(fr, 1u, (n != NULL) ? &n->time : NULL);
  /* the error ellipse is optional (many receivers leave it empty), but
   * all three fields or none */
  if ((nmea_field(fr, 3u).n != 0u) || (nmea_field(fr, 4u).n != 0u) ||
      (nmea_field(fr, 5u).n != 0u)) {
    count = GST_DEVIATIONS;
  }
  for (i = 0u; (i < count) && (st == DRDC_OK); i++) {
    st = drdc__nmea_fixed(fr, fields[i], NMEA_METRES_Q15_16, &v);
    if ((st == DRDC_OK) && (n != NULL)) {
      *deviation(n, i) = (drdc_q15_16_t)v;
    }
  }
  if ((st == DRDC_OK) && (count == GST_DEVIATIONS)) {
    /* degrees from true north -> binary angle, wrapping */
    st = drdc__nmea_fixed(fr, 5u, NMEA_DEGREES_BAM32, &v);
    if ((st == DRDC_OK) && (n != NULL)) {
      n->orientation = (drdc_bam32_t)(uint64_t)v;
      n->has |= DRDC_NMEA_HAS_ELLIPSE;
    }
  }
  if ((st == DRDC_OK) && (n != NULL)) {
    n->has |= DRDC_NMEA_HAS_GST;
  }
  return st;
}
