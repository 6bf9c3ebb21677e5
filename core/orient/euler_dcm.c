/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_orient
 * @brief Rotation matrix of Z-Y-X Euler angles: apart from euler.c,
 *        whose quaternion conversions have speed goals, so that it can
 *        be compiled for flash.
 */
#include <drdc/orient.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>
#include <drdc/fixed_trig.h>

#include "orient_impl.h"

/* Q1.30 product of three Q1.30 factors a b c plus or minus d e, rounded
 * once: a b is kept to Q1.31 (one rounding of 0.25 LSB), then the sum of
 * the two Q61 products is rounded to Q1.30. */
static drdc_q1_30_t triple(int32_t a, int32_t b, int32_t c, int32_t d,
                           int32_t e, int sign)
{
  int64_t ab = drdc_fx_rshift_round_s64((int64_t)a * b, 29u); /* Q1.31 */
  int64_t de = (int64_t)d * e * 2;                            /* Q61 */
  int64_t sum = (sign > 0) ? ((ab * c) + de) : ((ab * c) - de);

  return (drdc_q1_30_t)drdc_fx_rshift_round_s64(sum, 31u);
}

drdc_status_t drdc_dcm_from_euler(const drdc_euler_t *e, drdc_dcm_t *out)
{
  drdc_q1_30_t cy;
  drdc_q1_30_t sy;
  drdc_q1_30_t cp;
  drdc_q1_30_t sp;
  drdc_q1_30_t cr;
  drdc_q1_30_t sr;

  if ((e == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  drdc_fx_sincos_bam32(e->yaw, &sy, &cy);
  drdc_fx_sincos_bam32(e->pitch, &sp, &cp);
  drdc_fx_sincos_bam32(e->roll, &sr, &cr);
  out->m[0][0] = (drdc_q1_30_t)drdc_fx_rshift_round_s64((int64_t)cy * cp, 30u);
  out->m[0][1] = triple(cy, sp, sr, sy, cr, -1);
  out->m[0][2] = triple(cy, sp, cr, sy, sr, 1);
  out->m[1][0] = (drdc_q1_30_t)drdc_fx_rshift_round_s64((int64_t)sy * cp, 30u);
  out->m[1][1] = triple(sy, sp, sr, cy, cr, 1);
  out->m[1][2] = triple(sy, sp, cr, cy, sr, -1);
  out->m[2][0] = -sp;
  out->m[2][1] = (drdc_q1_30_t)drdc_fx_rshift_round_s64((int64_t)cp * sr, 30u);
  out->m[2][2] = (drdc_q1_30_t)drdc_fx_rshift_round_s64((int64_t)cp * cr, 30u);
  return DRDC_OK;
}
