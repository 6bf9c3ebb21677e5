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

/** Most fields kept: the decoders read fields 1..18 at most (GSA's
 *  system id is field 18); a sentence may have more, which no decoder
 *  reads (the count saturates here, above every decoder's minimum). */
#define NMEA_FIELDS_MAX 20u

/** Characters up to the end of the checksum: the line limits minus CR LF.
 *  Both fit the frame's one-byte field offsets. */
#define NMEA_BODY_MAX      (DRDC_NMEA_LENGTH_MAX - 2u)
#define NMEA_0183_BODY_MAX (DRDC_NMEA_0183_LENGTH_MAX - 2u)

/** One field: `n` characters at `p` (inside the caller's text). */
typedef struct nmea_field {
  const char *p;
  size_t n;
} nmea_field_t;

/** A sentence whose framing, checksum and address are valid. Fields are
 *  kept as one-byte offsets into the text: a sentence has at most
 *  NMEA_BODY_MAX characters. */
typedef struct drdc__nmea_frame {
  const char *text; /**< the sentence, from `$` (talker at
                         text[1], text[2]) */
  drdc_nmea_type_t type;
  uint8_t strict; /**< 1: DRDC_NMEA_STRICT (field counts of the layout) */
  uint8_t count;  /**< fields after the address */
  /** start[i - 1]: offset of field i; field i ends one character before
   *  start[i] (at its ',' or the '*') */
  uint8_t start[NMEA_FIELDS_MAX + 1u];
} nmea_frame_t;

/** Check framing, characters, length and checksum, decode the address
 *  and split the fields. */
drdc_status_t drdc__nmea_frame(const char *text, size_t length, uint32_t flags,
                               nmea_frame_t *fr);

/** Whether the sentence has the fields its decoder needs: `layout`, the
 *  count of NMEA 0183, in strict mode; else `required`, up to its last
 *  required field (the fields after it may be left off). */
static inline int nmea_has_fields(const nmea_frame_t *fr, size_t required,
                                  size_t layout)
{
  size_t need = (fr->strict != 0u) ? layout : required;

  return ((size_t)fr->count >= need) ? 1 : 0;
}

/** Field `i` (1-based as in the standard), or an empty field when the
 *  sentence has fewer. */
static inline nmea_field_t nmea_field(const nmea_frame_t *fr, size_t i)
{
  nmea_field_t f = {NULL, 0u};

  if ((i >= 1u) && (i <= (size_t)fr->count)) {
    f.p = &fr->text[fr->start[i - 1u]];
    f.n = ((size_t)fr->start[i] - (size_t)fr->start[i - 1u]) - 1u;
  }
  return f;
}

/** Mode letters of NMEA 0183 v4.10 (RMC, GLL, VTG, GNS): A autonomous,
 *  D differential, E estimated, F float RTK, M manual, N no fix,
 *  P precise, R RTK, S simulator. */
static inline int nmea_is_mode(char c)
{
  return ((c == 'A') || (c == 'D') || (c == 'E') || (c == 'F') || (c == 'M') ||
          (c == 'N') || (c == 'P') || (c == 'R') || (c == 'S'))
             ? 1
             : 0;
}

/* The field parsers and sentence decoders below write their outputs only
 * when the pointer is not NULL: drdc_nmea_parse() runs a decoder once
 * with NULL to validate the whole sentence, then again into the caller's
 * record (no scratch record on the stack). */

/** Unsigned decimal of `min_digits`..`max_digits` digits (<= 9): the
 *  `n` characters at `p`. */
drdc_status_t drdc__nmea_digits(const char *p, size_t n, size_t min_digits,
                                size_t max_digits, int32_t *out);

/** drdc__nmea_digits() of field `i` (1-based, as nmea_field()). */
drdc_status_t drdc__nmea_uint(const nmea_frame_t *fr, size_t i,
                              size_t min_digits, size_t max_digits,
                              int32_t *out);

/** [-]digits[.digits] of the `n` characters at `p` -> mantissa and
 *  10^decimals (at most 18 digits, 15 decimals: DRDC_E_RANGE beyond). */
drdc_status_t drdc__nmea_decimal(const char *p, size_t n, int64_t *mantissa,
                                 int64_t *scale);

/** Scalings of decimal fields (drdc__nmea_fixed()). */
typedef enum nmea_scale {
  NMEA_METRES_Q47_16 = 0, /**< metres -> Q47.16 m */
  NMEA_METRES_Q15_16 = 1, /**< metres (or a plain number) -> Q15.16 */
  NMEA_KNOTS_Q15_16 = 2,  /**< knots -> Q15.16 m/s */
  NMEA_KMH_Q15_16 = 3,    /**< km/h -> Q15.16 m/s */
  NMEA_DEGREES_BAM32 = 4  /**< degrees -> 2^32 per turn (wrap it) */
} nmea_scale_t;

/** Field `i` as [-]digits[.digits] -> value x num x 2^frac / den of the
 *  scale, rounded once to nearest, ties away from zero
 *  (drdc_fx_muldiv_s64). A Q15.16 result beyond int32_t is written as
 *  INT32_MAX (INT32_MIN if negative) with DRDC_W_SATURATED; a Q47.16
 *  beyond int64_t gives DRDC_E_RANGE. */
drdc_status_t drdc__nmea_fixed(const nmea_frame_t *fr, size_t i,
                               nmea_scale_t scale, int64_t *out);

/** drdc__nmea_fixed() into a Q15.16 field of `n` (unless `n` is NULL):
 *  `*field` written, DRDC_W_SATURATED turned into `beyond_bit` in
 *  n->beyond and `has_bit` set in n->has. */
drdc_status_t drdc__nmea_q15_16(const nmea_frame_t *fr, size_t i,
                                nmea_scale_t scale, drdc_nmea_t *n,
                                drdc_q15_16_t *field, uint32_t has_bit,
                                uint32_t beyond_bit);

/** One letter field `i` that must be `letter` when not empty (the unit
 *  letters of VTG and HDT); strict mode also requires it present. */
drdc_status_t drdc__nmea_letter(const nmea_frame_t *fr, size_t i, char letter);

/** Field `i` as hhmmss[.s..s] (up to 9 decimals) -> time of day, exact. */
drdc_status_t drdc__nmea_tod(const nmea_frame_t *fr, size_t i,
                             drdc_nmea_tod_t *out);

/** Field `i` as (d)ddmm[.m..m] with up to 10 decimals and field i + 1 as
 *  its hemisphere -> nas, exact. `latitude` selects N/S and 90 degrees,
 *  else E/W and 180. */
drdc_status_t drdc__nmea_angle(const nmea_frame_t *fr, size_t i, int latitude,
                               drdc_nas_t *out);

/** The time and position of a fix (GGA, GNS, RMC, GLL): field `time` as
 *  drdc__nmea_tod(), field `latitude` and the one after it as a
 *  latitude, the two after those as a longitude (drdc__nmea_angle()),
 *  checked in that order (the first failure's status) and written into
 *  n->time, n->latitude and n->longitude with their has bits, unless `n`
 *  is NULL. */
drdc_status_t drdc__nmea_fix(const nmea_frame_t *fr, size_t time,
                             size_t latitude, drdc_nmea_t *n);

/** Sentence decoders: `fr` is framed; they fill `*n` (zeroed by the
 *  caller) or, with `n` NULL, only check the sentence, returning the
 *  same status. */
/* The optional HDOP (field 8), altitude (field 9) and geoid separation
 * (field `separation`) that GGA and GNS share; each present one is parsed
 * and flagged in n->has. */
drdc_status_t drdc__nmea_precision(const nmea_frame_t *fr, size_t separation,
                                   drdc_nmea_t *n);

drdc_status_t drdc__nmea_gga(const nmea_frame_t *fr, drdc_nmea_t *n);
drdc_status_t drdc__nmea_rmc(const nmea_frame_t *fr, drdc_nmea_t *n);
drdc_status_t drdc__nmea_gns(const nmea_frame_t *fr, drdc_nmea_t *n);
drdc_status_t drdc__nmea_zda(const nmea_frame_t *fr, drdc_nmea_t *n);
drdc_status_t drdc__nmea_gst(const nmea_frame_t *fr, drdc_nmea_t *n);
drdc_status_t drdc__nmea_gll(const nmea_frame_t *fr, drdc_nmea_t *n);
drdc_status_t drdc__nmea_vtg(const nmea_frame_t *fr, drdc_nmea_t *n);
drdc_status_t drdc__nmea_hdt(const nmea_frame_t *fr, drdc_nmea_t *n);
drdc_status_t drdc__nmea_ths(const nmea_frame_t *fr, drdc_nmea_t *n);
drdc_status_t drdc__nmea_gsa(const nmea_frame_t *fr, drdc_nmea_t *n);

/** An RMC's time of day and date only, whatever its status and mode (for
 *  drdc_nmea_parse_date()): the status letter must still be A or V. */
drdc_status_t drdc__nmea_rmc_date(const nmea_frame_t *fr, drdc_nmea_t *n);

/** The flags' check and the framing every parse begins with: DRDC_OK
 *  with `*fr` the framed sentence, or the status of the first fault. */
drdc_status_t drdc__nmea_open(const char *text, size_t length, uint32_t flags,
                              nmea_frame_t *fr);

/** The caller's record made ready for the second pass (parse.c says
 *  why there are two): every field cleared, the type and talker set. */
void drdc__nmea_begin_record(const nmea_frame_t *fr, const char *text,
                             drdc_nmea_t *out);

/** One sentence type's decoding, for drdc_nmea_parse_some(). */
struct drdc_nmea_decoder {
  drdc_nmea_type_t type;
  /** the sentence's decoder above */
  drdc_status_t (*decode)(const nmea_frame_t *fr, drdc_nmea_t *n);
  /** GGA and GNS: the field of the geoid separation, after which
   *  drdc__nmea_precision() reads HDOP, altitude and separation; 0 for
   *  the others */
  size_t precision;
};

#endif /* DRDC_NMEA_IMPL_H */
