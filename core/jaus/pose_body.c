/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_jaus_pose
 * @brief The wire format of the JAUS pose bodies: presence vector,
 *        scaled fields and time stamp, little-endian by shifts.
 */
#include <stddef.h>

#include <drdc/jaus_pose.h>
#include <drdc/time_jaus.h>

#include "jaus_impl.h"

/* Bytes of each field in bit order (bits 0-3 32-bit, 4-7 16-bit, 8 the
 * 32-bit time stamp), the same in both messages and both forms; the
 * field tables' types have these sizes (checked by the suites' bytes).
 * Positions come from this table alone, so reads stay inside the length
 * drdc_jaus_pose_size() gave. */
static const uint8_t field_bytes[JAUS_POSE_SCALED + 1u] = { 4u, 4u, 4u, 4u,
                                                            2u, 2u, 2u, 2u,
                                                            4u };

#define PRESENCE_BYTES 2u
#define TIME_STAMP_BIT 8u
#define BYTE_MASK UINT32_C(0xFF)

static int present(uint16_t presence, unsigned bit)
{
  return ((((uint32_t)presence) >> bit) & 1u) != 0u;
}

/* n bytes of u, least significant first. */
static void put_le(uint8_t *p, uint32_t u, size_t n)
{
  size_t k;

  for (k = 0u; k < n; k++) {
    p[k] = (uint8_t)((u >> (8u * (uint32_t)k)) & BYTE_MASK);
  }
}

/* n little-endian bytes as an unsigned value. */
static uint32_t get_le(const uint8_t *p, size_t n)
{
  uint32_t u = 0u;
  size_t k;

  for (k = 0u; k < n; k++) {
    u |= ((uint32_t)p[k]) << (8u * (uint32_t)k);
  }
  return u;
}

/* The integer of an n-byte field of a signed or unsigned type, from its
 * bits (two's complement for the signed types). */
static int64_t from_bits(uint32_t u, size_t n, drdc_jaus_type_t type)
{
  int64_t v = (int64_t)u;
  int64_t half = INT64_C(1) << ((8u * (uint32_t)n) - 1u);

  if (((type == DRDC_JAUS_INT16) || (type == DRDC_JAUS_INT32))
      && (v >= half)) {
    v -= 2 * half;
  }
  return v;
}

/* The low 32 bits of an integer's two's complement (modulo 2^32). */
static uint32_t to_bits(int64_t v)
{
  return (uint32_t)((uint64_t)v);
}

drdc_status_t drdc_jaus_pose_size(uint16_t presence, size_t *size)
{
  size_t n = PRESENCE_BYTES;
  unsigned bit;

  if (size == NULL) {
    return DRDC_E_NULL;
  }
  if ((presence & (uint16_t)~DRDC_JAUS_PV_ALL) != 0u) {
    return DRDC_E_RANGE;
  }
  for (bit = 0u; bit <= TIME_STAMP_BIT; bit++) {
    if (present(presence, bit) != 0) {
      n += field_bytes[bit];
    }
  }
  *size = n;
  return DRDC_OK;
}

int64_t drdc_jaus_angle_value(uint32_t bam)
{
  int64_t v = (int64_t)bam;

  if (v >= JAUS_BAM_PI) {
    v -= 2 * JAUS_BAM_PI;
  }
  return v;
}

uint32_t drdc_jaus_angle_bam(int64_t value)
{
  return to_bits(value);
}

drdc_status_t drdc_jaus_body_pack(const jaus_field_t *fields,
                                  drdc_jaus_form_t form,
                                  const jaus_body_t *body, uint8_t *buf,
                                  size_t capacity, size_t *length)
{
  int64_t integer[JAUS_POSE_SCALED];
  drdc_time_jaus_fields_t stamp;
  size_t size = 0u;
  size_t pos = PRESENCE_BYTES;
  unsigned bit;
  drdc_status_t st;

  st = drdc_jaus_pose_size(body->presence, &size);
  if (st != DRDC_OK) {
    return st;
  }
  /* validate and scale everything before writing a byte */
  for (bit = 0u; bit < JAUS_POSE_SCALED; bit++) {
    if (present(body->presence, bit) != 0) {
      const jaus_field_t *f = &fields[bit];

      if ((body->value[bit] < f->min) || (body->value[bit] > f->max)) {
        return f->outside;
      }
      st = drdc_jaus_scaled_encode(body->value[bit], f->min, f->max, f->type,
                                   form, &integer[bit]);
      if (st != DRDC_OK) {
        return st;
      }
    } else {
      integer[bit] = 0;
    }
  }
  if (present(body->presence, TIME_STAMP_BIT) != 0) {
    st = drdc_time_jaus_unpack(body->stamp, &stamp);
    if (st != DRDC_OK) {
      return st;
    }
  }
  if (capacity < size) {
    return DRDC_E_BUFFER;
  }
  put_le(buf, (uint32_t)body->presence, PRESENCE_BYTES);
  for (bit = 0u; bit < JAUS_POSE_SCALED; bit++) {
    if (present(body->presence, bit) != 0) {
      put_le(&buf[pos], to_bits(integer[bit]), field_bytes[bit]);
      pos += field_bytes[bit];
    }
  }
  if (present(body->presence, TIME_STAMP_BIT) != 0) {
    put_le(&buf[pos], body->stamp, field_bytes[TIME_STAMP_BIT]);
  }
  *length = size;
  return DRDC_OK;
}

drdc_status_t drdc_jaus_body_unpack(const jaus_field_t *fields,
                                    drdc_jaus_form_t form,
                                    const uint8_t *buf, size_t length,
                                    jaus_body_t *body)
{
  drdc_time_jaus_fields_t stamp;
  size_t size = 0u;
  size_t pos = PRESENCE_BYTES;
  unsigned bit;
  drdc_status_t st;

  if (length < PRESENCE_BYTES) {
    return DRDC_E_TRUNCATED;
  }
  body->presence = (uint16_t)get_le(buf, PRESENCE_BYTES);
  st = drdc_jaus_pose_size(body->presence, &size);
  if (st != DRDC_OK) {
    return st;
  }
  if (length < size) {
    return DRDC_E_TRUNCATED;
  }
  if (length > size) {
    return DRDC_E_OVERLONG;
  }
  /* from here on pos + n <= size == length: every read is inside buf */
  for (bit = 0u; bit < JAUS_POSE_SCALED; bit++) {
    body->value[bit] = 0;
    if (present(body->presence, bit) != 0) {
      const jaus_field_t *f = &fields[bit];
      size_t n = field_bytes[bit];
      int64_t integer = from_bits(get_le(&buf[pos], n), n, f->type);

      st = drdc_jaus_scaled_decode(integer, f->min, f->max, f->type, form,
                                   &body->value[bit]);
      if (st != DRDC_OK) {
        return st;
      }
      pos += n;
    }
  }
  body->stamp = 0u;
  if (present(body->presence, TIME_STAMP_BIT) != 0) {
    body->stamp = get_le(&buf[pos], field_bytes[TIME_STAMP_BIT]);
    st = drdc_time_jaus_unpack(body->stamp, &stamp);
    if (st != DRDC_OK) {
      return st;
    }
  }
  return DRDC_OK;
}
