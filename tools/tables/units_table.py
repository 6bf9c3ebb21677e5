# SPDX-License-Identifier: BSD-2-Clause
"""Generator of core/units/table.c, the compact unit table, from
core/units/units.txt (written by tools/generate.py, which ./waf check
runs with --check).

The table is stored compactly for flash: the names as one string of
NUL-terminated names in row order (no pointer per row), each distinct
dimension once, each distinct factor number once (below 2^32 as uint32_t,
larger ones as int64_t) and four bytes per unit: the two factor indices,
the dimension row, and the offset row with the prefix flag. The numbers are
the very same exact integers as in units.txt.
"""
import os
import re
from fractions import Fraction

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SOURCE = os.path.join(TOP, "core", "units", "units.txt")
ROW = re.compile(r"^(\S+)\s+(-?\d+)\s+(-?\d+)\s+(-?\d+)\s+(-?\d+)\s+(-?\d+)"
                 r"\s+(-?\d+)\s+(\d+)/(\d+)(?:\s+(-?\d+)/(\d+))?(\s+prefix)?$")
# The one unit whose factor lies below 2^-56 (1 eV = 1.6e-19 J, also
# spelled ev): its denominator may use all 63 bits.
WIDE = {"eV", "ev"}


def read(path=SOURCE):
    """[(comments, name, dims, num, den, offset_num, offset_den, prefix)]
    in order."""
    rows, comments = [], []
    with open(path) as f:
        lines = f.read().splitlines()
    # the file's own header (up to the first blank line) is not a unit's
    body = lines[lines.index("") + 1:]
    for line in body:
        if not line.strip():
            continue
        if line.startswith("#"):
            comments.append(line[1:].strip())
            continue
        m = ROW.match(line)
        if not m:
            raise SystemExit("units.txt: bad line: " + line)
        g = m.groups()
        dims = tuple(int(x) for x in g[1:7])
        num, den = int(g[7]), int(g[8])
        onum, oden = (int(g[9]), int(g[10])) if g[9] is not None else (0, 1)
        prefix = g[11] is not None
        if prefix and onum != 0:
            raise SystemExit("units.txt: %s: a scale with an offset takes no"
                             " prefix" % g[0])
        for a, b in ((num, den), (onum, oden)):
            fr = Fraction(a, b)
            if (fr.numerator, fr.denominator) != (a, b) and a != 0:
                raise SystemExit("units.txt: %s: %d/%d not in lowest terms" % (g[0], a, b))
        limit = 2 ** 63 if g[0] in WIDE else 2 ** 56
        if not (0 < num < limit and 0 < den < limit):
            raise SystemExit("units.txt: %s: factor outside 1..2^56" % g[0])
        rows.append((comments, g[0], dims, num, den, onum, oden, prefix))
        comments = []
    names = [r[1] for r in rows]
    if len(set(names)) != len(names):
        raise SystemExit("units.txt: duplicate names")
    return rows


def c_string(name):
    if any(c in name for c in '"\\') or not name.isprintable():
        raise SystemExit("units.txt: name needs escaping: " + name)
    return '"%s\\0"' % name


def table_text(path=SOURCE):
    rows = read(path)
    dims = sorted(set(r[2] for r in rows), key=lambda d: [r[2] for r in rows].index(d))
    values = sorted(set(v for r in rows for v in (r[3], r[4])))
    small = [v for v in values if v < 2 ** 32]
    large = [v for v in values if v >= 2 ** 32]
    index = {v: i for i, v in enumerate(small + large)}
    offsets = [(0, 1)] + sorted(set((r[5], r[6]) for r in rows if r[5] != 0))
    if len(rows) > 255 or len(values) > 255:
        raise SystemExit("units.txt: too many units for one-byte indices")
    if len(dims) > 255 or len(offsets) > 15:
        raise SystemExit("units.txt: too many dimensions or offsets")

    def indent(lines):
        return ["  " + l if l else l for l in lines]

    names = ["/* The names, NUL-terminated, in row order. */",
             "static const char units_names[] ="]
    line = " "
    for r in rows:
        s = " " + c_string(r[1])
        if len(line) + len(s) > 76:
            names.append(line)
            line = " "
        line += s
    names.append(line + ";")
    dimensions = ["/* Exponents of m, kg, s, K, bit, A. */",
                  "static const int8_t units_dimensions[][DRDC_UNITS_DIMENSIONS] = {"]
    for d in dims:
        dimensions.append("  { %s }," % ", ".join(str(x) for x in d))
    dimensions.append("};")
    numbers = ["/* Factor numbers below 2^32, ascending. */",
               "static const uint32_t units_small[] = {"]
    line = " "
    for v in small:
        s = " %du," % v
        if len(line) + len(s) > 76:
            numbers.append(line)
            line = " "
        line += s
    numbers += [line, "};", "/* Factor numbers from 2^32 up, ascending (all below 2^63). */",
                "static const int64_t units_large[] = {"]
    for v in large:
        numbers.append("  INT64_C(%d)," % v)
    numbers.append("};")
    offs = ["/* Offsets num / den (the scale's zero in the unit); 0: linear. */",
            "static const int64_t units_offsets[][2] = {"]
    for a, b in offsets:
        offs.append("  { %d, %d }," % (a, b))
    offs.append("};")
    out = [
        "/* SPDX-License-Identifier: BSD-2-Clause */",
        "/**",
        " * @file",
        " * @ingroup drdc_units",
        " * @brief The unit table (generated by tools/tables/units_table.py from",
        " *        core/units/units.txt: edit that file, not this one).",
        " */",
        "#include \"units_impl.h\"",
        "",
        "/*",
        " * Units with pi use the convergent pi ~ 245850922 / 78256779 of pi's",
        " * continued fraction [3; 7, 15, 1, 292, 1, 1, 1, 2, 1, 3, 1, 14, 2, 1]:",
        " * |error| < 7.8e-17, relative 2.5e-17, far below the 1e-15 asked of the",
        " * table and below what GNU units prints. Every other factor is exact.",
        " *",
        " * Compact storage: every name once in units_names (row order), each",
        " * distinct dimension, factor number and offset once, and four bytes",
        " * per unit (%d units, %d bytes of rows)." % (len(rows), 4 * len(rows)),
        " */",
        "",
        "/* Number of factor numbers below 2^32 (units_small). */",
        "#define UNITS_SMALL_COUNT %du" % len(small),
        "",
        "/* { factor num, factor den, dimension, UNITS_FLAGS(offset, prefix) }:",
        " * indices into the tables of the readers below and whether SI",
        " * prefixes apply; the name is the row's string in units_names. */",
            "static const drdc_unit_t units_table[] = {"]
    for comments, name, d, num, den, onum, oden, prefix in rows:
        for c in comments:
            out.append("  /* %s */" % c)
        text = "%s: %d / %d" % (name, num, den)
        if onum:
            text += ", offset %d / %d" % (onum, oden)
        row = "  { %du, %du, %du, UNITS_FLAGS(%du, %du) }," % (
            index[num], index[den], dims.index(d), offsets.index((onum, oden)),
            1 if prefix else 0)
        if len(row) + len(text) + 7 <= 80:
            out.append("%s /* %s */" % (row, text))
        else:  # 80 columns: the row's comment above it
            out += ["  /* %s */" % text, row]
    out += ["};", "",
            "size_t drdc_units_count(void)",
            "{",
            "  return sizeof(units_table) / sizeof(units_table[0]);",
            "}",
            "",
            "const drdc_unit_t *drdc_units_at(size_t index)",
            "{",
            "  const drdc_unit_t *unit = NULL;",
            "",
            "  if (index < drdc_units_count()) {",
            "    unit = &units_table[index];",
            "  }",
            "  return unit;",
            "}",
            "",
            "const char *drdc__units_names_first(void)",
            "{"] + indent(names) + [
            "",
            "  return units_names;",
            "}",
            "",
            "size_t drdc__units_index(const drdc_unit_t *unit)",
            "{",
            "  size_t row = 0u;",
            "",
            "  while ((row < drdc_units_count()) && (unit != &units_table[row])) {",
            "    row++;",
            "  }",
            "  return row;",
            "}",
            "",
            "int8_t drdc__units_dimension(const drdc_unit_t *unit, size_t i)",
            "{"] + indent(dimensions) + [
            "",
            "  return units_dimensions[unit->dimension][i];",
            "}",
            "",
            "int64_t drdc__units_number(uint8_t index)",
            "{"] + indent(numbers) + [
            "",
            "  return (index < UNITS_SMALL_COUNT)",
            "             ? (int64_t)units_small[index]",
            "             : units_large[index - UNITS_SMALL_COUNT];",
            "}",
            "",
            "int64_t drdc__units_offset_part(const drdc_unit_t *unit, unsigned part)",
            "{"] + indent(offs) + [
            "",
            "  return units_offsets[units_offset_row(unit)][(part != 0u) ? 1 : 0];",
            "}",
            "",
            "units_rat_t drdc__units_offset(const drdc_unit_t *unit)",
            "{",
            "  units_rat_t r;",
            "",
            "  r.num = drdc__units_offset_part(unit, 0u);",
            "  r.den = drdc__units_offset_part(unit, 1u);",
            "  return r;",
            "}",
            ]
    return "\n".join(out) + "\n"


def generate():
    """{path from the top of the tree: text} of the generated file"""
    return {"core/units/table.c": table_text()}
