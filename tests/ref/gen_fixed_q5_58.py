# SPDX-License-Identifier: BSD-2-Clause
"""Reference vectors of fixed/ Q5.58 functions (fixed_q5_58.h and
drdc_fx_mul_q5_58 of fixed_arith.h).

Oracle: mpmath at 60 digits on the exact integer inputs, rounded to
nearest (ties away from zero). sin/cos: a grid of step 1/32 over [0, 8]
(negative arguments by the exact symmetry), random arguments in [-8, 8]
and over the whole Q5.58 range, points next to multiples of pi/4 and the
extremes. atan2: random angles at every magnitude from 1 to 2^63, the
axes, the diagonals and the extremes of int64_t. sqrt: every power of two
and its neighbours, squares and their neighbours, random values of every
magnitude. Quotient and product: random pairs of every magnitude, exact
ties, the overflow boundary (the expected status is DRDC_E_OVERFLOW when
the rounded result leaves int64_t)."""
import random

import mpmath

mpmath.mp.dps = 60

ONE = 1 << 58
I64_MIN, I64_MAX = -(1 << 63), (1 << 63) - 1
SINCOS_STEP = ONE >> 5
SINCOS_GRID = 257


def rnd(x):
    return int(mpmath.sign(x) * mpmath.floor(abs(x) + mpmath.mpf(1) / 2))


def lit(v):
    return "INT64_MIN" if v == I64_MIN else "INT64_C(%d)" % v


def real(x):
    return mpmath.mpf(x) / ONE


def rnd_ratio(a, b):
    """round(a / b) for integers, ties away from zero, exactly"""
    q, r = divmod(abs(a), abs(b))
    if 2 * r >= abs(b):
        q += 1
    return q if (a < 0) == (b < 0) else -q


def any_magnitude(rng, bits):
    return rng.choice([-1, 1]) * rng.getrandbits(rng.randint(1, bits))


def sincos_rows(rng):
    xs = [I64_MAX, I64_MIN, I64_MIN + 1, 1, -1]
    for j in range(1, 41):
        c = rnd(mpmath.pi / 4 * j * ONE)
        if c <= I64_MAX:
            xs += [c - 1, c, c + 1, -c]
    while len(xs) < 900:
        xs.append(rng.randint(-8 * ONE, 8 * ONE))
    while len(xs) < 1100:
        xs.append(rng.randint(I64_MIN, I64_MAX))
    while len(xs) < 1200:
        xs.append(any_magnitude(rng, 57))
    return ["  { %s, %s, %s }," % (lit(x), lit(rnd(mpmath.sin(real(x)) * ONE)),
                                   lit(rnd(mpmath.cos(real(x)) * ONE)))
            for x in xs]


def atan2_rows(rng):
    pairs = [(0, 1), (1, 0), (0, -1), (-1, 0), (1, 1), (-1, -1), (1, -1),
             (I64_MAX, I64_MAX), (I64_MIN, I64_MIN), (I64_MIN, I64_MAX),
             (0, I64_MIN), (I64_MIN, 0), (I64_MAX, 0), (0, I64_MAX),
             (I64_MAX, I64_MIN), (1, I64_MIN), (-1, I64_MIN),
             (I64_MAX, 1), (1, I64_MAX), (ONE, ONE), (3, 4), (-3, 4)]
    while len(pairs) < 1200:
        t = mpmath.mpf(rng.uniform(-3.1416, 3.1416))
        m = mpmath.mpf(2) ** rng.uniform(0, 62.9)
        y = max(I64_MIN, min(I64_MAX, rnd(m * mpmath.sin(t))))
        x = max(I64_MIN, min(I64_MAX, rnd(m * mpmath.cos(t))))
        if (y, x) != (0, 0):
            pairs.append((y, x))
    return ["  { %s, %s, %s }," % (lit(y), lit(x),
                                   lit(rnd(mpmath.atan2(y, x) * ONE)))
            for y, x in pairs]


def sqrt_rows(rng):
    xs = [0, 1, 2, 3, I64_MAX, ONE, 4 * ONE]
    for j in range(63):
        for d in (-1, 0, 1):
            if 0 <= (1 << j) + d <= I64_MAX:
                xs.append((1 << j) + d)
    while len(xs) < 700:
        r = rng.getrandbits(rng.randint(1, 31))
        for d in (-1, 0, 1):
            if r * r + d >= 0:
                xs.append(r * r + d)
    while len(xs) < 1200:
        xs.append(rng.getrandbits(rng.randint(1, 63)))
    return ["  { %s, %s }," % (lit(x), lit(rnd(mpmath.sqrt(real(x)) * ONE)))
            for x in sorted(set(xs))]


def pair_rows(rng, op):
    """op 'mul': a b / 2^58; 'div': a 2^58 / b"""
    pairs = [(1, 1 << 57), (-1, 1 << 57), (3, 1 << 57), (I64_MAX, 1),
             (I64_MIN, 1), (I64_MIN, -1), (I64_MAX, I64_MAX), (ONE, ONE),
             (-ONE, ONE), (0, 5), (I64_MIN, ONE), (I64_MIN, -ONE)]
    if op == "div":
        pairs += [(1, 1 << 59), (-1, 1 << 59), (1, 3 << 59), (ONE, 1),
                  (32 * ONE - 1, ONE), (I64_MAX, ONE - 1), (I64_MIN, ONE + 1)]
    else:
        s32 = rnd(mpmath.sqrt(32) * ONE)
        pairs += [(s32, s32), (s32 - 1, s32), (-s32, s32), (s32, -s32 + 1)]
    while len(pairs) < 800:
        pairs.append((any_magnitude(rng, 63), any_magnitude(rng, 63)))
    rows = []
    for a, b in pairs:
        if op == "mul":
            want = rnd_ratio(a * b, ONE)
        else:
            if b == 0:
                continue
            want = rnd_ratio(a * ONE, b)
        ok = I64_MIN <= want <= I64_MAX
        rows.append("  { %s, %s, %s, %d }," % (lit(a), lit(b),
                                               lit(want if ok else 0),
                                               1 if ok else 0))
    return rows


def generate():
    rng = random.Random(5858)
    grid = [(rnd(mpmath.sin(real(k * SINCOS_STEP)) * ONE),
             rnd(mpmath.cos(real(k * SINCOS_STEP)) * ONE))
            for k in range(SINCOS_GRID)]
    sc = sincos_rows(rng)
    at = atan2_rows(rng)
    sq = sqrt_rows(rng)
    mul = pair_rows(rng, "mul")
    div = pair_rows(rng, "div")
    text = """/* SPDX-License-Identifier: BSD-2-Clause */
/* Generated by tests/ref/gen_fixed_q5_58.py: sin/cos, atan2, sqrt,
 * quotient and product in Q5.58 from mpmath (60 digits), rounded to
 * nearest. Do not edit; run tools/generate.py. */
#ifndef VECTORS_Q5_58_H
#define VECTORS_Q5_58_H

#include <stdint.h>

/* sin and cos of k %(step)d / 2^58, k = 0..%(n)d */
#define Q5_58_SINCOS_STEP INT64_C(%(step)d)
static const int64_t q5_58_sincos_grid[%(n)d][2] = {
%(grid)s
};

struct q5_58_sincos_vector {
  int64_t x;
  int64_t s;
  int64_t c;
};

static const struct q5_58_sincos_vector q5_58_sincos_vectors[%(nsc)d] = {
%(sc)s
};

struct q5_58_atan2_vector {
  int64_t y;
  int64_t x;
  int64_t angle;
};

static const struct q5_58_atan2_vector q5_58_atan2_vectors[%(nat)d] = {
%(at)s
};

struct q5_58_sqrt_vector {
  int64_t x;
  int64_t root;
};

static const struct q5_58_sqrt_vector q5_58_sqrt_vectors[%(nsq)d] = {
%(sq)s
};

/* a, b -> the rounded result, or fits = 0 when it leaves int64_t */
struct q5_58_pair_vector {
  int64_t a;
  int64_t b;
  int64_t want;
  int fits;
};

static const struct q5_58_pair_vector q5_58_mul_vectors[%(nmul)d] = {
%(mul)s
};

static const struct q5_58_pair_vector q5_58_div_vectors[%(ndiv)d] = {
%(div)s
};

#endif
""" % {"step": SINCOS_STEP, "n": SINCOS_GRID,
       "grid": "\n".join("  { %s, %s }," % (lit(s), lit(c)) for s, c in grid),
       "nsc": len(sc), "sc": "\n".join(sc), "nat": len(at),
       "at": "\n".join(at), "nsq": len(sq), "sq": "\n".join(sq),
       "nmul": len(mul), "mul": "\n".join(mul), "ndiv": len(div),
       "div": "\n".join(div)}
    return {"tests/fixed/vectors_q5_58.h": text}
