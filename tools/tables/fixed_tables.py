# SPDX-License-Identifier: BSD-2-Clause
"""Generator of fixed/trig_table.c, the constant tables of fixed/ trig,
and of fixed/sqrt_table.c, the seeds of the Q15.16 square root (written
by tools/generate.py, which ./waf check runs with --check).
Values come from mpmath at 100 digits, rounded to nearest (ties away from
zero, never met by these irrational values) and written as exact integers.
The square-root seeds are exact integer roots (math.isqrt).
"""
import math
import os

import mpmath

mpmath.mp.dps = 100

SIN_STEPS = 256                      # intervals of the quarter wave
ATAN_STEPS = 128                     # intervals of atan's [0, 1]
B = mpmath.mpf(2) ** 32 / (2 * mpmath.pi)  # binary-angle units per radian


def rnd(x):
    return int(mpmath.sign(x) * mpmath.floor(abs(x) + mpmath.mpf(1) / 2))


def rows(values, per_line=6):
    out = []
    for i in range(0, len(values), per_line):
        out.append("  " + " ".join("%s," % v for v in values[i:i + per_line]))
    return "\n".join(out)


def table_text():
    """The text of fixed/trig_table.c."""
    sin_q31 = [rnd(mpmath.sin(mpmath.pi / 2 * i / SIN_STEPS) * 2 ** 31)
               for i in range(SIN_STEPS + 1)]
    t0 = [mpmath.mpf(i) / ATAN_STEPS for i in range(ATAN_STEPS + 1)]
    atan_a = [rnd(B * mpmath.atan(t) * 4) for t in t0]
    atan_d1 = [rnd(B / (1 + t * t) * 4) for t in t0]
    atan_c2 = [rnd(B * t / (1 + t * t) ** 2 * 4) for t in t0]
    atan_c3 = [rnd(B * (t * t - mpmath.mpf(1) / 3) / (1 + t * t) ** 3 * 4)
               for t in t0]
    assert max(sin_q31) == 2 ** 31 and atan_a[-1] == 2 ** 31
    assert min(atan_c2) >= 0
    text = """/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_trig
 * @brief Constant tables of the trig functions (generated: do not edit;
 *        run tools/generate.py). Values from mpmath at 100 digits,
 *        rounded to nearest.
 */
#include "trig_impl.h"

/* sin(i pi / 512) in Q0.31 (2^31 = 1.0), i = 0..256: a quarter wave. */
const uint32_t drdc__fx_sin_q31[FX_SIN_STEPS + 1] DRDC_FLASH_TABLE = {
%s
};

/* atan on [0, 1] at t = i / 128, i = 0..128, in binary-angle units times
 * 4 (B = 2^32 / (2 pi) units per radian), one node per row so that one
 * base address reaches all four:
 *   a   B atan(t)
 *   d1  B / (1 + t^2): the first derivative of B atan(t)
 *   c2  B t / (1 + t^2)^2: minus the second Taylor coefficient (>= 0)
 *   c3  B (t^2 - 1/3) / (1 + t^2)^3: the third Taylor coefficient
 * 129 nodes (2 064 B): |h| <= 2^-8 from the nearest keeps the cubic's
 * truncation at 0.031 units (fx_atan_ratio_bam() in trig_impl.h). */
const fx_atan_node_t drdc__fx_atan_nodes[FX_ATAN_STEPS + 1] DRDC_FLASH_TABLE = {
%s
};
""" % (rows(["%du" % v for v in sin_q31]),
       "\n".join("  { %du, %du, %du, %d }," % row
                  for row in zip(atan_a, atan_d1, atan_c2, atan_c3)))
    return text


SQRT_SEED_FIRST = 64   # first index: H >> 18 for H >= 2^24
SQRT_SEED_COUNT = 192  # indices 64..255 cover H in [2^24, 2^26)


def sqrt_table_text():
    """The text of fixed/sqrt_table.c: for each index j, floor(sqrt) of the
    largest H with H >> 18 == j, an upper bound of floor(sqrt(H)) over the
    whole bin from which one Newton step lands on floor(sqrt(H)) or one
    above it (fixed/sqrt.c)."""
    seeds = [math.isqrt(((j + 1) << 18) - 1)
             for j in range(SQRT_SEED_FIRST, SQRT_SEED_FIRST + SQRT_SEED_COUNT)]
    assert max(seeds) < 2 ** 13
    return """/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed_sqrt
 * @brief Seeds of the Q15.16 square root (generated: do not edit; run
 *        tools/generate.py).
 */
#include "sqrt_impl.h"

/* floor(sqrt(((j + 1) 2^18) - 1)) for j = 64..255: the root of the
 * largest 26-bit H whose top 8 bits are j. */
const uint16_t drdc__fx_sqrt_seed[FX_SQRT_SEED_COUNT] DRDC_FLASH_TABLE = {
%s
};
""" % rows(["%du" % v for v in seeds], per_line=10)


def generate():
    """{path from the top of the tree: text} of the generated files"""
    return {"fixed/trig_table.c": table_text(),
            "fixed/sqrt_table.c": sqrt_table_text()}
