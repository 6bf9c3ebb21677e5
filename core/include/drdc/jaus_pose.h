/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_jaus_pose
 * @brief JAUS message bodies Report Global Pose (4402h) and Report Local
 *        Pose (4403h): pack from and unpack to the pose types {We} and
 *        {le}, little-endian on the wire on every host.
 */
#ifndef DRDC_JAUS_POSE_H
#define DRDC_JAUS_POSE_H

#include <stddef.h>
#include <stdint.h>

#include <drdc/jaus_scaled.h>
#include <drdc/geo_pose.h>
#include <drdc/status.h>

/**
 * @defgroup drdc_jaus_pose JAUS pose message bodies
 *
 * The body of Report Global Pose (message ID 4402h) and of Report Local
 * Pose (4403h): a 16-bit presence vector, then each field whose bit is
 * set, in bit order, every integer little-endian (least significant byte
 * first) whatever the host's byte order (bytes are assembled by shifts,
 * never by copying an integer). The message ID itself belongs to the
 * transport header and is not part of the body.
 *
 * | bit | Report Global Pose | Report Local Pose | RA 3.x | AS6009 |
 * |---|---|---|---|---|
 * | - | presence vector | presence vector | uint16 | uint16 |
 * | 0 | Latitude     | X            | int32  | uint32 |
 * | 1 | Longitude    | Y            | int32  | uint32 |
 * | 2 | Altitude     | Z            | int32  | uint32 |
 * | 3 | Position RMS | Position RMS | uint32 | uint32 |
 * | 4 | Roll         | Roll         | int16  | uint16 |
 * | 5 | Pitch        | Pitch        | int16  | uint16 |
 * | 6 | Yaw          | Yaw          | int16  | uint16 |
 * | 7 | Attitude RMS | Attitude RMS | uint16 | uint16 |
 * | 8 | Time Stamp   | Time Stamp   | uint32 | uint32 |
 *
 * | field | real limits [min, max] |
 * |---|---|
 * | Latitude | [-90, 90] degree |
 * | Longitude | [-180, 180] degree |
 * | Altitude | [-10 000, 35 000] m |
 * | X, Y | [-100 000, 100 000] m |
 * | Z | RA 3.x [-10 000, 35 000] m; AS6009 [-100 000, 100 000] m |
 * | Position RMS | [0, 100] m |
 * | Roll, Pitch, Yaw | [-pi, pi] rad |
 * | Attitude RMS | [0, pi] rad |
 * | Time Stamp | JAUS time stamp of time_jaus.h (not scaled) |
 *
 * Bits 9-15 are reserved: a body that sets one is rejected.
 *
 * **Sources.** AS6009 (JAUS Mobility Service Set 1.0, SAE): field order,
 * presence-vector bits, unsigned scaled-integer types and limits of
 * ReportGlobalPose and ReportLocalPose as reprinted with SAE's permission
 * by OpenJAUS (openjaus.com/htmlDoc/triggers/ReportGlobalPose-4402.html,
 * ReportLocalPose-4403.html; the same in docs.openjaus.com, Mobility
 * v1.0). JAUS Reference Architecture 3.x: the same order and limits with
 * signed types for the signed quantities, as OpenJAUS 3.2's libjausC
 * (reportGlobalPoseMessage.c: Integer for latitude, longitude and
 * elevation, Unsigned Integer for Position RMS, Short for the angles,
 * Unsigned Short for Attitude RMS) and JAUS++ 1.x for RA 3.3/3.4
 * (reportlocalpose.cpp: X and Y Integer over [-100 000, 100 000] m, Z
 * Integer over [-10 000, 35 000] m) read them. Only facts are taken, no
 * code.
 *
 * **Scaled integers** are drdc_jaus_scaled_encode() and
 * drdc_jaus_scaled_decode() of the chosen form (RA 3.x: signed types use
 * [-(2^(n-1) - 1), 2^(n-1) - 1] with the range's midpoint at 0; AS6009:
 * unsigned types, the lower limit at 0): correctly rounded, ties away
 * from zero, in both directions. The real values are raw values of the
 * pose types: latitude and longitude in nano-arcseconds (drdc_nas_t),
 * altitude Q47.16 m, X, Y, Z and Position RMS Q15.16 m, roll, pitch, yaw
 * and Attitude RMS binary angles (2^32 per turn; pi = 2^31).
 *
 * **Resolution** (one integer step; RA 3.x differs in the 10th digit):
 * latitude 4.2e-8 degree (4.7 mm), longitude 8.4e-8 degree, altitude
 * 1.05e-5 m, Position RMS 2.3e-8 m, X, Y, Z 4.7e-5 m (RA 3.x Z 1.05e-5
 * m), roll, pitch, yaw 9.6e-5 rad (0.0055 degree), Attitude RMS 4.8e-5
 * rad.
 *
 * **Round trips.** pack(unpack(body)) gives back the same bytes for every
 * field whose raw format resolves its integer step (latitude, longitude,
 * X, Y, AS6009 Z, the angles, Attitude RMS, Time Stamp), except an angle
 * whose integer decodes to +pi: it comes back as -pi, whose integer
 * differs (RA 3.x 32767 -> -32767, AS6009 65535 -> 0). Altitude and RA
 * 3.x Z (Q47.16 and Q15.16 step 1.5e-5 m > 1.05e-5 m) and Position RMS
 * do not resolve their step: their bytes may change by one step, but
 * unpack(pack(unpack(body))) == unpack(body) always (each raw value is
 * the one nearest its integer, whose nearest integer lies within half a
 * step of it). Packing a pose and unpacking it gives each value within
 * half an integer step, except one: AS6009 X, Y or Z = 32 768 - 2^-16 m
 * (INT32_MAX in Q15.16) decodes to 32 768 m, beyond Q15.16, and unpacking
 * gives DRDC_E_OVERFLOW.
 *
 * **Heights.** The Altitude field carries `pose.height` unchanged. {W}
 * heights are above mean sea level; JAUS asks for the position "in
 * accordance with WGS 84" without naming the height datum. A peer that
 * expects ellipsoidal heights needs the geoid separation added before
 * packing (GGA field 11, drdc_nmea_t).
 *
 * **Angles.** Roll, pitch and yaw are the Z-Y-X Euler angles of
 * drdc_euler_t, which is JAUS's platform orientation (x forward, y right,
 * z down, yaw clockwise from north). A binary angle is read as a signed
 * value in [-pi, pi); an integer that decodes to +pi gives the binary
 * angle of -pi (the same angle).
 * @{
 */

/** Message ID of Report Global Pose. */
#define DRDC_JAUS_ID_REPORT_GLOBAL_POSE UINT16_C(0x4402)
/** Message ID of Report Local Pose. */
#define DRDC_JAUS_ID_REPORT_LOCAL_POSE UINT16_C(0x4403)

/** Presence-vector bit of Latitude (Report Global Pose). */
#define DRDC_JAUS_PV_LATITUDE UINT16_C(0x0001)
/** Presence-vector bit of Longitude (Report Global Pose). */
#define DRDC_JAUS_PV_LONGITUDE UINT16_C(0x0002)
/** Presence-vector bit of Altitude (Report Global Pose). */
#define DRDC_JAUS_PV_ALTITUDE UINT16_C(0x0004)
/** Presence-vector bit of X (Report Local Pose). */
#define DRDC_JAUS_PV_X UINT16_C(0x0001)
/** Presence-vector bit of Y (Report Local Pose). */
#define DRDC_JAUS_PV_Y UINT16_C(0x0002)
/** Presence-vector bit of Z (Report Local Pose). */
#define DRDC_JAUS_PV_Z UINT16_C(0x0004)
/** Presence-vector bit of Position RMS (both messages). */
#define DRDC_JAUS_PV_POSITION_RMS UINT16_C(0x0008)
/** Presence-vector bit of Roll (both messages). */
#define DRDC_JAUS_PV_ROLL UINT16_C(0x0010)
/** Presence-vector bit of Pitch (both messages). */
#define DRDC_JAUS_PV_PITCH UINT16_C(0x0020)
/** Presence-vector bit of Yaw (both messages). */
#define DRDC_JAUS_PV_YAW UINT16_C(0x0040)
/** Presence-vector bit of Attitude RMS (both messages). */
#define DRDC_JAUS_PV_ATTITUDE_RMS UINT16_C(0x0080)
/** Presence-vector bit of Time Stamp (both messages). */
#define DRDC_JAUS_PV_TIME_STAMP UINT16_C(0x0100)
/** Every defined presence-vector bit; the others are reserved. */
#define DRDC_JAUS_PV_ALL UINT16_C(0x01FF)

/** Longest pose body: presence vector 2 + four 4-byte fields + four
 *  2-byte fields + the 4-byte time stamp = 30 bytes. */
#define DRDC_JAUS_POSE_BODY_MAX 30u

/** Body of Report Global Pose (4402h). Fields whose presence bit is clear
 *  are neither validated nor sent; unpacking sets them to zero. */
typedef struct drdc_jaus_global_pose {
  uint16_t presence; /**< DRDC_JAUS_PV_* bits of the fields present */
  /** latitude and longitude (nas), Altitude = height (Q47.16 m), and
   *  yaw, pitch, roll (binary angles) */
  drdc_WePose_t pose;
  drdc_q15_16_t position_rms; /**< Position RMS, Q15.16 m, [0, 100] */
  drdc_bam32_t attitude_rms;  /**< Attitude RMS, binary angle, [0, 2^31] */
  uint32_t time_stamp;        /**< JAUS time stamp (drdc_time_jaus_pack()) */
} drdc_jaus_global_pose_t;

/** Body of Report Local Pose (4403h). Fields whose presence bit is clear
 *  are neither validated nor sent; unpacking sets them to zero. */
typedef struct drdc_jaus_local_pose {
  uint16_t presence; /**< DRDC_JAUS_PV_* bits of the fields present */
  /** X, Y, Z (Q15.16 m) and yaw, pitch, roll (binary angles) */
  drdc_lePose_t pose;
  drdc_q15_16_t position_rms; /**< Position RMS, Q15.16 m, [0, 100] */
  drdc_bam32_t attitude_rms;  /**< Attitude RMS, binary angle, [0, 2^31] */
  uint32_t time_stamp;        /**< JAUS time stamp (drdc_time_jaus_pack()) */
} drdc_jaus_local_pose_t;

/**
 * Length in bytes of a pose body with a given presence vector (the same
 * for both messages and both forms).
 *
 * @param presence presence vector, bits 0-8 only
 * @param[out] size 2 + 4 per 32-bit field + 2 per 16-bit field present,
 *             2..30; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `size` is NULL
 * @retval DRDC_E_RANGE `presence` sets a reserved bit (9-15)
 *
 * @code
 * size_t n;
 * drdc_jaus_pose_size(DRDC_JAUS_PV_ALL, &n); // n = 30
 * @endcode
 */
drdc_status_t drdc_jaus_pose_size(uint16_t presence, size_t *size);

/**
 * Pack a Report Global Pose body.
 *
 * @param body the fields; only those whose bit is set in `body->presence`
 *        are checked and sent. Latitude within [-90, 90] degrees,
 *        longitude within [-180, 180] degrees (wrap it first), height
 *        within [-10 000, 35 000] m, Position RMS within [0, 100] m,
 *        Attitude RMS within [0, pi] (binary angle <= 2^31), a valid time
 *        stamp; any roll, pitch and yaw.
 * @param form  DRDC_JAUS_FORM_RA3 or DRDC_JAUS_FORM_AS6009 (the types of
 *        the table above)
 * @param[out] buf the body, little-endian; unchanged on error
 * @param capacity bytes available at `buf`
 * @param[out] length bytes written, drdc_jaus_pose_size() of the
 *        presence vector; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `body`, `buf` or `length` is NULL
 * @retval DRDC_E_RANGE `form` is not one of the enumerators, the presence
 *         vector sets a reserved bit, or a height, Position RMS or
 *         Attitude RMS present is outside its range
 * @retval DRDC_E_LATITUDE a latitude present is outside [-90, 90] degrees
 * @retval DRDC_E_LONGITUDE a longitude present is outside [-180, 180]
 *         degrees
 * @retval DRDC_E_DAY a time stamp present has day 0
 * @retval DRDC_E_HOUR a time stamp present has hour 24..31
 * @retval DRDC_E_MINUTE a time stamp present has minute 60..63
 * @retval DRDC_E_SECOND a time stamp present has second 61..63
 * @retval DRDC_E_NANOSECOND a time stamp present has milliseconds
 *         1000..1023
 * @retval DRDC_E_BUFFER `capacity` is less than the body's length
 *
 * Checks in this order: pointers, form, reserved bits, the fields present
 * in bit order, the time stamp, `capacity`. Accuracy: every integer is
 * correctly rounded (0 LSB against an exact rational model,
 * tests/ref/gen_jaus_pose.py); the bytes are the same on every target
 * (checked on big-endian PowerPC e500).
 *
 * @code
 * drdc_jaus_global_pose_t b = { 0 };
 * uint8_t buf[DRDC_JAUS_POSE_BODY_MAX];
 * size_t n;
 * b.presence = DRDC_JAUS_PV_LATITUDE | DRDC_JAUS_PV_YAW;
 * b.pose.latitude = 45 * DRDC_NAS_PER_DEGREE;
 * b.pose.e.yaw = UINT32_C(0x40000000);                // 90 degrees
 * drdc_jaus_global_pose_pack(&b, DRDC_JAUS_FORM_AS6009, buf, sizeof buf, &n);
 * // n = 8: 41 00 | ff ff ff bf | ff bf
 * // (latitude 3221225471, yaw 49151 = round(0.75 x 65535))
 * @endcode
 */
drdc_status_t drdc_jaus_global_pose_pack(const drdc_jaus_global_pose_t *body,
                                         drdc_jaus_form_t form, uint8_t *buf,
                                         size_t capacity, size_t *length);

/**
 * Unpack a Report Global Pose body.
 *
 * @param buf the body as received, little-endian; only `length` bytes are
 *        read
 * @param length the body's length: exactly drdc_jaus_pose_size() of its
 *        presence vector
 * @param form  DRDC_JAUS_FORM_RA3 or DRDC_JAUS_FORM_AS6009: the sender's
 * @param[out] body the fields, absent ones zero; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `buf` or `body` is NULL
 * @retval DRDC_E_TRUNCATED `length` is shorter than 2 or than the length
 *         its presence vector needs
 * @retval DRDC_E_OVERLONG `length` is longer than its presence vector
 *         needs
 * @retval DRDC_E_RANGE `form` is not one of the enumerators, the presence
 *         vector sets a reserved bit, or (RA 3.x) a signed field holds
 *         the unused most negative integer (-2^31 or -32768)
 * @retval DRDC_E_DAY the time stamp has day 0
 * @retval DRDC_E_HOUR the time stamp has hour 24..31
 * @retval DRDC_E_MINUTE the time stamp has minute 60..63
 * @retval DRDC_E_SECOND the time stamp has second 61..63
 * @retval DRDC_E_NANOSECOND the time stamp has milliseconds 1000..1023
 *
 * Checks in this order: pointers, form, length of the presence vector,
 * reserved bits, length, then the fields in bit order. Accuracy: each raw
 * value is correctly rounded (0 LSB against the exact model). Never reads
 * beyond `buf[length - 1]`.
 */
drdc_status_t drdc_jaus_global_pose_unpack(const uint8_t *buf, size_t length,
                                           drdc_jaus_form_t form,
                                           drdc_jaus_global_pose_t *body);

/**
 * Pack a Report Local Pose body.
 *
 * @param body the fields; only those whose bit is set in `body->presence`
 *        are checked and sent. X and Y: any Q15.16 value (inside [-100
 *        000, 100 000] m); Z any Q15.16 value in AS6009, within [-10 000,
 *        35 000] m in RA 3.x; Position RMS within [0, 100] m, Attitude RMS
 *        within [0, pi], a valid time stamp; any roll, pitch and yaw.
 * @param form  DRDC_JAUS_FORM_RA3 or DRDC_JAUS_FORM_AS6009
 * @param[out] buf the body, little-endian; unchanged on error
 * @param capacity bytes available at `buf`
 * @param[out] length bytes written; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `body`, `buf` or `length` is NULL
 * @retval DRDC_E_RANGE `form` is not one of the enumerators, the presence
 *         vector sets a reserved bit, or a Z (RA 3.x), Position RMS or
 *         Attitude RMS present is outside its range
 * @retval DRDC_E_DAY a time stamp present has day 0
 * @retval DRDC_E_HOUR a time stamp present has hour 24..31
 * @retval DRDC_E_MINUTE a time stamp present has minute 60..63
 * @retval DRDC_E_SECOND a time stamp present has second 61..63
 * @retval DRDC_E_NANOSECOND a time stamp present has milliseconds
 *         1000..1023
 * @retval DRDC_E_BUFFER `capacity` is less than the body's length
 *
 * Accuracy: every integer correctly rounded (0 LSB against the exact
 * model); the same bytes on every target.
 */
drdc_status_t drdc_jaus_local_pose_pack(const drdc_jaus_local_pose_t *body,
                                        drdc_jaus_form_t form, uint8_t *buf,
                                        size_t capacity, size_t *length);

/**
 * Unpack a Report Local Pose body.
 *
 * @param buf the body as received, little-endian; only `length` bytes are
 *        read
 * @param length the body's length: exactly drdc_jaus_pose_size() of its
 *        presence vector
 * @param form  DRDC_JAUS_FORM_RA3 or DRDC_JAUS_FORM_AS6009: the sender's
 * @param[out] body the fields, absent ones zero; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `buf` or `body` is NULL
 * @retval DRDC_E_TRUNCATED `length` is shorter than 2 or than the length
 *         its presence vector needs
 * @retval DRDC_E_OVERLONG `length` is longer than its presence vector
 *         needs
 * @retval DRDC_E_RANGE `form` is not one of the enumerators, the presence
 *         vector sets a reserved bit, or (RA 3.x) a signed field holds
 *         the unused most negative integer (-2^31 or -32768)
 * @retval DRDC_E_OVERFLOW X, Y or Z lies outside the +-32 768 m of {le}'s
 *         Q15.16 (JAUS allows +-100 000 m)
 * @retval DRDC_E_DAY the time stamp has day 0
 * @retval DRDC_E_HOUR the time stamp has hour 24..31
 * @retval DRDC_E_MINUTE the time stamp has minute 60..63
 * @retval DRDC_E_SECOND the time stamp has second 61..63
 * @retval DRDC_E_NANOSECOND the time stamp has milliseconds 1000..1023
 *
 * Checks in the order of drdc_jaus_global_pose_unpack(), the Q15.16
 * overflow last. Accuracy: correctly rounded (0 LSB). Never reads beyond
 * `buf[length - 1]`.
 */
drdc_status_t drdc_jaus_local_pose_unpack(const uint8_t *buf, size_t length,
                                          drdc_jaus_form_t form,
                                          drdc_jaus_local_pose_t *body);

/** @} */

#endif /* DRDC_JAUS_POSE_H */
