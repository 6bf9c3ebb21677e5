/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_orient
 * @brief Frame changes FRD <-> FLU (body) and NED <-> ENU (world) for
 *        vectors and attitude quaternions.
 */
#include <drdc/orient.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>

#include "orient_impl.h"

/* 1/sqrt(2) in Q2.62, rounded: 2^61.5 = 3260954456333195553.3. With it
 * the products below are correctly rounded to Q1.30 except within 2^-32
 * LSB of a tie. */
#define INV_SQRT2_Q62 INT64_C(3260954456333195553)

drdc_status_t drdc_frame_frd_flu_q15_16(const drdc_vec3_q15_16_t *v,
                                        drdc_vec3_q15_16_t *out)
{
  drdc_vec3_q15_16_t r;

  if ((v == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  if ((v->y == INT32_MIN) || (v->z == INT32_MIN)) {
    return DRDC_E_OVERFLOW;
  }
  r.x = v->x;
  r.y = -v->y;
  r.z = -v->z;
  *out = r;
  return DRDC_OK;
}

drdc_status_t drdc_frame_ned_enu_q15_16(const drdc_vec3_q15_16_t *v,
                                        drdc_vec3_q15_16_t *out)
{
  drdc_vec3_q15_16_t r;

  if ((v == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  if (v->z == INT32_MIN) {
    return DRDC_E_OVERFLOW;
  }
  r.x = v->y;
  r.y = v->x;
  r.z = -v->z;
  *out = r;
  return DRDC_OK;
}

drdc_status_t drdc_frame_frd_flu_q47_16(const drdc_vec3_q47_16_t *v,
                                        drdc_vec3_q47_16_t *out)
{
  drdc_vec3_q47_16_t r;

  if ((v == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  if ((v->y == ORIENT_INT64_MIN) || (v->z == ORIENT_INT64_MIN)) {
    return DRDC_E_OVERFLOW;
  }
  r.x = v->x;
  r.y = -v->y;
  r.z = -v->z;
  *out = r;
  return DRDC_OK;
}

drdc_status_t drdc_frame_ned_enu_q47_16(const drdc_vec3_q47_16_t *v,
                                        drdc_vec3_q47_16_t *out)
{
  drdc_vec3_q47_16_t r;

  if ((v == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  if (v->z == ORIENT_INT64_MIN) {
    return DRDC_E_OVERFLOW;
  }
  r.x = v->y;
  r.y = v->x;
  r.z = -v->z;
  *out = r;
  return DRDC_OK;
}

drdc_status_t drdc_frame_frd_flu_quat(const drdc_quat_t *q, drdc_quat_t *out)
{
  drdc_quat_t r;

  if ((q == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  if ((q->x == INT32_MIN) || (q->y == INT32_MIN)) {
    return DRDC_E_OVERFLOW;
  }
  /* q * [0, 1, 0, 0]: a half turn about the body x axis, exact. */
  r.s = -q->x;
  r.x = q->s;
  r.y = q->z;
  r.z = -q->y;
  *out = r;
  return DRDC_OK;
}

static drdc_status_t scaled(int64_t sum, drdc_q1_30_t *out)
{
  int64_t v;
  drdc_status_t st =
      drdc_fx_muldiv_s64(sum, INV_SQRT2_Q62, orient_pow2_s64(62u), &v);

  if ((st != DRDC_OK) || (v > INT32_MAX) || (v < INT32_MIN)) {
    return DRDC_E_OVERFLOW;
  }
  *out = (drdc_q1_30_t)v;
  return DRDC_OK;
}

drdc_status_t drdc_frame_ned_enu_quat(const drdc_quat_t *q, drdc_quat_t *out)
{
  drdc_quat_t r;
  drdc_status_t st;

  if ((q == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  /* [0, r, r, 0] * q: the half turn about (north + east) / sqrt(2) that
   * swaps x and y and negates z. Sums of two int32 fit int64. */
  st = scaled(-((int64_t)q->x + q->y), &r.s);
  if (st == DRDC_OK) {
    st = scaled((int64_t)q->s + q->z, &r.x);
  }
  if (st == DRDC_OK) {
    st = scaled((int64_t)q->s - q->z, &r.y);
  }
  if (st == DRDC_OK) {
    st = scaled((int64_t)q->y - q->x, &r.z);
  }
  if (st == DRDC_OK) {
    *out = r;
  }
  return st;
}
