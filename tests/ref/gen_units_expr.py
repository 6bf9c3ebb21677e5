# SPDX-License-Identifier: BSD-2-Clause
"""Unit-expression vectors (drdc_units_parse(), drdc_units_convert_expr()).

Random expressions from a grammar of products, quotients, powers (`^n`
and digit suffixes), parentheses and SI prefixes over units that GNU
units 2.22, pint 0.25.3 and this library define alike. Each expression is
written three ways: ours, GNU units' (its spellings where it reads a
symbol otherwise: `hr` for `h`, `radian` for `rad`, `knot` for `kt`) and
pint's (`**` for powers). Two oracles, neither this project's code:

  GNU units (`units -t -d 15`): the factor from -> to, the expected value;
  pint: the same factor in double precision, which must agree with GNU
  units' to 1e-12 relative or the generator stops.

A conversion pairs two expressions of the same dimension (or an
expression with the SI base units of its dimension) and a random value at
formats that give about 2^50 LSB out, so the expected integer resolves
the factor to 1e-15; the test allows 1e-12 relative (docs/accuracy.md).
"""
import math
import os
import random
import subprocess
from fractions import Fraction

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(os.path.dirname(HERE))
EXPRESSIONS = 2000
TARGET_BITS = 50
FRAC_MAX = 62
AGREE = Fraction(1, 10 ** 12)

# (ours, GNU units, pint) spellings of one unit; dimension-checked by the
# oracles themselves.
UNITS = [
    ("m", "m", "m"), ("km", "km", "km"), ("cm", "cm", "cm"),
    ("inch", "inch", "inch"), ("ft", "ft", "ft"), ("yd", "yd", "yd"),
    ("mile", "mile", "mile"), ("nmi", "nmi", "nmi"), ("au", "au", "au"),
    ("parsec", "parsec", "parsec"), ("pc", "pc", "pc"),
    ("lightyear", "lightyear", "lightyear"), ("angstrom", "angstrom", "angstrom"),
    ("micron", "micron", "micron"),
    ("kg", "kg", "kg"), ("g", "g", "g"), ("lb", "lb", "lb"), ("oz", "oz", "oz"),
    ("grain", "grain", "grain"), ("stone", "stone", "stone"),
    ("carat", "carat", "carat"), ("slug", "slug", "slug"), ("ton", "ton", "ton"),
    ("tonne", "tonne", "tonne"),
    ("s", "s", "s"), ("min", "min", "min"), ("h", "hr", "h"),
    ("hour", "hour", "hour"), ("day", "day", "day"), ("week", "week", "week"),
    ("N", "N", "N"), ("lbf", "lbf", "lbf"), ("kgf", "kgf", "kgf"),
    ("dyne", "dyne", "dyne"), ("poundal", "poundal", "poundal"),
    ("kip", "kip", "kip"),
    ("Pa", "Pa", "Pa"), ("bar", "bar", "bar"), ("psi", "psi", "psi"),
    ("atm", "atm", "atm"), ("torr", "torr", "torr"), ("mmHg", "mmHg", "mmHg"),
    ("inHg", "inHg", "inHg"), ("at", "at", "at"), ("ksi", "ksi", "ksi"),
    ("J", "J", "J"), ("cal", "cal", "cal"), ("kcal", "kcal", "kcal"),
    ("eV", "eV", "eV"), ("erg", "erg", "erg"), ("Wh", "Wh", "Wh"),
    ("kWh", "kWh", "kWh"),
    ("W", "W", "W"), ("hp", "hp", "hp"),
    ("Hz", "Hz", "Hz"), ("rpm", "rpm", "rpm"), ("rps", "rps", "rps"),
    ("rad", "radian", "rad"), ("radian", "radian", "radian"),
    ("deg", "deg", "deg"), ("degree", "degree", "degree"),
    ("arcmin", "arcmin", "arcmin"), ("arcsec", "arcsec", "arcsec"),
    ("gon", "gon", "gon"), ("turn", "turn", "turn"), ("sr", "sr", "sr"),
    ("A", "A", "A"), ("C", "C", "C"), ("V", "V", "V"), ("ohm", "ohm", "ohm"),
    ("F", "F", "F"), ("H", "H", "H"), ("Wb", "Wb", "Wb"), ("T", "T", "T"),
    ("S", "S", "S"), ("Ah", "Ah", "Ah"), ("mAh", "mAh", "mAh"),
    ("K", "K", "K"), ("bit", "bit", "bit"), ("byte", "byte", "byte"),
    ("L", "L", "L"), ("gal", "gal", "gal"), ("quart", "quart", "quart"),
    ("cup", "cup", "cup"), ("floz", "floz", "floz"),
    ("hectare", "hectare", "hectare"), ("ha", "ha", "ha"),
    ("mph", "mph", "mph"), ("kph", "kph", "kph"), ("kt", "knot", "kt"),
    ("knot", "knot", "knot"), ("Gal", "Gal", "Gal"),
]
# SI prefixes and units that take them, combined at random (a combination
# that is a whole table name is left out: the whole name wins there).
PREFIXES = {"k": "kilo", "M": "mega", "G": "giga", "m": "milli",
            "u": "micro", "n": "nano", "c": "centi"}
PREFIXABLE = ["m", "g", "s", "N", "Pa", "J", "W", "Hz", "A", "V", "C", "F",
              "H", "T", "Wb", "ohm", "L", "eV", "bar", "Wh", "Ah", "rad"]
# SI base units of the dimension vector (m kg s K bit A): the target of a
# conversion without a partner of the same dimension.
BASE = ["m", "kg", "s", "K", "bit", "A"]


def table_names():
    import importlib.util
    spec = importlib.util.spec_from_file_location(
        "units_gen_table", os.path.join(TOP, "tools", "tables", "units_table.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return {row[1] for row in module.read()}


def unit_pool():
    """UNITS and the prefixed units. A prefixed spelling that GNU units
    reads otherwise than prefix x unit (its `Gs` is the gauss) is left
    out: GNU units is asked for each."""
    names = table_names()
    pool = list(UNITS)
    candidates = []
    for p, word in PREFIXES.items():
        for u in PREFIXABLE:
            gnu_unit = "radian" if u == "rad" else u
            if p + u not in names:
                candidates.append(((p + u, p + gnu_unit, p + u),
                                   "%s %s" % (word, gnu_unit)))
    same = gnu_factors([(c[0][1], spelled) for c, spelled in
                        zip(candidates, [c[1] for c in candidates])])
    for (entry, _), factor in zip(candidates, same):
        if factor == 1:
            pool.append(entry)
    return pool


def power_text(rng, n, style):
    """Exponent n in one of the three renderings."""
    if style == "pint":
        return "**%d" % n
    if style == "ours" and 2 <= n <= 9 and rng.random() < 0.5:
        return "%d" % n  # digit suffix, s2
    return "^%d" % n


class Node:
    """A unit (leaf) or a parenthesised group, with a power."""

    def __init__(self, leaf=None, terms=None, power=1):
        self.leaf = leaf          # (ours, gnu, pint)
        self.terms = terms        # [(op, [nodes juxtaposed or '*'])]
        self.power = power


def random_node(rng, pool, depth):
    power = rng.choice([1, 1, 1, 1, 1, 1, 2, 3, -1, -2])
    if depth < 2 and rng.random() < 0.15:
        return Node(terms=random_terms(rng, pool, depth + 1), power=power)
    return Node(leaf=rng.choice(pool), power=power)


def random_terms(rng, pool, depth):
    """[(op, [factors])]: op '*' or '/' before each term (the first '*');
    only the first term juxtaposes factors (GNU units and pint read a
    blank after '/' differently)."""
    terms = []
    for i in range(rng.choice([1, 1, 2, 2, 3])):
        op = "*" if i == 0 else rng.choice(["*", "/"])
        count = rng.choice([1, 1, 2]) if i == 0 else 1
        terms.append((op, [random_node(rng, pool, depth) for _ in range(count)]))
    return terms


def render_terms(terms, style, rng):
    out = []
    for i, (op, factors) in enumerate(terms):
        joiner = " " if style != "pint" else " * "
        text = joiner.join(render_node(f, style, rng) for f in factors)
        out.append(text if i == 0 else op + text)
    return "".join(out)


def render_node(node, style, rng):
    if node.leaf is not None:
        text = node.leaf[{"ours": 0, "gnu": 1, "pint": 2}[style]]
    else:
        text = "(" + render_terms(node.terms, style, rng) + ")"
    if node.power != 1:
        text += power_text(rng, node.power, style)
    return text


def gnu_factors(pairs):
    """GNU units' factor of each (have, want) pair, as a Fraction of its
    15 printed digits; None where it refuses."""
    env = dict(os.environ, LC_ALL="C", UNITS_ENGLISH="US")
    text = "".join("1 (%s)\n%s\n" % p for p in pairs)
    r = subprocess.run(["units", "-t", "-d", "15", "-f",
                        "/usr/share/units/definitions.units"],
                       input=text, capture_output=True, text=True, env=env)
    lines = r.stdout.split("\n")
    if len(lines) < len(pairs):
        raise SystemExit("GNU units: %d answers to %d questions"
                         % (len(lines), len(pairs)))
    out = []
    for line in lines[:len(pairs)]:
        try:
            out.append(Fraction(line.strip()))
        except ValueError:
            out.append(None)
    return out


def base_text(dims, style):
    """The SI base units of a dimension, e.g. kg m^2 s^-2."""
    parts = []
    for name, e in zip(BASE, dims):
        # powers of at most 9 a factor (DRDC_UNITS_EXPR_POWER_MAX):
        # m^16 is m^9 m^7
        while e != 0:
            step = max(-9, min(9, e))
            e -= step
            if step == 1:
                parts.append(name)
            else:
                parts.append(name + ("**%d" % step if style == "pint"
                                     else "^%d" % step))
    if not parts:
        return "radian"
    return (" * " if style == "pint" else " ").join(parts)


def round_away(x):
    n = (abs(x.numerator) * 2 + x.denominator) // (2 * x.denominator)
    return -n if x < 0 else n


def c_string(s):
    return '"%s"' % s.replace("\\", "\\\\").replace('"', '\\"')


def generate():
    import pint
    ureg = pint.UnitRegistry()
    rng = random.Random(20261126)
    pool = unit_pool()
    exprs = []   # (ours, gnu, pint, dims)
    dims_of = {}
    out_of_range = 0
    for _ in range(EXPRESSIONS):
        terms = random_terms(rng, pool, 0)
        seed = rng.random()
        texts = []
        for style in ("ours", "gnu", "pint"):
            rng_style = random.Random(seed)   # same digit-suffix choices
            texts.append(render_terms(terms, style, rng_style))
        q = ureg.Quantity(1, texts[2]).to_base_units()
        if not 2.0 ** -59 <= abs(q.magnitude) <= 2.0 ** 59:
            # beyond the factors drdc_units_parse() represents (2^+-61
            # unless the exact fraction fits: documented DRDC_E_OVERFLOW);
            # the running products on the way may go anywhere
            out_of_range += 1
            continue
        u = q.units
        dims = tuple(int(u._units.get(n, 0)) for n in
                     ("meter", "kilogram", "second", "kelvin", "bit", "ampere"))
        if any(abs(d) > 40 for d in dims):
            out_of_range += 1
            continue
        exprs.append((texts[0], texts[1], texts[2], dims))
        dims_of.setdefault(dims, []).append(len(exprs) - 1)
    # pairs: a partner of the same dimension where there is one, else the
    # SI base units
    pairs = []
    for i, (ours, gnu, pnt, dims) in enumerate(exprs):
        partners = [j for j in dims_of[dims] if j != i]
        if partners and rng.random() < 0.7:
            j = rng.choice(partners)
            pairs.append((ours, gnu, pnt, exprs[j][0], exprs[j][1], exprs[j][2]))
        else:
            pairs.append((ours, gnu, pnt, base_text(dims, "ours"),
                          base_text(dims, "gnu"), base_text(dims, "pint")))
    gnu = gnu_factors([(p[1], p[4]) for p in pairs])
    lines = []
    worst = Fraction(0)
    skipped = 0
    for (ours, g, pnt, to_ours, to_g, to_p), factor in zip(pairs, gnu):
        if factor is None or factor == 0:
            raise SystemExit("GNU units refused %s -> %s" % (g, to_g))
        p = ureg.Quantity(1, pnt).to(to_p).magnitude
        diff = abs(Fraction(p) - factor) / factor
        if diff > AGREE:
            raise SystemExit("oracles disagree: %s -> %s: GNU units %s,"
                             " pint %r" % (g, to_g, float(factor), p))
        worst = max(worst, diff)
        lg = math.log2(float(factor))
        # raw x factor x 2^(to - from) ~ 2^TARGET_BITS with from <= to
        bits = rng.randint(20, 52)
        shift = TARGET_BITS - bits - int(round(lg))
        if shift < 0:
            bits = max(1, bits + shift)
            shift = 0
        if shift > FRAC_MAX:
            bits = min(62, bits + shift - FRAC_MAX)
            shift = FRAC_MAX
        value = Fraction(1 << (bits - 1)) * factor * (1 << shift)
        if not (1 << 40) <= abs(value) <= (1 << 60):
            skipped += 1
            continue
        raw = rng.choice([-1, 1]) * rng.randint(1 << (bits - 1), (1 << bits) - 1)
        from_frac = rng.randint(0, FRAC_MAX - shift)
        to_frac = from_frac + shift
        expect = round_away(Fraction(raw) * factor * (1 << shift))
        lines.append("  { %s,\n    %s,\n    INT64_C(%d), %d, %d, INT64_C(%d) },"
                     % (c_string(ours), c_string(to_ours), raw, from_frac,
                        to_frac, expect))
    text = """/* SPDX-License-Identifier: BSD-2-Clause */
/* Generated by tests/ref/gen_units_expr.py: %d random unit expressions
 * converted to a partner of their dimension, the factor from GNU units
 * 2.22 (`units -t -d 15`), agreeing with pint 0.25.3 to %.1e relative at
 * worst. Of %d expressions drawn, %d have a factor beyond 2^+-59 or a
 * dimension exponent beyond +-40 (running products beyond 2^+-61 on the
 * way are kept) and %d pairs a ratio beyond what the formats reach: left
 * out. `expect` is raw x factor x
 * 2^(to_frac - from_frac) rounded to nearest.
 * Do not edit; run tools/generate.py. */
#ifndef VECTORS_UNITS_EXPR_H
#define VECTORS_UNITS_EXPR_H

#include <stdint.h>

struct units_expr_vector {
  const char *from;
  const char *to;
  int64_t raw;
  uint8_t from_frac;
  uint8_t to_frac;
  int64_t expect;
};

static const struct units_expr_vector units_expr_vectors[] = {
%s
};

#endif
""" % (len(lines), float(worst), EXPRESSIONS, out_of_range, skipped,
       "\n".join(lines))
    return {"tests/units/vectors_units_expr.h": text}
