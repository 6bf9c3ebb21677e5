#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Every generated file of the tree, from its generator: the library's
constant tables (tools/tables/, from mpmath and core/units/units.txt),
the CMake build's list of sources and flags (from the tree and the table
of targets) and
the reference vectors that the Unity suites include (tests/ref/, each
from an independent oracle, never from this project's code).

  tools/generate.py           write them all
  tools/generate.py --check   regenerate into memory; fail on any
                              difference from the committed files
                              (./waf check)

Each generator module has generate() -> {path from the top: C text}, the
values as exact integers. Run with the project's Python packages:
PYTHONPATH=.deps/python.
"""
import argparse
import difflib
import importlib
import os
import sys

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TABLES = os.path.join(TOP, "tools", "tables")
VECTORS = os.path.join(TOP, "tests", "ref")

# (folder, module) of every generator.
GENERATORS = [(TABLES, m) for m in (
    "cmake_sources",
    "fixed_tables",
    "geo_consts",
    "units_table",
)] + [(VECTORS, m) for m in (
    "gen_time_civil",
    "gen_time_scales",
    "gen_time_text",
    "gen_time_calculus",
    "gen_fixed_arith",
    "gen_fixed_sqrt",
    "gen_fixed_trig",
    "gen_fixed_hyper",
    "gen_fixed_q5_58",
    "gen_fixed_wide",
    "gen_fixed_format",
    "gen_orient_quat",
    "gen_orient_dh",
    "gen_orient_bounds",
    "gen_units",
    "gen_units_expr",
    "gen_jaus",
    "gen_jaus_pose",
    "gen_nmea",
    "gen_geo",
    "gen_geo_mgrs",
    "gen_geo_ecef",
    "gen_geo_pose",
)]


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--check", action="store_true",
                    help="compare with the committed files instead of writing")
    args = ap.parse_args()
    # the generators import each other by module name
    sys.path[:0] = [TABLES, VECTORS]
    stale = count = 0
    for _, name in GENERATORS:
        for rel, text in importlib.import_module(name).generate().items():
            count += 1
            path = os.path.join(TOP, rel)
            if args.check:
                old = open(path).read() if os.path.exists(path) else ""
                if old != text:
                    stale += 1
                    diff = difflib.unified_diff(old.splitlines(), text.splitlines(),
                                                rel + " (committed)", rel + " (generated)",
                                                lineterm="", n=1)
                    print("\n".join(list(diff)[:20]))
            else:
                with open(path, "w") as f:
                    f.write(text)
                print("wrote " + rel)
    if args.check:
        if stale:
            sys.exit("generated files: %d differ from their generators; "
                     "run tools/generate.py and commit" % stale)
        print("generated files: %d up to date (tables and reference "
              "vectors)" % count)


if __name__ == "__main__":
    main()
