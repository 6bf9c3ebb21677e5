#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""MISRA C:2012 check of core/ and fixed/ with cppcheck's MISRA addon.

Fails on any finding of a rule not in tools/misra-deviations.txt, and
prints how many findings each deviation covers (run by ./waf check).
"""
import collections
import os
import re
import subprocess
import sys

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FINDING = re.compile(r"^(\S+):(\d+):(\d+): \w+: .*\[misra-c2012-([0-9.]+)\]$")


def rule_of(path, line, column, rule):
    """The rule as the deviation list names it: cppcheck 2.10 reports rule
    12.1 at the ':' of every conditional operator, bracketed or not; those
    findings are "12.1:conditional", so a real 12.1 finding still fails."""
    if rule == "12.1":
        with open(os.path.join(TOP, path)) as f:
            text = f.read().splitlines()[line - 1]
        if 0 < column <= len(text) and text[column - 1] == ":":
            return "12.1:conditional"
    return rule


def deviations():
    rules = {}
    with open(os.path.join(TOP, "tools", "misra-deviations.txt")) as f:
        for line in f:
            line = line.strip()
            if line and not line.startswith("#"):
                rule, _, reason = line.partition(" ")
                rules[rule] = reason
    return rules


def main():
    allowed = deviations()
    sources = sorted(os.path.relpath(os.path.join(d, f), TOP)
                     for top in ("core", "fixed")
                     for d, _, files in os.walk(os.path.join(TOP, top))
                     for f in files if f.endswith(".c"))
    r = subprocess.run(["cppcheck", "--addon=misra", "--std=c99", "-q",
                        "--error-exitcode=0", "--suppress=missingIncludeSystem",
                        "--template={file}:{line}:{column}: {severity}: {message} [{id}]",
                        "-Ifixed/internal", "-Ifixed/include", "-Icore/include"] + sources,
                       cwd=TOP, capture_output=True, text=True)
    covered = collections.Counter()
    bad = []
    for line in r.stderr.splitlines():
        m = FINDING.match(line)
        if not m:
            if line.strip() and ": error:" in line:
                bad.append(line)   # cppcheck could not analyse something
            continue
        rule = rule_of(m.group(1), int(m.group(2)), int(m.group(3)), m.group(4))
        if rule in allowed:
            covered[rule] += 1
        else:
            bad.append(line)
    for rule in sorted(allowed, key=lambda r: [int(x) for x in r.split(":")[0].split(".")]):
        print("deviation %-5s %3d finding(s): %s" % (rule, covered[rule],
                                                      allowed[rule][:60] + "..."))
    for line in bad:
        print("FINDING " + line)
    print("MISRA C:2012: %d source files, %d finding(s) outside the %d deviations"
          % (len(sources), len(bad), len(allowed)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
