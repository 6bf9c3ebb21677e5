# SPDX-License-Identifier: BSD-2-Clause
"""Reference vectors of fixed/ trig: sin, cos, tan, atan2, asin, acos.

Oracle: mpmath at 50 digits, rounded to nearest (ties away from zero),
written as exact integers. To fit the Cortex-M3 flash, dense grids are
stored compactly and exactly:
  - sin on the 16 385 points k 2^16 of the first quadrant as second
    differences (int8); the test rebuilds the integers and derives the
    other quadrants and cos by exact symmetries (65 536 points each);
  - tan on the 16 384 points of the first quadrant as first differences
    (non-negative, LEB128 bytes); the other quadrants by symmetry;
  - atan2 on one octant (x = INT32_MAX, y = floor(k INT32_MAX / 8192))
    as second differences; the other seven octants by exact identities;
  - asin of the rebuilt sines R[k] as the (int8) deviation of the
    correctly rounded asin from k 2^16.
Random off-grid points and named extremes are stored whole.
"""
import random

import mpmath

mpmath.mp.dps = 50

TURN = 1 << 32
B = mpmath.mpf(TURN) / (2 * mpmath.pi)  # binary-angle units per radian
I32_MIN, I32_MAX = -(1 << 31), (1 << 31) - 1
GRID = 1 << 16              # grid step of sin, tan, asin (units)
QUAD = (1 << 30) // GRID    # 16 384 grid intervals per quadrant
OCT = 8192                  # atan2 grid intervals per octant


def rnd(x):
    """Nearest integer to the mpf x, ties away from zero."""
    return int(mpmath.sign(x) * mpmath.floor(abs(x) + mpmath.mpf(1) / 2))


def rad(a):
    return mpmath.mpf(a) * 2 * mpmath.pi / TURN


def sin_q30(a):
    return rnd(mpmath.sin(rad(a)) * (1 << 30))


def cos_q30(a):
    return rnd(mpmath.cos(rad(a)) * (1 << 30))


def tan_q16(a):
    return rnd(mpmath.tan(rad(a)) * (1 << 16))


def bam(theta):
    return rnd(theta * B) % TURN


def second_differences(v):
    dd = [v[k + 1] - 2 * v[k] + v[k - 1] for k in range(1, len(v) - 1)]
    assert all(-128 <= d <= 127 for d in dd), (min(dd), max(dd))
    return dd


def leb128(values):
    out = []
    for v in values:
        assert v >= 0
        while True:
            byte = v & 0x7F
            v >>= 7
            out.append(byte | (0x80 if v else 0))
            if not v:
                break
    return out


def c_rows(values, per_line=16):
    return "\n".join("  " + " ".join("%d," % v for v in values[i:i + per_line])
                     for i in range(0, len(values), per_line))


def i32(v):
    return "INT32_MIN" if v == I32_MIN else "%d" % v


def generate():
    rng = random.Random(3)
    # sin quadrant
    sin_grid = [sin_q30(k * GRID) for k in range(QUAD + 1)]
    assert sin_grid[0] == 0 and sin_grid[QUAD] == 1 << 30
    sin_dd = second_differences(sin_grid)
    # named and random angles, sin and cos stored whole
    angles = []
    for m in range(8):
        for d in (-2, -1, 0, 1, 2):
            angles.append((m * (1 << 29) + d) % TURN)
    angles += [(1 << 30) - (1 << 21), (1 << 30) - (1 << 21) - 1, (1 << 21),
               (1 << 21) - 1, (1 << 22) + (1 << 21), TURN - 1]
    angles += [rng.randrange(TURN) for _ in range(1000 - len(angles))]
    sin_rows = ["  { %du, %s, %s }," % (a, i32(sin_q30(a)), i32(cos_q30(a)))
                for a in angles]
    # tan quadrant, k = 0..QUAD-1 (k = QUAD is the pole)
    tan_grid = [tan_q16(k * GRID) for k in range(QUAD)]
    tan_bytes = leb128([tan_grid[k] - tan_grid[k - 1] for k in range(1, QUAD)])
    # tan near each pole and random angles, whole
    tan_angles = []
    for pole in (1 << 30, 3 << 30):
        for m in [1, 2, 3, 5, 10, 100, 1000, 20860, 20861, 20862, 20863,
                  (1 << 21) - 1, 1 << 21, (1 << 21) + 1, 1 << 22]:
            tan_angles += [(pole - m) % TURN, (pole + m) % TURN]
        tan_angles += [(pole + rng.choice([-1, 1]) * rng.randint(1, 1 << 23))
                       % TURN for _ in range(200)]
    tan_angles += [rng.randrange(TURN) for _ in range(300)]
    tan_rows = []
    for a in tan_angles:
        t = tan_q16(a)
        over = not (I32_MIN <= t <= I32_MAX)
        t = max(I32_MIN, min(I32_MAX, t))
        tan_rows.append("  { %du, %s, %d }," % (a, i32(t), int(over)))
    # atan2 octant
    ys = [(k * I32_MAX) // OCT for k in range(OCT + 1)]
    atan_grid = [bam(mpmath.atan2(y, I32_MAX)) for y in ys]
    assert atan_grid[OCT] == 1 << 29
    atan_dd = second_differences(atan_grid)
    pairs = [(0, 1), (0, -1), (1, 0), (-1, 0), (I32_MIN, I32_MIN),
             (I32_MIN, 0), (0, I32_MIN), (I32_MIN, I32_MAX), (I32_MAX, I32_MIN),
             (I32_MAX, I32_MAX), (1, 1), (-1, -1), (1, -1), (-1, 1),
             (1, I32_MAX), (I32_MAX, 1), (-1, I32_MIN), (I32_MIN, -1),
             (1, 2), (2, 1), (-1, I32_MAX), (I32_MIN, 1), (3, -4), (-4, 3)]
    while len(pairs) < 1500:
        bits = rng.randint(1, 32)
        y = rng.randint(-(1 << (bits - 1)), (1 << (bits - 1)) - 1)
        bits = rng.randint(1, 32) if rng.random() < 0.5 else bits
        x = rng.randint(-(1 << (bits - 1)), (1 << (bits - 1)) - 1)
        if x or y:
            pairs.append((y, x))
    atan_rows = ["  { %s, %s, %du }," % (i32(y), i32(x), bam(mpmath.atan2(y, x)))
                 for y, x in pairs]
    # atan2 midway between the library's atan nodes (t = i / 128):
    # y / x = (2k + 1) / 256, x = 2^30, where its cubic's truncation is
    # largest
    midnode = [bam(mpmath.atan2((2 * k + 1) << 22, 1 << 30))
               for k in range(128)]
    # asin of the grid sines, as deviation from k 2^16
    asin_dev = [bam(mpmath.asin(mpmath.mpf(s) / (1 << 30))) - k * GRID
                for k, s in enumerate(sin_grid)]
    # near 90 deg asin magnifies the sine's rounding: deviations beyond
    # int8 are escaped as -128 and listed whole
    asin_big = [(k, d) for k, d in enumerate(asin_dev) if not -127 <= d <= 127]
    asin_dev = [d if -127 <= d <= 127 else -128 for d in asin_dev]
    xs = [1 << 30, -(1 << 30), (1 << 30) - 1, -(1 << 30) + 1, 0, 1, -1,
          1 << 29, -(1 << 29)]
    xs += [rng.randint(-(1 << 30), 1 << 30) for _ in range(1000)]
    asin_rows = ["  { %d, %du }," % (x, bam(mpmath.asin(mpmath.mpf(x) / (1 << 30))))
                 for x in xs]

    text = """/* SPDX-License-Identifier: BSD-2-Clause */
/* Generated by tests/ref/gen_fixed_trig.py: sin, cos, tan, atan2, asin of
 * binary angles and Q1.30 values from mpmath (50 digits), rounded to
 * nearest. Grids are stored as exact differences (see the generator).
 * Do not edit; run tools/generate.py. */
#ifndef VECTORS_TRIG_H
#define VECTORS_TRIG_H

#include <stdint.h>

/* Grid step (binary-angle units) and intervals per quadrant. */
#define TRIG_GRID_STEP %du
#define TRIG_GRID_QUAD %d
/* atan2 grid: intervals per octant */
#define ATAN_GRID_OCT %d

/* sin grid: R[0] = 0, R[1] = SIN_GRID_1, R[k+1] = 2 R[k] - R[k-1] +
 * sin_dd[k-1] for k = 1..16383 */
#define SIN_GRID_1 %d
static const int8_t sin_dd[] = {
%s
};

struct sin_vector {
  uint32_t a;
  int32_t s, c;
};

static const struct sin_vector sin_vectors[] = {
%s
};

/* tan grid: T[0] = 0, T[k] = T[k-1] + (k-th LEB128 number), k < 16384 */
static const uint8_t tan_leb[] = {
%s
};

struct tan_vector {
  uint32_t a;
  int32_t t; /* saturated when `over` */
  uint8_t over;
};

static const struct tan_vector tan_vectors[] = {
%s
};

/* atan2 grid: A[k] = atan2(floor(k INT32_MAX / 8192), INT32_MAX); A[0] =
 * 0, A[1] = ATAN_GRID_1, A[k+1] = 2 A[k] - A[k-1] + atan_dd[k-1] */
#define ATAN_GRID_1 %d
static const int8_t atan_dd[] = {
%s
};

struct atan2_vector {
  int32_t y, x;
  uint32_t a;
};

static const struct atan2_vector atan2_vectors[] = {
%s
};

/* atan2((2k + 1) 2^22, 2^30), k = 0..127: midway between the nodes of
 * the library's atan table (fixed/trig_table.c, t = i / 128) */
static const uint32_t atan2_midnode[128] = {
%s
};

/* asin(R[k] / 2^30) = k 2^16 + asin_dev[k] (binary angle), k = 0..16384;
 * -128 means: the deviation is in asin_dev_big */
static const int8_t asin_dev[] = {
%s
};

struct asin_dev_big {
  uint16_t k;
  int16_t dev;
};

static const struct asin_dev_big asin_dev_big[] = {
%s
};

struct asin_vector {
  int32_t x;
  uint32_t a;
};

static const struct asin_vector asin_vectors[] = {
%s
};

#endif
""" % (GRID, QUAD, OCT, sin_grid[1], c_rows(sin_dd), "\n".join(sin_rows),
       c_rows(tan_bytes), "\n".join(tan_rows), atan_grid[1], c_rows(atan_dd),
       "\n".join(atan_rows), c_rows(midnode, 8),
       c_rows(asin_dev),
       "\n".join("  { %d, %d }," % kd for kd in asin_big),
       "\n".join(asin_rows))
    return {"tests/fixed/vectors_trig.h": text}
