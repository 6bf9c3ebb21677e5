/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Local poses: {l} <-> {W} through the north-east-down plane of a
 *        reference pose, and the Euler forms {le} <-> {l}, {le} <-> {We}.
 *
 * The local frame is the body frame of the reference pose: an offset in
 * it is turned by the reference's attitude into north-east-down at the
 * reference, and drdc_geo_from_ned() / drdc_geo_to_ned() take it to and
 * from the ellipsoid. The poses hold heights above mean sea level; the
 * caller's geoid separation N makes them ellipsoidal (h + N) for the
 * geodesy and back. Every conversion validates all its inputs before it
 * writes its output, which is left unchanged on error.
 */
#include <drdc/geo_pose.h>

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include <drdc/geo_ecef.h>

/* h + n, the ellipsoidal height of the height h above the geoid (Q47.16
 * m) for a checked separation |n| <= DRDC_GEO_HEIGHT_MAX (< 2^40),
 * without signed overflow: the sum is taken modulo 2^64 in uint64_t. A
 * true sum beyond int64_t lands within 2^40 of the other end, far beyond
 * +-DRDC_GEO_HEIGHT_MAX, so the point's check refuses it as it would the
 * true sum (DRDC_E_HEIGHT, after the latitude and longitude); every
 * other sum is exact. uint64_t -> int64_t of a value above INT64_MAX is
 * modulo 2^64 in GCC and Clang (implementation-defined in C99, no
 * undefined behaviour). */
static drdc_q47_16_t ellipsoidal_height(drdc_q47_16_t h, drdc_q47_16_t n)
{
  uint64_t sum = (uint64_t)h + (uint64_t)n;

  return (drdc_q47_16_t)sum;
}

/* the ellipsoidal point of a pose's position (height above the geoid h,
 * separation n) */
static void ellipsoidal(drdc_nas_t lat, drdc_nas_t lon, drdc_q47_16_t h,
                        drdc_q47_16_t n, drdc_geo_point_t *p)
{
  p->lat = lat;
  p->lon = lon;
  p->height = ellipsoidal_height(h, n);
}

/* |N| up to 10 000 km keeps every sum in range */
static bool separation_ok(drdc_q47_16_t n)
{
  return (n <= DRDC_GEO_HEIGHT_MAX) && (n >= -DRDC_GEO_HEIGHT_MAX);
}

/* The errors in this order: the separation, the offset's rotation (a
 * zero ref->q), the reference's position, the result's height, the
 * relative attitude. */
drdc_status_t drdc_pose_w_from_l(const drdc_WPose_t *ref,
                                 drdc_q47_16_t geoid_separation,
                                 const drdc_lPose_t *l, drdc_WPose_t *out)
{
  drdc_vec3_q15_16_t ned = {0, 0, 0};
  drdc_quat_t q = {0, 0, 0, 0};
  drdc_geo_point_t origin;
  drdc_geo_point_t result = {0, 0, 0};
  drdc_status_t att;
  drdc_status_t st;

  if ((ref == NULL) || (l == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  if (!separation_ok(geoid_separation)) {
    return DRDC_E_HEIGHT;
  }
  att = drdc_quat_compose(&ref->q, &l->q, &q);
  st = drdc_quat_rotate_q15_16(&ref->q, &l->p, &ned);
  if (st == DRDC_OK) {
    ellipsoidal(ref->latitude, ref->longitude, ref->height, geoid_separation,
                &origin);
    st = drdc_geo_from_ned(&origin, &ned, &result);
  }
  if (st == DRDC_OK) {
    st = att;
  }
  if (st != DRDC_OK) {
    return st;
  }
  /* out may be ref: every input is read by now */
  out->latitude = result.lat;
  out->longitude = result.lon;
  out->height = result.height - geoid_separation;
  out->q = q;
  return DRDC_OK;
}

/* The errors in this order: the separation, the two positions, the
 * offset's range, the reference's attitude, the relative attitude, the
 * offset's rotation into ref's body axes. */
drdc_status_t drdc_pose_l_from_w(const drdc_WPose_t *ref,
                                 drdc_q47_16_t geoid_separation,
                                 const drdc_WPose_t *w, drdc_lPose_t *out)
{
  drdc_geo_point_t origin;
  drdc_geo_point_t point;
  drdc_vec3_q15_16_t ned = {0, 0, 0};
  drdc_vec3_q15_16_t offset = {0, 0, 0};
  drdc_quat_t inv = {0, 0, 0, 0};
  drdc_quat_t q = {0, 0, 0, 0};
  drdc_status_t rot;
  drdc_status_t st;

  if ((ref == NULL) || (w == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  if (!separation_ok(geoid_separation)) {
    return DRDC_E_HEIGHT;
  }
  ellipsoidal(ref->latitude, ref->longitude, ref->height, geoid_separation,
              &origin);
  ellipsoidal(w->latitude, w->longitude, w->height, geoid_separation, &point);
  st = drdc_geo_to_ned(&origin, &point, &ned);
  if (st == DRDC_OK) {
    st = drdc_quat_conj(&ref->q, &inv);
  }
  if (st != DRDC_OK) {
    return st;
  }
  rot = drdc_quat_rotate_q15_16(&inv, &ned, &offset);
  st = drdc_quat_compose(&inv, &w->q, &q);
  if (st == DRDC_OK) {
    st = rot;
  }
  if (st != DRDC_OK) {
    return st;
  }
  out->p = offset;
  out->q = q;
  return DRDC_OK;
}

drdc_status_t drdc_pose_l_from_le(const drdc_lePose_t *le, drdc_lPose_t *out)
{
  drdc_quat_t q = {0, 0, 0, 0};

  if ((le == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  (void)drdc_quat_from_euler(&le->e, &q);
  out->p = le->p;
  out->q = q;
  return DRDC_OK;
}

drdc_status_t drdc_pose_le_from_l(const drdc_lPose_t *l, drdc_lePose_t *out)
{
  drdc_euler_t e = {0u, 0u, 0u};
  drdc_status_t st;

  if ((l == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc_euler_from_quat(&l->q, &e);
  if (st != DRDC_OK) {
    return st;
  }
  out->p = l->p;
  out->e = e;
  return DRDC_OK;
}

/* drdc_pose_w_from_l() with the attitudes as Euler angles, through
 * quaternions. The angles of the result cannot fail:
 * drdc_euler_from_quat() refuses only a zero quaternion, and
 * drdc_quat_compose()'s result is within 2 LSB of unit length. */
drdc_status_t drdc_pose_we_from_le(const drdc_WePose_t *ref,
                                   drdc_q47_16_t geoid_separation,
                                   const drdc_lePose_t *le, drdc_WePose_t *out)
{
  drdc_quat_t q_ref = {0, 0, 0, 0};
  drdc_quat_t q_le = {0, 0, 0, 0};
  drdc_quat_t q = {0, 0, 0, 0};
  drdc_vec3_q15_16_t ned = {0, 0, 0};
  drdc_geo_point_t origin;
  drdc_geo_point_t result = {0, 0, 0};
  drdc_status_t att;
  drdc_status_t st;

  if ((ref == NULL) || (le == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  if (!separation_ok(geoid_separation)) {
    return DRDC_E_HEIGHT;
  }
  (void)drdc_quat_from_euler(&ref->e, &q_ref);
  st = drdc_quat_rotate_q15_16(&q_ref, &le->p, &ned);
  if (st != DRDC_OK) {
    return st;
  }
  (void)drdc_quat_from_euler(&le->e, &q_le);
  att = drdc_quat_compose(&q_ref, &q_le, &q);
  ellipsoidal(ref->latitude, ref->longitude, ref->height, geoid_separation,
              &origin);
  st = drdc_geo_from_ned(&origin, &ned, &result);
  if (st == DRDC_OK) {
    st = att;
  }
  if (st != DRDC_OK) {
    return st;
  }
  /* out may be ref: every input is read by now */
  out->latitude = result.lat;
  out->longitude = result.lon;
  out->height = result.height - geoid_separation;
  (void)drdc_euler_from_quat(&q, &out->e);
  return DRDC_OK;
}

/* drdc_pose_l_from_w() with the attitudes as Euler angles, then
 * drdc_pose_le_from_l() */
drdc_status_t drdc_pose_le_from_we(const drdc_WePose_t *ref,
                                   drdc_q47_16_t geoid_separation,
                                   const drdc_WePose_t *we, drdc_lePose_t *out)
{
  drdc_geo_point_t origin;
  drdc_geo_point_t point;
  drdc_vec3_q15_16_t ned = {0, 0, 0};
  drdc_quat_t q_ref = {0, 0, 0, 0};
  drdc_quat_t inv = {0, 0, 0, 0};
  drdc_quat_t q_we = {0, 0, 0, 0};
  drdc_lPose_t l = {{0, 0, 0}, {0, 0, 0, 0}};
  drdc_status_t rot;
  drdc_status_t st;

  if ((ref == NULL) || (we == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  if (!separation_ok(geoid_separation)) {
    return DRDC_E_HEIGHT;
  }
  ellipsoidal(ref->latitude, ref->longitude, ref->height, geoid_separation,
              &origin);
  ellipsoidal(we->latitude, we->longitude, we->height, geoid_separation,
              &point);
  st = drdc_geo_to_ned(&origin, &point, &ned);
  if (st == DRDC_OK) {
    (void)drdc_quat_from_euler(&ref->e, &q_ref);
    st = drdc_quat_conj(&q_ref, &inv);
  }
  if (st != DRDC_OK) {
    return st;
  }
  rot = drdc_quat_rotate_q15_16(&inv, &ned, &l.p);
  (void)drdc_quat_from_euler(&we->e, &q_we);
  st = drdc_quat_compose(&inv, &q_we, &l.q);
  if (st == DRDC_OK) {
    st = rot;
  }
  if (st != DRDC_OK) {
    return st;
  }
  return drdc_pose_le_from_l(&l, out);
}
