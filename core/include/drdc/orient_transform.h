/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_transform
 * @brief Homogeneous transforms: a Q1.30 rotation matrix plus a local
 *        (Q15.16) or global (Q47.16) translation; compose, invert, apply.
 */
#ifndef DRDC_TRANSFORM_H
#define DRDC_TRANSFORM_H

#include <drdc/orient.h>

/**
 * @defgroup drdc_transform Homogeneous transforms
 *
 * A transform T = [R t; 0 1] maps coordinates in a frame B to a frame A:
 * p_A = R p_B + t (R body-to-world in the sense of orient.h, t the origin
 * of B in A). Two kinds, by the format of t:
 * - drdc_transform_t: local, t in Q15.16 metres (+-32 km, 15 um);
 * - drdc_transform_global_t: t in Q47.16 metres (the same binary point),
 *   for frames placed in a global frame (UTM, ECEF).
 * Local and global meet without loss: a global transform maps local
 * points to global ones (R p + t, exact widening of p), and global points
 * back to local ones as R^T (p - t), where p - t is an exact local
 * difference; R is never applied to a global-size vector.
 *
 * Rounding: every element of a result is one correctly rounded sum of
 * exact products (error <= 0.5 LSB from the arithmetic); the errors of the
 * inputs (a Q1.30 matrix is within 0.5 LSB of a rotation when it comes
 * from drdc_dcm_from_quat()) add up as stated per function.
 * @{
 */

/** Local transform: rotation Q1.30 and translation Q15.16 metres. */
typedef struct drdc_transform {
  drdc_dcm_t r;         /**< rotation, frame B to frame A */
  drdc_vec3_q15_16_t t; /**< origin of B in A, Q15.16 m */
} drdc_transform_t;

/** Global transform: rotation Q1.30 and translation Q47.16 metres. */
typedef struct drdc_transform_global {
  drdc_dcm_t r;         /**< rotation, frame B to frame A */
  drdc_vec3_q47_16_t t; /**< origin of B in A, Q47.16 m */
} drdc_transform_global_t;

/**
 * Transform from an attitude quaternion and a local translation.
 * @param q non-zero quaternion (its rotation q / |q|, matrix correctly
 *          rounded)
 * @param t translation, Q15.16 m
 * @param[out] out transform; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_DOMAIN q is zero
 */
drdc_status_t drdc_transform_from_quat(const drdc_quat_t *q,
                                       const drdc_vec3_q15_16_t *t,
                                       drdc_transform_t *out);

/**
 * Composition out = a b (apply b, then a): R = Ra Rb, t = Ra tb + ta.
 * @param a outer transform (applied second)
 * @param b inner transform (applied first)
 * @param[out] out may be a or b; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_OVERFLOW the translation leaves +-32768 m
 *
 * Accuracy: R within 0.5 LSB of Ra Rb as given (each element one
 * rounding); t within 0.5 LSB of Q15.16 (7.6 um) plus |tb| times the
 * error of Ra.
 */
drdc_status_t drdc_transform_compose(const drdc_transform_t *a,
                                     const drdc_transform_t *b,
                                     drdc_transform_t *out);

/**
 * Inverse [R^T, -R^T t]: R^T is exact; -R^T t is rounded once (0.5 LSB).
 * @param a transform
 * @param[out] out may be a; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_OVERFLOW the translation leaves +-32768 m
 *
 * Accuracy: T T^-1 (by drdc_transform_compose()) is the identity to R's
 * own departure from a rotation: for drdc_dh_forward() results of up to
 * 16 links, within 11 LSB of rotation and 1 LSB plus 12 x 2^-30 |t|
 * of translation (|t| the largest part of T's: 25 LSB, 0.38 mm, at
 * 32 km; measured 9.3 x 2^-30 and 17 LSB): the composed translation is
 * (I - R R^T) t, and R R^T differs from I by twice R's error.
 */
drdc_status_t drdc_transform_invert(const drdc_transform_t *a,
                                    drdc_transform_t *out);

/**
 * Point mapping p_A = R p_B + t (Q15.16 m).
 * @param a transform from frame B to frame A
 * @param p point in frame B, Q15.16 m
 * @param[out] out may be p; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_OVERFLOW a part leaves +-32768 m
 *
 * Accuracy: 0.5 LSB of Q15.16 from the arithmetic plus |p| times the
 * error of R.
 */
drdc_status_t drdc_transform_point(const drdc_transform_t *a,
                                   const drdc_vec3_q15_16_t *p,
                                   drdc_vec3_q15_16_t *out);

/**
 * Direction (free vector) mapping d_A = R d_B: the translation does not
 * apply. Same accuracy as drdc_transform_point().
 * @param a transform from frame B to frame A
 * @param d direction in frame B, Q15.16
 * @param[out] out may be d; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_OVERFLOW a part leaves +-32768 m
 */
drdc_status_t drdc_transform_direction(const drdc_transform_t *a,
                                       const drdc_vec3_q15_16_t *d,
                                       drdc_vec3_q15_16_t *out);

/**
 * Global transform followed by a local one: out = g b, R = Rg Rb,
 * t = Rg tb + tg (Q47.16; the local part is exact-widened).
 * @param g global transform (applied second)
 * @param b local transform (applied first)
 * @param[out] out unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_OVERFLOW the translation leaves Q47.16
 */
drdc_status_t drdc_transform_global_compose(const drdc_transform_global_t *g,
                                            const drdc_transform_t *b,
                                            drdc_transform_global_t *out);

/**
 * Local point to global: p_A = R p_B + t, p_B Q15.16, result Q47.16.
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_OVERFLOW the result leaves Q47.16
 *
 * Accuracy: as drdc_transform_point(): 0.5 LSB plus |p_B| times the
 * error of R; the global translation adds no error.
 */
drdc_status_t drdc_transform_global_to_world(const drdc_transform_global_t *g,
                                             const drdc_vec3_q15_16_t *p,
                                             drdc_vec3_q47_16_t *out);

/**
 * Global point back to local: p_B = R^T (p_A - t), the difference exact.
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_OVERFLOW p_A - t is outside the Q15.16 range in some
 *         part, or the result is
 *
 * Accuracy: 0.5 LSB plus |p_A - t| times the error of R.
 */
drdc_status_t drdc_transform_global_to_local(const drdc_transform_global_t *g,
                                             const drdc_vec3_q47_16_t *p,
                                             drdc_vec3_q15_16_t *out);

/** @} */

#endif /* DRDC_TRANSFORM_H */
