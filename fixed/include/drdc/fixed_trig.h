/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_trig
 * @brief Trigonometry on binary angles: sin, cos, sincos, tan, atan2,
 *        asin, acos.
 */
#ifndef DRDC_FIXED_TRIG_H
#define DRDC_FIXED_TRIG_H

#include <stdint.h>

#include <drdc/fixed_types.h>
#include <drdc/status.h>

/**
 * @defgroup drdc_fixed_trig Trigonometry
 *
 * Angles are drdc_bam32_t binary angles: 2^32 units per turn, one unit
 * = 2 pi / 2^32 = 1.4629e-9 rad = 8.38e-8 degree. Every input angle is
 * valid (they wrap); an output angle is in [0, 2^32), and reading it as
 * int32_t gives the signed range [-pi, pi).
 *
 * Method: a 257-entry quarter-wave sine table (Q0.31) with a cubic
 * Taylor correction for sin/cos; a 129-point table of atan on [0, 1] with
 * its first three derivatives for atan2/asin/acos (tables generated from
 * mpmath by tools/tables/fixed_tables.py, 3 KiB of const data in all).
 * Quadrants and octants are reduced exactly, so the symmetries sin(-a) =
 * -sin(a), sin(pi - a) = sin(a), cos(a) = sin(pi/2 - a), atan2(-y, x) =
 * -atan2(y, x), atan2(x, y) = pi/2 - atan2(y, x) hold bit for bit.
 *
 * Errors are measured against mpmath at 50 digits rounded to nearest
 * (tests/ref/gen_fixed_trig.py) and stated as the largest difference in
 * LSB from that correctly rounded value: 0 LSB means correctly rounded.
 * @{
 */

/**
 * sin of a binary angle, in Q1.30.
 *
 * @param a any angle (2^32 units per turn)
 * @return sin(a) in Q1.30, -2^30..2^30 (exactly 0 at a = 0 and 2^31,
 *         exactly +-2^30 at a = 2^30 and 3 2^30)
 *
 * Accuracy: max error 1 LSB of Q1.30 (9.3e-10) against the correctly
 * rounded value; measured over the full circle on 65 536 grid points
 * (multiples of 2^16, derived from a stored quadrant by the exact
 * symmetries, sin and cos each), every multiple of 2^29 and its
 * neighbours +-1, +-2, and 1 000 random angles: 133 080 values, 87 % of
 * them correctly rounded, none off by more than 1. The error comes from
 * the Q0.31 table (0.25 LSB) plus the final rounding (0.5 LSB).
 *
 * @code
 * drdc_fx_sin_bam32(UINT32_C(1) << 29);   // sin(45 deg) = 759250125
 * @endcode
 */
drdc_q1_30_t drdc_fx_sin_bam32(drdc_bam32_t a);

/** cos of a binary angle in Q1.30 = drdc_fx_sin_bam32(a + 2^30) bit for
 *  bit; same accuracy (max error 1 LSB). */
drdc_q1_30_t drdc_fx_cos_bam32(drdc_bam32_t a);

/**
 * sin and cos of one angle, each identical to drdc_fx_sin_bam32() and
 * drdc_fx_cos_bam32().
 *
 * @param a any angle
 * @param[out] s sin(a) in Q1.30; may be NULL when not wanted
 * @param[out] c cos(a) in Q1.30; may be NULL when not wanted
 */
void drdc_fx_sincos_bam32(drdc_bam32_t a, drdc_q1_30_t *s, drdc_q1_30_t *c);

/**
 * tan of a binary angle, in Q15.16.
 *
 * Domain: every angle except the poles a = 2^30 and 3 2^30 (+-90 deg).
 * Near a pole the result leaves Q15.16: |tan(a)| >= 32768 - 2^-17 when a
 * is within 20 861 units (30.5 urad, 1.75e-3 degree) of a pole; there
 * the function reports DRDC_E_OVERFLOW. tan(a + pi) = tan(a) and
 * tan(-a) = -tan(a) hold bit for bit.
 *
 * @param a any angle
 * @param[out] out tan(a) in Q15.16; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_DOMAIN a is a pole (2^30 or 3 2^30): tan is undefined
 * @retval DRDC_E_OVERFLOW |tan(a)| does not fit Q15.16
 *
 * Accuracy: max error 1 LSB of Q15.16 (1.5e-5) over the whole domain,
 * up to the overflow limit (99.8 % correctly rounded). Measured on the
 * 65 536-point circle grid (one quadrant stored, the rest by the exact
 * symmetries; poles excluded), 230 angles within 2^23 units of each pole
 * (overflow and saturation included) and 300 random angles.
 */
drdc_status_t drdc_fx_tan_bam32(drdc_bam32_t a, drdc_q15_16_t *out);

/**
 * Saturating form of drdc_fx_tan_bam32(): the same correctly rounded result
 * when it fits; otherwise `*out` = INT32_MIN or INT32_MAX, the limit on the
 * side of the true result, and DRDC_W_SATURATED.
 *
 * @retval DRDC_OK written
 * @retval DRDC_W_SATURATED written, clamped to the limit
 * @retval DRDC_E_NULL `out` is NULL; nothing written
 * @retval DRDC_E_DOMAIN a pole (2^30 or 3 2^30); `*out` unchanged
 */
drdc_status_t drdc_fx_tan_bam32_sat(drdc_bam32_t a, drdc_q15_16_t *out);

/**
 * Angle of the vector (x, y), as a binary angle.
 *
 * @param y, x any int32_t coordinates in a common unit or Q format
 *             (INT32_MIN included), not both zero
 * @param[out] out angle from +x towards +y, [0, 2^32): 0 on +x, 2^30 on
 *             +y, 2^31 on -x (half a turn), 3 2^30 on -y; unchanged on
 *             error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_DOMAIN x == 0 and y == 0: no direction
 *
 * Accuracy: max error 1 LSB of the binary angle (1.5e-9 rad) against the
 * correctly rounded value (92 % correctly rounded); measured on 65 544
 * grid points over the full circle (one octant stored, the rest by exact
 * identities), 1 500 random points of every magnitude and the
 * extremes (INT32_MIN, 0, +-1 in each coordinate), and the 128 ratios
 * midway between the nodes of the atan table.
 *
 * @code
 * drdc_bam32_t a;
 * drdc_fx_atan2_bam32(1, -1, &a);   // a == 3 << 29 (135 deg)
 * @endcode
 */
drdc_status_t drdc_fx_atan2_bam32(int32_t y, int32_t x, drdc_bam32_t *out);

/**
 * asin of a Q1.30 value, as a binary angle in [-2^30, 2^30] (written as
 * drdc_bam32_t, so negative angles wrap to [3 2^30, 2^32)).
 *
 * @param x Q1.30 value in [-1, 1] (-2^30..2^30)
 * @param[out] out asin(x); unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_DOMAIN |x| > 1
 *
 * Accuracy: max error 1 LSB of the binary angle against the correctly
 * rounded asin of the exact input (94 % correctly rounded); measured on
 * the 32 769 Q1.30 sines of a 65 536-point circle grid, both ends and
 * 1 000 random inputs.
 */
drdc_status_t drdc_fx_asin_q1_30(drdc_q1_30_t x, drdc_bam32_t *out);

/**
 * acos of a Q1.30 value, as a binary angle in [0, 2^31]; equals
 * 2^30 - asin(x) bit for bit.
 *
 * @param x Q1.30 value in [-1, 1]
 * @param[out] out acos(x); unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `out` is NULL
 * @retval DRDC_E_DOMAIN |x| > 1
 *
 * Accuracy: as drdc_fx_asin_q1_30() (max error 1 LSB).
 */
drdc_status_t drdc_fx_acos_q1_30(drdc_q1_30_t x, drdc_bam32_t *out);

/** @} */

#endif /* DRDC_FIXED_TRIG_H */
