/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief drdc_nmea_parse(): frame the sentence, decode it into a scratch
 *        record, copy it out only when every field was valid.
 */
#include "nmea_impl.h"

/* Field-wise copy (a structure assignment may become a memcpy call,
 * which freestanding targets do not have). With `from` NULL: every field
 * 0, strings empty. */
static void copy(const drdc_nmea_t *from, drdc_nmea_t *to)
{
  size_t i;

  if (from == NULL) {
    to->type = DRDC_NMEA_GGA;
    for (i = 0u; i < sizeof(to->talker); i++) {
      to->talker[i] = '\0';
    }
    for (i = 0u; i < sizeof(to->mode); i++) {
      to->mode[i] = '\0';
    }
    to->has = 0u;
    to->time.hour = 0;
    to->time.minute = 0;
    to->time.second = 0;
    to->time.nsec = 0;
    to->latitude = 0;
    to->longitude = 0;
    to->altitude = 0;
    to->separation = 0;
    to->quality = 0;
    to->satellites = 0;
    to->hdop = 0;
    to->speed = 0;
    to->course = 0u;
    to->year = 0;
    to->month = 0;
    to->day = 0;
    to->zone_hours = 0;
    to->zone_minutes = 0;
    to->rms = 0;
    to->sigma_major = 0;
    to->sigma_minor = 0;
    to->orientation = 0u;
    to->sigma_latitude = 0;
    to->sigma_longitude = 0;
    to->sigma_altitude = 0;
    return;
  }
  to->type = from->type;
  for (i = 0u; i < sizeof(to->talker); i++) {
    to->talker[i] = from->talker[i];
  }
  for (i = 0u; i < sizeof(to->mode); i++) {
    to->mode[i] = from->mode[i];
  }
  to->has = from->has;
  to->time.hour = from->time.hour;
  to->time.minute = from->time.minute;
  to->time.second = from->time.second;
  to->time.nsec = from->time.nsec;
  to->latitude = from->latitude;
  to->longitude = from->longitude;
  to->altitude = from->altitude;
  to->separation = from->separation;
  to->quality = from->quality;
  to->satellites = from->satellites;
  to->hdop = from->hdop;
  to->speed = from->speed;
  to->course = from->course;
  to->year = from->year;
  to->month = from->month;
  to->day = from->day;
  to->zone_hours = from->zone_hours;
  to->zone_minutes = from->zone_minutes;
  to->rms = from->rms;
  to->sigma_major = from->sigma_major;
  to->sigma_minor = from->sigma_minor;
  to->orientation = from->orientation;
  to->sigma_latitude = from->sigma_latitude;
  to->sigma_longitude = from->sigma_longitude;
  to->sigma_altitude = from->sigma_altitude;
}

drdc_status_t drdc_nmea_parse(const char *text, size_t length,
                              drdc_nmea_t *out)
{
  nmea_frame_t fr;
  drdc_nmea_t n;
  drdc_status_t st;

  if ((text == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  copy(NULL, &n);
  st = nmea_frame(text, length, &fr);
  if (st != DRDC_OK) {
    return st;
  }
  n.type = fr.type;
  n.talker[0] = fr.talker[0];
  n.talker[1] = fr.talker[1];
  switch (fr.type) {
  case DRDC_NMEA_GGA:
    st = nmea_gga(&fr, &n);
    break;
  case DRDC_NMEA_RMC:
    st = nmea_rmc(&fr, &n);
    break;
  case DRDC_NMEA_GNS:
    st = nmea_gns(&fr, &n);
    break;
  case DRDC_NMEA_ZDA:
    st = nmea_zda(&fr, &n);
    break;
  default:
    st = nmea_gst(&fr, &n);
    break;
  }
  if (st == DRDC_OK) {
    copy(&n, out);
  }
  return st;
}
