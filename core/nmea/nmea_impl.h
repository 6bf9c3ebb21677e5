/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief Internal: the framed sentence (address and fields) and the field
 *        parsers shared by the sentence decoders.
 */
#ifndef DRDC_NMEA_IMPL_H
#define DRDC_NMEA_IMPL_H

#include <stddef.h>
#include <stdint.h>

#include <drdc/nmea.h>

/** Most fields kept; a sentence of at most 80 characters may have more
 *  (all empty), which no decoder reads. */
#define NMEA_FIELDS_MAX 32u

/** One field: `n` characters at `p` (inside the caller's text). */
typedef struct nmea_field {
  const char *p;
  size_t n;
} nmea_field_t;

/** A sentence whose framing, checksum and address are valid. */
typedef struct nmea_frame {
  drdc_nmea_type_t type;
  char talker[3];
  size_t count;                      /**< fields after the address */
  nmea_field_t f[NMEA_FIELDS_MAX];   /**< f[0] is field 1 */
} nmea_frame_t;

/** Check framing, characters, length and checksum, decode the address
 *  and split the fields. */
drdc_status_t nmea_frame(const char *text, size_t length, nmea_frame_t *fr);

/** Field `i` (1-based as in the standard), or an empty field when the
 *  sentence has fewer. */
nmea_field_t nmea_field(const nmea_frame_t *fr, size_t i);

/** Unsigned decimal of `min_digits`..`max_digits` digits (<= 9). */
drdc_status_t nmea_uint(nmea_field_t f, size_t min_digits, size_t max_digits,
                        int32_t *out);

/** [-]digits[.digits] -> value x num x 2^frac / den, rounded once to
 *  nearest, ties away from zero (drdc_fx_muldiv_s64). */
drdc_status_t nmea_fixed(nmea_field_t f, int64_t num, int64_t den,
                         unsigned frac, int64_t *out);

/** hhmmss[.s..s] (up to 9 decimals) -> time of day, exact. */
drdc_status_t nmea_tod(nmea_field_t f, drdc_nmea_tod_t *out);

/** (d)ddmm[.m..m] with up to 10 decimals and its hemisphere -> nas,
 *  exact. `latitude` selects N/S and 90 degrees, else E/W and 180. */
drdc_status_t nmea_angle(nmea_field_t value, nmea_field_t hemisphere,
                         int latitude, drdc_nas_t *out);

/** Sentence decoders: `fr` is framed; they fill `*n` (a scratch copy). */
/* The optional HDOP (field 8), altitude (field 9) and geoid separation
 * (field `separation`) that GGA and GNS share; each present one is parsed
 * and flagged in n->has. */
drdc_status_t nmea_precision(const nmea_frame_t *fr, size_t separation,
                             drdc_nmea_t *n);

drdc_status_t nmea_gga(const nmea_frame_t *fr, drdc_nmea_t *n);
drdc_status_t nmea_rmc(const nmea_frame_t *fr, drdc_nmea_t *n);
drdc_status_t nmea_gns(const nmea_frame_t *fr, drdc_nmea_t *n);
drdc_status_t nmea_zda(const nmea_frame_t *fr, drdc_nmea_t *n);
drdc_status_t nmea_gst(const nmea_frame_t *fr, drdc_nmea_t *n);

#endif /* DRDC_NMEA_IMPL_H */
