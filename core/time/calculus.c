/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time_calculus
 * @brief Delta derivative and delta integral on a non-uniform time scale,
 *        exact integers with one final rounding.
 */
#include <drdc/time_calculus.h>

#include <stdbool.h>

#include "time_impl.h"

#define NS_PER_SECOND_U64 UINT64_C(1000000000)
#define LOW32             ((uint64_t)0xFFFFFFFFu)

/* Graininess of stamps a < b, as an unsigned count (the difference of two
 * int64_t may exceed INT64_MAX; computed modulo 2^64 it is exact). */
static uint64_t graininess(int64_t a, int64_t b)
{
  return (uint64_t)b - (uint64_t)a;
}

/* Every stamp after its predecessor: DRDC_OK, or the status to return. */
static drdc_status_t check_stamps(const int64_t *t, size_t n)
{
  size_t i;

  for (i = 0; (i + 1u) < n; i++) {
    if (t[i + 1u] == t[i]) {
      return DRDC_E_DIVIDE_BY_ZERO;
    }
    if (t[i + 1u] < t[i]) {
      return DRDC_E_RANGE;
    }
  }
  return DRDC_OK;
}

/* round(num / den) of magnitudes, halves up: den > 0. */
static uint64_t div_round(uint64_t num, uint64_t den)
{
  uint64_t q = num / den;
  uint64_t r = num - (q * den);

  /* r >= den - r, written so that nothing overflows */
  return (r >= (den - r)) ? (q + 1u) : q;
}

drdc_status_t drdc_time_delta_derivative(const int64_t *t_ns, const int32_t *f,
                                         size_t n, int64_t *deriv)
{
  size_t i;
  drdc_status_t st;

  if ((t_ns == NULL) || (f == NULL) || (deriv == NULL)) {
    return DRDC_E_NULL;
  }
  if (n < 2u) {
    return DRDC_E_RANGE;
  }
  st = check_stamps(t_ns, n);
  if (st != DRDC_OK) {
    return st;
  }
  for (i = 0; (i + 1u) < n; i++) {
    int64_t df = (int64_t)f[i + 1u] - (int64_t)f[i]; /* 33 bits */
    uint64_t mag = (uint64_t)((df < 0) ? -df : df) * NS_PER_SECOND_U64;
    /* mag < 2^32 * 2^30 = 2^62, and so is the quotient: fits int64_t */
    int64_t q = (int64_t)div_round(mag, graininess(t_ns[i], t_ns[i + 1u]));

    deriv[i] = (df < 0) ? -q : q;
  }
  return DRDC_OK;
}

/* A signed 128-bit integer as two's complement in two uint64_t. */
struct i128 {
  uint64_t hi;
  uint64_t lo;
};

static void add128(struct i128 *acc, uint64_t hi, uint64_t lo, bool negative)
{
  uint64_t h = hi;
  uint64_t l = lo;

  if (negative) { /* two's complement of (hi, lo) */
    h = ~hi;
    l = ~lo + 1u;
    if (l == 0u) {
      h += 1u;
    }
  }
  acc->lo += l;
  acc->hi += h + ((acc->lo < l) ? 1u : 0u);
}

drdc_status_t drdc_time_delta_integral(const int64_t *t_ns, const int32_t *f,
                                       size_t n, int64_t *integral)
{
  struct i128 acc = {0u, 0u};
  uint64_t chunk[4];
  uint64_t rem = 0;
  uint64_t q_hi;
  uint64_t q_lo;
  bool negative;
  size_t i;
  int k;
  drdc_status_t st;

  if ((t_ns == NULL) || (f == NULL) || (integral == NULL)) {
    return DRDC_E_NULL;
  }
  if (n == 0u) {
    return DRDC_E_RANGE;
  }
  st = check_stamps(t_ns, n);
  if (st != DRDC_OK) {
    return st;
  }
  for (i = 0; (i + 1u) < n; i++) {
    uint64_t mu = graininess(t_ns[i], t_ns[i + 1u]);
    uint64_t a = (f[i] < 0) ? (uint64_t)(-(int64_t)f[i]) : (uint64_t)f[i];
    /* a <= 2^31, mu < 2^64: a * mu = a * mu_hi * 2^32 + a * mu_lo, each
     * partial product < 2^63. */
    uint64_t p_lo = a * (mu & LOW32);
    uint64_t p_mid = a * (mu >> 32);
    uint64_t lo = p_lo + (p_mid << 32);
    uint64_t hi = (p_mid >> 32) + ((lo < p_lo) ? 1u : 0u);

    add128(&acc, hi, lo, f[i] < 0);
  }
  /* |acc| / 1e9 by long division in 32-bit chunks: each step divides
   * rem * 2^32 + chunk < 1e9 * 2^32 < 2^62 by 1e9. */
  negative = (acc.hi >> 63) != 0u;
  if (negative) {
    acc.hi = ~acc.hi;
    acc.lo = ~acc.lo + 1u;
    if (acc.lo == 0u) {
      acc.hi += 1u;
    }
  }
  chunk[0] = acc.hi >> 32;
  chunk[1] = acc.hi & LOW32;
  chunk[2] = acc.lo >> 32;
  chunk[3] = acc.lo & LOW32;
  for (k = 0; k < 4; k++) {
    uint64_t cur = (rem << 32) | chunk[k];

    chunk[k] = cur / NS_PER_SECOND_U64;
    rem = cur - (chunk[k] * NS_PER_SECOND_U64);
  }
  q_hi = (chunk[0] << 32) | chunk[1];
  q_lo = (chunk[2] << 32) | chunk[3];
  if (rem >= NS_PER_SECOND_U64 - rem) { /* round half away from zero */
    q_lo += 1u;
    if (q_lo == 0u) {
      q_hi += 1u;
    }
  }
  /* The magnitude must fit: up to 2^63 - 1, or 2^63 for a negative. */
  if ((q_hi != 0u) ||
      (q_lo > (negative ? (UINT64_C(1) << 63) : (uint64_t)INT64_MAX))) {
    return DRDC_E_OVERFLOW;
  }
  if (negative) {
    /* -q_lo in [-2^63, 0]: written without overflowing int64_t, and -2^63
     * spelt -INT64_MAX - 1 as <stdint.h> does, an int64_t expression */
    *integral =
        (q_lo == (UINT64_C(1) << 63)) ? (-INT64_MAX - 1) : -(int64_t)q_lo;
  } else {
    *integral = (int64_t)q_lo;
  }
  return DRDC_OK;
}
