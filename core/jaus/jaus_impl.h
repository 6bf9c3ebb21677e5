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

#include <drdc/jaus_pose.h>
#include <drdc/jaus_scaled.h>
#include <drdc/status.h>

/** Scaled fields of a pose body (presence bits 0-7). */
#define JAUS_POSE_SCALED 8u

/** Nano-arcseconds in 90 and 180 degrees. */
#define JAUS_NAS_90  INT64_C(324000000000000)
#define JAUS_NAS_180 INT64_C(648000000000000)
/** Metres as Q15.16 / Q47.16 raw values. */
#define JAUS_METRES(m) ((int64_t)(m)*INT64_C(65536))
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

/** Rows of drdc__jaus_fields: the 32 fields of the two messages in the two
 *  forms have 12 distinct ones, each stored once; a message's fields in
 *  a form are their rows, one byte each. _RA3 and _AS:
 *  the type of RA 3.x and of AS6009. */
#define JAUS_F_LAT_RA3   0u
#define JAUS_F_LAT_AS    1u
#define JAUS_F_LON_RA3   2u
#define JAUS_F_LON_AS    3u
#define JAUS_F_ALT_RA3   4u
#define JAUS_F_ALT_AS    5u
#define JAUS_F_XY_RA3    6u
#define JAUS_F_XY_AS     7u
#define JAUS_F_ANGLE_RA3 8u
#define JAUS_F_ANGLE_AS  9u
#define JAUS_F_POS_RMS   10u
#define JAUS_F_ATT_RMS   11u
#define JAUS_FIELDS      12u

/** The distinct fields (pose_messages.c). */
extern const jaus_field_t drdc__jaus_fields[JAUS_FIELDS];

/** Bytes of the presence vector, before the fields. */
#define JAUS_PRESENCE_BYTES 2u
/** Presence bit of the time stamp, the last field (4 bytes). */
#define JAUS_TIME_STAMP_BIT 8u
/** Bytes of the time stamp. */
#define JAUS_TIME_STAMP_BYTES 4u

/** 1 when field `bit` is present. */
static inline int jaus_present(uint16_t presence, unsigned bit)
{
  return ((((uint32_t)presence) >> bit) & 1u) != 0u;
}

/** Bytes of field `bit` on the wire: bits 0-3 32-bit, 4-7 16-bit, 8 the
 *  32-bit time stamp, the same in both messages and both forms; the
 *  field tables' types have these sizes (checked by the suites' bytes).
 *  Positions come from this alone, so reads stay inside the length
 *  drdc_jaus_pose_size() gave. */
static inline size_t jaus_field_size(unsigned bit)
{
  return ((bit >= 4u) && (bit < JAUS_TIME_STAMP_BIT)) ? 2u : 4u;
}

/** Write the n low bytes of u at p, least significant first. */
static inline void jaus_put_le(uint8_t *p, uint32_t u, size_t n)
{
  size_t k;

  for (k = 0u; k < n; k++) {
    p[k] = (uint8_t)((u >> (8u * (uint32_t)k)) & UINT32_C(0xFF));
  }
}

/** n little-endian bytes at p as an unsigned value. */
static inline uint32_t jaus_get_le(const uint8_t *p, size_t n)
{
  uint32_t u = 0u;
  size_t k;

  for (k = 0u; k < n; k++) {
    u |= ((uint32_t)p[k]) << (8u * (uint32_t)k);
  }
  return u;
}

/*
 * The two bodies are read and written in place, field by field, through
 * a pair of pointers of which exactly one is set (the other NULL): no
 * copy of the eight raw values on the stack. The time stamp's check
 * (pose_stamp.c) is a call of its own, so its unpacked fields are not
 * live where the fields are scaled.
 */

/**
 * Validate the fields present in the body (`local` or `global`), check
 * the time stamp and the capacity, then scale the fields by `fields`
 * (their rows of drdc__jaus_fields, in presence-bit order) and write them
 * little-endian. Nothing is written before every check has
 * passed: outputs unchanged on error.
 */
drdc_status_t drdc_jaus_body_pack(const uint8_t *fields, drdc_jaus_form_t form,
                                  const drdc_jaus_local_pose_t *local,
                                  const drdc_jaus_global_pose_t *global,
                                  uint8_t *buf, size_t capacity,
                                  size_t *length);

/**
 * Read a body of exactly `length` bytes and decode its fields by
 * `fields` into `local` or `global`; absent fields are 0. Two passes:
 * the first decodes and checks everything (a local X, Y or Z must fit
 * Q15.16: DRDC_E_OVERFLOW after every other check), the second decodes
 * again into the body, so the body is unchanged on error.
 */
drdc_status_t drdc_jaus_body_unpack(const uint8_t *fields,
                                    drdc_jaus_form_t form, const uint8_t *buf,
                                    size_t length,
                                    drdc_jaus_local_pose_t *local,
                                    drdc_jaus_global_pose_t *global);

/** DRDC_OK when the time stamp is absent from `presence` or unpacks
 *  (drdc_time_jaus_unpack()), else that function's status. */
drdc_status_t drdc_jaus_stamp_check(uint16_t presence, uint32_t time_stamp);

/** A binary angle as a signed raw value in [-2^31, 2^31). */
int64_t drdc_jaus_angle_value(uint32_t bam);

/** A raw value in [-2^31, 2^31] as a binary angle (2^31 wraps to -pi). */
uint32_t drdc_jaus_angle_bam(int64_t value);

#endif /* DRDC_JAUS_IMPL_H */
