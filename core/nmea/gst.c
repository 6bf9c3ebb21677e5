/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief GST: pseudorange residual RMS and error ellipse, 1-sigma errors.
 */
#include "nmea_impl.h"

/* $--GST,hhmmss.ss,x.x,x.x,x.x,x.x,x.x,x.x,x.x: every field up to the
 * altitude deviation (field 8) is required. */
#define GST_FIELDS 8u
/* RMS, latitude, longitude, altitude deviations, ellipse semi-axes */
#define GST_DEVIATIONS 6u

/* Deviation `i` of GST_DEVIATIONS: its field, where it goes in `n` and
 * its DRDC_NMEA_BEYOND_* bit. */
typedef struct gst_deviation {
  size_t field;
  drdc_q15_16_t *value;
  uint32_t beyond;
} gst_deviation_t;

static gst_deviation_t deviation(drdc_nmea_t *n, size_t i)
{
  gst_deviation_t d = {2u, NULL, DRDC_NMEA_BEYOND_RMS};

  switch (i) {
  case 0u:
    d.field = 2u;
    d.value = (n != NULL) ? &n->rms : NULL;
    d.beyond = DRDC_NMEA_BEYOND_RMS;
    break;
  case 1u:
    d.field = 6u;
    d.value = (n != NULL) ? &n->sigma_latitude : NULL;
    d.beyond = DRDC_NMEA_BEYOND_SIGMA_LATITUDE;
    break;
  case 2u:
    d.field = 7u;
    d.value = (n != NULL) ? &n->sigma_longitude : NULL;
    d.beyond = DRDC_NMEA_BEYOND_SIGMA_LONGITUDE;
    break;
  case 3u:
    d.field = 8u;
    d.value = (n != NULL) ? &n->sigma_altitude : NULL;
    d.beyond = DRDC_NMEA_BEYOND_SIGMA_ALTITUDE;
    break;
  case 4u:
    d.field = 3u;
    d.value = (n != NULL) ? &n->sigma_major : NULL;
    d.beyond = DRDC_NMEA_BEYOND_SIGMA_MAJOR;
    break;
  default:
    d.field = 4u;
    d.value = (n != NULL) ? &n->sigma_minor : NULL;
    d.beyond = DRDC_NMEA_BEYOND_SIGMA_MINOR;
    break;
  }
  return d;
}

drdc_status_t drdc__nmea_gst(const nmea_frame_t *fr, drdc_nmea_t *n)
{
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
  /* metres -> Q15.16; a deviation beyond 32767 m (a receiver before it
   * converges) is flagged, not refused */
  for (i = 0u; (i < count) && (st == DRDC_OK); i++) {
    gst_deviation_t d = deviation(n, i);

    st = drdc__nmea_q15_16(fr, d.field, NMEA_METRES_Q15_16, n, d.value, 0u,
                           d.beyond);
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
    n->has |= DRDC_NMEA_HAS_TIME | DRDC_NMEA_HAS_GST;
  }
  return st;
}
