/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_trig
 * @brief Internal part of the trig functions: the tables and the
 *        first-quadrant kernels shared by sin, cos, tan, atan2, asin, acos.
 */
#ifndef DRDC_TRIG_IMPL_H
#define DRDC_TRIG_IMPL_H

#include <stdbool.h>
#include <stdint.h>

#include <drdc/compiler.h>

#include "fixed_impl.h"

/** Intervals of the sine table: 256 per quarter wave (pi / 512 each).
 *  Not 128 as the atan table: with 129 entries
 *  sin and cos stay within 1 LSB, but 9 % of them change (the entries'
 *  own 0.25-LSB roundings), and what multiplies several of them leaves
 *  its documented bound: Euler to matrix 2 LSB (bound 1), T T^-1 5 LSB
 *  (4), drdc_pose_we_from_le heights 4 LSB (2), drdc_pose_le_from_we
 *  Euler angles 12 LSB (8). */
#define FX_SIN_STEPS 256

/** Intervals of the atan table: 128 over [0, 1] (1/128 each). */
#define FX_ATAN_STEPS 128

/** Binary-angle units in a quarter turn (pi/2) and an eighth (pi/4). */
#define FX_BAM_QUARTER (UINT32_C(1) << 30)
#define FX_BAM_EIGHTH  (UINT32_C(1) << 29)

extern const uint32_t drdc__fx_sin_q31[FX_SIN_STEPS + 1] DRDC_FLASH_TABLE;

/** A node of the atan table: B atan(t), its first derivative and its second
 *  and third Taylor coefficients at t = i / 128, in binary-angle units
 *  times 4 (trig_table.c). */
typedef struct fx_atan_node {
  uint32_t a;  /**< B atan(t) */
  uint32_t d1; /**< B / (1 + t^2) */
  uint32_t c2; /**< B t / (1 + t^2)^2, minus the second coefficient */
  int32_t c3;  /**< B (t^2 - 1/3) / (1 + t^2)^3 */
} fx_atan_node_t;

extern const fx_atan_node_t
    drdc__fx_atan_nodes[FX_ATAN_STEPS + 1] DRDC_FLASH_TABLE;

/*
 * The kernels below are static inline so that sin, cos, tan and atan2 pay
 * no call. Every intermediate is an unsigned magnitude in a 32-bit word,
 * every product a 32 x 32 -> 64 multiply (UMULL on Cortex-M3, mullw and
 * mulhwu on PowerPC), so no 64 x 64 product and no libgcc call is left.
 * The sign of a signed intermediate is carried beside its magnitude, and
 * floor(-m / 2^n) is taken as -ceil(m / 2^n) = -((m + 2^n - 1) >> n).
 */

/* 2 pi 2^31 = 3 2^32 + FX_TWO_PI_Q31_LOW: one binary-angle unit is
 * 2 pi / 2^32 rad, so d units times 2 pi 2^31 is d radians in Q63;
 * rounding the constant to an integer (up, by 0.48) adds 0.48 |d| 2^-63
 * rad, below 0.06 LSB of Q39 for |d| <= 2^21. */
#define FX_TWO_PI_Q31_LOW UINT32_C(608135817)

/**
 * sin(r 2 pi / 2^32) for 0 <= r <= 2^30 (first quadrant) in Q2.62-ish:
 * the value times 2^62, >= 0, before the final rounding. Error below
 * 2^-32 (from the table) plus 2^-38.9.
 *
 * With x0 the nearest of the 257 table angles and delta = x - x0,
 * |delta| <= pi / 1024 = 3.07e-3 rad,
 *   sin(x0 + delta) = s0 (1 - delta^2 / 2) + c0 (delta - delta^3 / 6)
 * with a truncation error s0 delta^4 / 24 <= 3.7e-12 (0.004 LSB of Q1.30).
 * Intermediate formats (magnitudes; every step rounds towards minus
 * infinity, of the signed value):
 *   |delta| Q39 <= 2^30.65 (32 bits), delta^2 Q46 <= 2^29.3,
 *   |delta^3| / 6 Q58 <= 2^30.4 (truncated towards zero), s0 and c0 Q0.31
 *   <= 2^31, products Q70, Q77 and Q89 <= 2^61.7, summed in Q62 (< 2^63).
 * The table entries carry the error (<= 2^-32, 0.25 LSB of Q1.30); the
 * rounding of |delta| (below 1 LSB of Q39, plus the constant's 0.06)
 * adds at most 1.06 2^-39 = 2^-38.9 (2^-38.93 measured on 100 000 random
 * angles and the midpoints between entries, against the exact cubic of
 * the same entries), the other roundings less than 2^-46.
 */
static inline int64_t fx_sin_quadrant_q62(uint32_t r)
{
  uint32_t i = (r + (UINT32_C(1) << 21)) >> 22; /* nearest table point */
  uint32_t node = i << 22;
  bool neg = r < node;                         /* delta < 0 */
  uint32_t ad = neg ? (node - r) : (r - node); /* |d| <= 2^21 units */
  uint32_t s0 = drdc__flash_u32(&drdc__fx_sin_q31[i]);
  uint32_t c0 = drdc__flash_u32(&drdc__fx_sin_q31[(uint32_t)FX_SIN_STEPS - i]);
  /* |delta| Q39: |d| 2 pi 2^31 / 2^24, the low product (< 2^51) shifted,
   * the 3 2^32 part exact as 768 |d| */
  uint32_t adl = (uint32_t)((((uint64_t)ad * FX_TWO_PI_Q31_LOW) +
                             (neg ? ((UINT64_C(1) << 24) - 1u) : 0u)) >>
                            24) +
                 (ad * 768u);
  uint32_t d2 = (uint32_t)(((uint64_t)adl * adl) >> 32); /* Q46 */
  /* |delta^3| / 6 in Q58: floor(floor(m / 2^27) / 6) = floor(m / 3 2^28)
   * for the magnitude m (< 2^60) rounded as the signed floor demands */
  uint32_t d3 = (uint32_t)((((uint64_t)d2 * adl) +
                            (neg ? ((UINT64_C(1) << 27) - 1u) : 0u)) >>
                           28) /
                3u;
  uint64_t t1 = (uint64_t)c0 * adl; /* |c0 delta|: Q70 */
  uint64_t t3 = (uint64_t)c0 * d3;  /* c0 |delta^3| / 6: Q89 */
  /* s0 - s0 delta^2 / 2 in Q62; s0 2^31 <= 2^62 */
  uint64_t acc = ((uint64_t)s0 << 31) - (((uint64_t)s0 * d2) >> 16);

  if (neg) {
    acc =
        (acc - ((t1 + 255u) >> 8)) + ((t3 + ((UINT64_C(1) << 27) - 1u)) >> 27);
  } else {
    acc = (acc + (t1 >> 8)) - (t3 >> 27);
  }
  /* a negative sum (bit 63 of the two's complement) is clamped to 0 */
  return ((acc >> 63) != 0u) ? 0 : (int64_t)acc;
}

/**
 * round(num 2^32 / den) = floor((num 2^32 + floor(den / 2)) / den) for
 * 0 <= num < den <= 2^31 (the quotient fits 32 bits), by Knuth's
 * algorithm D with two 16-bit quotient digits: normalise den so its top
 * bit is set, estimate each digit from the top 32 bits of the remainder
 * divided by the top 16 bits of the divisor (one 32-bit hardware divide,
 * UDIV or divwu), and correct the estimate (at most twice) with its next
 * digit. No 64-bit division (libgcc's costs a call and a loop). The low
 * word of the dividend, floor(den / 2) < 2^(31 - s), gives no bits to the
 * high word when both are shifted left by the normalising s.
 */
static inline uint32_t fx_div_ratio_q32(uint32_t num, uint32_t den)
{
  const uint32_t base = UINT32_C(1) << 16;
  unsigned s = drdc__clz32(den); /* den > num >= 0 */
  uint32_t vn = den << s;
  uint32_t vn1 = vn >> 16;
  uint32_t vn0 = vn & 0xFFFFu;
  uint32_t un32 = num << s;
  uint32_t un10 = (den >> 1) << s;
  uint32_t un1 = un10 >> 16;
  uint32_t un0 = un10 & 0xFFFFu;
  uint32_t q1 = un32 / vn1;
  uint32_t rhat = un32 - (q1 * vn1);
  uint32_t un21;
  uint32_t q0;

  while ((q1 >= base) || ((q1 * vn0) > ((rhat << 16) | un1))) {
    q1--;
    rhat += vn1;
    if (rhat >= base) {
      break;
    }
  }
  un21 = ((un32 << 16) | un1) - (q1 * vn); /* < vn, exact modulo 2^32 */
  q0 = un21 / vn1;
  rhat = un21 - (q0 * vn1);
  while ((q0 >= base) || ((q0 * vn0) > ((rhat << 16) | un0))) {
    q0--;
    rhat += vn1;
    if (rhat >= base) {
      break;
    }
  }
  return (q1 << 16) | q0;
}

/**
 * atan(num / den) in binary-angle units, rounded, for 0 <= num <= den,
 * 0 < den <= 2^31. Result 0..2^29.
 *
 * t = num / den in Q32 (rounded, <= 2^-33 error), t0 = i / 128 the
 * nearest table point, h = t - t0, |h| <= 2^-8:
 *   B atan(t0 + h) = A + D1 h - C2 h^2 + C3 h^3
 * (B = 2^32 / (2 pi) binary-angle units per radian), truncation error
 * max |c4| B h^4 = 0.1945 B 2^-32 = 0.031 units (c4 the fourth Taylor
 * coefficient of atan, largest in magnitude on [0, 1] at t = 0.325).
 * Intermediates: |h| Q32 (<= 2^24), h^2 Q42 (<= 2^26), |h^3| Q42
 * (<= 2^18), table values in units times 4 (D1 <= 2^31.35, C2 <= 2^29.73,
 * |C3| <= 2^29.76), products in units times 2^34 and 2^44 (D1 |h| <=
 * 2^55.35, C2 h^2 <= 2^55.73, |C3 h^3| <= 2^47.8), summed in units times
 * 2^33 (A 2^31 <= 2^62, the sum <= 2^62 + 2^54.4 < 2^63); each product
 * term is rounded towards minus infinity, of its signed value.
 * Error before the final rounding: t's 2^-33 (0.080 units), A's 1/8
 * unit, the truncation (0.031), D1's 1/8 unit times |h| (0.0005) and
 * the roundings of h^2, h^3 and the products (< 0.00011; 0.00007
 * measured against the exact cubic of the same nodes): < 0.24 units,
 * so the result is within 1 unit of the correctly rounded one.
 */
static inline uint32_t fx_atan_ratio_bam(uint32_t num, uint32_t den)
{
  uint32_t t;
  uint32_t i;
  uint32_t low;
  bool neg;
  bool c3_neg;
  uint32_t ah;
  uint32_t h2;
  uint32_t ah3;
  uint64_t acc;
  uint64_t p3;
  const fx_atan_node_t *node;
  uint32_t node_a;
  uint32_t node_d1;
  uint32_t node_c2;
  int32_t node_c3;

  if (num == den) {
    /* t = 1: A = 2^31 is pi/4 exactly, units times 4 */
    return (drdc__flash_u32(&drdc__fx_atan_nodes[FX_ATAN_STEPS].a) + 2u) >> 2;
  }
  /* t = round(num 2^32 / den) < 2^32: the floor of (num 2^32 + den / 2)
   * over den */
  t = fx_div_ratio_q32(num, den);
  i = (t >> 25) + ((t >> 24) & 1u); /* nearest, 0..128 */
  low = t & 0x1FFFFFFu;
  neg = (t & (UINT32_C(1) << 24)) != 0u;        /* rounded up: h < 0 */
  ah = neg ? ((UINT32_C(1) << 25) - low) : low; /* |h| <= 2^24 */
  h2 = (uint32_t)(((uint64_t)ah * ah) >> 22);   /* Q42 */
  /* |h^3| Q42, the magnitude of floor(h2 h / 2^32) */
  ah3 = (uint32_t)((((uint64_t)h2 * ah) +
                    (neg ? ((UINT64_C(1) << 32) - 1u) : 0u)) >>
                   32);
  node = &drdc__fx_atan_nodes[i];
  node_a = drdc__flash_u32(&node->a);
  node_d1 = drdc__flash_u32(&node->d1);
  node_c2 = drdc__flash_u32(&node->c2);
  node_c3 = drdc__flash_s32(&node->c3);
  acc = (uint64_t)node_a << 31; /* units 2^33 */
  acc -= ((uint64_t)node_c2 * h2) >> 11;
  if (neg) {
    acc -= (((uint64_t)node_d1 * ah) + 1u) >> 1;
  } else {
    acc += ((uint64_t)node_d1 * ah) >> 1;
  }
  /* C3 h^3: the sign of C3 (negative below t = 1/sqrt(3)) times that of h */
  p3 = (uint64_t)fx_abs32(node_c3) * ah3; /* <= 2^47.8 */
  c3_neg = node_c3 < 0;
  if (neg == c3_neg) {
    acc += p3 >> 11;
  } else {
    acc -= (p3 + ((UINT64_C(1) << 11) - 1u)) >> 11;
  }
  if ((acc >> 63) != 0u) {
    return 0;
  }
  return (uint32_t)((acc + (UINT64_C(1) << 32)) >> 33);
}

/** Angle of (ax, ay) in the first quadrant, magnitudes <= 2^31, not both
 *  zero: the octant below the diagonal directly, the other by
 *  atan(y/x) = pi/2 - atan(x/y). */
static inline uint32_t fx_atan_first_quadrant(uint32_t ay, uint32_t ax)
{
  bool steep = ay > ax;
  uint32_t a = fx_atan_ratio_bam(steep ? ax : ay, steep ? ay : ax);

  return steep ? (FX_BAM_QUARTER - a) : a;
}

/** drdc_fx_atan2_bam32() of (y, x), not both zero, without the checks:
 *  the body of that function and the seed of drdc_fx_atan2_q5_58(). */
static inline uint32_t fx_atan2_bam(int32_t y, int32_t x)
{
  uint32_t a = fx_atan_first_quadrant(fx_abs32(y), fx_abs32(x));

  if (x < 0) {
    a = (FX_BAM_QUARTER << 1) - a; /* pi - a */
  }
  return (y < 0) ? (0u - a) : a; /* -a modulo one turn */
}

/** floor(x / 2^n) for 0 < n < 64, shifting only unsigned values. */
static inline int64_t fx_floor_shift64(int64_t x, unsigned n)
{
  int64_t result;

  if (x < 0) {
    /* -x - 1 (= ~x) is >= 0 and in range; floor(x / 2^n) = -(m + 1)
     * where m = (-x - 1) / 2^n truncated */
    uint64_t m = (uint64_t)(-(x + 1)) >> n;

    result = -(int64_t)m - 1;
  } else {
    uint64_t m = (uint64_t)x >> n;

    result = (int64_t)m;
  }
  return result;
}

/** x * 2^n for 0 <= n < 63 by multiplication (no shift of a signed
 *  value); the caller keeps the product within int64_t. */
static inline int64_t fx_scale_pow2_64(int64_t x, unsigned n)
{
  uint64_t p = UINT64_C(1) << n;
  int64_t factor = (int64_t)p;

  return x * factor;
}

#endif /* DRDC_TRIG_IMPL_H */
