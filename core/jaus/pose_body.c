/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_jaus_pose
 * @brief The wire format of the JAUS pose bodies: presence vector,
 *        sizes, the checks before packing and unpacking, and the time
 *        stamp, little-endian by shifts.
 */
#include <stddef.h>

#include <drdc/jaus_pose.h>

#include "jaus_impl.h"

drdc_status_t drdc_jaus_pose_size(uint16_t presence, size_t *size)
{
  size_t n = JAUS_PRESENCE_BYTES;
  unsigned bit;

  if (size == NULL) {
    return DRDC_E_NULL;
  }
  if ((presence & (uint16_t)~DRDC_JAUS_PV_ALL) != 0u) {
    return DRDC_E_RANGE;
  }
  for (bit = 0u; bit <= JAUS_TIME_STAMP_BIT; bit++) {
    if (jaus_present(presence, bit) != 0) {
      n += jaus_field_size(bit);
    }
  }
  *size = n;
  return DRDC_OK;
}

/* The low 32 bits of an integer's two's complement (modulo 2^32). */
static uint32_t to_bits(int64_t v)
{
  return (uint32_t)((uint64_t)v);
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

/* The integer of an n-byte field of a signed or unsigned type, from its
 * bits (two's complement for the signed types). */
static int64_t from_bits(uint32_t u, size_t n, drdc_jaus_type_t type)
{
  int64_t v = (int64_t)u;
  int64_t half = INT64_C(1) << ((8u * (uint32_t)n) - 1u);

  if (((type == DRDC_JAUS_INT16) || (type == DRDC_JAUS_INT32)) && (v >= half)) {
    v -= 2 * half;
  }
  return v;
}

/* The raw value of scaled field `bit` of the body. */
static int64_t field_get(const drdc_jaus_local_pose_t *local,
                         const drdc_jaus_global_pose_t *global, unsigned bit)
{
  const drdc_euler_t *e = (local != NULL) ? &local->pose.e : &global->pose.e;
  int64_t v;

  switch (bit) {
  case 0u:
    v = (local != NULL) ? (int64_t)local->pose.p.x : global->pose.latitude;
    break;
  case 1u:
    v = (local != NULL) ? (int64_t)local->pose.p.y : global->pose.longitude;
    break;
  case 2u:
    v = (local != NULL) ? (int64_t)local->pose.p.z : global->pose.height;
    break;
  case 3u:
    v = (local != NULL) ? local->position_rms : global->position_rms;
    break;
  case 4u:
    v = drdc_jaus_angle_value(e->roll);
    break;
  case 5u:
    v = drdc_jaus_angle_value(e->pitch);
    break;
  case 6u:
    v = drdc_jaus_angle_value(e->yaw);
    break;
  default:
    v = (int64_t)((local != NULL) ? local->attitude_rms : global->attitude_rms);
    break;
  }
  return v;
}

/* Store the raw value of scaled field `bit` into the body; the value lies
 * within the field's limits (and, for a local X, Y, Z, in Q15.16). */
static void field_set(drdc_jaus_local_pose_t *local,
                      drdc_jaus_global_pose_t *global, unsigned bit, int64_t v)
{
  drdc_euler_t *e = (local != NULL) ? &local->pose.e : &global->pose.e;

  switch (bit) {
  case 0u:
    if (local != NULL) {
      local->pose.p.x = (drdc_q15_16_t)v;
    } else {
      global->pose.latitude = v;
    }
    break;
  case 1u:
    if (local != NULL) {
      local->pose.p.y = (drdc_q15_16_t)v;
    } else {
      global->pose.longitude = v;
    }
    break;
  case 2u:
    if (local != NULL) {
      local->pose.p.z = (drdc_q15_16_t)v;
    } else {
      global->pose.height = v;
    }
    break;
  case 3u:
    if (local != NULL) {
      local->position_rms = (drdc_q15_16_t)v;
    } else {
      global->position_rms = (drdc_q15_16_t)v;
    }
    break;
  case 4u:
    e->roll = drdc_jaus_angle_bam(v);
    break;
  case 5u:
    e->pitch = drdc_jaus_angle_bam(v);
    break;
  case 6u:
    e->yaw = drdc_jaus_angle_bam(v);
    break;
  default:
    if (local != NULL) {
      local->attitude_rms = (drdc_bam32_t)v;
    } else {
      global->attitude_rms = (drdc_bam32_t)v;
    }
    break;
  }
}

static int local_fits_q15_16(int64_t v)
{
  return (v >= (int64_t)INT32_MIN) && (v <= (int64_t)INT32_MAX);
}

drdc_status_t drdc_jaus_body_pack(const uint8_t *fields, drdc_jaus_form_t form,
                                  const drdc_jaus_local_pose_t *local,
                                  const drdc_jaus_global_pose_t *global,
                                  uint8_t *buf, size_t capacity, size_t *length)
{
  uint16_t presence = (local != NULL) ? local->presence : global->presence;
  uint32_t time_stamp =
      (local != NULL) ? local->time_stamp : global->time_stamp;
  size_t size = 0u;
  size_t pos = JAUS_PRESENCE_BYTES;
  unsigned bit;
  drdc_status_t st;

  st = drdc_jaus_pose_size(presence, &size);
  if (st != DRDC_OK) {
    return st;
  }
  /* validate everything before writing a byte: each present value within
   * its field's limits (in bit order), the time stamp, the capacity */
  for (bit = 0u; bit < JAUS_POSE_SCALED; bit++) {
    if (jaus_present(presence, bit) != 0) {
      const jaus_field_t *f = &drdc__jaus_fields[fields[bit]];
      int64_t v = field_get(local, global, bit);

      if ((v < f->min) || (v > f->max)) {
        return f->outside;
      }
    }
  }
  st = drdc_jaus_stamp_check(presence, time_stamp);
  if (st != DRDC_OK) {
    return st;
  }
  if (capacity < size) {
    return DRDC_E_BUFFER;
  }
  /* With the field tables' bounds and types and a valid form, a value
   * within its limits always scales: drdc_jaus_scaled_encode() makes no
   * check here that has not passed above, so the buffer is written only
   * on the way to DRDC_OK (its status is still passed on). */
  for (bit = 0u; bit < JAUS_POSE_SCALED; bit++) {
    if (jaus_present(presence, bit) != 0) {
      int64_t v = field_get(local, global, bit);
      const jaus_field_t *f = &drdc__jaus_fields[fields[bit]];
      int64_t integer = 0;

      st = drdc_jaus_scaled_encode(v, f->min, f->max, f->type, form, &integer);
      if (st != DRDC_OK) {
        return st;
      }
      jaus_put_le(&buf[pos], to_bits(integer), jaus_field_size(bit));
      pos += jaus_field_size(bit);
    }
  }
  jaus_put_le(buf, (uint32_t)presence, JAUS_PRESENCE_BYTES);
  if (jaus_present(presence, JAUS_TIME_STAMP_BIT) != 0) {
    jaus_put_le(&buf[size - JAUS_TIME_STAMP_BYTES], time_stamp,
                JAUS_TIME_STAMP_BYTES);
  }
  *length = size;
  return DRDC_OK;
}

drdc_status_t drdc_jaus_body_unpack(const uint8_t *fields,
                                    drdc_jaus_form_t form, const uint8_t *buf,
                                    size_t length,
                                    drdc_jaus_local_pose_t *local,
                                    drdc_jaus_global_pose_t *global)
{
  uint16_t presence;
  uint32_t time_stamp = 0u;
  size_t size = 0u;
  unsigned pass;
  int overflow = 0;
  drdc_status_t st;

  if (length < JAUS_PRESENCE_BYTES) {
    return DRDC_E_TRUNCATED;
  }
  presence = (uint16_t)jaus_get_le(buf, JAUS_PRESENCE_BYTES);
  st = drdc_jaus_pose_size(presence, &size);
  if (st != DRDC_OK) {
    return st;
  }
  if (length < size) {
    return DRDC_E_TRUNCATED;
  }
  if (length > size) {
    return DRDC_E_OVERLONG;
  }
  if (jaus_present(presence, JAUS_TIME_STAMP_BIT) != 0) {
    time_stamp =
        jaus_get_le(&buf[size - JAUS_TIME_STAMP_BYTES], JAUS_TIME_STAMP_BYTES);
  }
  /* From here on every read is inside buf (size == length). Pass 0
   * decodes and checks with the body untouched (a local X, Y or Z outside
   * Q15.16 is reported after the time stamp's check); pass 1 decodes
   * again, which then succeeds, into the body. */
  for (pass = 0u; pass < 2u; pass++) {
    size_t pos = JAUS_PRESENCE_BYTES;
    unsigned bit;

    for (bit = 0u; bit < JAUS_POSE_SCALED; bit++) {
      int64_t v = 0;

      if (jaus_present(presence, bit) != 0) {
        const jaus_field_t *f = &drdc__jaus_fields[fields[bit]];
        size_t n = jaus_field_size(bit);

        st = drdc_jaus_scaled_decode(
            from_bits(jaus_get_le(&buf[pos], n), n, f->type), f->min, f->max,
            f->type, form, &v);
        if (st != DRDC_OK) {
          return st;
        }
        pos += n;
      }
      if (pass == 0u) {
        /* JAUS allows +-100 km, {le} holds +-32 km */
        if ((local != NULL) && (bit < 3u) && (local_fits_q15_16(v) == 0)) {
          overflow = 1;
        }
      } else {
        field_set(local, global, bit, v);
      }
    }
    if (pass == 0u) {
      st = drdc_jaus_stamp_check(presence, time_stamp);
      if (st != DRDC_OK) {
        return st;
      }
      if (overflow != 0) {
        return DRDC_E_OVERFLOW;
      }
    }
  }
  if (local != NULL) {
    local->presence = presence;
    local->time_stamp = time_stamp;
  } else {
    global->presence = presence;
    global->time_stamp = time_stamp;
  }
  return DRDC_OK;
}
