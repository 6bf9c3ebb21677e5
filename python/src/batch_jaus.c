/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Array loops of JAUS: scaled integers both ways (exact and
 *        saturating) and the Report Global Pose and Report Local Pose
 *        message bodies, packed and unpacked, one public function call per
 *        element.
 *
 * Only python/build_backend.py compiles this file; drdc/_jaus.py declares
 * the prototypes and the columns. A body's fields travel as a row of 10
 * int64 (presence, then the pose in its struct's order, position RMS,
 * attitude RMS, time stamp; the caller has checked each fits its C
 * field); a body's bytes as a row of DRDC_JAUS_POSE_BODY_MAX bytes with
 * its length. Outputs of an element whose status is an error are 0.
 */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <drdc/jaus_pose.h>
#include <drdc/jaus_scaled.h>

#define BODY_FIELDS 10u

/* value -> integer (encode) or integer -> value (decode), saturating or
 * not: the four functions of jaus_scaled.h by number */
void drdc_batch_jaus_scaled(int32_t which, size_t n, const int64_t *in,
                            const int64_t *min, const int64_t *max,
                            const int32_t *type, const int32_t *form,
                            int64_t *out, int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    int64_t v = 0;
    drdc_jaus_type_t t = (drdc_jaus_type_t)type[i];
    drdc_jaus_form_t f = (drdc_jaus_form_t)form[i];
    drdc_status_t st;

    switch (which) {
    case 0:
      st = drdc_jaus_scaled_encode(in[i], min[i], max[i], t, f, &v);
      break;
    case 1:
      st = drdc_jaus_scaled_encode_sat(in[i], min[i], max[i], t, f, &v);
      break;
    case 2:
      st = drdc_jaus_scaled_decode(in[i], min[i], max[i], t, f, &v);
      break;
    case 3:
      st = drdc_jaus_scaled_decode_sat(in[i], min[i], max[i], t, f, &v);
      break;
    default:
      st = DRDC_E_RANGE;
      break;
    }
    status[i] = (int32_t)st;
    out[i] = drdc_status_is_error(st) ? 0 : v;
  }
}

void drdc_batch_jaus_scaled_range(size_t n, const int32_t *type,
                                  const int32_t *form, int64_t *ilo,
                                  int64_t *ihi, int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    int64_t lo = 0;
    int64_t hi = 0;

    status[i] = (int32_t)drdc_jaus_scaled_range(
        (drdc_jaus_type_t)type[i], (drdc_jaus_form_t)form[i], &lo, &hi);
    ilo[i] = lo;
    ihi[i] = hi;
  }
}

void drdc_batch_jaus_pose_size(size_t n, const uint16_t *presence,
                               int64_t *size, int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    size_t s = 0u;

    status[i] = (int32_t)drdc_jaus_pose_size(presence[i], &s);
    size[i] = (int64_t)s;
  }
}

static void rms_and_stamp_in(const int64_t *r, drdc_q15_16_t *position_rms,
                             drdc_bam32_t *attitude_rms, uint32_t *stamp)
{
  *position_rms = (int32_t)r[7];
  *attitude_rms = (uint32_t)r[8];
  *stamp = (uint32_t)r[9];
}

static void rms_and_stamp_out(int64_t *r, drdc_q15_16_t position_rms,
                              drdc_bam32_t attitude_rms, uint32_t stamp)
{
  r[7] = position_rms;
  r[8] = attitude_rms;
  r[9] = stamp;
}

/* local: 1 for Report Local Pose, 0 for Report Global Pose */
void drdc_batch_jaus_pose_pack(int32_t local, size_t n, const int64_t *fields,
                               int32_t form, uint8_t *body, int64_t *length,
                               int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    const int64_t *r = &fields[i * BODY_FIELDS];
    uint8_t *b = &body[i * DRDC_JAUS_POSE_BODY_MAX];
    size_t len = 0u;
    drdc_status_t st;

    memset(b, 0, DRDC_JAUS_POSE_BODY_MAX);
    if (local != 0) {
      drdc_jaus_local_pose_t p;

      p.presence = (uint16_t)r[0];
      p.pose.p.x = (int32_t)r[1];
      p.pose.p.y = (int32_t)r[2];
      p.pose.p.z = (int32_t)r[3];
      p.pose.e.yaw = (uint32_t)r[4];
      p.pose.e.pitch = (uint32_t)r[5];
      p.pose.e.roll = (uint32_t)r[6];
      rms_and_stamp_in(r, &p.position_rms, &p.attitude_rms, &p.time_stamp);
      st = drdc_jaus_local_pose_pack(&p, (drdc_jaus_form_t)form, b,
                                     DRDC_JAUS_POSE_BODY_MAX, &len);
    } else {
      drdc_jaus_global_pose_t p;

      p.presence = (uint16_t)r[0];
      p.pose.longitude = r[1];
      p.pose.latitude = r[2];
      p.pose.height = r[3];
      p.pose.e.yaw = (uint32_t)r[4];
      p.pose.e.pitch = (uint32_t)r[5];
      p.pose.e.roll = (uint32_t)r[6];
      rms_and_stamp_in(r, &p.position_rms, &p.attitude_rms, &p.time_stamp);
      st = drdc_jaus_global_pose_pack(&p, (drdc_jaus_form_t)form, b,
                                      DRDC_JAUS_POSE_BODY_MAX, &len);
    }
    status[i] = (int32_t)st;
    length[i] = drdc_status_is_error(st) ? 0 : (int64_t)len;
    if (drdc_status_is_error(st)) {
      memset(b, 0, DRDC_JAUS_POSE_BODY_MAX);
    }
  }
}

/* bodies: rows of `width` bytes, `length[i]` of them the body's */
void drdc_batch_jaus_pose_unpack(int32_t local, size_t n, const uint8_t *body,
                                 size_t width, const int64_t *length,
                                 int32_t form, int64_t *fields, int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    const uint8_t *b = &body[i * width];
    int64_t *r = &fields[i * BODY_FIELDS];
    size_t len = (size_t)length[i];
    drdc_status_t st;

    memset(r, 0, BODY_FIELDS * sizeof *r);
    if (local != 0) {
      drdc_jaus_local_pose_t p;

      st = drdc_jaus_local_pose_unpack(b, len, (drdc_jaus_form_t)form, &p);
      if (!drdc_status_is_error(st)) {
        r[0] = p.presence;
        r[1] = p.pose.p.x;
        r[2] = p.pose.p.y;
        r[3] = p.pose.p.z;
        r[4] = p.pose.e.yaw;
        r[5] = p.pose.e.pitch;
        r[6] = p.pose.e.roll;
        rms_and_stamp_out(r, p.position_rms, p.attitude_rms, p.time_stamp);
      }
    } else {
      drdc_jaus_global_pose_t p;

      st = drdc_jaus_global_pose_unpack(b, len, (drdc_jaus_form_t)form, &p);
      if (!drdc_status_is_error(st)) {
        r[0] = p.presence;
        r[1] = p.pose.longitude;
        r[2] = p.pose.latitude;
        r[3] = p.pose.height;
        r[4] = p.pose.e.yaw;
        r[5] = p.pose.e.pitch;
        r[6] = p.pose.e.roll;
        rms_and_stamp_out(r, p.position_rms, p.attitude_rms, p.time_stamp);
      }
    }
    status[i] = (int32_t)st;
  }
}
