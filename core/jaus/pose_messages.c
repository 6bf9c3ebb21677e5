/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_jaus_pose
 * @brief JAUS Report Global Pose (4402h) <-> {We} and Report Local Pose
 *        (4403h) <-> {le} bodies: each message's field tables per form,
 *        and the public pack/unpack of both over pose_body.c.
 */
#include <stdbool.h>
#include <stddef.h>

#include <drdc/jaus_pose.h>

#include "jaus_impl.h"

/* The limit of local X and Y (and of Z in AS6009): 100 km. */
#define LOCAL_XY JAUS_METRES(100000)

const jaus_field_t drdc__jaus_fields[JAUS_FIELDS] = {
    /* Limits from the JAUS field tables (see jaus_pose.h for the sources),
     * as raw values of the pose types, and the integer type, by form where
     * it differs (RA 3.x signed, AS6009 unsigned); rows JAUS_F_*. */
    {-JAUS_NAS_90, JAUS_NAS_90, DRDC_JAUS_INT32, DRDC_E_LATITUDE},
    {-JAUS_NAS_90, JAUS_NAS_90, DRDC_JAUS_UINT32, DRDC_E_LATITUDE},
    {-JAUS_NAS_180, JAUS_NAS_180, DRDC_JAUS_INT32, DRDC_E_LONGITUDE},
    {-JAUS_NAS_180, JAUS_NAS_180, DRDC_JAUS_UINT32, DRDC_E_LONGITUDE},
    {JAUS_METRES(-10000), JAUS_METRES(35000), DRDC_JAUS_INT32, DRDC_E_RANGE},
    {JAUS_METRES(-10000), JAUS_METRES(35000), DRDC_JAUS_UINT32, DRDC_E_RANGE},
    {-LOCAL_XY, LOCAL_XY, DRDC_JAUS_INT32, DRDC_E_RANGE},
    {-LOCAL_XY, LOCAL_XY, DRDC_JAUS_UINT32, DRDC_E_RANGE},
    {-JAUS_BAM_PI, JAUS_BAM_PI, DRDC_JAUS_INT16, DRDC_E_RANGE},
    {-JAUS_BAM_PI, JAUS_BAM_PI, DRDC_JAUS_UINT16, DRDC_E_RANGE},
    {0, JAUS_METRES(100), DRDC_JAUS_UINT32, DRDC_E_RANGE},
    {0, JAUS_BAM_PI, DRDC_JAUS_UINT16, DRDC_E_RANGE},
};

/* The rows of drdc__jaus_fields of a message's fields in a form; NULL for a
 * value that is not a form (the callers report DRDC_E_RANGE) */
static const uint8_t *fields_of(bool local, drdc_jaus_form_t form)
{
  /* Fields in presence-bit order, by message (global, local) and form
   * (RA 3.x, AS6009). RA 3.x gives local Z the altitude's range. */
  static const uint8_t pose_fields[2][2][JAUS_POSE_SCALED] = {
      {
          /* Report Global Pose */
          {JAUS_F_LAT_RA3, JAUS_F_LON_RA3, JAUS_F_ALT_RA3, JAUS_F_POS_RMS,
           JAUS_F_ANGLE_RA3, JAUS_F_ANGLE_RA3, JAUS_F_ANGLE_RA3,
           JAUS_F_ATT_RMS},
          {JAUS_F_LAT_AS, JAUS_F_LON_AS, JAUS_F_ALT_AS, JAUS_F_POS_RMS,
           JAUS_F_ANGLE_AS, JAUS_F_ANGLE_AS, JAUS_F_ANGLE_AS, JAUS_F_ATT_RMS},
      },
      {
          /* Report Local Pose */
          {JAUS_F_XY_RA3, JAUS_F_XY_RA3, JAUS_F_ALT_RA3, JAUS_F_POS_RMS,
           JAUS_F_ANGLE_RA3, JAUS_F_ANGLE_RA3, JAUS_F_ANGLE_RA3,
           JAUS_F_ATT_RMS},
          {JAUS_F_XY_AS, JAUS_F_XY_AS, JAUS_F_XY_AS, JAUS_F_POS_RMS,
           JAUS_F_ANGLE_AS, JAUS_F_ANGLE_AS, JAUS_F_ANGLE_AS, JAUS_F_ATT_RMS},
      },
  };
  const uint8_t *f = NULL;

  if ((form == DRDC_JAUS_FORM_RA3) || (form == DRDC_JAUS_FORM_AS6009)) {
    f = pose_fields[local ? 1 : 0][(form == DRDC_JAUS_FORM_AS6009) ? 1 : 0];
  }
  return f;
}

/* Either message's pack once its body (local or global, the other NULL)
 * is known to be there: the remaining NULL checks, then the form. */
static inline drdc_status_t pack(const drdc_jaus_local_pose_t *local,
                                 const drdc_jaus_global_pose_t *global,
                                 drdc_jaus_form_t form, uint8_t *buf,
                                 size_t capacity, size_t *length)
{
  const uint8_t *fields = fields_of(local != NULL, form);

  if ((buf == NULL) || (length == NULL)) {
    return DRDC_E_NULL;
  }
  if (fields == NULL) {
    return DRDC_E_RANGE;
  }
  return drdc_jaus_body_pack(fields, form, local, global, buf, capacity,
                             length);
}

/* Either message's unpack once its body is known to be there (every
 * decoded value lies within its field's limits, which fit the pose
 * types; a local X, Y or Z beyond Q15.16 is DRDC_E_OVERFLOW: JAUS allows
 * +-100 km, {le} holds +-32 km) */
static inline drdc_status_t unpack(const uint8_t *buf, size_t length,
                                   drdc_jaus_form_t form,
                                   drdc_jaus_local_pose_t *local,
                                   drdc_jaus_global_pose_t *global)
{
  const uint8_t *fields = fields_of(local != NULL, form);

  if (buf == NULL) {
    return DRDC_E_NULL;
  }
  if (fields == NULL) {
    return DRDC_E_RANGE;
  }
  return drdc_jaus_body_unpack(fields, form, buf, length, local, global);
}

drdc_status_t drdc_jaus_global_pose_pack(const drdc_jaus_global_pose_t *body,
                                         drdc_jaus_form_t form, uint8_t *buf,
                                         size_t capacity, size_t *length)
{
  if (body == NULL) {
    return DRDC_E_NULL;
  }
  return pack(NULL, body, form, buf, capacity, length);
}

drdc_status_t drdc_jaus_global_pose_unpack(const uint8_t *buf, size_t length,
                                           drdc_jaus_form_t form,
                                           drdc_jaus_global_pose_t *body)
{
  if (body == NULL) {
    return DRDC_E_NULL;
  }
  return unpack(buf, length, form, NULL, body);
}

drdc_status_t drdc_jaus_local_pose_pack(const drdc_jaus_local_pose_t *body,
                                        drdc_jaus_form_t form, uint8_t *buf,
                                        size_t capacity, size_t *length)
{
  if (body == NULL) {
    return DRDC_E_NULL;
  }
  return pack(body, NULL, form, buf, capacity, length);
}

drdc_status_t drdc_jaus_local_pose_unpack(const uint8_t *buf, size_t length,
                                          drdc_jaus_form_t form,
                                          drdc_jaus_local_pose_t *body)
{
  if (body == NULL) {
    return DRDC_E_NULL;
  }
  return unpack(buf, length, form, body, NULL);
}
