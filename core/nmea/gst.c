/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief GST: pseudorange residual RMS and error ellipse, 1-sigma errors.
 */
#include "nmea_impl.h"

/* $--GST,hhmmss.ss,x.x,x.x,x.x,x.x,x.x,x.x,x.x */
#define GST_FIELDS 8u

/* A deviation in metres -> Q15.16. */
static drdc_status_t metres(const nmea_frame_t *fr, size_t i,
                            drdc_q15_16_t *out)
{
  int64_t v = 0;
  drdc_status_t st = nmea_fixed(nmea_field(fr, i), 1, 1, 16u, &v);

  if ((st == DRDC_OK) && ((v > INT32_MAX) || (v < INT32_MIN))) {
    st = DRDC_E_RANGE;
  }
  if (st == DRDC_OK) {
    *out = (drdc_q15_16_t)v;
  }
  return st;
}

drdc_status_t nmea_gst(const nmea_frame_t *fr, drdc_nmea_t *n)
{
  drdc_status_t st;
  int64_t v = 0;

  if (fr->count < GST_FIELDS) {
    return DRDC_E_MISSING_FIELD;
  }
  st = nmea_tod(nmea_field(fr, 1u), &n->time);
  if (st == DRDC_OK) {
    st = metres(fr, 2u, &n->rms);
  }
  if (st == DRDC_OK) {
    st = metres(fr, 6u, &n->sigma_latitude);
  }
  if (st == DRDC_OK) {
    st = metres(fr, 7u, &n->sigma_longitude);
  }
  if (st == DRDC_OK) {
    st = metres(fr, 8u, &n->sigma_altitude);
  }
  if (st != DRDC_OK) {
    return st;
  }
  n->has |= DRDC_NMEA_HAS_GST;
  /* the error ellipse is optional (many receivers leave it empty), but
   * all three fields or none */
  if ((nmea_field(fr, 3u).n == 0u) && (nmea_field(fr, 4u).n == 0u)
      && (nmea_field(fr, 5u).n == 0u)) {
    return DRDC_OK;
  }
  st = metres(fr, 3u, &n->sigma_major);
  if (st == DRDC_OK) {
    st = metres(fr, 4u, &n->sigma_minor);
  }
  if (st == DRDC_OK) {
    /* degrees from true north -> binary angle, wrapping */
    st = nmea_fixed(nmea_field(fr, 5u), 1, 360, 32u, &v);
  }
  if (st == DRDC_OK) {
    n->orientation = (drdc_bam32_t)(uint64_t)v;
    n->has |= DRDC_NMEA_HAS_ELLIPSE;
  }
  return st;
}
