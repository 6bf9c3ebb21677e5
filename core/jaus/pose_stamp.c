/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_jaus_pose
 * @brief The time stamp check of the JAUS pose bodies: a present stamp
 *        must unpack to valid day, hour, minute, second and millisecond
 *        fields.
 */
#include <drdc/time_jaus.h>

#include "jaus_impl.h"

drdc_status_t drdc_jaus_stamp_check(uint16_t presence, uint32_t time_stamp)
{
  drdc_time_jaus_fields_t stamp;

  if (jaus_present(presence, JAUS_TIME_STAMP_BIT) == 0) {
    return DRDC_OK;
  }
  return drdc_time_jaus_unpack(time_stamp, &stamp);
}
