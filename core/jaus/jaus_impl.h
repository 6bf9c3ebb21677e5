/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_jaus_pose
 * @brief Internal: the table-driven wire format shared by the pose bodies.
 *
 * Both pose bodies are a presence vector, eight scaled fields (bits 0-7)
 * and a time stamp (bit 8). A message describes its eight scaled fields
 * by a table per form; pose_body.c validates, scales and puts them on the
 * wire, and back.
 */
#ifndef DRDC_JAUS_IMPL_H
#define DRDC_JAUS_IMPL_H

#include <stddef.h>
#include <stdint.h>

#include <drdc/jaus_scaled.h>
#include <drdc/status.h>

/** Scaled fields of a pose body (presence bits 0-7). */
#define JAUS_POSE_SCALED 8u

/** Nano-arcseconds in 90 and 180 degrees. */
#define JAUS_NAS_90 INT64_C(324000000000000)
#define JAUS_NAS_180 INT64_C(648000000000000)
/** Metres as Q15.16 / Q47.16 raw values. */
#define JAUS_METRES(m) ((int64_t)(m) * INT64_C(65536))
/** pi as a binary angle (2^32 per turn). */
#define JAUS_BAM_PI INT64_C(2147483648)

/** One scaled field: real limits as raw values, integer type, and the
 *  status of a value outside the limits when packing (24 bytes). */
typedef struct jaus_field {
  int64_t min;
  int64_t max;
  drdc_jaus_type_t type;
  drdc_status_t outside;
} jaus_field_t;

/** A pose body with its fields as raw real values. */
typedef struct jaus_body {
  uint16_t presence;
  int64_t value[JAUS_POSE_SCALED]; /* raw values of bits 0-7 */
  uint32_t stamp;                  /* bit 8 */
} jaus_body_t;

/**
 * Validate and scale the fields present in `body` by `fields`, then write
 * them little-endian. Outputs unchanged on error.
 */
drdc_status_t drdc_jaus_body_pack(const jaus_field_t *fields,
                                  drdc_jaus_form_t form,
                                  const jaus_body_t *body, uint8_t *buf,
                                  size_t capacity, size_t *length);

/**
 * Read a body of exactly `length` bytes and decode its fields by
 * `fields` into `body` (the caller's scratch copy); absent fields are 0.
 * On error `body` holds partial results: the public functions copy it
 * out only on success.
 */
drdc_status_t drdc_jaus_body_unpack(const jaus_field_t *fields,
                                    drdc_jaus_form_t form,
                                    const uint8_t *buf, size_t length,
                                    jaus_body_t *body);

/** A binary angle as a signed raw value in [-2^31, 2^31). */
int64_t drdc_jaus_angle_value(uint32_t bam);

/** A raw value in [-2^31, 2^31] as a binary angle (2^31 wraps to -pi). */
uint32_t drdc_jaus_angle_bam(int64_t value);

#endif /* DRDC_JAUS_IMPL_H */
