/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Text of drdc geo: angles in decimal degrees or degrees, minutes
 *        and seconds read to nas exactly, and fixed-point values written
 *        as decimals rounded half to even from their exact value.
 */
#ifndef DRDC_TOOL_GEO_TEXT_H
#define DRDC_TOOL_GEO_TEXT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/** nas per degree, minute and second of arc. */
#define GEO_TEXT_NAS_PER_DEGREE INT64_C(3600000000000)
#define GEO_TEXT_NAS_PER_MINUTE INT64_C(60000000000)
#define GEO_TEXT_NAS_PER_SECOND INT64_C(1000000000)
/** Largest |angle| held, degrees: in nas, it and the sum of two pieces
 *  fit int64. GeoConvert reads any; a larger angle is read (so that the
 *  text's other errors come first) and marked too_large. */
#define GEO_TEXT_DEGREES_MAX 1000000

/** Which coordinate a hemisphere letter made of an angle. */
enum geo_text_hemisphere {
  GEO_TEXT_NONE = 0,
  GEO_TEXT_LATITUDE = 1,
  GEO_TEXT_LONGITUDE = 2
};

/** An angle read from text. */
typedef struct geo_text_angle {
  int64_t nas;   /**< the angle, nas, rounded to nearest (ties to even) */
  bool negative; /**< the text's value is below zero or a negative zero
                      ("-0", "0S"), as the sign bit of GeoConvert's double */
  bool exact;    /**< nas is the text's value exactly, no rounding */
  enum geo_text_hemisphere hemisphere; /**< from N, S, E or W, or NONE */
  bool too_large; /**< |angle| beyond GEO_TEXT_DEGREES_MAX: nas is 0 */
} geo_text_angle_t;

/**
 * Read one angle as GeoConvert's DMS::Decode does: decimal degrees, or
 * components with d ' " (and the UTF-8 degree, prime and double prime
 * signs GeoConvert knows) or ':' separators, only the last with a
 * fraction, minutes and seconds below 60; an optional sign; a hemisphere
 * letter N S E W before or after; interior signs add pieces
 * ("39N+0:0:15"). No exponent, nan or inf.
 *
 * @param[out] why on failure, GeoConvert's message for the text (quoting
 *        the offending piece as it does), cut at why_size.
 * @return true and *out written, or false and *why written.
 */
bool geo_text_read_angle(const char *text, geo_text_angle_t *out, char *why,
                         size_t why_size);

/**
 * Read a decimal number of metres, [+-]digits[.digits][e[+-]digits] (at
 * most 1e12 m), to Q47.16, rounded to nearest (ties to even) from its
 * exact value, and what the rounding dropped.
 *
 * @param[out] rest the text's value minus *q16, in units of 2^-48 m
 *        (2^-32 of the Q47.16 LSB), rounded to nearest from the exact
 *        value: |*rest| <= 2^31.
 * @param[out] exact true when no rounding happened to *q16.
 * @return true when the text is such a number.
 */
bool geo_text_read_metres(const char *text, int64_t *q16, int64_t *rest,
                          bool *exact);

/**
 * The value of a number of metres that geo_text_read_metres() reads,
 * plus `add` whole metres, times 10^decimals (-9..18), rounded half to
 * even, or down when `down` is set: exactly, from the text's digits.
 *
 * @param[out] negative whether the text's value plus add is below zero,
 *        or is a negative zero ("-0" and no add).
 * @return true and *out, *negative written; false when the text is not
 *         such a number or the result leaves int64.
 */
bool geo_text_metres_scaled(const char *text, int64_t add, int decimals,
                            bool down, int64_t *out, bool *negative);

/**
 * Write value / unit with `decimals` (>= 0) decimals, rounded to nearest
 * with ties to even from the exact quotient, as printf("%.*f") rounds the
 * exact value of a double. A '-' leads when value < 0, or when value is
 * 0 and `negative` is set (printf's "-0.00"). unit > 0; |value| *
 * 10^decimals / unit < 2^64.
 */
void geo_text_put_fixed(char *out, size_t size, int64_t value, int64_t unit,
                        int decimals, bool negative);

/**
 * Write value / unit as printf("%g") writes the double nearest to it (as
 * GeoConvert's error messages quote the numbers it read or divided):
 * the quotient rounded to 53 significant bits, then to 6 significant
 * digits from that binary value, half to even; trailing zeros dropped,
 * an exponent (1e-05, 1.5e+06) below 1e-4 and from 1e6 on. A '-' as for
 * geo_text_put_fixed(). unit > 0, |value| / unit >= 2^-64.
 */
void geo_text_put_general(char *out, size_t size, int64_t value, int64_t unit,
                          bool negative);

/**
 * Write an angle as GeoConvert's DMS::Encode with `prec` digits (0..15):
 * degrees with prec decimals (prec < 2), degrees and minutes with
 * prec - 2 decimals (prec < 4), or degrees, minutes and seconds with
 * prec - 4 decimals, rounded half to even from the exact nas value; the
 * degrees zero-filled to 2 (latitude) or 3 (longitude) digits, 'd' ' "
 * or `sep` between, and N S E W for the sign.
 */
void geo_text_put_dms(char *out, size_t size, int64_t nas, bool negative,
                      int prec, enum geo_text_hemisphere which, char sep);

#endif /* DRDC_TOOL_GEO_TEXT_H */
