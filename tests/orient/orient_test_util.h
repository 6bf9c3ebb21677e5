/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Helpers shared by the orientation suites: error measures in LSB
 *        and a small deterministic pseudo-random generator.
 */
#ifndef ORIENT_TEST_UTIL_H
#define ORIENT_TEST_UTIL_H

#include <stdint.h>

#include <drdc/orient.h>

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

/* Prints the measured maximum of each check when built with
 * -DORIENT_PRINT_MAXIMA (host measurement builds for docs/accuracy.md). */
#ifdef ORIENT_PRINT_MAXIMA
#include <stdio.h>
#define ORIENT_REPORT(name, value)                                             \
  printf("MAX %-40s %lld\n", (name), (long long)(value))
#else
#define ORIENT_REPORT(name, value) ((void)(name), (void)(value))
#endif

/* xorshift32: deterministic, the same sequence on every target. */
static inline uint32_t orient_rand(uint32_t *state)
{
  uint32_t x = *state;

  x ^= x << 13;
  x ^= x >> 17;
  x ^= x << 5;
  *state = x;
  return x;
}

static inline int64_t orient_abs64(int64_t x)
{
  return (x < 0) ? -x : x;
}

/* Largest |a_i - b_i| over n int32 parts. */
static inline int64_t orient_maxdiff32(const int32_t *a, const int32_t *b,
                                       unsigned n)
{
  int64_t m = 0;
  unsigned i;

  for (i = 0u; i < n; i++) {
    int64_t d = orient_abs64((int64_t)a[i] - b[i]);
    m = (d > m) ? d : m;
  }
  return m;
}

/* Largest part difference of two quaternions as rotations: q or -q,
 * whichever is nearer. */
static inline int64_t orient_qdiff(const drdc_quat_t *q, const int32_t r[4])
{
  const int32_t a[4] = {q->s, q->x, q->y, q->z};
  int64_t plus = 0;
  int64_t minus = 0;
  unsigned i;

  for (i = 0u; i < 4u; i++) {
    int64_t dp = orient_abs64((int64_t)a[i] - r[i]);
    int64_t dm = orient_abs64((int64_t)a[i] + r[i]);
    plus = (dp > plus) ? dp : plus;
    minus = (dm > minus) ? dm : minus;
  }
  return (plus < minus) ? plus : minus;
}

/* Exact part difference with the sign kept. */
static inline int64_t orient_qdiff_signed(const drdc_quat_t *q,
                                          const int32_t r[4])
{
  const int32_t a[4] = {q->s, q->x, q->y, q->z};

  return orient_maxdiff32(a, r, 4u);
}

/* Difference of two binary angles, wrapped to [-2^31, 2^31). */
static inline int64_t orient_bam_diff(uint32_t a, uint32_t b)
{
  return (int64_t)(int32_t)(a - b);
}

/* |angle - ref| in 1/sub units, ref in 1/sub binary-angle units; wraps
 * modulo a turn. */
static inline int64_t orient_angle_err(uint32_t a, int64_t ref, int64_t sub)
{
  const int64_t turn = (int64_t)1 << 32;
  int64_t d = ((int64_t)a * sub) - ref;
  int64_t m = turn * sub;

  d %= m;
  if (d >= m / 2) {
    d -= m;
  }
  if (d < -(m / 2)) {
    d += m;
  }
  return orient_abs64(d);
}

/* |q|^2 - 1 in units of 2^-60 (exact integers; 2 LSB of |q| - 1 is about
 * 2^32 of these units). */
static inline int64_t orient_norm_err(const drdc_quat_t *q)
{
  int64_t n = ((int64_t)q->s * q->s) + ((int64_t)q->x * q->x) +
              ((int64_t)q->y * q->y) + ((int64_t)q->z * q->z);

  return orient_abs64(n - ((int64_t)1 << 60));
}

#endif /* ORIENT_TEST_UTIL_H */
