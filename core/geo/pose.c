/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Local pose conversions: {l} <-> {W} through NED, and their
 *        Euler forms {le} <-> {We}; the grid poses are in grid_pose.c.
 */
#include <drdc/compiler.h>
#include <drdc/geo_pose.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>
#include <drdc/fixed_trig.h>

#include "geo_impl.h"

/* h + n, the ellipsoidal height of the height h above the geoid (Q47.16
 * m) for a checked separation |n| <= DRDC_GEO_HEIGHT_MAX (< 2^40),
 * without signed overflow: the sum is taken modulo 2^64 in uint64_t. A
 * true sum beyond int64_t lands within 2^40 of the other end, far beyond
 * +-DRDC_GEO_HEIGHT_MAX, so the point's check refuses it as it would the
 * true sum (DRDC_E_HEIGHT, after the latitude and longitude); every
 * other sum is exact. The same add instruction as a signed sum: a
 * branch here grew the frames under drdc_pose_l_from_w() and
 * drdc_pose_le_from_we() past 256 B (issue 8). uint64_t -> int64_t of a
 * value above INT64_MAX is modulo 2^64 in GCC and Clang (implementation-
 * defined in C99, no undefined behaviour). */
static inline drdc_q47_16_t ellipsoidal_height(drdc_q47_16_t h, drdc_q47_16_t n)
{
  uint64_t sum = (uint64_t)h + (uint64_t)n;

  return (drdc_q47_16_t)sum;
}

/* the ellipsoidal point of a pose */
static void ellipsoidal(const drdc_WPose_t *w, drdc_q47_16_t n,
                        drdc_geo_point_t *p)
{
  p->lat = w->latitude;
  p->lon = w->longitude;
  p->height = ellipsoidal_height(w->height, n);
}

/* |N| up to 10 000 km keeps every sum in range */
static bool separation_ok(drdc_q47_16_t n)
{
  return (n <= DRDC_GEO_HEIGHT_MAX) && (n >= -DRDC_GEO_HEIGHT_MAX);
}

/* The steps of drdc_geo_from_ned() at the ellipsoidal point of a {W} or
 * {We} reference, in frames that hold one buffer each, so that the pose
 * conversions keep in their own frames, which are on top of the
 * rotation's chain, only the offset (and quaternion) the rotation needs:
 * position_*() holds the geo_bowring_t of the inverse, ecef_at() the
 * reference's latitude and longitude beside it (16 bytes; the
 * ellipsoidal height waits in the bowring_t's free slot p). position_*()
 * take the 64-bit separation first: arguments in registers on
 * Cortex-M3. */

/* the offset in b's slots (north, up, east) in Q15.16, as
 * drdc__geo_ecef_of_plane() takes it (it scales it there, so that the shifts'
 * temporaries take no saved registers in the frames of position_w() and
 * position_we(): issue 8's stack) */
static void load_ned(const drdc_vec3_q15_16_t *ned, geo_bowring_t *b)
{
  b->z = ned->x;
  b->u = -(int64_t)ned->z;
  b->v = ned->y;
}

/* the ellipsoidal point of a {W} or {We} reference, read in place
 * through pointers to its latitude, longitude and height (the one body
 * for both pose types; b->p holds the separation, to which the height is
 * added), checked (drdc_geo_from_ned()'s first status), then the ECEF
 * point of b's offset (north b->z, up b->u, east b->v) there, into b.
 * `used` (callers GCC cannot see) keeps the pointers: IPA-SRA would pass
 * the three values instead, copied in the frames of position_*() (16
 * bytes more each on PowerPC); the linker still drops it with them. */
static DRDC_NOINLINE __attribute__((used)) drdc_status_t
ecef_at(const drdc_nas_t *lat, const drdc_nas_t *lon,
        const drdc_q47_16_t *height, geo_bowring_t *b)
{
  geo_lat_lon_t ll;

  ll.lat = *lat;
  ll.lon = *lon;
  b->p = ellipsoidal_height(*height, b->p);
  return drdc__geo_ecef_of_plane(&ll, b);
}

/* drdc_geo_from_ned() of ned at the ellipsoidal point of ref: on DRDC_OK
 * the latitude, longitude and ellipsoidal height into out, unless out is
 * NULL (the status alone); out unchanged on error. Only out is kept
 * across the calls. */
static DRDC_NOINLINE drdc_status_t position_w(drdc_q47_16_t geoid_separation,
                                              const drdc_WPose_t *ref,
                                              const drdc_vec3_q15_16_t *ned,
                                              drdc_WPose_t *out)
{
  geo_bowring_t b;
  drdc_status_t st;

  load_ned(ned, &b);
  b.p = geoid_separation;
  st = ecef_at(&ref->latitude, &ref->longitude, &ref->height, &b);
  if (st == DRDC_OK) {
    st = drdc__geo_geodetic_q36(&b);
  }
  if ((st == DRDC_OK) && (out != NULL)) {
    out->latitude = b.v;
    out->longitude = b.u;
    out->height = b.p;
  }
  return st;
}

/* the status of drdc_pose_w_from_l()'s relative attitude alone (the
 * product in this frame, discarded) */
static DRDC_NOINLINE drdc_status_t compose_status(const drdc_WPose_t *ref,
                                                  const drdc_lPose_t *l)
{
  drdc_quat_t q = {0, 0, 0, 0};

  return drdc_quat_compose(&ref->q, &l->q, &q);
}

/* drdc_pose_w_from_l()'s relative attitude straight into out->q (written
 * only on DRDC_OK); taking the poses, so that the caller keeps no
 * pointer to their quaternions beside them */
static DRDC_NOINLINE drdc_status_t compose_into(const drdc_WPose_t *ref,
                                                const drdc_lPose_t *l,
                                                drdc_WPose_t *out)
{
  return drdc_quat_compose(&ref->q, &l->q, &out->q);
}

/* {l} -> {W} with the offset alone in this frame (on top of the
 * rotation's chain): the attitude's status first, for its place in the
 * order; the offset turned into NED; then position_w(), which writes the
 * position into out only when the attitude will succeed, and is then the
 * last step that can fail; the separation taken off the height, and the
 * attitude again, straight into out->q: the same inputs, the same
 * status, DRDC_OK. out unchanged on every error, the statuses in their
 * order (rotation, reference, result's height, attitude). ref's
 * quaternion is read after out's position is written, which it does not
 * share (out may be ref). */
drdc_status_t drdc_pose_w_from_l(const drdc_WPose_t *ref,
                                 drdc_q47_16_t geoid_separation,
                                 const drdc_lPose_t *l, drdc_WPose_t *out)
{
  drdc_vec3_q15_16_t ned = {0, 0, 0};
  drdc_status_t att;
  drdc_status_t st;

  if ((ref == NULL) || (l == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  if (!separation_ok(geoid_separation)) {
    return DRDC_E_HEIGHT;
  }
  att = compose_status(ref, l);
  st = drdc_quat_rotate_q15_16(&ref->q, &l->p, &ned);
  if (st == DRDC_OK) {
    st = position_w(geoid_separation, ref, &ned, (att == DRDC_OK) ? out : NULL);
  }
  if (st == DRDC_OK) {
    st = att;
  }
  if (st != DRDC_OK) {
    return st;
  }
  out->height = out->height - geoid_separation;
  return compose_into(ref, l, out);
}

/* NED of w at ref (both ellipsoidal by the separation): drdc_geo_to_ned()
 * in its stages (the same checks in the same order, the same sums), with
 * one point on the stack, filled with each point in turn, beside the
 * ECEF difference; then the conjugate of ref's attitude into *inv, which
 * turns the offset into ref's body axes. Out of line: neither the point
 * nor the difference is on the stack during the caller's rotation, and
 * the caller keeps no pointer to ref across this call (the 64-bit
 * separation first: on Cortex-M3 the arguments then leave one word
 * fewer on the caller's stack). */
static DRDC_NOINLINE drdc_status_t ned_of(drdc_q47_16_t geoid_separation,
                                          const drdc_WPose_t *ref,
                                          const drdc_WPose_t *w,
                                          drdc_vec3_q15_16_t *ned,
                                          drdc_quat_t *inv)
{
  drdc_geo_point_t pt;
  int64_t d[3] = {0, 0, 0};
  drdc_status_t st;

  ellipsoidal(ref, geoid_separation, &pt);
  st = drdc__geo_check_point(&pt);
  if (st == DRDC_OK) {
    ellipsoidal(w, geoid_separation, &pt);
    st = drdc__geo_check_point(&pt);
  }
  if (st != DRDC_OK) {
    return st;
  }
  /* pt holds w's point: the difference w - ref */
  drdc__geo_ecef_acc_q36(&pt, false, &d[0], &d[1], &d[2]);
  ellipsoidal(ref, geoid_separation, &pt);
  drdc__geo_ecef_acc_q36(&pt, true, &d[0], &d[1], &d[2]);
  st = drdc__geo_plane_turn(&pt, true, d, ned);
  if (st == DRDC_OK) {
    st = drdc_quat_conj(&ref->q, inv);
  }
  return st;
}

/* The status of drdc_pose_l_from_w() when its rotation failed with rot:
 * the attitude's error first, as l_from_ned() gives it (the relative
 * attitude is composed into inv, no longer needed, for its status
 * alone). Out of line, so that no status is kept across a call in the
 * caller's frame. */
static DRDC_NOINLINE drdc_status_t first_error(drdc_quat_t *inv,
                                               const drdc_quat_t *wq,
                                               drdc_status_t rot)
{
  drdc_status_t st = drdc_quat_compose(inv, wq, inv);

  return (st != DRDC_OK) ? st : rot;
}

drdc_status_t drdc_pose_l_from_w(const drdc_WPose_t *ref,
                                 drdc_q47_16_t geoid_separation,
                                 const drdc_WPose_t *w, drdc_lPose_t *out)
{
  drdc_vec3_q15_16_t ned = {0, 0, 0};
  drdc_quat_t inv = {0, 0, 0, 0};
  drdc_status_t st;

  if ((ref == NULL) || (w == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  if (!separation_ok(geoid_separation)) {
    return DRDC_E_HEIGHT;
  }
  st = ned_of(geoid_separation, ref, w, &ned, &inv);
  if (st != DRDC_OK) {
    return st;
  }
  /* l_from_ned() with one quaternion on the stack instead of two, so
   * that the rotation's chain starts from this small frame: the offset
   * turned in place first, then the relative attitude straight into
   * out->q (drdc_quat_compose() writes only on DRDC_OK and is then the
   * last step that can fail) */
  st = drdc_quat_rotate_q15_16(&inv, &ned, &ned);
  if (st != DRDC_OK) {
    return first_error(&inv, &w->q, st);
  }
  st = drdc_quat_compose(&inv, &w->q, &out->q);
  if (st != DRDC_OK) {
    return st;
  }
  out->p.x = ned.x;
  out->p.y = ned.y;
  out->p.z = ned.z;
  return DRDC_OK;
}

/* the four MGRS poses are in utm_forward.c (to MGRS) and utm_reverse.c
 * (from MGRS), as the UTM poses */

drdc_status_t drdc_pose_l_from_le(const drdc_lePose_t *le, drdc_lPose_t *out)
{
  drdc_quat_t q = {0, 0, 0, 0};

  if ((le == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  (void)drdc_quat_from_euler(&le->e, &q);
  out->p.x = le->p.x;
  out->p.y = le->p.y;
  out->p.z = le->p.z;
  out->q.s = q.s;
  out->q.x = q.x;
  out->q.y = q.y;
  out->q.z = q.z;
  return DRDC_OK;
}

drdc_status_t drdc_pose_le_from_l(const drdc_lPose_t *l, drdc_lePose_t *out)
{
  drdc_status_t st;

  if ((l == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  /* the angles straight into out: drdc_euler_from_quat() writes them
   * only on DRDC_OK and is the one step that can fail, so out stays
   * unchanged on error, and no copy of them is in this frame (which
   * sits on top of the whole chain of drdc_euler_from_quat()) */
  st = drdc_euler_from_quat(&l->q, &out->e);
  if (st != DRDC_OK) {
    return st;
  }
  out->p.x = l->p.x;
  out->p.y = l->p.y;
  out->p.z = l->p.z;
  return DRDC_OK;
}

/* the ellipsoidal point of a {We} pose */
static void ellipsoidal_we(const drdc_WePose_t *we, drdc_q47_16_t n,
                           drdc_geo_point_t *p)
{
  p->lat = we->latitude;
  p->lon = we->longitude;
  p->height = ellipsoidal_height(we->height, n);
}

/* *inv composed in place with the quaternion of the angles e: the
 * relative attitude of drdc_pose_le_from_we() and of
 * drdc_pose_we_from_le(), in its own frame (the second quaternion is not
 * on the caller's stack under the rotation) */
static DRDC_NOINLINE drdc_status_t compose_euler(drdc_quat_t *inv,
                                                 const drdc_euler_t *e)
{
  drdc_quat_t q = {0, 0, 0, 0};

  (void)drdc_quat_from_euler(e, &q);
  return drdc_quat_compose(inv, &q, inv);
}

/* position_w() for a {We} reference and result */
static DRDC_NOINLINE drdc_status_t position_we(drdc_q47_16_t geoid_separation,
                                               const drdc_WePose_t *ref,
                                               const drdc_vec3_q15_16_t *ned,
                                               drdc_WePose_t *out)
{
  geo_bowring_t b;
  drdc_status_t st;

  load_ned(ned, &b);
  b.p = geoid_separation;
  st = ecef_at(&ref->latitude, &ref->longitude, &ref->height, &b);
  if (st == DRDC_OK) {
    st = drdc__geo_geodetic_q36(&b);
  }
  if ((st == DRDC_OK) && (out != NULL)) {
    out->latitude = b.v;
    out->longitude = b.u;
    out->height = b.p;
  }
  return st;
}

/* {le} -> {We}: drdc_pose_w_from_l() of the two poses as {W}, then the
 * angles of the result, with one local pose in this frame and no {W}
 * copy of ref: the quaternion of ref's angles and the offset turned into
 * NED by it wait in t; the relative attitude is then composed into t.q
 * in place (compose_euler(): the second quaternion in its own frame; its
 * status kept for its place in the order), and position_we() writes the
 * position into out only when the attitude succeeded (it is then the
 * last step that can fail). The angles of t.q last, straight into
 * out->e: drdc_euler_from_quat() fails only on a zero quaternion, and
 * drdc_quat_compose()'s result is within 2 LSB of unit length. out
 * unchanged on every error, the statuses in their order of before
 * (rotation, reference, result's height, attitude). ref's angles are
 * read before out is written (out may be ref). */
drdc_status_t drdc_pose_we_from_le(const drdc_WePose_t *ref,
                                   drdc_q47_16_t geoid_separation,
                                   const drdc_lePose_t *le, drdc_WePose_t *out)
{
  drdc_lPose_t t = {{0, 0, 0}, {0, 0, 0, 0}};
  drdc_status_t att;
  drdc_status_t st;

  if ((ref == NULL) || (le == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  if (!separation_ok(geoid_separation)) {
    return DRDC_E_HEIGHT;
  }
  (void)drdc_quat_from_euler(&ref->e, &t.q);
  st = drdc_quat_rotate_q15_16(&t.q, &le->p, &t.p);
  if (st != DRDC_OK) {
    return st;
  }
  att = compose_euler(&t.q, &le->e);
  st = position_we(geoid_separation, ref, &t.p, (att == DRDC_OK) ? out : NULL);
  if (st == DRDC_OK) {
    st = att;
  }
  if (st != DRDC_OK) {
    return st;
  }
  out->height = out->height - geoid_separation;
  (void)drdc_euler_from_quat(&t.q, &out->e);
  return DRDC_OK;
}

/* ned_of() for two {We} poses, read in place (no {W} copy of either on
 * the stack): the same checks, sums and statuses; the conjugate of the
 * quaternion of ref's angles into *inv. */
static DRDC_NOINLINE drdc_status_t ned_of_we(drdc_q47_16_t geoid_separation,
                                             const drdc_WePose_t *ref,
                                             const drdc_WePose_t *we,
                                             drdc_vec3_q15_16_t *ned,
                                             drdc_quat_t *inv)
{
  drdc_geo_point_t pt;
  int64_t d[3] = {0, 0, 0};
  drdc_status_t st;

  ellipsoidal_we(ref, geoid_separation, &pt);
  st = drdc__geo_check_point(&pt);
  if (st == DRDC_OK) {
    ellipsoidal_we(we, geoid_separation, &pt);
    st = drdc__geo_check_point(&pt);
  }
  if (st != DRDC_OK) {
    return st;
  }
  drdc__geo_ecef_acc_q36(&pt, false, &d[0], &d[1], &d[2]);
  ellipsoidal_we(ref, geoid_separation, &pt);
  drdc__geo_ecef_acc_q36(&pt, true, &d[0], &d[1], &d[2]);
  st = drdc__geo_plane_turn(&pt, true, d, ned);
  if (st == DRDC_OK) {
    (void)drdc_quat_from_euler(&ref->e, inv);
    st = drdc_quat_conj(inv, inv);
  }
  return st;
}

/* drdc_pose_l_from_w() of the two poses as {W}, then
 * drdc_pose_le_from_l(), with one local pose on the stack: the offset
 * and the conjugate reference attitude wait in l, the offset is turned
 * in place, then the relative attitude composed in place (the statuses
 * in the order of drdc_pose_l_from_w(): the attitude's first) */
drdc_status_t drdc_pose_le_from_we(const drdc_WePose_t *ref,
                                   drdc_q47_16_t geoid_separation,
                                   const drdc_WePose_t *we, drdc_lePose_t *out)
{
  drdc_lPose_t l = {{0, 0, 0}, {0, 0, 0, 0}};
  drdc_status_t st;
  drdc_status_t rot;

  if ((ref == NULL) || (we == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  if (!separation_ok(geoid_separation)) {
    return DRDC_E_HEIGHT;
  }
  st = ned_of_we(geoid_separation, ref, we, &l.p, &l.q);
  if (st != DRDC_OK) {
    return st;
  }
  rot = drdc_quat_rotate_q15_16(&l.q, &l.p, &l.p);
  st = compose_euler(&l.q, &we->e);
  if (st == DRDC_OK) {
    st = rot;
  }
  if (st != DRDC_OK) {
    return st;
  }
  return drdc_pose_le_from_l(&l, out);
}
