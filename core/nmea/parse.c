/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief drdc_nmea_parse(), drdc_nmea_parse_with() and
 *        drdc_nmea_parse_date(): frame the sentence, check that every
 *        field decodes, then decode it into the caller's record.
 */
#include "nmea_impl.h"

/* Every field 0, strings empty (field by field: a structure assignment
 * may become a memset call, which freestanding targets do not have). */
static void clear(drdc_nmea_t *to)
{
  size_t i;

  to->type = DRDC_NMEA_GGA;
  for (i = 0u; i < sizeof(to->talker); i++) {
    to->talker[i] = '\0';
  }
  for (i = 0u; i < sizeof(to->mode); i++) {
    to->mode[i] = '\0';
  }
  to->has = 0u;
  to->beyond = 0u;
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
  to->pdop = 0;
  to->vdop = 0;
  to->speed = 0;
  to->course = 0u;
  to->course_magnetic = 0u;
  to->heading = 0u;
  to->fix_type = 0;
  to->system_id = 0;
  for (i = 0u; i < DRDC_NMEA_GSA_IDS; i++) {
    to->satellite_ids[i] = 0u;
  }
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
}

/* The sentence's decoder; with `n` NULL it only checks. The HDOP,
 * altitude and separation of GGA and GNS are decoded here, after the
 * sentence's own fields, not from inside its decoder, so that the
 * 128-bit division of drdc__nmea_fixed() is not called one level
 * deeper. */
static drdc_status_t decode_sentence(const nmea_frame_t *fr, drdc_nmea_t *n)
{
  drdc_status_t st;

  switch (fr->type) {
  case DRDC_NMEA_GGA:
    st = drdc__nmea_gga(fr, n);
    if (st == DRDC_OK) {
      st = drdc__nmea_precision(fr, 11u, n);
    }
    break;
  case DRDC_NMEA_RMC:
    st = drdc__nmea_rmc(fr, n);
    break;
  case DRDC_NMEA_GNS:
    st = drdc__nmea_gns(fr, n);
    if (st == DRDC_OK) {
      st = drdc__nmea_precision(fr, 10u, n);
    }
    break;
  case DRDC_NMEA_ZDA:
    st = drdc__nmea_zda(fr, n);
    break;
  case DRDC_NMEA_GLL:
    st = drdc__nmea_gll(fr, n);
    break;
  case DRDC_NMEA_VTG:
    st = drdc__nmea_vtg(fr, n);
    break;
  case DRDC_NMEA_HDT:
    st = drdc__nmea_hdt(fr, n);
    break;
  case DRDC_NMEA_THS:
    st = drdc__nmea_ths(fr, n);
    break;
  case DRDC_NMEA_GSA:
    st = drdc__nmea_gsa(fr, n);
    break;
  default:
    st = drdc__nmea_gst(fr, n);
    break;
  }
  return st;
}

/* What one parse decodes: the whole sentence, or the date only. */
typedef enum parse_what { PARSE_SENTENCE = 0, PARSE_DATE = 1 } parse_what_t;

/* The date-bearing part of an RMC or ZDA; any other sentence has none
 * (DRDC_E_SENTENCE). A ZDA is all date: its whole decoder runs. */
static drdc_status_t decode_date(const nmea_frame_t *fr, drdc_nmea_t *n)
{
  drdc_status_t st;

  switch (fr->type) {
  case DRDC_NMEA_RMC:
    st = drdc__nmea_rmc_date(fr, n);
    break;
  case DRDC_NMEA_ZDA:
    st = drdc__nmea_zda(fr, n);
    break;
  default:
    st = DRDC_E_SENTENCE;
    break;
  }
  return st;
}

/*
 * Two passes over the framed sentence instead of a scratch record: the
 * first checks every field (the decoders write nothing with NULL), the
 * second, run only when the first succeeded, writes the caller's record.
 * The second pass reads the same text with the same code, so it succeeds
 * too. The record is written only on success without a second
 * drdc_nmea_t on the stack, for about twice the decoding cycles.
 */
drdc_status_t drdc__nmea_open(const char *text, size_t length, uint32_t flags,
                              nmea_frame_t *fr)
{
  if ((flags & ~DRDC_NMEA_STRICT) != 0u) {
    return DRDC_E_RANGE;
  }
  return drdc__nmea_frame(text, length, flags, fr);
}

void drdc__nmea_begin_record(const nmea_frame_t *fr, const char *text,
                             drdc_nmea_t *out)
{
  clear(out);
  out->type = fr->type;
  out->talker[0] = text[1];
  out->talker[1] = text[2];
}

static drdc_status_t parse(const char *text, size_t length, uint32_t flags,
                           parse_what_t what, drdc_nmea_t *out)
{
  nmea_frame_t fr;
  drdc_nmea_t *n = NULL;
  drdc_status_t st;
  unsigned pass;

  if ((text == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc__nmea_open(text, length, flags, &fr);
  /* pass 0 checks (n NULL), pass 1 decodes into out */
  for (pass = 0u; (pass < 2u) && (st == DRDC_OK); pass++) {
    if (pass == 1u) {
      drdc__nmea_begin_record(&fr, text, out);
      n = out;
    }
    st = (what == PARSE_DATE) ? decode_date(&fr, n) : decode_sentence(&fr, n);
  }
  return st;
}

drdc_status_t drdc_nmea_parse_with(const char *text, size_t length,
                                   uint32_t flags, drdc_nmea_t *out)
{
  return parse(text, length, flags, PARSE_SENTENCE, out);
}

drdc_status_t drdc_nmea_parse(const char *text, size_t length, drdc_nmea_t *out)
{
  return parse(text, length, 0u, PARSE_SENTENCE, out);
}

drdc_status_t drdc_nmea_parse_date(const char *text, size_t length,
                                   uint32_t flags, drdc_nmea_t *out)
{
  return parse(text, length, flags, PARSE_DATE, out);
}
