#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Host generator of the reference vectors that the Unity suites include.

Each gen_*.py module here computes vectors with an independent oracle (never
with this project's code) and returns the C text of one or more headers as
exact integers. `generate.py` writes them into tests/<module>/;
`generate.py --check` regenerates into memory and fails on any difference
from the committed files (run by ./waf check).
"""
import argparse
import difflib
import importlib
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(os.path.dirname(HERE))

# One entry per generator module; each has generate() -> {path: text}.
GENERATORS = [
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
    "gen_fixed_tables",
    "gen_fixed_format",
    "gen_orient_quat",
    "gen_orient_dh",
    "gen_orient_bounds",
    "gen_units",
    "gen_units_table",
    "gen_units_expr",
    "gen_jaus",
    "gen_jaus_pose",
    "gen_nmea",
    "gen_geo",
    "gen_geo_mgrs",
    "gen_geo_ecef",
    "gen_geo_pose",
    "gen_geo_consts",
]


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--check", action="store_true",
                    help="compare with the committed files instead of writing")
    args = ap.parse_args()
    sys.path.insert(0, HERE)
    stale = 0
    for name in GENERATORS:
        for rel, text in importlib.import_module(name).generate().items():
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
            sys.exit("reference vectors: %d file(s) differ from the generator; "
                     "run tests/ref/generate.py and commit" % stale)
        print("reference vectors: up to date")


if __name__ == "__main__":
    main()
