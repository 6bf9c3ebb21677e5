/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_jaus_pose
 * @brief JAUS Report Local Pose (4403h) body <-> {le} with RMS values and
 *        time stamp.
 */
#include <stddef.h>

#include <drdc/jaus_pose.h>

#include "jaus_impl.h"

/* The limit of X and Y (and of Z in AS6009): 100 km. */
#define LOCAL_XY JAUS_METRES(100000)

static const jaus_field_t *local_fields_of(drdc_jaus_form_t form)
{
  /* Fields in presence-bit order; limits from the JAUS field tables (see
   * jaus_pose.h for the sources). RA 3.x gives Z the altitude's range. */
  static const jaus_field_t fields_ra3[JAUS_POSE_SCALED] = {
    { -LOCAL_XY, LOCAL_XY, DRDC_JAUS_INT32, DRDC_E_RANGE },
    { -LOCAL_XY, LOCAL_XY, DRDC_JAUS_INT32, DRDC_E_RANGE },
    { JAUS_METRES(-10000), JAUS_METRES(35000), DRDC_JAUS_INT32, DRDC_E_RANGE },
    { 0, JAUS_METRES(100), DRDC_JAUS_UINT32, DRDC_E_RANGE },
    { -JAUS_BAM_PI, JAUS_BAM_PI, DRDC_JAUS_INT16, DRDC_E_RANGE },
    { -JAUS_BAM_PI, JAUS_BAM_PI, DRDC_JAUS_INT16, DRDC_E_RANGE },
    { -JAUS_BAM_PI, JAUS_BAM_PI, DRDC_JAUS_INT16, DRDC_E_RANGE },
    { 0, JAUS_BAM_PI, DRDC_JAUS_UINT16, DRDC_E_RANGE },
  };

  static const jaus_field_t fields_as6009[JAUS_POSE_SCALED] = {
    { -LOCAL_XY, LOCAL_XY, DRDC_JAUS_UINT32, DRDC_E_RANGE },
    { -LOCAL_XY, LOCAL_XY, DRDC_JAUS_UINT32, DRDC_E_RANGE },
    { -LOCAL_XY, LOCAL_XY, DRDC_JAUS_UINT32, DRDC_E_RANGE },
    { 0, JAUS_METRES(100), DRDC_JAUS_UINT32, DRDC_E_RANGE },
    { -JAUS_BAM_PI, JAUS_BAM_PI, DRDC_JAUS_UINT16, DRDC_E_RANGE },
    { -JAUS_BAM_PI, JAUS_BAM_PI, DRDC_JAUS_UINT16, DRDC_E_RANGE },
    { -JAUS_BAM_PI, JAUS_BAM_PI, DRDC_JAUS_UINT16, DRDC_E_RANGE },
    { 0, JAUS_BAM_PI, DRDC_JAUS_UINT16, DRDC_E_RANGE },
  };
  const jaus_field_t *f = NULL;

  if (form == DRDC_JAUS_FORM_RA3) {
    f = fields_ra3;
  } else if (form == DRDC_JAUS_FORM_AS6009) {
    f = fields_as6009;
  } else {
    /* not a form: the caller reports DRDC_E_RANGE */
  }
  return f;
}

static int local_fits_q15_16(int64_t v)
{
  return (v >= (int64_t)INT32_MIN) && (v <= (int64_t)INT32_MAX);
}

drdc_status_t drdc_jaus_local_pose_pack(const drdc_jaus_local_pose_t *body,
                                        drdc_jaus_form_t form, uint8_t *buf,
                                        size_t capacity, size_t *length)
{
  const jaus_field_t *fields = local_fields_of(form);
  jaus_body_t b;

  if ((body == NULL) || (buf == NULL) || (length == NULL)) {
    return DRDC_E_NULL;
  }
  if (fields == NULL) {
    return DRDC_E_RANGE;
  }
  b.presence = body->presence;
  b.value[0] = body->pose.p.x;
  b.value[1] = body->pose.p.y;
  b.value[2] = body->pose.p.z;
  b.value[3] = body->position_rms;
  b.value[4] = drdc_jaus_angle_value(body->pose.e.roll);
  b.value[5] = drdc_jaus_angle_value(body->pose.e.pitch);
  b.value[6] = drdc_jaus_angle_value(body->pose.e.yaw);
  b.value[7] = (int64_t)body->attitude_rms;
  b.stamp = body->time_stamp;
  return drdc_jaus_body_pack(fields, form, &b, buf, capacity, length);
}

drdc_status_t drdc_jaus_local_pose_unpack(const uint8_t *buf, size_t length,
                                          drdc_jaus_form_t form,
                                          drdc_jaus_local_pose_t *body)
{
  const jaus_field_t *fields = local_fields_of(form);
  jaus_body_t b;
  drdc_status_t st;

  if ((buf == NULL) || (body == NULL)) {
    return DRDC_E_NULL;
  }
  if (fields == NULL) {
    return DRDC_E_RANGE;
  }
  st = drdc_jaus_body_unpack(fields, form, buf, length, &b);
  if (st != DRDC_OK) {
    return st;
  }
  /* JAUS allows +-100 km, {le} holds +-32 km */
  if ((local_fits_q15_16(b.value[0]) == 0)
      || (local_fits_q15_16(b.value[1]) == 0)
      || (local_fits_q15_16(b.value[2]) == 0)) {
    return DRDC_E_OVERFLOW;
  }
  body->presence = b.presence;
  body->pose.p.x = (drdc_q15_16_t)b.value[0];
  body->pose.p.y = (drdc_q15_16_t)b.value[1];
  body->pose.p.z = (drdc_q15_16_t)b.value[2];
  body->position_rms = (drdc_q15_16_t)b.value[3];
  body->pose.e.roll = drdc_jaus_angle_bam(b.value[4]);
  body->pose.e.pitch = drdc_jaus_angle_bam(b.value[5]);
  body->pose.e.yaw = drdc_jaus_angle_bam(b.value[6]);
  body->attitude_rms = (drdc_bam32_t)b.value[7];
  body->time_stamp = b.stamp;
  return DRDC_OK;
}
