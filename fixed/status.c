/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_status
 * @brief Names of the status codes.
 */
#include <drdc/status.h>

const char *drdc_status_name(drdc_status_t status)
{
  /* Indexed by the enum value; the enum is dense from 0. */
  static const char *const names[DRDC_STATUS_COUNT] = {
    "DRDC_OK",    "DRDC_E_NULL", "DRDC_E_RANGE", "DRDC_E_OVERFLOW",
    "DRDC_E_YEAR", "DRDC_E_MONTH", "DRDC_E_DAY",
  };
  unsigned index = (unsigned)status;

  return (index < (unsigned)DRDC_STATUS_COUNT) ? names[index] : "DRDC_E_?";
}
