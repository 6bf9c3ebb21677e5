/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief The pose types of the libdrdc standard ({W}, {We}, {W-UTM},
 *        {We-UTM}, {W-MGRS}, {We-MGRS}, {l}, {le}) and the conversions
 *        between true-north and grid-north orientation and between local
 *        and global poses.
 */
#ifndef DRDC_POSE_H
#define DRDC_POSE_H

#include <drdc/geo.h>
#include <drdc/geo_ecef.h>
#include <drdc/geo_mgrs.h>
#include <drdc/orient.h>

/**
 * @addtogroup drdc_geo
 * @{
 */

/** Global pose {W}: [longitude, latitude, height, q] (paper eq. 1):
 *  longitude first, where the geodesy functions take latitude first
 *  (docs/conventions.md, section 9), so initialise it by field name.
 *  Height above mean sea level; q body -> north-east-down, true north. */
typedef struct drdc_WPose {
  drdc_nas_t longitude; /**< longitude, nas, east positive */
  drdc_nas_t latitude;  /**< latitude, nas, north positive */
  drdc_q47_16_t height; /**< height above mean sea level, Q47.16 m */
  drdc_quat_t q;        /**< attitude, true north (NED), Q1.30 */
} drdc_WPose_t;

/** Global pose {We}: as {W} with Z-Y-X Euler angles, yaw from true north. */
typedef struct drdc_WePose {
  drdc_nas_t longitude; /**< longitude, nas */
  drdc_nas_t latitude;  /**< latitude, nas */
  drdc_q47_16_t height; /**< height above mean sea level, Q47.16 m */
  drdc_euler_t e;       /**< yaw, pitch, roll; yaw from true north */
} drdc_WePose_t;

/** Global pose {W-UTM}: UTM/UPS position, height, attitude with x of the
 *  world frame towards grid north. */
typedef struct drdc_WUTMPose {
  drdc_geo_utm_t utm;   /**< zone, hemisphere, easting, northing */
  drdc_q47_16_t height; /**< height above mean sea level, Q47.16 m */
  drdc_quat_t q;        /**< attitude, grid north, Q1.30 */
} drdc_WUTMPose_t;

/** Global pose {We-UTM}: as {W-UTM} with Euler angles, yaw from grid
 *  north. */
typedef struct drdc_WeUTMPose {
  drdc_geo_utm_t utm;   /**< zone, hemisphere, easting, northing */
  drdc_q47_16_t height; /**< height above mean sea level, Q47.16 m */
  drdc_euler_t e;       /**< yaw, pitch, roll; yaw from grid north */
} drdc_WeUTMPose_t;

/** Global pose {W-MGRS}: MGRS position (the cell of a UTM/UPS position
 *  at some precision), height, attitude with x of the world frame towards
 *  grid north (the grid north of the MGRS zone, as {W-UTM}). */
typedef struct drdc_WMGRSPose {
  char mgrs[DRDC_GEO_MGRS_SIZE]; /**< MGRS text, NUL-terminated */
  drdc_q47_16_t height;          /**< height above mean sea level, Q47.16 m */
  drdc_quat_t q;                 /**< attitude, grid north, Q1.30 */
} drdc_WMGRSPose_t;

/** Global pose {We-MGRS}: as {W-MGRS} with Euler angles, yaw from grid
 *  north. */
typedef struct drdc_WeMGRSPose {
  char mgrs[DRDC_GEO_MGRS_SIZE]; /**< MGRS text, NUL-terminated */
  drdc_q47_16_t height;          /**< height above mean sea level, Q47.16 m */
  drdc_euler_t e;                /**< yaw, pitch, roll; yaw from grid north */
} drdc_WeMGRSPose_t;

/** Local pose {l}: position x forward, y right, z down (Q15.16 m) and
 *  attitude in the local frame. */
typedef struct drdc_lPose {
  drdc_vec3_q15_16_t p; /**< x, y, z, Q15.16 m */
  drdc_quat_t q;        /**< attitude, Q1.30 */
} drdc_lPose_t;

/** Local pose {le}: as {l} with Euler angles. */
typedef struct drdc_lePose {
  drdc_vec3_q15_16_t p; /**< x, y, z, Q15.16 m */
  drdc_euler_t e;       /**< yaw, pitch, roll */
} drdc_lePose_t;

/**
 * Meridian convergence (nas, GeographicLib's gamma: grid north's bearing
 * clockwise from true north) as a binary angle, rounded to nearest.
 *
 * @param convergence angle, nas, |convergence| <= 180 degrees.
 * @return the angle in binary-angle units (2^32 per turn), modulo a turn.
 *
 * Error <= 0.5 LSB (4.2e-8 degree).
 */
drdc_bam32_t drdc_pose_bam_from_convergence(drdc_nas_t convergence);

/**
 * True-north attitude -> grid-north attitude at a point of meridian
 * convergence gamma: q_grid = q_z(-gamma) * q_true (the world frame turned
 * by gamma about its down axis; a heading psi becomes psi - gamma).
 *
 * @param q_true attitude in {W} (NED, true north), unit quaternion.
 * @param convergence gamma, nas, |gamma| <= 180 degrees.
 * @param[out] q_grid attitude in {W-UTM} (grid north).
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL q_true or q_grid is NULL.
 * @retval DRDC_E_RANGE |convergence| beyond 180 degrees.
 * @retval DRDC_E_OVERFLOW q_true is far from unit length and a part of
 *         the product leaves Q1.30.
 *
 * Output unchanged on error. Accuracy: gamma is rounded to a binary angle
 * (0.5 LSB, 4.2e-8 degree) and the product is correctly rounded Q1.30;
 * measured on 2 000 GeoConvert convergences with 2 000 attitudes (pitch
 * within +-60 degrees): the Euler yaw of the result is yaw - gamma within
 * 4 binary-angle LSB (3.4e-7 degree), pitch and roll unchanged within 3
 * LSB, most of it the Q1.30 quaternion itself (2^-30).
 */
drdc_status_t drdc_pose_grid_from_true(const drdc_quat_t *q_true,
                                       drdc_nas_t convergence,
                                       drdc_quat_t *q_grid);

/**
 * Grid-north attitude -> true-north attitude: q_true = q_z(gamma) * q_grid.
 *
 * @param q_grid attitude in {W-UTM}, unit quaternion.
 * @param convergence gamma, nas, |gamma| <= 180 degrees.
 * @param[out] q_true attitude in {W}.
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL q_grid or q_true is NULL.
 * @retval DRDC_E_RANGE |convergence| beyond 180 degrees.
 * @retval DRDC_E_OVERFLOW q_grid is far from unit length and a part of
 *         the product leaves Q1.30.
 */
drdc_status_t drdc_pose_true_from_grid(const drdc_quat_t *q_grid,
                                       drdc_nas_t convergence,
                                       drdc_quat_t *q_true);

/**
 * {W} -> {W-UTM}: position by drdc_geo_to_utm(), attitude turned to grid
 * north by the point's convergence, height unchanged (MSL).
 *
 * @param w the global pose.
 * @param zone as drdc_geo_to_utm(): DRDC_GEO_ZONE_STANDARD, UPS or 1..60.
 * @param[out] out the grid pose.
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL w or out is NULL.
 * @retval DRDC_E_LATITUDE w->latitude outside [-90, 90] degrees.
 * @retval DRDC_E_LONGITUDE w->longitude outside [-540, 540) degrees.
 * @retval DRDC_E_ZONE zone is not a zone code of drdc_geo_to_utm().
 * @retval DRDC_E_RANGE the point is outside the forced zone's range.
 * @retval DRDC_E_OVERFLOW w->q is far from unit length.
 */
drdc_status_t drdc_pose_wutm_from_w(const drdc_WPose_t *w, int32_t zone,
                                    drdc_WUTMPose_t *out);

/**
 * {W-UTM} -> {W}: position by drdc_geo_from_utm(), attitude turned back
 * to true north.
 *
 * @param u the grid pose.
 * @param[out] out the global pose.
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL u or out is NULL.
 * @retval DRDC_E_ZONE u->utm.zone outside 0..60.
 * @retval DRDC_E_EASTING easting outside its zone's range.
 * @retval DRDC_E_NORTHING northing outside its zone's range.
 * @retval DRDC_E_OVERFLOW u->q is far from unit length.
 *
 * Output unchanged on error. An attitude with a part beyond [-1, 1]
 * (whose turn may overflow) costs a second reverse projection, about
 * twice the cycles.
 */
drdc_status_t drdc_pose_w_from_wutm(const drdc_WUTMPose_t *u,
                                    drdc_WPose_t *out);

/**
 * {We} -> {We-UTM}: position by drdc_geo_to_utm(), yaw from grid north
 * = yaw from true north - convergence (binary angles, modulo a turn);
 * pitch, roll and height unchanged.
 *
 * @param w the global pose with Euler angles.
 * @param zone as drdc_geo_to_utm(): DRDC_GEO_ZONE_STANDARD, UPS or 1..60.
 * @param[out] out the grid pose.
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL w or out is NULL.
 * @retval DRDC_E_LATITUDE w->latitude outside [-90, 90] degrees.
 * @retval DRDC_E_LONGITUDE w->longitude outside [-540, 540) degrees.
 * @retval DRDC_E_ZONE zone is not a zone code of drdc_geo_to_utm().
 * @retval DRDC_E_RANGE the point is outside the forced zone's range.
 *
 * Output unchanged on error. Accuracy: the convergence is rounded to a
 * binary angle (0.5 LSB = 4.2e-8 degree) after its 1 nas error.
 */
drdc_status_t drdc_pose_weutm_from_we(const drdc_WePose_t *w, int32_t zone,
                                      drdc_WeUTMPose_t *out);

/**
 * {We-UTM} -> {We}: position by drdc_geo_from_utm(), yaw + convergence.
 *
 * @param u the grid pose with Euler angles.
 * @param[out] out the global pose.
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL u or out is NULL.
 * @retval DRDC_E_ZONE u->utm.zone outside 0..60.
 * @retval DRDC_E_EASTING easting outside its zone's range.
 * @retval DRDC_E_NORTHING northing outside its zone's range.
 */
drdc_status_t drdc_pose_we_from_weutm(const drdc_WeUTMPose_t *u,
                                      drdc_WePose_t *out);

/**
 * {W} -> {W-MGRS}: the MGRS text of the position at precision prec as
 * drdc_geo_mgrs_encode() (standard UTM zone or UPS, digits truncated,
 * never rounded), the attitude turned to grid north by the convergence
 * at the position itself (as drdc_pose_wutm_from_w()), height unchanged
 * (MSL).
 *
 * @param w the global pose.
 * @param prec MGRS digits per coordinate: -1 (grid zone only), 0 (100 km
 *        square) .. 5 (1 m) .. 11 (1 um); GeoConvert's -p P is P + 5.
 * @param[out] out the MGRS pose.
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL w or out is NULL.
 * @retval DRDC_E_LATITUDE w->latitude outside [-90, 90] degrees.
 * @retval DRDC_E_LONGITUDE w->longitude outside [-540, 540) degrees.
 * @retval DRDC_E_RANGE prec outside -1..11.
 * @retval DRDC_E_OVERFLOW w->q is far from unit length and a part of
 *         the turned quaternion leaves Q1.30.
 *
 * Output unchanged on error. Accuracy: the text is drdc_geo_mgrs_encode()'s
 * (the coordinates truncated before their rounding to Q47.16): identical
 * to GeoConvert's on all 500 measured points at every precision -1..11
 * (109 of them finer than 1 mm); at 1 um a point whose GeographicLib
 * coordinate lies within a few nm of a digit boundary may differ by one
 * unit of the last digit (see drdc_geo_mgrs_encode()). The
 * attitude as drdc_pose_grid_from_true(); measured on 500 GeoConvert
 * points with SciPy rotations (q_z(-gamma) q of the exact input): every
 * part of q within 2 LSB of Q1.30.
 *
 * @code
 * drdc_WPose_t w = { 159840000000000, 119880000000000, 0,   // 44.4 E, 33.3 N
 *                    { 1073741824, 0, 0, 0 } };             // facing north
 * drdc_WMGRSPose_t m;
 * drdc_pose_wmgrs_from_w(&w, 5, &m);   // m.mgrs = "38SMB4414084706"
 * @endcode
 */
drdc_status_t drdc_pose_wmgrs_from_w(const drdc_WPose_t *w, int32_t prec,
                                     drdc_WMGRSPose_t *out);

/**
 * {W-MGRS} -> {W}: the position is the centre of the MGRS cell
 * (drdc_geo_mgrs_decode(), then drdc_geo_from_utm(); for a grid zone
 * alone GeographicLib's representative point), the attitude turned back
 * to true north by the convergence at that centre.
 *
 * @param m the MGRS pose; m->mgrs must be NUL-terminated within
 *        DRDC_GEO_MGRS_SIZE bytes, letters in either case.
 * @param[out] out the global pose.
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL m or out is NULL.
 * @retval DRDC_E_ZONE zone digits 0 or above 60.
 * @retval DRDC_E_MGRS malformed text (as drdc_geo_mgrs_decode()), or no
 *         NUL within DRDC_GEO_MGRS_SIZE bytes.
 * @retval DRDC_E_BAND the 100 km square does not lie in the latitude band.
 * @retval DRDC_E_OVERFLOW m->q is far from unit length.
 *
 * Output unchanged on error; an attitude with a part beyond [-1, 1]
 * costs a second reverse projection, about twice the cycles. Accuracy:
 * the position within 1 nas of GeoConvert's position of the cell's
 * centre as it is held in Q47.16
 * (rounded to 15 um for cells finer than 1 m); the attitude measured
 * on 500 GeoConvert cells with SciPy rotations (q_z(gamma) q,
 * gamma GeoConvert's at the centre): every part within 2 LSB.
 * A round trip {W} -> {W-MGRS} -> {W} moves the position to the cell's
 * centre and turns the yaw by the change of convergence across half a
 * cell (about 1.5e-7 rad per metre times tan(latitude)): use precision 5
 * or finer where attitude matters.
 */
drdc_status_t drdc_pose_w_from_wmgrs(const drdc_WMGRSPose_t *m,
                                     drdc_WPose_t *out);

/**
 * {We} -> {We-MGRS}: the MGRS text as drdc_pose_wmgrs_from_w(), yaw from
 * grid north = yaw from true north - convergence (binary angles, modulo a
 * turn); pitch, roll and height unchanged.
 *
 * @param w the global pose with Euler angles.
 * @param prec MGRS digits per coordinate, -1..11.
 * @param[out] out the MGRS pose.
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL w or out is NULL.
 * @retval DRDC_E_LATITUDE w->latitude outside [-90, 90] degrees.
 * @retval DRDC_E_LONGITUDE w->longitude outside [-540, 540) degrees.
 * @retval DRDC_E_RANGE prec outside -1..11.
 *
 * Output unchanged on error. Accuracy: the yaw is yaw - gamma with gamma
 * drdc_pose_bam_from_convergence() of the 1 nas convergence, so within 1
 * binary-angle LSB of yaw - GeoConvert's convergence; measured on 500
 * points: identical on all.
 */
drdc_status_t drdc_pose_wemgrs_from_we(const drdc_WePose_t *w, int32_t prec,
                                       drdc_WeMGRSPose_t *out);

/**
 * {We-MGRS} -> {We}: position at the cell's centre as
 * drdc_pose_w_from_wmgrs(), yaw + the convergence at that centre.
 *
 * @param m the MGRS pose with Euler angles; m->mgrs NUL-terminated within
 *        DRDC_GEO_MGRS_SIZE bytes.
 * @param[out] out the global pose.
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL m or out is NULL.
 * @retval DRDC_E_ZONE zone digits 0 or above 60.
 * @retval DRDC_E_MGRS malformed text, or no NUL within DRDC_GEO_MGRS_SIZE
 *         bytes.
 * @retval DRDC_E_BAND the 100 km square does not lie in the latitude band.
 *
 * Output unchanged on error. Accuracy: the yaw within 1 binary-angle LSB
 * of yaw + GeoConvert's convergence at the centre (measured on 500 cells:
 * identical on all).
 */
drdc_status_t drdc_pose_we_from_wemgrs(const drdc_WeMGRSPose_t *m,
                                       drdc_WePose_t *out);

/**
 * {l} -> {W}: the local frame is the body frame of the reference pose
 * ref (x forward, y right, z down); the local position is rotated by
 * ref->q into north-east-down at ref and placed on the ellipsoid, the
 * attitude composed (ref->q * l->q).
 *
 * @param ref reference global pose (MSL height).
 * @param geoid_separation geoid height N at the reference (ellipsoidal =
 *        MSL + N), Q47.16 m, from the caller (GNSS GGA field 11, a geoid
 *        model).
 * @param l local pose.
 * @param[out] out global pose (MSL height, using the same N).
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL ref, l or out is NULL.
 * @retval DRDC_E_LATITUDE ref->latitude outside [-90, 90] degrees.
 * @retval DRDC_E_LONGITUDE ref->longitude outside [-540, 540) degrees.
 * @retval DRDC_E_HEIGHT |geoid_separation|, the reference's or the
 *         result's ellipsoidal height beyond 10 000 km.
 * @retval DRDC_E_DOMAIN ref->q or l->q is zero.
 * @retval DRDC_E_OVERFLOW the local offset turned into north-east-down
 *         leaves Q15.16 (an axis beyond 32 km).
 *
 * Output unchanged on error; out may be ref. Accuracy: as
 * drdc_pose_l_from_w(), whose inverse it is (round trips within 2 LSB of
 * height and the 7.6 um of the Q15.16 position).
 */
drdc_status_t drdc_pose_w_from_l(const drdc_WPose_t *ref,
                                 drdc_q47_16_t geoid_separation,
                                 const drdc_lPose_t *l, drdc_WPose_t *out);

/**
 * {W} -> {l} at the reference pose ref (inverse of drdc_pose_w_from_l()).
 *
 * @param ref reference global pose (MSL height).
 * @param geoid_separation geoid height N, Q47.16 m (as
 *        drdc_pose_w_from_l()).
 * @param w global pose (MSL height).
 * @param[out] out local pose.
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL ref, w or out is NULL.
 * @retval DRDC_E_LATITUDE a latitude outside [-90, 90] degrees.
 * @retval DRDC_E_LONGITUDE a longitude outside [-540, 540) degrees.
 * @retval DRDC_E_HEIGHT |geoid_separation| or an ellipsoidal height
 *         beyond 10 000 km.
 * @retval DRDC_E_DOMAIN ref->q or w->q is zero.
 * @retval DRDC_E_OVERFLOW w is more than 32 km from ref on an axis.
 *
 * Output unchanged on error. Accuracy (measured on 1 000 CartConvert
 * points, ref facing north and east): the position within 1 LSB of
 * CartConvert's local frame; round trips with drdc_pose_w_from_l()
 * within 2 LSB of height and the 7.6 um of the Q15.16 position in
 * latitude and longitude.
 */
drdc_status_t drdc_pose_l_from_w(const drdc_WPose_t *ref,
                                 drdc_q47_16_t geoid_separation,
                                 const drdc_WPose_t *w, drdc_lPose_t *out);

/**
 * {le} -> {l}: position copied, attitude by drdc_quat_from_euler().
 *
 * @param le local pose with Z-Y-X Euler angles (any binary angles).
 * @param[out] out local pose with a unit quaternion.
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL le or out is NULL.
 *
 * Output unchanged on error. Accuracy: as drdc_quat_from_euler() (2 LSB
 * of Q1.30 per part); the position is exact.
 */
drdc_status_t drdc_pose_l_from_le(const drdc_lePose_t *le, drdc_lPose_t *out);

/**
 * {l} -> {le}: position copied, attitude by drdc_euler_from_quat()
 * (yaw and roll in [-180, 180), pitch in [-90, 90]; its gimbal-lock rule).
 *
 * @param l local pose, non-zero quaternion.
 * @param[out] out local pose with Euler angles.
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL l or out is NULL.
 * @retval DRDC_E_DOMAIN l->q is zero.
 *
 * Output unchanged on error. Accuracy: as drdc_euler_from_quat() (1.125
 * binary-angle LSB away from gimbal lock); the position is exact.
 */
drdc_status_t drdc_pose_le_from_l(const drdc_lPose_t *l, drdc_lePose_t *out);

/**
 * {le} -> {We} through the local tangent plane of the reference pose,
 * as drdc_pose_w_from_l(): the local frame is the body frame of ref
 * (x forward, y right, z down), the position rotated into north-east-down
 * at ref and placed on the ellipsoid, the attitude composed
 * (R(ref) R(le)); Euler angles through quaternions.
 *
 * @param ref reference global pose with Euler angles (MSL height).
 * @param geoid_separation geoid height N at ref, Q47.16 m (as
 *        drdc_pose_w_from_l()).
 * @param le local pose with Euler angles.
 * @param[out] out global pose with Euler angles (MSL height).
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL ref, le or out is NULL.
 * @retval DRDC_E_LATITUDE ref->latitude outside [-90, 90] degrees.
 * @retval DRDC_E_LONGITUDE ref->longitude outside [-540, 540) degrees.
 * @retval DRDC_E_HEIGHT |geoid_separation|, the reference's or the
 *         result's ellipsoidal height beyond 10 000 km.
 * @retval DRDC_E_OVERFLOW the local offset turned into north-east-down
 *         leaves Q15.16 (an axis beyond 32 km).
 *
 * Output unchanged on error. Accuracy, measured on 400 points
 * within 20 km of 20 reference poses of random attitude against
 * CartConvert's local frame and SciPy's rotations: latitude and longitude
 * within 2 000 nas (0.062 mm), height within 2 LSB of
 * Q47.16, the Euler angles within 8 binary-angle LSB (pitch
 * within 80 degrees).
 */
drdc_status_t drdc_pose_we_from_le(const drdc_WePose_t *ref,
                                   drdc_q47_16_t geoid_separation,
                                   const drdc_lePose_t *le, drdc_WePose_t *out);

/**
 * {We} -> {le} at the reference pose ref (inverse of
 * drdc_pose_we_from_le(), as drdc_pose_l_from_w()).
 *
 * @param ref reference global pose with Euler angles (MSL height).
 * @param geoid_separation geoid height N, Q47.16 m.
 * @param we global pose with Euler angles (MSL height).
 * @param[out] out local pose with Euler angles.
 * @retval DRDC_OK written.
 * @retval DRDC_E_NULL ref, we or out is NULL.
 * @retval DRDC_E_LATITUDE a latitude outside [-90, 90] degrees.
 * @retval DRDC_E_LONGITUDE a longitude outside [-540, 540) degrees.
 * @retval DRDC_E_HEIGHT |geoid_separation| or an ellipsoidal height
 *         beyond 10 000 km.
 * @retval DRDC_E_OVERFLOW we is more than 32 km from ref on a local axis.
 *
 * Output unchanged on error. Accuracy (as drdc_pose_we_from_le(), the
 * same vectors the other way): the position within 4 LSB of
 * Q15.16, the Euler angles within 8 binary-angle LSB.
 */
drdc_status_t drdc_pose_le_from_we(const drdc_WePose_t *ref,
                                   drdc_q47_16_t geoid_separation,
                                   const drdc_WePose_t *we, drdc_lePose_t *out);

/** @} */

#endif /* DRDC_POSE_H */
