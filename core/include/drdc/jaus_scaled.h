/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_jaus_scaled
 * @brief JAUS scaled integers: a real value in [min, max] <-> an int8,
 *        uint8, int16, uint16, int32 or uint32 field, in the JAUS
 *        Reference Architecture 3.x form and in the AS6009 form.
 */
#ifndef DRDC_JAUS_SCALED_H
#define DRDC_JAUS_SCALED_H

#include <stdint.h>

#include <drdc/status.h>

/**
 * @defgroup drdc_jaus_scaled JAUS scaled integers
 *
 * JAUS sends a bounded real value as an integer field: the real range
 * [min, max] is mapped linearly onto an integer range [ilo, ihi] of the
 * field's type,
 *
 *     real = min + (integer - ilo) x (max - min) / (ihi - ilo).
 *
 * The two forms differ only in the integer range of the signed types:
 *
 * | type | RA 3.x [ilo, ihi] | AS6009 [ilo, ihi] |
 * |---|---|---|
 * | uint8/16/32 | [0, 2^n - 1] | [0, 2^n - 1] |
 * | int8/16/32  | [-(2^(n-1) - 1), 2^(n-1) - 1] | [-2^(n-1), 2^(n-1) - 1] |
 *
 * - **JAUS RA 3.x** (Reference Architecture 3.3, "scaled integer":
 *   Real = Integer x ScaleFactor + Bias). Unsigned: Bias = min,
 *   ScaleFactor = (max - min) / (2^n - 1). Signed: Bias = (min + max) / 2,
 *   ScaleFactor = (max - min) / (2^n - 2): the range is symmetric, the
 *   midpoint of [min, max] is integer 0 exactly, and the most negative
 *   integer (-128, -32768, -2^31) is not used (decoded it lies below
 *   min: an error, or min for the _sat form).
 * - **AS6009** (JAUS Mobility Service Set, with the scaled_range of the
 *   JSIDL, AS5684): ScaleFactor = (max - min) / (2^n - 1) and the whole
 *   integer range of the type is used, min <-> the type's minimum, for
 *   signed and unsigned types alike; the midpoint of [min, max] falls
 *   half-way between -1 and 0 for signed types.
 *
 * The same bounds therefore give different integers for signed fields in
 * the two forms; a receiver must decode with the form of the sender.
 *
 * **Formats**: `value`, `min` and `max` are int64_t raw values of one
 * fixed-point format of the caller's choice (Q47.16 metres, drdc_nas_t
 * nano-arcseconds, Q15.16 widened, ...); the mapping does not depend on
 * the format, only on the raw values. The integer is an int64_t holding
 * the field's value (cast it to the field's type to send it).
 *
 * **Rounding**: one rounding, to nearest with ties away from zero in the
 * rounded quantity (the integer when encoding, the raw real value when
 * decoding), so the encoding of a value mirrored about the RA signed
 * midpoint is the negated integer; older implementations that added 0.5
 * and truncated rounded negative values wrongly. Exact rational
 * intermediate: one factor of the product is the integer span (below
 * 2^32), so quotient and remainder come exactly from 64-bit arithmetic
 * (32 steps of Horner's rule), without a 128-bit product or division;
 * no call but the range lookup.
 *
 * **Round trips**: decode(encode(v)) is within half a ScaleFactor of v;
 * encode(decode(i)) == i exactly whenever the real format resolves the
 * ScaleFactor (max - min >= ihi - ilo raw LSB).
 *
 * **Domain**: min < max and max - min <= INT64_MAX (else DRDC_E_RANGE).
 *
 * Accuracy: correctly rounded, 0 LSB against an exact model with Python's
 * fractions.Fraction (tests/ref/gen_jaus.py): every type and form at min,
 * max, zero, negative and random values, both directions.
 * @{
 */

/** The integer type of a scaled-integer field. */
typedef enum drdc_jaus_type {
  DRDC_JAUS_INT8 = 0,   /**< JAUS byte (signed) */
  DRDC_JAUS_UINT8 = 1,  /**< JAUS unsigned byte */
  DRDC_JAUS_INT16 = 2,  /**< JAUS short integer */
  DRDC_JAUS_UINT16 = 3, /**< JAUS unsigned short integer */
  DRDC_JAUS_INT32 = 4,  /**< JAUS integer */
  DRDC_JAUS_UINT32 = 5  /**< JAUS unsigned integer */
} drdc_jaus_type_t;

/** Which standard's scaled-integer mapping (see the table above). */
typedef enum drdc_jaus_form {
  DRDC_JAUS_FORM_RA3 = 0,   /**< JAUS Reference Architecture 3.x */
  DRDC_JAUS_FORM_AS6009 = 1 /**< SAE AS6009 (JSIDL scaled_range) */
} drdc_jaus_form_t;

/**
 * Integer range [ilo, ihi] of a field type in a form.
 *
 * @param type field type
 * @param form RA 3.x or AS6009
 * @param[out] ilo smallest integer used; unchanged on error
 * @param[out] ihi largest integer used; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `ilo` or `ihi` is NULL
 * @retval DRDC_E_RANGE `type` or `form` is not one of the enumerators
 */
drdc_status_t drdc_jaus_scaled_range(drdc_jaus_type_t type,
                                     drdc_jaus_form_t form, int64_t *ilo,
                                     int64_t *ihi);

/**
 * Encode a real value as a scaled integer.
 *
 * @param value real value, raw, min <= value <= max
 * @param min   real lower limit, raw (same format as `value`)
 * @param max   real upper limit, raw, > min
 * @param type  field type
 * @param form  RA 3.x or AS6009
 * @param[out] integer ilo + round((value - min) x (ihi - ilo) / (max -
 *             min)), ties away from zero; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `integer` is NULL
 * @retval DRDC_E_RANGE value outside [min, max], min >= max, max - min
 *         beyond INT64_MAX, or a bad `type` or `form`
 *
 * @code
 * int64_t i;
 * // heading -180..180 degrees in Q47.16, int16, RA 3.x: 90 degrees
 * drdc_jaus_scaled_encode(INT64_C(90) << 16, INT64_C(-180) << 16,
 *                         INT64_C(180) << 16, DRDC_JAUS_INT16,
 *                         DRDC_JAUS_FORM_RA3, &i);   // i = 16384 (16383.5)
 * @endcode
 */
drdc_status_t drdc_jaus_scaled_encode(int64_t value, int64_t min, int64_t max,
                                      drdc_jaus_type_t type,
                                      drdc_jaus_form_t form, int64_t *integer);

/**
 * Saturating drdc_jaus_scaled_encode(): a value below min encodes as
 * ilo, above max as ihi.
 *
 * @retval DRDC_OK written
 * @retval DRDC_W_SATURATED value outside [min, max]: clamped, written
 * @retval DRDC_E_NULL `integer` is NULL
 * @retval DRDC_E_RANGE min >= max, max - min beyond INT64_MAX, or a bad
 *         `type` or `form`
 */
drdc_status_t drdc_jaus_scaled_encode_sat(int64_t value, int64_t min,
                                          int64_t max, drdc_jaus_type_t type,
                                          drdc_jaus_form_t form,
                                          int64_t *integer);

/**
 * Decode a scaled integer to a real value.
 *
 * @param integer field value, ilo..ihi
 * @param min, max real limits, raw, min < max
 * @param type  field type
 * @param form  RA 3.x or AS6009
 * @param[out] value min + round((integer - ilo) x (max - min) / (ihi -
 *             ilo)), ties away from zero, raw in the format of min and
 *             max; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `value` is NULL
 * @retval DRDC_E_RANGE integer outside [ilo, ihi] (for example -32768 in
 *         an RA 3.x int16), min >= max, max - min beyond INT64_MAX, or a
 *         bad `type` or `form`
 */
drdc_status_t drdc_jaus_scaled_decode(int64_t integer, int64_t min, int64_t max,
                                      drdc_jaus_type_t type,
                                      drdc_jaus_form_t form, int64_t *value);

/**
 * Saturating drdc_jaus_scaled_decode(): an integer below ilo decodes as
 * min, above ihi as max.
 *
 * @retval DRDC_OK written
 * @retval DRDC_W_SATURATED integer outside [ilo, ihi]: clamped, written
 * @retval DRDC_E_NULL `value` is NULL
 * @retval DRDC_E_RANGE min >= max, max - min beyond INT64_MAX, or a bad
 *         `type` or `form`
 */
drdc_status_t drdc_jaus_scaled_decode_sat(int64_t integer, int64_t min,
                                          int64_t max, drdc_jaus_type_t type,
                                          drdc_jaus_form_t form,
                                          int64_t *value);

/** @} */

#endif /* DRDC_JAUS_SCALED_H */
