/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_orient
 * @brief Orientation: unit quaternions, Euler Z-Y-X angles, rotation
 *        matrices, axis-angle, interpolation and frame changes.
 */
#ifndef DRDC_ORIENT_H
#define DRDC_ORIENT_H

#include <stdint.h>

#include <drdc/types.h>

/**
 * @defgroup drdc_orient Orientation
 *
 * Conventions:
 * - quaternions are scalar first, q = [s, x, y, z], Hamilton product,
 *   each part Q1.30 (2^30 = 1.0); q = [1, 0, 0, 0] is the body x axis on
 *   True North, level, no roll. q and -q are the same orientation.
 * - body frame {l}: x forward, y right, z down (FRD); world frame:
 *   north-east-down (NED). A quaternion or matrix rotates body
 *   coordinates into world coordinates: v_world = R(q) v_body.
 * - Euler angles [yaw, pitch, roll] are the Z-Y-X (intrinsic) sequence,
 *   R = Rz(yaw) Ry(pitch) Rx(roll), as drdc_bam32_t binary angles (2^32
 *   per turn; read as int32_t for [-180, 180) degrees). Pitch is in
 *   [-90, 90] degrees, i.e. [3 2^30, 2^32) or [0, 2^30].
 * - the rotation matrix ("DCM") is body-to-world, Q1.30, m[row][col].
 * - local lengths are Q15.16 metres, global lengths Q47.16 metres.
 *
 * Gimbal lock: when cos(pitch) < 2^-DRDC_ORIENT_GIMBAL_COS_LOG2 (2^-24:
 * |pitch| within 6e-8 rad, 3.4e-6 degree, of 90 degrees), yaw and roll
 * are not separable; the conversions to Euler angles then set roll to 0
 * and put all the rotation about the vertical into yaw (yaw - roll at
 * pitch +90, yaw + roll at pitch -90).
 *
 * Rounding: every result is computed from exact 64-bit (Q60) or 128-bit
 * intermediates and rounded once to nearest, ties away from zero, unless
 * a function says otherwise. Errors are stated against the exact result
 * of the exact (integer) inputs, measured against SciPy 1.17
 * (scipy.spatial.transform.Rotation) and numpy double precision on the
 * vectors of tests/ref/gen_orient_*.py; docs/accuracy.md has the table.
 *
 * Non-unit quaternions: every function that takes a quaternion accepts
 * any non-zero int32_t parts and uses the rotation of q / |q| unless it
 * says otherwise (multiply, conjugate and the linear operations work on
 * the parts as given). A quaternion with a part beyond +-1.0 is first
 * halved, rounded, which moves its rotation by at most 2^-30 rad.
 * @{
 */

/** Quaternion, scalar first, each part Q1.30. */
typedef struct drdc_quat {
  drdc_q1_30_t s; /**< scalar part (cos of half the rotation angle) */
  drdc_q1_30_t x; /**< vector part along x */
  drdc_q1_30_t y; /**< vector part along y */
  drdc_q1_30_t z; /**< vector part along z */
} drdc_quat_t;

/** Euler angles, Z-Y-X sequence, binary angles (2^32 per turn). */
typedef struct drdc_euler {
  drdc_bam32_t yaw;   /**< Psi, about z (down): positive turns right */
  drdc_bam32_t pitch; /**< Theta, about the new y: positive nose up */
  drdc_bam32_t roll;  /**< Phi, about the new x: positive right wing down */
} drdc_euler_t;

/** Rotation matrix (body to world), Q1.30, m[row][column]. */
typedef struct drdc_dcm {
  drdc_q1_30_t m[3][3]; /**< elements, each in [-1, 1] */
} drdc_dcm_t;

/** Unit-scale 3-vector (rotation axis, direction), Q1.30 parts. */
typedef struct drdc_vec3_q1_30 {
  drdc_q1_30_t x; /**< x part */
  drdc_q1_30_t y; /**< y part */
  drdc_q1_30_t z; /**< z part */
} drdc_vec3_q1_30_t;

/** Local 3-vector in metres, Q15.16 parts (+-32 km, 15 um). */
typedef struct drdc_vec3_q15_16 {
  drdc_q15_16_t x; /**< x part, m */
  drdc_q15_16_t y; /**< y part, m */
  drdc_q15_16_t z; /**< z part, m */
} drdc_vec3_q15_16_t;

/** Global 3-vector in metres, Q47.16 parts. */
typedef struct drdc_vec3_q47_16 {
  drdc_q47_16_t x; /**< x part, m */
  drdc_q47_16_t y; /**< y part, m */
  drdc_q47_16_t z; /**< z part, m */
} drdc_vec3_q47_16_t;

/** Gimbal-lock threshold of the Euler conversions: cos(pitch) below
 *  2^-DRDC_ORIENT_GIMBAL_COS_LOG2 counts as pitch = +-90 degrees. 2^-24
 *  (6e-8 rad) is far above the 2^-30 quantisation of a Q1.30 quaternion
 *  at pitch = +-90 degrees and below SciPy's 1e-7 rad. */
#define DRDC_ORIENT_GIMBAL_COS_LOG2 24

/** Largest |part| of a Q47.16 vector that the rotations accept:
 *  2^55 raw (5.5e11 m), so the 6 guard bits of their sums fit int64. */
#define DRDC_ORIENT_Q47_16_MAX (INT64_C(1) << 55)

/* ---------------------------------------------------------------- */
/** @name Quaternion algebra (quat.c, quat_ops.c, quat_rotate*.c)
 *  @{ */

/**
 * Hamilton product out = a * b (apply b, then a: the orientation b given
 * in the body frame of a, expressed in a's world frame).
 *
 * @param a, b quaternions, any Q1.30 parts
 * @param[out] out product, Q1.30; may be the same object as a or b;
 *             unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_OVERFLOW a part of the product is outside [-2, 2)
 *         (only possible when |a| |b| >= 2)
 *
 * Scaling: each part is a sum of four exact Q60 products (64-bit; when a
 * part of a is beyond +-1.0 the sums are checked for overflow), rounded
 * once: correctly rounded, error <= 0.5 LSB. Measured: 0 LSB against
 * exact Python-integer products (55 cases incl. overflow); q * conj(q) of
 * a normalised q is 1 within 2 LSB.
 *
 * Cost: within 1.5 times the cycles of a hand-written 16
 * multiply-accumulate product with truncating shifts and the same
 * signature, on Cortex-M3 and PowerPC e500 (the rounding, the range test
 * and the overflow checks); soft-float double takes more than 10 times
 * as long on Cortex-M3. docs/performance.md has the measured ratios
 * (`./waf bench`).
 *
 * @code
 * drdc_quat_t yaw90 = { 759250125, 0, 0, 759250125 }, r;
 * drdc_quat_mul(&yaw90, &yaw90, &r);   // r = { 0, 0, 0, 2^30 }: yaw 180 deg
 * @endcode
 */
drdc_status_t drdc_quat_mul(const drdc_quat_t *a, const drdc_quat_t *b,
                            drdc_quat_t *out);

/**
 * Conjugate [s, -x, -y, -z]: exact. For a unit quaternion this is the
 * inverse rotation (world to body).
 * @param q any quaternion
 * @param[out] out conjugate; may be q; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_OVERFLOW a vector part is INT32_MIN (-2.0): +2.0 does
 *         not fit Q1.30
 */
drdc_status_t drdc_quat_conj(const drdc_quat_t *q, drdc_quat_t *out);

/**
 * Inverse q^-1 = conj(q) / |q|^2, so that q * q^-1 = [1, 0, 0, 0] for
 * any non-zero q (for a unit q it equals the conjugate).
 * @param q non-zero quaternion
 * @param[out] out inverse in Q1.30; may be q; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_DOMAIN q is zero
 * @retval DRDC_E_OVERFLOW a part of the inverse is outside [-2, 2)
 *         (|q| below about 0.5)
 *
 * Accuracy: correctly rounded (0.5 LSB) when every |part| <= 1.0; one
 * more LSB when q had to be halved first.
 */
drdc_status_t drdc_quat_inverse(const drdc_quat_t *q, drdc_quat_t *out);

/**
 * Unit quaternion q / |q| from any non-zero quaternion, however far from
 * unit length (from one LSB to INT32_MIN parts). The sign is kept.
 * @param q non-zero quaternion, any int32_t parts
 * @param[out] out q / |q| in Q1.30; may be q; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_DOMAIN q is zero: no direction
 *
 * Method: exact power-of-two prescaling (halving with rounding above 1.0),
 * exact 64-bit sum of squares, a correctly rounded 64-bit square root with
 * 31 to 32 significant bits, one correctly rounded division per part.
 * Accuracy: each part within 0.75 LSB of the exact q / |q| (0.5 for the
 * final rounding, 0.25 from the 31-bit root); | |out| - 1 | measured at
 * most 1.01 LSB of Q1.30 (20 000 random quaternions of every length;
 * required: at most 2 LSB).
 *
 * @code
 * drdc_quat_t q = { 3, 0, 4, 0 }, n;   // any length
 * drdc_quat_normalize(&q, &n);   // n = { 644245094, 0, 858993459, 0 }
 * @endcode
 */
drdc_status_t drdc_quat_normalize(const drdc_quat_t *q, drdc_quat_t *out);

/**
 * The same rotation with the sign chosen so that s > 0, or, when s == 0,
 * so that the first non-zero part is positive (the canonical form of the
 * `drdc attitude` tool). Exact.
 * @param q any quaternion
 * @param[out] out q or -q; may be q; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_OVERFLOW -q is needed and a part is INT32_MIN
 */
drdc_status_t drdc_quat_canonical(const drdc_quat_t *q, drdc_quat_t *out);

/**
 * Rotate a local vector: out = R(q) v (body to world for an attitude q).
 * @param q non-zero quaternion (its rotation q / |q| is used)
 * @param v vector, Q15.16 metres
 * @param[out] out rotated vector, Q15.16; may be v; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_DOMAIN q is zero
 * @retval DRDC_E_OVERFLOW a rotated part is outside +-32768 m (possible
 *         when |v| >= 32768 m)
 *
 * Method: the exact Q60 numerators p of R(q) and the exact |q|^2 (the
 * matrix is never rounded to Q1.30); each part sum(p v) is exact in 96
 * bits and divided once by |q|^2 with a precomputed reciprocal (two
 * 32x32 products per quotient, Moeller and Granlund's division by an
 * invariant integer), the remainder deciding the rounding.
 * Accuracy: correctly rounded (0.5 LSB of Q15.16, 7.6 um; ties away from
 * zero) against the exact rotation of q / |q| when every |part| of q is
 * at most 1.0 (above, q is first halved with rounding: one more rounding
 * of q). Checked exactly against Python integers (64 rows incl. 8 that
 * the former per-term rounding got wrong); 0 LSB against SciPy rounded.
 *
 * @code
 * drdc_quat_t yaw90 = { 759250125, 0, 0, 759250125 };
 * drdc_vec3_q15_16_t v = { 1 << 16, 0, 0 };   // 1 m forward
 * drdc_quat_rotate_q15_16(&yaw90, &v, &v);   // v = { 0, 65536, 0 }: east
 * @endcode
 */
drdc_status_t drdc_quat_rotate_q15_16(const drdc_quat_t *q,
                                      const drdc_vec3_q15_16_t *v,
                                      drdc_vec3_q15_16_t *out);

/**
 * Rotate a global vector: out = R(q) v, Q47.16 metres.
 * @param q non-zero quaternion
 * @param v vector, |parts| <= DRDC_ORIENT_Q47_16_MAX
 * @param[out] out rotated vector; may be v; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_DOMAIN q is zero
 * @retval DRDC_E_RANGE a part of v is beyond DRDC_ORIENT_Q47_16_MAX
 *
 * Method: the exact Q60 numerators of R(q) and |q|^2 as for
 * drdc_quat_rotate_q15_16(), each term p v / |q|^2 rounded with 6 guard
 * bits through a 128-bit intermediate, the sum rounded once.
 * Accuracy: within 0.53 LSB of Q47.16 of the exact rotation, at every
 * length up to 5.5e11 m (the loss of a Q1.30 matrix, 2^-31 |v|, is
 * avoided).
 */
drdc_status_t drdc_quat_rotate_q47_16(const drdc_quat_t *q,
                                      const drdc_vec3_q47_16_t *v,
                                      drdc_vec3_q47_16_t *out);

/**
 * Composition of orientations: out = normalize(a * b). With a the
 * attitude of frame B in frame A and b that of C in B, out is the
 * attitude of C in A.
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_DOMAIN the product is zero (a or b zero)
 * @retval DRDC_E_OVERFLOW the product overflows (only possible when
 *         |a| |b| >= 2)
 *
 * Accuracy: parts within 1 LSB of the exact normalised product (0.5 LSB
 * of the product plus the normalisation), |out| - 1 within 2 LSB.
 */
drdc_status_t drdc_quat_compose(const drdc_quat_t *a, const drdc_quat_t *b,
                                drdc_quat_t *out);

/**
 * Difference of orientations: out = normalize(conj(a) * b), the rotation
 * that takes orientation a to orientation b, in a's body frame, so that
 * compose(a, out) == b (within rounding).
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_DOMAIN the product is zero
 * @retval DRDC_E_OVERFLOW a vector part of `a` is INT32_MIN (its conjugate
 *         does not fit Q1.30), or the product overflows (only possible
 *         when |a| |b| >= 2)
 */
drdc_status_t drdc_quat_difference(const drdc_quat_t *a, const drdc_quat_t *b,
                                   drdc_quat_t *out);

/**
 * Angle of the shortest rotation between two orientations, in [0, pi]
 * (0..2^31 as a binary angle): 2 atan2(|v|, |s|) of conj(a) * b, so it is
 * accurate for small and large angles alike (no acos). q and -q give the
 * same answer.
 * @param a, b non-zero quaternions (their rotations are used)
 * @param[out] angle binary angle 0..2^31; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_DOMAIN a or b is zero
 */
drdc_status_t drdc_quat_angle_between(const drdc_quat_t *a,
                                      const drdc_quat_t *b,
                                      drdc_bam32_t *angle);

/** @} */

/* ---------------------------------------------------------------- */
/** @name Conversions (euler*.c, dcm.c, axis_angle.c)
 *  @{ */

/**
 * Quaternion of Z-Y-X Euler angles: q = qz(yaw) * qy(pitch) * qx(roll).
 * @param e any angles (each wraps; pitch beyond +-90 deg is accepted and
 *          gives the same rotation formula)
 * @param[out] out unit quaternion; unchanged on error. Half angles are
 *             taken in [-90, 90) degrees, so the sign follows from them
 *             (s < 0 is possible; q and -q are the same rotation).
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 *
 * Method: sin and cos of the half angles from drdc_fx_sincos_bam32()
 * (odd binary angles by the mean of the two neighbours), products kept
 * in 64 bits with one intermediate rounding to Q1.31 and one final one.
 * Accuracy: measured max 2 LSB of Q1.30 per part against SciPy (20 256
 * orientations incl. yaw +-180 and pitch +-90 degrees; required: at
 * most 4 LSB).
 *
 * @code
 * drdc_euler_t e = { 1u << 30, 0u, 0u };   // heading east (yaw 90 deg)
 * drdc_quat_t q;
 * drdc_quat_from_euler(&e, &q);   // q = { 759250125, 0, 0, 759250125 }
 * @endcode
 */
drdc_status_t drdc_quat_from_euler(const drdc_euler_t *e, drdc_quat_t *out);

/**
 * Z-Y-X Euler angles of a quaternion.
 * @param q non-zero quaternion (q / |q| is used)
 * @param[out] out yaw and roll in [-180, 180) degrees (as int32_t), pitch
 *             in [-90, 90]; unchanged on error. In gimbal lock (see
 *             DRDC_ORIENT_GIMBAL_COS_LOG2) roll = 0 and yaw carries the
 *             whole rotation about the vertical.
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_DOMAIN q is zero
 *
 * Method: the matrix elements needed are exact Q60 integers of q; yaw =
 * atan2(R21, R11), pitch = atan2(-R31, hypot(R11, R21)), roll =
 * atan2(R32, R33), each with both arguments scaled to 31 bits.
 * Accuracy: measured max 1.125 binary-angle units (9.4e-8 degree) from
 * SciPy's angles of the exact integer input, when |pitch| is at least
 * 0.001 degree from 90 degrees or exactly in gimbal lock (20 249 cases;
 * required: at most 1e-7 degree). Closer to the lock the angles are
 * ill-conditioned; they then describe the input rotation to 3 LSB per
 * matrix element.
 *
 * @code
 * drdc_quat_t q = { 759250125, 0, 0, 759250125 };
 * drdc_euler_t e;
 * drdc_euler_from_quat(&q, &e);   // e = { 1u << 30, 0u, 0u }
 * @endcode
 */
drdc_status_t drdc_euler_from_quat(const drdc_quat_t *q, drdc_euler_t *out);

/**
 * Rotation matrix of a quaternion (body to world), correctly rounded:
 * every element is the exact element of the rotation q / |q| rounded to
 * Q1.30 (error <= 0.5 LSB), from exact Q60 numerators divided by the
 * exact |q|^2 with 128-bit intermediates. Measured: 1 LSB against SciPy
 * (its double rounding), 2 LSB when a part of q is beyond 1.0 (q is
 * halved first).
 * @param q non-zero quaternion
 * @param[out] out matrix; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_DOMAIN q is zero
 *
 * @code
 * drdc_quat_t q = { 759250125, 0, 0, 759250125 };   // yaw 90 deg
 * drdc_dcm_t r;
 * drdc_dcm_from_quat(&q, &r);   // first column { 0, 2^30, 0 }: x -> east
 * @endcode
 */
drdc_status_t drdc_dcm_from_quat(const drdc_quat_t *q, drdc_dcm_t *out);

/**
 * Quaternion of a rotation matrix, robust for every angle including 180
 * degrees (Shepperd's method: the largest of 1 + trace, 1 + 2 R11 - trace,
 * ... decides which part is computed from a square root).
 * @param r rotation matrix, Q1.30; a matrix that is orthonormal to a few
 *          LSB (as from any function here) gives a quaternion of the
 *          nearest rotation to within that error
 * @param[out] out unit quaternion with its largest part positive;
 *             unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_DOMAIN the matrix is far from a rotation: the
 *         quaternion it gives has |q|^2 outside [0.5, 2] before
 *         normalisation (e.g. the zero matrix)
 *
 * Accuracy: measured max 1 LSB per part against SciPy (124 matrices incl.
 * 24 half turns); |out| - 1 within 1.01 LSB.
 */
drdc_status_t drdc_quat_from_dcm(const drdc_dcm_t *r, drdc_quat_t *out);

/**
 * The same Euler angles in their canonical ranges, exactly: pitch in
 * [-90, 90] degrees (a pitch beyond, e.g. 100 degrees, becomes 80 degrees
 * with yaw and roll turned by 180 degrees), and at pitch exactly +-90
 * degrees (2^30 or 3 2^30) the gimbal-lock rule: roll 0, yaw - roll
 * (pitch +90) or yaw + roll (pitch -90) in yaw. Yaw and roll stay binary
 * angles ([-180, 180) read as int32_t). Integer arithmetic modulo a turn:
 * no rounding.
 * @param e any angles
 * @param[out] out canonical angles; may be e
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 */
drdc_status_t drdc_euler_canonical(const drdc_euler_t *e, drdc_euler_t *out);

/**
 * Rotation matrix of Z-Y-X Euler angles: R = Rz(yaw) Ry(pitch) Rx(roll).
 * @param e any angles
 * @param[out] out matrix; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 *
 * Accuracy: measured max 1 LSB per element against SciPy (256 rows).
 */
drdc_status_t drdc_dcm_from_euler(const drdc_euler_t *e, drdc_dcm_t *out);

/**
 * Z-Y-X Euler angles of a rotation matrix; same formulas, ranges and
 * gimbal-lock rule as drdc_euler_from_quat().
 * @param r rotation matrix, Q1.30
 * @param[out] out angles; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_DOMAIN yaw and pitch are undefined: the first column is
 *         zero, or the matrix is at gimbal lock with R12 = R22 = 0 (not
 *         a rotation matrix)
 */
drdc_status_t drdc_euler_from_dcm(const drdc_dcm_t *r, drdc_euler_t *out);

/**
 * Product of rotation matrices out = a b, each element one correctly
 * rounded sum of three exact Q60 products.
 * @param a left factor, Q1.30
 * @param b right factor, Q1.30
 * @param[out] out product; may be a or b; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_OVERFLOW an element is outside [-2, 2) (not for
 *         rotation matrices)
 */
drdc_status_t drdc_dcm_mul(const drdc_dcm_t *a, const drdc_dcm_t *b,
                           drdc_dcm_t *out);

/**
 * Transpose (the inverse rotation, world to body): exact.
 * @param r rotation matrix, Q1.30
 * @param[out] out transpose; may be r
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 */
drdc_status_t drdc_dcm_transpose(const drdc_dcm_t *r, drdc_dcm_t *out);

/**
 * out = R v for a local vector (Q15.16 metres): each part one correctly
 * rounded sum of three exact products (error <= 0.5 LSB of Q15.16 from
 * the arithmetic, plus |v| times the matrix's own error).
 * @param r rotation matrix, Q1.30
 * @param v local vector, Q15.16 m
 * @param[out] out may be v; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_OVERFLOW a part is outside +-32768 m
 */
drdc_status_t drdc_dcm_apply_q15_16(const drdc_dcm_t *r,
                                    const drdc_vec3_q15_16_t *v,
                                    drdc_vec3_q15_16_t *out);

/**
 * out = R v for a global vector (Q47.16 metres). Each product is rounded
 * to 6 guard bits (128-bit intermediate), the sum once more: error <= 0.55
 * LSB of Q47.16 from the arithmetic.
 * @param r rotation matrix, Q1.30
 * @param v |parts| <= DRDC_ORIENT_Q47_16_MAX
 * @param[out] out may be v; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_RANGE a part of v is beyond DRDC_ORIENT_Q47_16_MAX
 * @retval DRDC_E_OVERFLOW a sum overflows (only for matrix elements
 *         beyond +-1.0)
 */
drdc_status_t drdc_dcm_apply_q47_16(const drdc_dcm_t *r,
                                    const drdc_vec3_q47_16_t *v,
                                    drdc_vec3_q47_16_t *out);

/**
 * Quaternion of a rotation by `angle` about `axis` (right-handed).
 * @param axis non-zero vector, any int32_t parts (normalised here)
 * @param angle any binary angle; the half angle is taken in [-90, 90)
 *              degrees
 * @param[out] out unit quaternion; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_DOMAIN the axis is zero
 *
 * Accuracy: measured max 1 LSB per part against SciPy (48 rows).
 */
drdc_status_t drdc_quat_from_axis_angle(const drdc_vec3_q1_30_t *axis,
                                        drdc_bam32_t angle, drdc_quat_t *out);

/**
 * Axis and angle of a quaternion, the angle in [0, 180] degrees (0..2^31)
 * as 2 atan2(|v|, |s|), the axis a unit vector (sign chosen with the
 * angle so that the angle is at most 180 degrees).
 * @param q non-zero quaternion, any int32_t parts
 * @param[out] axis unit axis, Q1.30: q's own vector part over its
 *             length, negated when q's scalar part is negative;
 *             [1, 0, 0] when the vector part is zero; may be NULL
 * @param[out] angle rotation angle; may be NULL
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL both outputs are NULL or q is NULL
 * @retval DRDC_E_DOMAIN q is zero
 *
 * Method: the half angle is atan2(|v|, |s|) of q's exact parts, both
 * scaled by one power of two so that the larger lies in [2^30, 2^31]
 * (|v| a correctly rounded root of the exact sum of squares); the axis
 * is v 2^30 / |v| with |v| likewise scaled into [2^30, 2^31].
 * Accuracy: axis 1 LSB per part (within 1 before rounding: half from
 * the root, half from the quotient; 0.93 measured), angle 1.8
 * binary-angle units (2.6e-9 rad; twice the atan2's error) against
 * mpmath on 112 000 random quaternions of every length from 1 LSB to
 * the int32_t limit, near the identity and near 180 degrees included
 * (tools/accuracy/orient_bounds.py).
 */
drdc_status_t drdc_axis_angle_from_quat(const drdc_quat_t *q,
                                        drdc_vec3_q1_30_t *axis,
                                        drdc_bam32_t *angle);

/** @} */

/* ---------------------------------------------------------------- */
/** @name Interpolation (quat_interp.c)
 *  @{ */

/**
 * Normalised linear interpolation along the shorter arc:
 * normalize((1 - t) a + t b'), b' = -b when the exact integer dot
 * product a . b is negative, else b.
 * @param a, b unit quaternions (non-unit ones, of any int32_t parts,
 *        weigh by their length)
 * @param t Q1.30 fraction in [0, 1] (0..2^30)
 * @param[out] out unit quaternion; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_RANGE t outside [0, 1]
 * @retval DRDC_E_DOMAIN the interpolated quaternion is zero
 *
 * Method: (1 - t) a + t b' exactly (int64), shifted as a whole so that
 * its largest part is within (2^29, 2^30], then normalised.
 * Accuracy: 1 LSB per part (1.49 before rounding) against mpmath's
 * normalised weighted sum on 112 000 random pairs of every length from
 * 1 LSB to the int32_t limit (near-equal, near-opposite and near a
 * quarter turn apart included; tools/accuracy/orient_bounds.py).
 */
drdc_status_t drdc_quat_nlerp(const drdc_quat_t *a, const drdc_quat_t *b,
                              drdc_q1_30_t t, drdc_quat_t *out);

/**
 * Spherical linear interpolation along the shorter arc (constant angular
 * rate): out = a * (conj(a) * b')^t.
 * @param a, b non-zero quaternions (their rotations are used)
 * @param t Q1.30 fraction in [0, 1]
 * @param[out] out unit quaternion; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_RANGE t outside [0, 1]
 * @retval DRDC_E_DOMAIN a or b is zero
 *
 * The shorter arc is the one of the sign of the exact integer dot
 * product a . b (at a dot of exactly 0 both arcs are a half turn long;
 * b is kept).
 *
 * Accuracy: 3 LSB per part (3.07 before rounding) against mpmath's
 * slerp on 112 000 random pairs of every length from 1 LSB to the int32_t
 * limit (near-equal, near-opposite and near a quarter turn apart
 * included; tools/accuracy/orient_bounds.py); |out| - 1 within 1.01 LSB.
 */
drdc_status_t drdc_quat_slerp(const drdc_quat_t *a, const drdc_quat_t *b,
                              drdc_q1_30_t t, drdc_quat_t *out);

/**
 * Control point ("quad" of libdrdc) of a squad spline at key q1 between
 * its neighbours q0 and q2:
 * s1 = q1 exp(-(log(q1^-1 q2) + log(q1^-1 q0)) / 4).
 * @param q0, q1, q2 consecutive unit keys
 * @param[out] out control quaternion; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_DOMAIN a key is zero
 */
drdc_status_t drdc_quat_squad_control(const drdc_quat_t *q0,
                                      const drdc_quat_t *q1,
                                      const drdc_quat_t *q2, drdc_quat_t *out);

/**
 * Spherical quadrangle interpolation between keys q1 and q2 with control
 * points s1 and s2: slerp(slerp(q1, q2, t), slerp(s1, s2, t), 2t(1 - t))
 * (the first inner slerp takes the shorter arc; the one between the
 * control points does not, as Shoemake defines it).
 * @param q1 key at t = 0, unit quaternion
 * @param q2 key at t = 1, unit quaternion
 * @param s1 control point of q1 (drdc_quat_squad_control())
 * @param s2 control point of q2
 * @param t Q1.30 fraction in [0, 1]
 * @param[out] out unit quaternion; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_RANGE t outside [0, 1]
 * @retval DRDC_E_DOMAIN a quaternion is zero
 */
drdc_status_t drdc_quat_squad(const drdc_quat_t *q1, const drdc_quat_t *q2,
                              const drdc_quat_t *s1, const drdc_quat_t *s2,
                              drdc_q1_30_t t, drdc_quat_t *out);

/** @} */

/* ---------------------------------------------------------------- */
/** @name Frame changes (frames.c)
 *  Body FRD (x forward, y right, z down) <-> FLU (x forward, y left,
 *  z up): a half turn about x. World NED <-> ENU: x and y swapped, z
 *  negated. Each map is its own inverse, so one function serves both
 *  directions.
 *  @{ */

/**
 * FRD <-> FLU body vector: [x, -y, -z], exact.
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_OVERFLOW y or z is INT32_MIN
 */
drdc_status_t drdc_frame_frd_flu_q15_16(const drdc_vec3_q15_16_t *v,
                                        drdc_vec3_q15_16_t *out);

/** NED <-> ENU world vector: [y, x, -z], exact.
 *  @retval DRDC_OK written
 *  @retval DRDC_E_NULL a pointer is NULL
 *  @retval DRDC_E_OVERFLOW z is INT32_MIN */
drdc_status_t drdc_frame_ned_enu_q15_16(const drdc_vec3_q15_16_t *v,
                                        drdc_vec3_q15_16_t *out);

/** FRD <-> FLU for a global (Q47.16) vector, exact.
 *  @retval DRDC_OK written
 *  @retval DRDC_E_NULL a pointer is NULL
 *  @retval DRDC_E_OVERFLOW y or z is INT64_MIN */
drdc_status_t drdc_frame_frd_flu_q47_16(const drdc_vec3_q47_16_t *v,
                                        drdc_vec3_q47_16_t *out);

/** NED <-> ENU for a global (Q47.16) vector, exact.
 *  @retval DRDC_OK written
 *  @retval DRDC_E_NULL a pointer is NULL
 *  @retval DRDC_E_OVERFLOW z is INT64_MIN */
drdc_status_t drdc_frame_ned_enu_q47_16(const drdc_vec3_q47_16_t *v,
                                        drdc_vec3_q47_16_t *out);

/**
 * Attitude with the body frame changed FRD <-> FLU: out = q * [0, 1, 0, 0]
 * = [-x, s, z, -y], exact.
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_OVERFLOW x or y is INT32_MIN
 */
drdc_status_t drdc_frame_frd_flu_quat(const drdc_quat_t *q, drdc_quat_t *out);

/**
 * Attitude with the world frame changed NED <-> ENU: out = [0, r, r, 0] * q
 * with r = 1/sqrt(2): [-(x + y) r, (s + z) r, (s - z) r, (y - x) r], each
 * part correctly rounded (r held to 2^-62).
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_OVERFLOW a part is outside [-2, 2) (only for |q| > 1.4)
 */
drdc_status_t drdc_frame_ned_enu_quat(const drdc_quat_t *q, drdc_quat_t *out);

/** @} */

/** @} */

#endif /* DRDC_ORIENT_H */
