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

drdc_status_t drdc_jaus_local_pose_pack(const drdc_jaus_local_pose_t *body,
                                        drdc_jaus_form_t form, uint8_t *buf,
                                        size_t capacity, size_t *length)
{
  const jaus_field_t *fields = local_fields_of(form);

  if ((body == NULL) || (buf == NULL) || (length == NULL)) {
    return DRDC_E_NULL;
  }
  if (fields == NULL) {
    return DRDC_E_RANGE;
  }
  return drdc_jaus_body_pack(fields, form, body, NULL, buf, capacity,
                             length);
}

drdc_status_t drdc_jaus_local_pose_unpack(const uint8_t *buf, size_t length,
                                          drdc_jaus_form_t form,
                                          drdc_jaus_local_pose_t *body)
{
  const jaus_field_t *fields = local_fields_of(form);

  if ((buf == NULL) || (body == NULL)) {
    return DRDC_E_NULL;
  }
  if (fields == NULL) {
    return DRDC_E_RANGE;
  }
  /* JAUS allows +-100 km, {le} holds +-32 km: the unpacking reports
   * DRDC_E_OVERFLOW */
  return drdc_jaus_body_unpack(fields, form, buf, length, body, NULL);
}
