#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""The C and C++ sources of the tree against .clang-format (./waf check).

  formatcheck.py          list the files clang-format would change; exit 1
  formatcheck.py --fix    format them in place

Every tracked .c, .h, .cpp and .hpp file is checked except generated ones (their
first lines say "do not edit"): their generators own their layout.
"""
import argparse
import os
import re
import subprocess
import sys

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CLANG_FORMAT = "clang-format-14"
GENERATED = re.compile(r"do not edit|edit that file, not this one", re.I)


def sources():
    out = subprocess.run(["git", "ls-files", "*.c", "*.h", "*.cpp",
                          "*.hpp"], cwd=TOP,
                         check=True, capture_output=True, text=True).stdout
    for path in out.split():
        with open(os.path.join(TOP, path), encoding="utf-8") as f:
            head = "".join(f.readline() for _ in range(12))
        if not GENERATED.search(head):
            yield path


def formatted(path):
    return subprocess.run([CLANG_FORMAT, "--style=file", path], cwd=TOP,
                          check=True, capture_output=True,
                          text=True).stdout


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--fix", action="store_true", help="format in place")
    args = ap.parse_args()
    paths = list(sources())
    if args.fix:
        subprocess.run([CLANG_FORMAT, "--style=file", "-i"] + paths, cwd=TOP,
                       check=True)
        print("formatcheck: formatted %d files" % len(paths))
        return 0
    differ = []
    for path in paths:
        with open(os.path.join(TOP, path), encoding="utf-8") as f:
            if f.read() != formatted(path):
                differ.append(path)
    for path in differ:
        print("formatcheck: %s differs from %s's layout" % (path, CLANG_FORMAT))
    if differ:
        print("formatcheck: run tools/formatcheck.py --fix")
        return 1
    print("formatcheck: %d files as .clang-format lays them out" % len(paths))
    return 0


if __name__ == "__main__":
    sys.exit(main())
