# SPDX-License-Identifier: BSD-2-Clause
"""Reference vectors of fixed/ multiply, divide and multiply-divide.

Oracle: Python's fractions.Fraction, exact rational arithmetic, then the
library's one rounding rule (to nearest, ties away from zero). Each row
holds the inputs, the correctly rounded result and whether it overflows
the output format (then the row holds the saturated value)."""
import random
from fractions import Fraction

I32 = (-(1 << 31), (1 << 31) - 1)
I64 = (-(1 << 63), (1 << 63) - 1)

# op codes shared with tests/fixed/test_arith.c
OPS32 = ["MUL_Q1_30", "MUL_Q15_16", "DIV_Q1_30", "DIV_Q15_16", "MULDIV_S32"]
OPS64 = ["MUL_Q47_16", "DIV_Q47_16", "MULDIV_S64"]
ROWS_PER_OP = 80


def round_away(x):
    """Nearest integer to the Fraction x, ties away from zero."""
    n = (abs(x.numerator) * 2 + x.denominator) // (2 * x.denominator)
    return -n if x < 0 else n


def exact(op, a, b, c):
    if op.startswith("MUL_"):
        shift = {"MUL_Q1_30": 30, "MUL_Q15_16": 16, "MUL_Q47_16": 16}[op]
        return Fraction(a * b, 1 << shift)
    if op.startswith("DIV_"):
        shift = {"DIV_Q1_30": 30, "DIV_Q15_16": 16, "DIV_Q47_16": 16}[op]
        return Fraction(a << shift, b)
    return Fraction(a * b, c)


def _value(rng, bits):
    """Random signed value: uniform, or of a random bit length, or special."""
    lo, hi = -(1 << (bits - 1)), (1 << (bits - 1)) - 1
    k = rng.randrange(6)
    if k == 0:
        return rng.randint(lo, hi)
    if k == 1:
        return rng.choice([0, 1, -1, lo, hi, lo + 1, 1 << 16, -(1 << 16),
                           1 << 30, -(1 << 30), 1 << 15, -(1 << 15),
                           1 << 29, -(1 << 29)])
    n = rng.randint(1, bits - 1)
    return rng.choice([-1, 1]) * rng.randint(0, (1 << n) - 1)


# Named cases: ties, limits, the most negative values, exact overflows.
SPECIAL32 = [
    ("MUL_Q15_16", 1, 1 << 15, 0), ("MUL_Q15_16", -1, 1 << 15, 0),
    ("MUL_Q15_16", 3, 1 << 15, 0), ("MUL_Q15_16", 1, (1 << 15) - 1, 0),
    ("MUL_Q1_30", 1, 1 << 29, 0), ("MUL_Q1_30", -1, 1 << 29, 0),
    ("MUL_Q1_30", I32[0], I32[0], 0), ("MUL_Q1_30", I32[0], 1 << 30, 0),
    ("MUL_Q1_30", I32[0], -(1 << 30), 0), ("MUL_Q1_30", I32[1], I32[1], 0),
    ("MUL_Q15_16", I32[0], 1 << 16, 0), ("MUL_Q15_16", I32[0], -(1 << 16), 0),
    ("MUL_Q15_16", I32[1], I32[1], 0), ("MUL_Q15_16", 0, I32[0], 0),
    ("DIV_Q1_30", 1, 2, 0), ("DIV_Q1_30", 1, -3, 0),
    ("DIV_Q1_30", I32[0], I32[0], 0), ("DIV_Q1_30", I32[0], 1 << 30, 0),
    ("DIV_Q1_30", I32[0], -(1 << 30), 0), ("DIV_Q1_30", 1 << 30, 1 << 29, 0),
    ("DIV_Q15_16", I32[0], -1, 0), ("DIV_Q15_16", I32[0], 1 << 16, 0),
    ("DIV_Q15_16", I32[0], -(1 << 16), 0), ("DIV_Q15_16", 1, 1 << 17, 0),
    ("DIV_Q15_16", -1, 1 << 17, 0), ("DIV_Q15_16", 1, I32[0], 0),
    ("MULDIV_S32", I32[0], I32[0], I32[0], ), ("MULDIV_S32", I32[0], -1, 1),
    ("MULDIV_S32", I32[0], 1, -1), ("MULDIV_S32", I32[1], I32[1], I32[1]),
    ("MULDIV_S32", 5, 1, 2), ("MULDIV_S32", -5, 1, 2), ("MULDIV_S32", 5, 1, -2),
    ("MULDIV_S32", 0, I32[0], -1), ("MULDIV_S32", I32[0], I32[0], 1),
    # products whose rounding decides overflow (the multiplies' fast path
    # judges the rounded high word): ties at 2^31 - 1/2 (positive:
    # overflows; negative: INT32_MIN), at -(2^31 + 1/2) (overflows) and at
    # 2^31 - 3/2 (INT32_MAX); factors of 2^15 (2^32 - 1), 2^15 (2^32 + 1),
    # 2^15 (2^32 - 3) and, in Q1.30, 2^29 (2^32 -+ 1)
    ("MUL_Q15_16", 8355840, 16843009, 0), ("MUL_Q15_16", -8355840, 16843009, 0),
    ("MUL_Q15_16", -21004288, 6700417, 0), ("MUL_Q15_16", 302809088, 464773, 0),
    ("MUL_Q1_30", 1610612736, 1431655765, 0),
    ("MUL_Q1_30", -1610612736, 1431655765, 0),
    ("MUL_Q1_30", -1715306752, 1344274432, 0),
]
SPECIAL64 = [
    ("MUL_Q47_16", 1, 1 << 15, 1), ("MUL_Q47_16", -1, 1 << 15, 1),
    ("MUL_Q47_16", I64[0], I64[0], 1), ("MUL_Q47_16", I64[0], 1 << 16, 1),
    ("MUL_Q47_16", I64[0], -(1 << 16), 1), ("MUL_Q47_16", I64[1], I64[1], 1),
    ("MUL_Q47_16", 1 << 40, 1 << 39, 1), ("MUL_Q47_16", 1 << 40, -(1 << 39), 1),
    ("DIV_Q47_16", I64[0], -(1 << 16), 1), ("DIV_Q47_16", I64[0], 1 << 16, 1),
    ("DIV_Q47_16", I64[1], 1, 1), ("DIV_Q47_16", 1, I64[0], 1),
    ("DIV_Q47_16", 1, 1 << 17, 1), ("DIV_Q47_16", -1, 1 << 17, 1),
    ("DIV_Q47_16", I64[1], I64[1], 1), ("DIV_Q47_16", 3, 7, 1),
    ("MULDIV_S64", I64[0], I64[0], I64[0]), ("MULDIV_S64", I64[0], -1, 1),
    ("MULDIV_S64", I64[0], 1, -1), ("MULDIV_S64", I64[1], I64[1], I64[1]),
    ("MULDIV_S64", I64[1], I64[1], I64[1] - 1), ("MULDIV_S64", 5, 1, 2),
    ("MULDIV_S64", -5, 1, 2), ("MULDIV_S64", I64[1], I64[1], 1),
    ("MULDIV_S64", I64[1], 3, 5), ("MULDIV_S64", I64[0], I64[1], I64[0]),
]


def _rows(ops, special, bits, rng):
    lo, hi = -(1 << (bits - 1)), (1 << (bits - 1)) - 1
    cases = [s if len(s) == 4 else s + (1,) for s in special]
    for op in ops:
        for _ in range(ROWS_PER_OP):
            a, b = _value(rng, bits), _value(rng, bits)
            c = _value(rng, bits) if op.startswith("MULDIV") else 1
            if op.startswith("DIV") and b == 0:
                b = 1
            if c == 0:
                c = -1
            cases.append((op, a, b, c))
    rows = []
    for op, a, b, c in cases:
        r = round_away(exact(op, a, b, c))
        over = not (lo <= r <= hi)
        r = max(lo, min(hi, r))
        rows.append("  { %s, %d, %s, %s, %s, %s }," % (
            "FX_" + op, int(over), _lit(a, bits), _lit(b, bits),
            _lit(c, bits), _lit(r, bits)))
    return rows


def _lit(v, bits):
    if bits == 32:
        return "INT32_MIN" if v == -(1 << 31) else "%d" % v
    return "INT64_MIN" if v == -(1 << 63) else "INT64_C(%d)" % v


def generate():
    rng = random.Random(20261122)
    rows32 = _rows(OPS32, SPECIAL32, 32, rng)
    rows64 = _rows(OPS64, SPECIAL64, 64, rng)
    text = """/* SPDX-License-Identifier: BSD-2-Clause */
/* Generated by tests/ref/gen_fixed_arith.py: exact rational results of
 * fixed/ multiply, divide and multiply-divide (Python fractions), rounded
 * to nearest with ties away from zero; `over` marks a result outside the
 * output format, whose row then holds the saturated value.
 * Do not edit; run tools/generate.py. */
#ifndef VECTORS_ARITH_H
#define VECTORS_ARITH_H

#include <stdint.h>

enum fx_op { %s };

struct arith32_vector {
  uint8_t op;
  uint8_t over;
  int32_t a, b, c;
  int32_t result;
};

struct arith64_vector {
  uint8_t op;
  uint8_t over;
  int64_t a, b, c;
  int64_t result;
};

static const struct arith32_vector arith32_vectors[] = {
%s
};

static const struct arith64_vector arith64_vectors[] = {
%s
};

#endif
""" % (", ".join("FX_" + o for o in OPS32 + OPS64), "\n".join(rows32),
       "\n".join(rows64))
    return {"tests/fixed/vectors_arith.h": text}
