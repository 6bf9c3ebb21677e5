/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_fix16
 * @brief fix16_t <-> Q15.16: the same bits, with libfixmath's overflow
 *        marker 0x80000000 kept out of both directions.
 */
#include <drdc/fixed_fix16.h>

#include <stddef.h>

/* libfixmath's fix16_overflow (and fix16_minimum). */
#define FIX16_OVERFLOW INT32_MIN

drdc_status_t drdc_fx_q15_16_from_fix16(int32_t f, drdc_q15_16_t *out)
{
  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if (f == FIX16_OVERFLOW) {
    return DRDC_E_OVERFLOW;
  }
  *out = f;
  return DRDC_OK;
}

drdc_status_t drdc_fx_fix16_from_q15_16(drdc_q15_16_t x, int32_t *out)
{
  if (out == NULL) {
    return DRDC_E_NULL;
  }
  if (x == FIX16_OVERFLOW) {
    return DRDC_E_RANGE;
  }
  *out = x;
  return DRDC_OK;
}
