/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief HDOP, altitude and geoid separation: the fields GGA and GNS share.
 */
#include "nmea_impl.h"

drdc_status_t drdc__nmea_precision(const nmea_frame_t *fr, size_t separation,
                                   drdc_nmea_t *n)
{
  drdc_status_t st;

  if (nmea_field(fr, 8u).n != 0u) {
    st = drdc__nmea_q15_16(fr, 8u, NMEA_METRES_Q15_16, n,
                           (n != NULL) ? &n->hdop : NULL, DRDC_NMEA_HAS_HDOP,
                           DRDC_NMEA_BEYOND_HDOP);
    if (st != DRDC_OK) {
      return st;
    }
  }
  if (nmea_field(fr, 9u).n != 0u) {
    st = drdc__nmea_fixed(fr, 9u, NMEA_METRES_Q47_16,
                          (n != NULL) ? &n->altitude : NULL);
    if (st != DRDC_OK) {
      return st;
    }
    if (n != NULL) {
      n->has |= DRDC_NMEA_HAS_ALTITUDE;
    }
  }
  if (nmea_field(fr, separation).n != 0u) {
    st = drdc__nmea_fixed(fr, separation, NMEA_METRES_Q47_16,
                          (n != NULL) ? &n->separation : NULL);
    if (st != DRDC_OK) {
      return st;
    }
    if (n != NULL) {
      n->has |= DRDC_NMEA_HAS_SEPARATION;
    }
  }
  return DRDC_OK;
}
