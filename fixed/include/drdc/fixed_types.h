/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed
 * @brief Fixed-point storage types: each type name carries its Q format.
 *
 * Notation rule: Qm.n has m integer bits NOT counting the sign bit and n
 * fraction bits, so a signed Qm.n value occupies 1 + m + n bits and its
 * real value is raw / 2^n. Q1.30 is an int32_t covering [-2, 2) in steps
 * of 2^-30; Q15.16 is an int32_t covering [-32768, 32768) in steps of
 * 2^-16, bit-identical to libfixmath's fix16_t. Q47.16 and Q5.58 are
 * int64_t formats (global lengths; hyperbolic functions).
 *
 * Rounding rule of the whole library: every result that is not exact is
 * rounded to nearest, ties away from zero (2.5 -> 3, -2.5 -> -3), never
 * truncated. A function documented as "correctly rounded" returns exactly
 * that rounding of the true real result (error <= 0.5 LSB); the others
 * state their measured maximum error in LSB against the correctly rounded
 * value.
 *
 * The choice of each format, its range, resolution and reason are in
 * docs/conventions.md.
 */
#ifndef DRDC_FIXED_TYPES_H
#define DRDC_FIXED_TYPES_H

#include <stdint.h>

/**
 * @defgroup drdc_fixed Fixed-point types
 * @{
 */

/** Unit values (quaternion parts, direction cosines, sin, cos):
 *  Q1.30 in int32_t, range [-2, 2), resolution 2^-30 = 9.3e-10. */
typedef int32_t drdc_q1_30_t;

/** Local lengths in metres (local pose, link lengths, ENU/NED offsets):
 *  Q15.16 in int32_t, range [-32768, 32768) m, resolution 2^-16 m
 *  = 15.3 um. Same bits as libfixmath's fix16_t. */
typedef int32_t drdc_q15_16_t;

/** Global lengths in metres (UTM, ECEF, heights): Q47.16 in int64_t,
 *  range +-1.4e14 m, resolution 2^-16 m. Same binary point as
 *  drdc_q15_16_t, so global minus global is a local length with no shift. */
typedef int64_t drdc_q47_16_t;

/** Arguments and results of the hyperbolic functions (geodesy: the
 *  transverse Mercator series): Q5.58 in int64_t, range [-32, 32),
 *  resolution 2^-58 = 3.5e-18. */
typedef int64_t drdc_q5_58_t;

/** Attitude angles (yaw, pitch, roll, heading) as a binary angle: 2^32
 *  units per turn, resolution 1.46e-9 rad. Unsigned so that adding and
 *  subtracting angles wraps modulo one turn without undefined behaviour;
 *  read it as int32_t for the signed range [-pi, pi). */
typedef uint32_t drdc_bam32_t;

/** One binary-angle unit per turn: 2^32 (as a 64-bit constant). */
#define DRDC_BAM32_PER_TURN ((int64_t)1 << 32)

/** The value 1.0 in Q1.30. */
#define DRDC_Q1_30_ONE ((drdc_q1_30_t)1 << 30)

/** The value 1.0 m in Q15.16 (and Q47.16). */
#define DRDC_Q15_16_ONE ((drdc_q15_16_t)1 << 16)

/** The value 1.0 in Q5.58. */
#define DRDC_Q5_58_ONE ((drdc_q5_58_t)1 << 58)

/** @} */

#endif /* DRDC_FIXED_TYPES_H */
