# SPDX-License-Identifier: BSD-2-Clause
"""Reference vectors of fixed/ wide-integer primitives (fixed_wide.h).

Oracle: Python's exact integers. Floors are //, remainders %, rounding to
nearest with ties away from zero is taken on the magnitude
((2 |n| + d) // (2 d), the sign put back), square roots by math.isqrt
(round(sqrt(N)) = (isqrt(4 N) + 1) // 2). Nothing here runs the library's
code or its algorithms (no reciprocals, no Newton steps)."""
import math
import random

M32 = (1 << 32) - 1
M64 = (1 << 64) - 1
I64_MIN, I64_MAX = -(1 << 63), (1 << 63) - 1


def round_div(n, d):
    """n / d to nearest, ties away from zero, for d > 0."""
    q = (2 * abs(n) + d) // (2 * d)
    return -q if n < 0 else q


def _u64(v):
    return "UINT64_C(%d)" % v


def _s64(v):
    return "INT64_MIN" if v == I64_MIN else "INT64_C(%d)" % v


def _bits(rng, lo, hi):
    """A value of a random bit length in [lo, hi] bits (top bit set)."""
    n = rng.randint(lo, hi)
    return (1 << (n - 1)) | rng.getrandbits(n - 1) if n > 1 else n


def _norm32(rng):
    return (1 << 31) | rng.getrandbits(31)


def _norm64(rng):
    return (1 << 63) | rng.getrandbits(63)


def _digit16_rows(rng):
    rows = []
    ds = [1 << 31, (1 << 31) + 1, M32, M32 - 1, 0x80008000, 0xFFFF0000,
          0x8000FFFF]
    ds += [_norm32(rng) for _ in range(250)]
    for i, d in enumerate(ds):
        for r in ((0, d - 1, d >> 1, rng.randrange(d)) if i < 7
                  else (rng.randrange(d),)):
            for u in ((0, 0xFFFF, rng.getrandbits(16)) if i < 7
                      else (rng.getrandbits(16),)):
                n = (r << 16) | u
                rows.append("  { %du, %du, %du, %du, %du }," % (
                    r, u, d, n // d, n % d))
    return rows


def _recip2_rows(rng):
    ds = [1 << 31, (1 << 31) + 1, M32, M32 - 1, 0xC0000000, 0xAAAAAAAA]
    ds += [_norm32(rng) for _ in range(300)]
    return ["  { %du, %du }," % (d, M64 // d - (1 << 32)) for d in ds]


def _recip3_rows(rng):
    ds = [1 << 63, (1 << 63) + 1, M64, M64 - 1, 0x8000000100000000,
          0x80000000FFFFFFFF, 0xFFFFFFFF00000000, 0xC000000000000000]
    ds += [_norm64(rng) for _ in range(300)]
    return ["  { %du, %du, %du }," % (d >> 32, d & M32,
                                      ((1 << 96) - 1) // d - (1 << 32))
            for d in ds]


def _div3by2_rows(rng):
    rows = []
    ds = [1 << 63, M64, (1 << 63) + 1, 0xFFFFFFFF00000000]
    ds += [_norm64(rng) for _ in range(300)]
    for i, d in enumerate(ds):
        tops = [0, d - 1, (d - 1) >> 32 << 32, rng.randrange(d)] if i < 4 \
            else [rng.randrange(d), rng.randrange(1 << rng.randint(1, 64)) % d]
        for top in tops:
            u0 = rng.getrandbits(32) if top else M32
            n = (top << 32) | u0
            rows.append("  { %du, %du, %du, %s, %du, %s }," % (
                top >> 32, top & M32, u0, _u64(d), n // d, _u64(n % d)))
    return rows


def _mul_rows(rng):
    xs = [0, 1, M32, 1 << 32, M64, M64 - 1, 1 << 63, (1 << 63) - 1]
    pairs = [(a, b) for a in xs for b in xs]
    pairs += [(_bits(rng, 1, 64), _bits(rng, 1, 64)) for _ in range(300)]
    return ["  { %s, %s, %s, %s }," % (_u64(a), _u64(b), _u64((a * b) >> 64),
                                       _u64((a * b) & M64)) for a, b in pairs]


def _round_div_shifted_rows(rng):
    """(p, t, d): round(p 2^t / d) with z = 63 - bitlen(d) added to t by
    the test; |p| 2^(t + z) < dn 2^32 and 31 <= t + z <= 63."""
    rows = []
    while len(rows) < 400:
        d = _bits(rng, 2, 64)
        z = 64 - d.bit_length()
        t = rng.randint(max(31 - z, 0), 63 - z)
        # |p| 2^t < d 2^32: the quotient below 2^32
        pmax = ((d << 32) - 1) >> t
        pmax = min(pmax, I64_MAX)
        if pmax < 1:
            continue
        kind = len(rows) % 4
        if kind == 0:
            p = rng.randint(-pmax, pmax)
        elif kind == 1:
            p = rng.choice((pmax, -pmax, 1, -1, 0))
        else:
            # near a tie: p 2^t = (k + 1/2) d + e
            k = rng.randrange(1 << 31)
            p = ((2 * k + 1) * d) // (2 << t) + rng.randint(-1, 1)
            p = max(min(p, pmax), 0) * rng.choice((1, -1))
        q = round_div(p << t, d)
        rows.append("  { %s, %du, %s, %du }," % (_s64(p), t, _u64(d),
                                                 q & M32))
    return rows


def _round_div_128_rows(rng):
    """(p, w, d): round(p w / d) for |p| <= d, |w| < 2^63."""
    rows = []
    for i in range(400):
        d = _bits(rng, 1, 63) if i % 5 else rng.choice((1, I64_MAX, 3))
        if i % 3 == 0:
            p = rng.choice((d, -d, 0, 1, -1))
        else:
            p = rng.randint(-d, d)
        w = rng.randint(-I64_MAX, I64_MAX) if i % 2 else \
            _bits(rng, 1, 63) * rng.choice((1, -1))
        if i % 7 == 3:
            # a tie: p w / d = w / 2 for d even, p = d / 2, w odd
            d = 2 * rng.randrange(1, 1 << 61)
            w = (rng.randrange(1, 1 << 61) * 2 + 1) * rng.choice((1, -1))
            p = d // 2 * rng.choice((1, -1))
        rows.append("  { %s, %s, %s, %s }," % (_s64(p), _s64(w), _u64(d),
                                               _s64(round_div(p * w, d))))
    return rows


def _muldiv64_rows(rng):
    rows = []
    for i in range(400):
        c = rng.randint(1, (1 << 31) - 1) if i % 4 else \
            rng.choice((1, 2, 3, (1 << 31) - 1))
        b = rng.randint(-(1 << 31), (1 << 31) - 1)
        # |a b| < 2^64 and a quotient within int64_t
        lim = min(M64, I64_MAX * c) // max(abs(b), 1)
        a = rng.randint(-min(lim, I64_MAX), min(lim, I64_MAX))
        if i % 5 == 2 and c % 2 == 0:
            a = c // 2  # ties with b = +-1
            b = rng.choice((1, -1))
        rows.append("  { %s, %d, %d, %s }," % (
            _s64(a), b, c, _s64(round_div(a * b, c))))
    rows.append("  { INT64_C(%d), %d, %d, %s }," % (
        (1 << 32) - 1, -(1 << 31), 1, _s64(-((1 << 32) - 1) * (1 << 31))))
    return rows


def _mul_rshift_rows(rng):
    rows = []
    for i in range(400):
        n = rng.randint(1, 63)
        a = _bits(rng, 1, 64) % (1 << 63) * rng.choice((1, -1))
        # |a b| / 2^n < 2^63
        bmax = min(((1 << (63 + n)) - 1) // max(abs(a), 1), I64_MAX)
        b = rng.randint(-bmax, bmax)
        if i % 6 == 1:
            # a tie: a b = (2k + 1) 2^(n - 1)
            a = (2 * rng.randrange(1 << 20) + 1) * rng.choice((1, -1))
            b = (1 << (n - 1)) * rng.choice((1, -1))
        rows.append("  { %s, %s, %du, %s }," % (
            _s64(a), _s64(b), n, _s64(round_div(a * b, 1 << n))))
    return rows


def _div128_rows(rng):
    rows = []
    for i in range(300):
        x = _bits(rng, 1, 64)
        nh = rng.randrange(x) if i % 3 else rng.choice((0, x - 1))
        nh %= (1 << 64)
        nl = rng.getrandbits(64) if i % 4 else rng.choice((0, M64))
        n = (nh << 64) | nl
        rows.append("  { %s, %s, %s, %s }," % (_u64(nh), _u64(nl), _u64(x),
                                               _u64(n // x)))
    return rows


def _hypot62_rows(rng):
    lim = 1 << 62
    pairs = [(lim, lim), (-lim, -lim), (lim, 0), (0, -lim), (0, 0), (3, 4),
             (1, 1), (1 << 32, 1 << 32), ((1 << 32) - 1, 1 << 32),
             (lim - 1, lim - 1), (1, lim), (M32, M32)]
    for i in range(400):
        bits = rng.randint(1, 63)
        a = rng.randint(-min(1 << (bits - 1), lim), min(1 << (bits - 1), lim))
        b = rng.randint(-min(1 << (bits - 1), lim), min(1 << (bits - 1), lim))
        if i % 4 == 0:
            # beside exact squares: r^2 + b^2 with b = 0..3 (the root is r,
            # r + 1/(2r) ... rounds down)
            a = rng.randrange(1 << 40, lim) * rng.choice((1, -1))
            b = rng.randint(0, 3)
        pairs.append((a, b))
    return ["  { %s, %s, %s }," % (_s64(x), _s64(y), _u64(
        (math.isqrt(4 * (x * x + y * y)) + 1) // 2)) for x, y in pairs]


def _headroom_rows(rng):
    rows = []
    vs = [0, 1, 2, 3, M32, 1 << 32, M64, 1 << 63, (1 << 62) + 1]
    vs += [_bits(rng, 1, 64) for _ in range(120)]
    for v in vs:
        for limit in (0, 1, 31, 32, 62, 63, 64, 65, rng.randint(1, 64)):
            s = 0 if (v == 0 or limit == 0 or limit > 64) else \
                max(0, limit - v.bit_length())
            rows.append("  { %s, %du, %du }," % (_u64(v), limit, s))
    return rows


def generate():
    rng = random.Random(20261122)
    parts = [
        ("digit16_vector", "uint32_t r, u, d, q, rem;",
         "digit16_vectors", "floor((r 2^16 + u) / d) and the remainder",
         _digit16_rows(rng)),
        ("recip2_vector", "uint32_t d, v;", "recip2_vectors",
         "floor((2^64 - 1) / d) - 2^32", _recip2_rows(rng)),
        ("recip3_vector", "uint32_t d1, d0, v;", "recip3_vectors",
         "floor((2^96 - 1) / (d1 2^32 + d0)) - 2^32", _recip3_rows(rng)),
        ("div3by2_vector", "uint32_t u2, u1, u0; uint64_t d; uint32_t q; "
         "uint64_t r;", "div3by2_vectors",
         "floor((u2 2^64 + u1 2^32 + u0) / d) and the remainder",
         _div3by2_rows(rng)),
        ("mul128_vector", "uint64_t x, y, hi, lo;", "mul128_vectors",
         "x y as two 64-bit words", _mul_rows(rng)),
        ("rdshift_vector", "int64_t p; unsigned t; uint64_t d; uint32_t q;",
         "rdshift_vectors", "low 32 bits of round(p 2^t / d)",
         _round_div_shifted_rows(rng)),
        ("rd128_vector", "int64_t p, w; uint64_t d; int64_t q;",
         "rd128_vectors", "round(p w / d)", _round_div_128_rows(rng)),
        ("muldiv64_vector", "int64_t a; int32_t b, c; int64_t q;",
         "muldiv64_vectors", "round(a b / c)", _muldiv64_rows(rng)),
        ("mulrs_vector", "int64_t a, b; unsigned n; int64_t q;",
         "mulrs_vectors", "round(a b / 2^n)", _mul_rshift_rows(rng)),
        ("div128_vector", "uint64_t nh, nl, x, q;", "div128_vectors",
         "floor((nh 2^64 + nl) / x)", _div128_rows(rng)),
        ("hypot62_vector", "int64_t x, y; uint64_t r;", "hypot62_vectors",
         "round(sqrt(x^2 + y^2))", _hypot62_rows(rng)),
        ("headroom_vector", "uint64_t v; unsigned limit, s;",
         "headroom_vectors", "limit - bit length of v (0 if negative)",
         _headroom_rows(rng)),
    ]
    out = ["""/* SPDX-License-Identifier: BSD-2-Clause */
/* Generated by tests/ref/gen_fixed_wide.py: the wide-integer primitives
 * of fixed_wide.h from exact Python integers.
 * Do not edit; run tools/generate.py. */
#ifndef VECTORS_WIDE_H
#define VECTORS_WIDE_H

#include <stdint.h>
"""]
    for sname, fields, aname, what, rows in parts:
        out.append("struct %s {\n  %s\n};\n\n/* %s */\n"
                   "static const struct %s %s[] = {\n%s\n};\n" % (
                       sname, fields.replace("; ", ";\n  "), what, sname,
                       aname, "\n".join(rows)))
    out.append("#endif\n")
    return {"tests/fixed/vectors_wide.h": "\n".join(out)}
