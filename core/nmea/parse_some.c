/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief drdc_nmea_parse_some(): a parse with the decoders the caller
 *        names, in a file of its own, so that it links those decoders
 *        and no other (drdc_nmea_parse() calls every one).
 */
#include "nmea_impl.h"

drdc_status_t drdc_nmea_parse_some(const char *text, size_t length,
                                   uint32_t flags,
                                   const drdc_nmea_decoder_t *const *decoders,
                                   size_t count, drdc_nmea_t *out)
{
  nmea_frame_t fr;
  const drdc_nmea_decoder_t *d = NULL;
  drdc_nmea_t *n = NULL;
  drdc_status_t st;
  size_t i;
  unsigned pass;

  if ((text == NULL) || (out == NULL) ||
      ((decoders == NULL) && (count != 0u))) {
    return DRDC_E_NULL;
  }
  for (i = 0u; i < count; i++) {
    if (decoders[i] == NULL) {
      return DRDC_E_NULL;
    }
  }
  st = drdc__nmea_open(text, length, flags, &fr);
  for (i = 0u; (st == DRDC_OK) && (i < count) && (d == NULL); i++) {
    if (decoders[i]->type == fr.type) {
      d = decoders[i];
    }
  }
  if ((st == DRDC_OK) && (d == NULL)) {
    st = DRDC_E_SENTENCE;
  }
  /* the two passes of every parse (parse.c says why): check, then write;
   * GGA's and GNS's precision fields after their own, as there */
  for (pass = 0u; (pass < 2u) && (st == DRDC_OK); pass++) {
    if (pass == 1u) {
      drdc__nmea_begin_record(&fr, text, out);
      n = out;
    }
    st = d->decode(&fr, n);
    if ((st == DRDC_OK) && (d->precision != 0u)) {
      st = drdc__nmea_precision(&fr, d->precision, n);
    }
  }
  return st;
}
