# SPDX-License-Identifier: BSD-2-Clause
"""Unit conversion vectors. Oracle: GNU units 2.22 (Debian package `units`,
pinned in waftools/deps.py), run as `units -t -d 15` (15 significant digits),
never this project's factors: only the unit names and dimensions are read
from core/units/units.txt (the source of the table core/units/table.c).

For every unit: a factor check each way (a power of two of the unit to its
SI unit and back) at formats chosen so the result has about 2^39 LSB (so
GNU units' 15 digits resolve the LSB and 1 LSB is a relative error below
1e-9), and random values both ways. Temperatures go through GNU units'
tempC(x) / tempF(x) functions, since GNU units' own degC and degF are
temperature differences."""
import importlib.util
import math
import os
import random
import subprocess
from fractions import Fraction

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(os.path.dirname(HERE))
RANDOM_PER_DIRECTION = 4
TARGET_BITS = 39  # result magnitude: 2^39 LSB, well inside [2^32, 2^46]
FRAC_MAX = 62
# Our affine temperature names -> GNU units' function for that scale.
GNU_TEMPERATURE = {"degC": "tempC", "tempC": "tempC", "degF": "tempF",
                   "tempF": "tempF"}


def table():
    """(name, dimension, has offset) of every unit, in table order."""
    spec = importlib.util.spec_from_file_location(
        "units_gen_table", os.path.join(TOP, "tools", "tables", "units_table.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return [(name, dims, onum != 0)
            for _, name, dims, _, _, onum, _, _ in module.read()]


def table_factors():
    """{name: the table's factor}, only to keep the random formats inside
    what drdc_units_convert() documents (never as an expected value)."""
    spec = importlib.util.spec_from_file_location(
        "units_gen_table", os.path.join(TOP, "tools", "tables", "units_table.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return {name: Fraction(num, den)
            for _, name, _, num, den, _, _, _ in module.read()}


def downshift_fits(ratio, from_frac, to_frac):
    """Whether ratio / 2^(from_frac - to_frac) has a 63-bit numerator and
    denominator, the condition of drdc_units_convert() when the format
    loses bits (it cannot shift the input right exactly)."""
    if from_frac <= to_frac:
        return True
    f = ratio / (1 << (from_frac - to_frac))
    return f.numerator < (1 << 63) and f.denominator < (1 << 63)


def si_unit(rows, dim):
    """The coherent SI unit of a dimension: the first row GNU units gives
    factor 1 for (checked in generate())."""
    names = {(1, 0, 0, 0, 0): "m", (2, 0, 0, 0, 0): "m^2", (3, 0, 0, 0, 0): "m^3",
             (0, 1, 0, 0, 0): "kg", (0, 0, 1, 0, 0): "s", (1, 0, -1, 0, 0): "m/s",
             (1, 0, -2, 0, 0): "m/s^2", (0, 0, 0, 0, 0): "radian",
             (0, 0, -1, 0, 0): "Hz", (1, 1, -2, 0, 0): "N", (-1, 1, -2, 0, 0): "Pa",
             (2, 1, -2, 0, 0): "J", (2, 1, -3, 0, 0): "W", (0, 0, 0, 1, 0): "K",
             (0, 0, 0, 0, 1): "bit", (0, 0, -1, 0, 1): "bps"}
    # the sixth exponent, the ampere's
    electric = {(0, 0, 0, 0, 0, 1): "A", (0, 0, 1, 0, 0, 1): "C",
                (2, 1, -3, 0, 0, -1): "V", (2, 1, -3, 0, 0, -2): "ohm",
                (-2, -1, 3, 0, 0, 2): "S", (-2, -1, 4, 0, 0, 2): "F",
                (2, 1, -2, 0, 0, -1): "Wb", (2, 1, -2, 0, 0, -2): "H",
                (0, 1, -2, 0, 0, -1): "T"}
    if dim[5] == 0:
        return names[dim[:5]]
    return electric[dim]


# Our names that GNU units 2.22 reads otherwise (the SI symbol wins here,
# core/include/drdc/units.h), and GNU units' spelling of the same unit.
GNU_NAME = {"h": "hr", "rad": "radian", "kt": "knot", "BTU": "btu"}


def gnu_name(unit):
    return GNU_NAME.get(unit, unit)


def units_batch(pairs):
    """Run GNU units once over (have, want) pairs; the printed values as
    Fractions of the decimal text."""
    env = dict(os.environ, LC_ALL="C", UNITS_ENGLISH="US")
    text = "".join("%s\n%s\n" % p for p in pairs)
    return run_gnu_units(text, pairs, env)


def run_gnu_units(text, pairs, env):
    """GNU units over `text` (have / want lines): Fractions of its
    answers, one per pair."""
    r = subprocess.run(["units", "-t", "-d", "15", "-f",
                        "/usr/share/units/definitions.units"],
                       input=text, capture_output=True, text=True, env=env,
                       check=True)
    lines = r.stdout.split("\n")
    out = []
    for (have, want), line in zip(pairs, lines):
        try:
            out.append(Fraction(line.strip()))
        except ValueError:
            raise SystemExit("GNU units: %s -> %s: %r" % (have, want, line))
    if len(out) != len(pairs):
        raise SystemExit("GNU units: %d answers to %d questions"
                         % (len(out), len(pairs)))
    return out


def have_text(value, unit):
    """GNU units' input for value (a float-exact Fraction) in unit."""
    x = repr(float(value))
    if unit in GNU_TEMPERATURE:
        return "%s(%s)" % (GNU_TEMPERATURE[unit], x)
    return "%s %s" % (x, gnu_name(unit))


def want_text(unit):
    return GNU_TEMPERATURE.get(unit, gnu_name(unit))


def round_away(x):
    n = (abs(x.numerator) * 2 + x.denominator) // (2 * x.denominator)
    return -n if x < 0 else n


def formats(log2_factor, raw_bits):
    """(from_frac, to_frac) with raw 2^raw_bits in, about 2^TARGET_BITS out."""
    k = TARGET_BITS - raw_bits - int(round(log2_factor))  # to - from
    if k >= 0:
        return 0, min(FRAC_MAX, k)
    return min(FRAC_MAX, -k), 0


def generate():
    rows = table()
    exact = table_factors()
    rng = random.Random(20260705)
    # first pass: GNU units' factor of every unit to its SI unit, and SI
    # units' own factor (must be 1)
    linear = [(n, d) for n, d, off in rows if not off]
    factors = dict(zip([n for n, _ in linear],
                       units_batch([("1 " + gnu_name(n), si_unit(rows, d))
                                    for n, d in linear])))
    for n, d, off in rows:
        if not off and factors[si_unit(rows, d)] != 1:
            raise SystemExit("SI unit %s has factor %s" % (si_unit(rows, d),
                                                        factors[si_unit(rows, d)]))
    cases = []   # (unit, si, direction, raw, from_frac, to_frac)
    for n, d, off in rows:
        si = si_unit(rows, d)
        if off or d == (0, 0, 0, 1, 0, 0):
            # temperatures: values of everyday and process range, Q31.32
            values = [0, 100, -40, 37, 1000, 451]
            values += [rng.randint(-100 << 16, 3000 << 16) / 65536.0
                       for _ in range(2 * RANDOM_PER_DIRECTION)]
            for i, v in enumerate(values):
                raw = int(Fraction(v) * (1 << 32))
                if i % 2 == 0:
                    cases.append((n, si, 0, raw, 32, 32))
                else:
                    # from K: keep to physical temperatures (GNU's domain)
                    cases.append((si, n, 1, abs(raw) + (300 << 32), 32, 32))
            continue
        lf = math.log2(float(factors[n]))
        for direction, lg in ((0, lf), (1, -lf)):
            src, dst = (n, si) if direction == 0 else (si, n)
            # factor check: 2^p units of the source
            f_from, f_to = formats(lg, 0)
            p = 0
            if TARGET_BITS - lg > FRAC_MAX:   # tiny factor: a bigger input
                p = min(60, int(TARGET_BITS - lg - FRAC_MAX + 1))
            cases.append((src, dst, direction, 1 << p, f_from, f_to))
            for _ in range(RANDOM_PER_DIRECTION):
                bits = rng.randint(20, 52)
                raw = rng.choice([-1, 1]) * rng.randint(1 << (bits - 1), (1 << bits) - 1)
                f_from, f_to = formats(lg, bits)
                k = TARGET_BITS - bits - int(round(lg))
                if k > FRAC_MAX:   # shift the rest into the input
                    raw <<= min(62 - bits, k - FRAC_MAX)
                if not downshift_fits(exact[src] / exact[dst], f_from, f_to):
                    continue
                cases.append((src, dst, direction, raw, f_from, f_to))
    answers = units_batch([(have_text(Fraction(raw, 1 << ff), src), want_text(dst))
                           for src, dst, _, raw, ff, tf in cases])
    lines = []
    worst = 0
    for (src, dst, direction, raw, ff, tf), value in zip(cases, answers):
        expect = round_away(value * (1 << tf))
        if not -(1 << 63) <= expect < (1 << 63):
            continue
        lines.append('  { "%s", "%s", INT64_C(%d), %d, %d, INT64_C(%d) },'
                     % (src, dst, raw, ff, tf, expect))
    text = """/* SPDX-License-Identifier: BSD-2-Clause */
/* Generated by tests/ref/gen_units.py: conversions of every unit of
 * core/units/table.c to and from its SI unit, from GNU units 2.22
 * (`units -t -d 15`, tempC(x)/tempF(x) for temperatures). `expect` is GNU
 * units' printed value x 2^to_frac rounded to nearest.
 * Do not edit; run tools/generate.py. */
#ifndef VECTORS_UNITS_H
#define VECTORS_UNITS_H

#include <stdint.h>

struct units_vector {
  const char *from;
  const char *to;
  int64_t raw;
  uint8_t from_frac;
  uint8_t to_frac;
  int64_t expect;
};

static const struct units_vector units_vectors[] = {
%s
};

#endif
""" % "\n".join(lines)
    return {"tests/units/vectors_units.h": text}
