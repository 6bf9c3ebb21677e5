#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""The C and C++ sources of the tree against .clang-format (./waf check).

  formatcheck.py          list the files clang-format would change; exit 1
  formatcheck.py --fix    format them in place

Every tracked .c, .h, .cpp and .hpp file is checked except generated ones (their
first lines say "do not edit"): their generators own their layout.

The layout is clang-format 14.0.6's, from its wheel on PyPI (pinned by
SHA-256 in waftools/deps.py, a static binary), so every machine and Debian
release lays the sources out alike; run with PYTHONPATH=.deps/python as
./waf check does.
"""
import argparse
import os
import re
import subprocess
import sys

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CLANG_VERSION = "14.0.6"


def clang_format():
    """The binary of the pinned clang-format wheel."""
    try:
        import clang_format as wheel
    except ImportError:
        sys.exit("formatcheck: no clang_format package on PYTHONPATH "
                 "(waftools/deps.py installs it into .deps/python)")
    path = os.path.join(os.path.dirname(wheel.__file__), "data", "bin",
                        "clang-format")
    version = subprocess.run([path, "--version"], check=True,
                             capture_output=True, text=True).stdout
    if CLANG_VERSION not in version:
        sys.exit("formatcheck: %s is not clang-format %s: %s"
                 % (path, CLANG_VERSION, version.strip()))
    return path

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


def formatted(binary, path):
    return subprocess.run([binary, "--style=file", path], cwd=TOP,
                          check=True, capture_output=True,
                          text=True).stdout


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--fix", action="store_true", help="format in place")
    args = ap.parse_args()
    binary = clang_format()
    paths = list(sources())
    if args.fix:
        subprocess.run([binary, "--style=file", "-i"] + paths, cwd=TOP,
                       check=True)
        print("formatcheck: formatted %d files" % len(paths))
        return 0
    differ = []
    for path in paths:
        with open(os.path.join(TOP, path), encoding="utf-8") as f:
            if f.read() != formatted(binary, path):
                differ.append(path)
    for path in differ:
        print("formatcheck: %s differs from clang-format %s's layout"
              % (path, CLANG_VERSION))
    if differ:
        print("formatcheck: run tools/gates/formatcheck.py --fix")
        return 1
    print("formatcheck: %d files as .clang-format lays them out" % len(paths))
    return 0


if __name__ == "__main__":
    sys.exit(main())
