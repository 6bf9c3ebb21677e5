/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_orient
 * @brief Quaternion algebra: product, normalisation, composition,
 *        difference and angle between (conjugate, inverse and canonical
 *        sign in quat_ops.c, compiled for flash).
 */
#include <drdc/compiler.h>
#include <drdc/orient.h>

#include <stddef.h>

#include <drdc/fixed_arith.h>
#include <drdc/fixed_sqrt.h>
#include <drdc/fixed_trig.h>

#include "orient_impl.h"

/* The end of both products: DRDC_E_OVERFLOW when bit 30 or 31 of ovf
 * is set (a part does not fit int32_t), else the parts' bits into out. */
static inline drdc_status_t store_parts(uint32_t ovf, uint32_t rs, uint32_t rx,
                                        uint32_t ry, uint32_t rz,
                                        drdc_quat_t *out)
{
  if ((ovf >> 30u) != 0u) {
    return DRDC_E_OVERFLOW;
  }
  out->s = (drdc_q1_30_t)rs;
  out->x = (drdc_q1_30_t)rx;
  out->y = (drdc_q1_30_t)ry;
  out->z = (drdc_q1_30_t)rz;
  return DRDC_OK;
}

/* The product for a part of a beyond (-1, 1]: each sum is checked for
 * the 2^63 bound by its high words. */
/* noinline: the quaternion-multiply goal of docs/performance.md (within
 * 1.5x of the hand floor on ppc-e500) fails when it is inlined. */
static DRDC_NOINLINE drdc_status_t quat_mul_wide(const drdc_quat_t *a,
                                                 const drdc_quat_t *b,
                                                 drdc_quat_t *out)
{
  uint32_t ovf = 0u;
  uint32_t rs;
  uint32_t rx;
  uint32_t ry;
  uint32_t rz;

  rs = orient_sum4_round_bits((int64_t)a->s * b->s, -((int64_t)a->x * b->x),
                              -((int64_t)a->y * b->y), -((int64_t)a->z * b->z),
                              &ovf);
  rx = orient_sum4_round_bits((int64_t)a->s * b->x, (int64_t)a->x * b->s,
                              (int64_t)a->y * b->z, -((int64_t)a->z * b->y),
                              &ovf);
  ry = orient_sum4_round_bits((int64_t)a->s * b->y, -((int64_t)a->x * b->z),
                              (int64_t)a->y * b->s, (int64_t)a->z * b->x, &ovf);
  rz = orient_sum4_round_bits((int64_t)a->s * b->z, (int64_t)a->x * b->y,
                              -((int64_t)a->y * b->x), (int64_t)a->z * b->s,
                              &ovf);
  return store_parts(ovf, rs, rx, ry, rz, out);
}

/* The Q1.30 bits of the exact Q60 sum v (|v| < 2^63), rounded to
 * nearest, ties away from zero, as orient_q60_round_bits() does, with
 * its bias 2^29 - [v < 0] added as one 32-bit word (it is 2^29 or
 * 2^29 - 1, never negative): one carry into the high word instead of a
 * 64-bit addition and a 64-bit subtraction. Bits 30..31 of *ovf are set
 * when the rounded value does not fit int32_t. */
static inline uint32_t round_q60_bits(int64_t v, uint32_t *ovf)
{
  uint64_t u = (uint64_t)v;
  uint32_t bias = UINT32_C(0x20000000) - (uint32_t)(u >> 63u);
  uint32_t hi;

  u += bias;
  hi = (uint32_t)(u >> 32u);
  *ovf |= hi + UINT32_C(0x20000000);
  return (uint32_t)(u >> 30u);
}

/* The product when every part of a is in (-1.0, 1.0] (raw (-2^30,
 * 2^30]): every product with a part of b (any int32) is then within
 * [-2^61, 2^61), a negated one within (-2^61, 2^61], and each part below
 * has a negated term whose own product is above -2^61 (it would need a
 * part of a of -2^30): every sum of four, and every partial sum, is in
 * (-2^63, 2^63), exact in int64_t without checks. */
static inline drdc_status_t
quat_mul_unit(const drdc_quat_t *a, const drdc_quat_t *b, drdc_quat_t *out)
{
  const int64_t as = a->s;
  const int64_t ax = a->x;
  const int64_t ay = a->y;
  const int64_t az = a->z;
  const int32_t bs = b->s;
  const int32_t bx = b->x;
  const int32_t by = b->y;
  const int32_t bz = b->z;
  uint32_t ovf = 0u;
  uint32_t rs;
  uint32_t rx;
  uint32_t ry;
  uint32_t rz;

  rs = round_q60_bits((as * bs) - (ax * bx) - (ay * by) - (az * bz), &ovf);
  rx = round_q60_bits((as * bx) + (ax * bs) + (ay * bz) - (az * by), &ovf);
  ry = round_q60_bits((as * by) - (ax * bz) + (ay * bs) + (az * bx), &ovf);
  rz = round_q60_bits((as * bz) + (ax * by) - (ay * bx) + (az * bs), &ovf);
  return store_parts(ovf, rs, rx, ry, rz, out);
}

drdc_status_t drdc_quat_mul(const drdc_quat_t *a, const drdc_quat_t *b,
                            drdc_quat_t *out)
{
  const uint32_t one = UINT32_C(1) << 30;

  if ((a == NULL) || (b == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  /* 2^30 - part in [0, 2^31) as uint32_t for each part of a in (-2^30,
   * 2^30]: bit 31 clear in the OR of the four. Only a is tested: the
   * bound of quat_mul_unit() holds for any b. A part of a of exactly
   * -1.0, or beyond, takes the checked path, with the same result. */
  if ((((one - (uint32_t)a->s) | (one - (uint32_t)a->x) |
        (one - (uint32_t)a->y) | (one - (uint32_t)a->z)) >>
       31u) == 0u) {
    return quat_mul_unit(a, b, out);
  }
  return quat_mul_wide(a, b, out);
}

/* round(|c| 2^e / root) with the sign of c, to nearest, ties away from
 * zero, for |c| 2^e <= 2^62 and a root in [2^31, 2^32] (quotient <=
 * 2^30): an exact 64/32 division in two 16-bit digits of Knuth's
 * algorithm D (the 32/32 hardware division), its remainder rounding; for
 * root = 2^32 a shift. The value of drdc_fx_muldiv_s64(c, 2^e, root). */
static int32_t div_root(int32_t c, unsigned e, uint64_t root)
{
  uint32_t mag = (c < 0) ? (0u - (uint32_t)c) : (uint32_t)c;
  uint64_t num = (uint64_t)mag << e;
  uint32_t lo = (uint32_t)num;
  uint32_t r = (uint32_t)(num >> 32u);
  uint32_t d = (uint32_t)root;
  uint32_t quo;

  if (root > UINT32_MAX) {
    quo = r; /* num / 2^32, remainder lo: up when lo >= 2^32 / 2 */
    quo += lo >> 31u;
  } else {
    /* num < 2^62 and quotient <= 2^30: the high word is below d */
    uint32_t q1 = drdc_fx_div_digit16(&r, lo >> 16u, d);
    uint32_t q0 = drdc_fx_div_digit16(&r, lo & 0xFFFFu, d);

    quo = (q1 << 16u) | q0;
    quo += (r >= (d - r)) ? 1u : 0u;
  }
  if (c < 0) {
    quo = 0u - quo;
  }
  return (int32_t)quo;
}

drdc_status_t drdc_quat_normalize(const drdc_quat_t *q, drdc_quat_t *out)
{
  orient_scaled_quat_t sq;
  unsigned j;
  unsigned shift;
  unsigned e;
  uint64_t root;
  drdc_status_t st;

  if ((q == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc_orient_impl_scale(q, &sq);
  if (st != DRDC_OK) {
    return st;
  }
  /* n2 in [2^58, 2^62]: shift it by an even 2j into [2^62, 2^64) so the
   * root r = sqrt(n2) 2^j is in [2^31, 2^32]; then part = c 2^(30 + j) / r,
   * |c| 2^(30 + j) <= 2^62, |part| <= 2^30: cannot overflow. */
  j = (unsigned)__builtin_clzll((uint64_t)sq.n2) / 2u;
  shift = 2u * j;
  root = drdc_fx_sqrt_u64((uint64_t)sq.n2 << shift);
  e = 30u + j;
  out->s = div_root(sq.c[0], e, root);
  out->x = div_root(sq.c[1], e, root);
  out->y = div_root(sq.c[2], e, root);
  out->z = div_root(sq.c[3], e, root);
  return DRDC_OK;
}

drdc_status_t drdc_quat_compose(const drdc_quat_t *a, const drdc_quat_t *b,
                                drdc_quat_t *out)
{
  drdc_quat_t p;
  drdc_status_t st;

  if ((a == NULL) || (b == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc_quat_mul(a, b, &p);
  if (st == DRDC_OK) {
    st = drdc_quat_normalize(&p, out);
  }
  return st;
}

drdc_status_t drdc_quat_difference(const drdc_quat_t *a, const drdc_quat_t *b,
                                   drdc_quat_t *out)
{
  drdc_quat_t c;
  drdc_status_t st;

  if ((a == NULL) || (b == NULL) || (out == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc_quat_conj(a, &c);
  if (st == DRDC_OK) {
    st = drdc_quat_compose(&c, b, out);
  }
  return st;
}

drdc_status_t drdc_quat_angle_between(const drdc_quat_t *a,
                                      const drdc_quat_t *b, drdc_bam32_t *angle)
{
  drdc_quat_t na;
  drdc_quat_t nb;
  drdc_quat_t conj_a;
  drdc_quat_t d;
  uint64_t v2;
  uint64_t vn;
  int32_t s;
  drdc_bam32_t half;
  drdc_status_t st;

  if ((a == NULL) || (b == NULL) || (angle == NULL)) {
    return DRDC_E_NULL;
  }
  st = drdc_quat_normalize(a, &na);
  if (st == DRDC_OK) {
    st = drdc_quat_normalize(b, &nb);
  }
  if (st != DRDC_OK) {
    return st;
  }
  /* Unit inputs: conj never overflows (|x| <= 2^30), nor the product. */
  conj_a.s = na.s;
  conj_a.x = -na.x;
  conj_a.y = -na.y;
  conj_a.z = -na.z;
  (void)drdc_quat_mul(&conj_a, &nb, &d);
  /* |v| from the exact sum of squares (<= 3 2^60), correctly rounded. */
  v2 = orient_square_u64(d.x) + orient_square_u64(d.y) + orient_square_u64(d.z);
  vn = drdc_fx_sqrt_u64(v2);
  s = (d.s < 0) ? -d.s : d.s;
  if ((vn == 0u) && (s == 0)) {
    return DRDC_E_DOMAIN; /* not reachable for unit inputs */
  }
  st = drdc_fx_atan2_bam32((int32_t)vn, s, &half);
  if (st == DRDC_OK) {
    *angle = half * 2u; /* half in [0, 2^30]: the angle in [0, 2^31] */
  }
  return st;
}
