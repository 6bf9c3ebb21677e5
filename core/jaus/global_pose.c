/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_jaus_pose
 * @brief JAUS Report Global Pose (4402h) body <-> {We} with RMS values and
 *        time stamp.
 */
#include <stddef.h>

#include <drdc/jaus_pose.h>

#include "jaus_impl.h"

static const jaus_field_t *global_fields_of(drdc_jaus_form_t form)
{
  /* Fields in presence-bit order; limits from the JAUS field tables (see
   * jaus_pose.h for the sources), as raw values of the pose types. */
  static const jaus_field_t fields_ra3[JAUS_POSE_SCALED] = {
    { -JAUS_NAS_90, JAUS_NAS_90, DRDC_JAUS_INT32, DRDC_E_LATITUDE },
    { -JAUS_NAS_180, JAUS_NAS_180, DRDC_JAUS_INT32, DRDC_E_LONGITUDE },
    { JAUS_METRES(-10000), JAUS_METRES(35000), DRDC_JAUS_INT32, DRDC_E_RANGE },
    { 0, JAUS_METRES(100), DRDC_JAUS_UINT32, DRDC_E_RANGE },
    { -JAUS_BAM_PI, JAUS_BAM_PI, DRDC_JAUS_INT16, DRDC_E_RANGE },
    { -JAUS_BAM_PI, JAUS_BAM_PI, DRDC_JAUS_INT16, DRDC_E_RANGE },
    { -JAUS_BAM_PI, JAUS_BAM_PI, DRDC_JAUS_INT16, DRDC_E_RANGE },
    { 0, JAUS_BAM_PI, DRDC_JAUS_UINT16, DRDC_E_RANGE },
  };

  static const jaus_field_t fields_as6009[JAUS_POSE_SCALED] = {
    { -JAUS_NAS_90, JAUS_NAS_90, DRDC_JAUS_UINT32, DRDC_E_LATITUDE },
    { -JAUS_NAS_180, JAUS_NAS_180, DRDC_JAUS_UINT32, DRDC_E_LONGITUDE },
    { JAUS_METRES(-10000), JAUS_METRES(35000), DRDC_JAUS_UINT32, DRDC_E_RANGE },
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

drdc_status_t drdc_jaus_global_pose_pack(const drdc_jaus_global_pose_t *body,
                                         drdc_jaus_form_t form, uint8_t *buf,
                                         size_t capacity, size_t *length)
{
  const jaus_field_t *fields = global_fields_of(form);

  if ((body == NULL) || (buf == NULL) || (length == NULL)) {
    return DRDC_E_NULL;
  }
  if (fields == NULL) {
    return DRDC_E_RANGE;
  }
  return drdc_jaus_body_pack(fields, form, NULL, body, buf, capacity,
                             length);
}

drdc_status_t drdc_jaus_global_pose_unpack(const uint8_t *buf, size_t length,
                                           drdc_jaus_form_t form,
                                           drdc_jaus_global_pose_t *body)
{
  const jaus_field_t *fields = global_fields_of(form);

  if ((buf == NULL) || (body == NULL)) {
    return DRDC_E_NULL;
  }
  if (fields == NULL) {
    return DRDC_E_RANGE;
  }
  /* every decoded value lies within its field's limits, which fit the
   * pose types */
  return drdc_jaus_body_unpack(fields, form, buf, length, NULL, body);
}
