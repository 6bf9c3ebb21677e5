/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_kinematics
 * @brief Manipulator link parameters (Denavit-Hartenberg, standard and
 *        modified) and forward kinematics of chains of up to 16 links.
 */
#ifndef DRDC_KINEMATICS_H
#define DRDC_KINEMATICS_H

#include <drdc/orient_transform.h>

/**
 * @defgroup drdc_kinematics Manipulator kinematics
 *
 * Link i is described by four parameters: link length a (Q15.16 m), link
 * twist alpha (binary angle), link offset d (Q15.16 m) and joint angle
 * theta (binary angle). The joint variable q adds to theta (revolute) or
 * to d (prismatic). Conventions:
 * - standard (distal) DH: T = Rz(theta) Tz(d) Tx(a) Rx(alpha);
 * - modified (proximal, Craig) DH: T = Rx(alpha) Tx(a) Rz(theta) Tz(d).
 * A chain's transform is T1 T2 ... Tn (base to tool).
 * @{
 */

/** Longest chain of drdc_dh_forward(). */
#define DRDC_DH_MAX_LINKS 16

/** Kind of joint: which parameter the joint variable moves. */
typedef enum drdc_joint_type {
  DRDC_JOINT_REVOLUTE = 0, /**< q is an angle added to theta */
  DRDC_JOINT_PRISMATIC = 1 /**< q is a length added to d */
} drdc_joint_type_t;

/** Which Denavit-Hartenberg convention the parameters follow. */
typedef enum drdc_dh_convention {
  DRDC_DH_STANDARD = 0, /**< T = Rz(theta) Tz(d) Tx(a) Rx(alpha) */
  DRDC_DH_MODIFIED = 1  /**< T = Rx(alpha) Tx(a) Rz(theta) Tz(d) (Craig) */
} drdc_dh_convention_t;

/** One link's parameters. */
typedef struct drdc_dh_link {
  drdc_q15_16_t a;        /**< link length, Q15.16 m */
  drdc_bam32_t alpha;     /**< link twist, binary angle */
  drdc_q15_16_t d;        /**< link offset, Q15.16 m (plus q if prismatic) */
  drdc_bam32_t theta;     /**< joint angle offset (plus q if revolute) */
  drdc_joint_type_t type; /**< revolute or prismatic */
} drdc_dh_link_t;

/**
 * Transform of one link for the joint variable q.
 * @param convention DRDC_DH_STANDARD or DRDC_DH_MODIFIED
 * @param link parameters
 * @param q joint variable: a binary angle (drdc_bam32_t bits in an
 *          int32_t) for a revolute joint, Q15.16 metres for a prismatic
 *          one
 * @param[out] out link transform; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_RANGE bad convention or joint type
 * @retval DRDC_E_OVERFLOW d + q leaves +-32768 m (prismatic)
 *
 * Accuracy: each element of R is one rounding of an exact product of
 * two drdc_fx_sincos_bam32() values (each within 0.75 LSB): within 2 LSB
 * of the exact value (measured 1.81 on 124 000 random links);
 * t within 0.5 LSB of Q15.16 plus |a| or |d| times 1 LSB of Q1.30.
 */
drdc_status_t drdc_dh_link_transform(drdc_dh_convention_t convention,
                                     const drdc_dh_link_t *link, int32_t q,
                                     drdc_transform_t *out);

/**
 * Forward kinematics: the base-to-tool transform T1(q1) ... Tn(qn).
 * @param convention DRDC_DH_STANDARD or DRDC_DH_MODIFIED
 * @param links n link parameter sets
 * @param n number of links, 0..DRDC_DH_MAX_LINKS (0 gives the identity)
 * @param q n joint variables (see drdc_dh_link_transform())
 * @param[out] out base-to-tool transform; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL (links and q may be NULL for n 0)
 * @retval DRDC_E_RANGE n > DRDC_DH_MAX_LINKS, or a bad convention or
 *         joint type
 * @retval DRDC_E_OVERFLOW a partial product T1(q1) ... Tk(qk), k <= n,
 *         has a translation outside +-32768 m (even if later links bring
 *         it back), or d + q of a prismatic link leaves that range
 *
 * The overflow rule is that of composing the links one by one with
 * drdc_dh_link_transform() and drdc_transform_compose(), in the same
 * order of statuses (the first error in link order). The two can
 * differ only for a partial translation within their position
 * difference (below) of the edge, since each rounds its own partial
 * products.
 *
 * Method: the product is accumulated with the rotation in Q2.61 and the
 * translation in Q17.46 (int64), one row at a time (row i of each
 * product needs only row i of the one before), each link's elements
 * exact products of its sines and cosines (formed on demand, never
 * stored as a matrix),
 * every step correctly rounded from the exact 128-bit product (a rounded
 * shift: the divisors are 2^60 and 2^61); the result is rounded once.
 * Accuracy, against an independent numpy float64 model on 444 182
 * random chains of 1-16 links (both conventions, revolute and prismatic
 * joints, any angles, link lengths from 2^-16 m to the Q15.16 limit;
 * tools/accuracy/orient_bounds.py): rotation within 6 LSB per element
 * (6.09 before rounding; each link's sines and cosines, 0.75 LSB, add
 * their errors along the chain, so long chains reach it). Position
 * within 0.5 LSB of Q15.16 (7.6 um, the final rounding) plus 4 x 2^-30
 * of the sum of the link lengths sqrt(a^2 + d^2), since a link's
 * rotation error turns the links after it (measured 2.98 x 2^-30,
 * 140 um at most): 7.6 um for arms of metres. Composing the link
 * transforms one by one instead (each compose rounds) differs from this
 * result by up to 7 LSB of rotation and 13 LSB (198 um) of position.
 * Required: at most 8 LSB and 10 um; the position requirement holds
 * for chains of up to 600 m of summed link length.
 *
 * @code
 * static const drdc_dh_link_t arm[2] = {
 *   { 1 << 16, 0u, 0, 0u, DRDC_JOINT_REVOLUTE },    // a = 1 m
 *   { 0, 0u, 0, 0u, DRDC_JOINT_PRISMATIC },
 * };
 * const int32_t q[2] = { 1 << 30, 1 << 15 };   // 90 deg, 0.5 m
 * drdc_transform_t t;
 * drdc_dh_forward(DRDC_DH_STANDARD, arm, 2u, q, &t);   // t.t = (0, 1, 0.5)
 * @endcode
 */
drdc_status_t drdc_dh_forward(drdc_dh_convention_t convention,
                              const drdc_dh_link_t *links, unsigned n,
                              const int32_t *q, drdc_transform_t *out);

/** @} */

#endif /* DRDC_KINEMATICS_H */
