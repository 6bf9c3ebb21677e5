#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""MISRA C:2012 check of core/ and fixed/ with cppcheck's MISRA addon.

Fails on any finding of a rule not in tools/gates/misra-deviations.txt, and
prints how many findings each deviation covers (run by ./waf check).
"""
import collections
import os
import re
import subprocess
import sys

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FINDING = re.compile(r"^(\S+):(\d+):(\d+): \w+: .*\[misra-c2012-([0-9.]+)\]$")


# <stdint.h>'s integer constant macros
STDINT_CONSTANT = re.compile(r"^U?INT(8|16|32|64|MAX)_C$")
DEFINE = re.compile(r"^\s*#\s*define\s+(\w+)(?:\([^)]*\))?\s+(.*)$")


def stdint_macros():
    """Names of every macro of core/ and fixed/ whose replacement reaches
    a <stdint.h> constant macro."""
    replacement = {}
    for top in ("core", "fixed"):
        for d, _, files in os.walk(os.path.join(TOP, top)):
            for f in files:
                if f.endswith((".c", ".h")):
                    with open(os.path.join(d, f)) as fh:
                        for line in fh:
                            m = DEFINE.match(line)
                            if m:
                                replacement[m.group(1)] = set(
                                    re.findall(r"\w+", m.group(2)))
    found = set()
    changed = True
    while changed:
        changed = False
        for name, words in replacement.items():
            if name not in found and any(STDINT_CONSTANT.match(w) or w in found
                                         for w in words):
                found.add(name)
                changed = True
    return found


def rule_of(path, line, column, rule, stdint):
    """The rule as the deviation list names it, where a finding is the
    tool's, not the code's:
    - "12.1:conditional": cppcheck 2.10 reports rule 12.1 at the ':' of
      every conditional operator, bracketed or not;
    - "17.3:stdint": the check reads no system header, so cppcheck 2.11
      and later take <stdint.h>'s INTn_C()/UINTn_C() for undeclared
      functions, reported at the macro or at a macro of ours (stdint)
      that expands to one.
    A real 12.1 or 17.3 finding elsewhere still fails."""
    if rule not in ("12.1", "17.3"):
        return rule
    with open(os.path.join(TOP, path)) as f:
        text = f.read().splitlines()[line - 1]
    if not 0 < column <= len(text):
        return rule
    if rule == "12.1" and text[column - 1] == ":":
        return "12.1:conditional"
    word = re.match(r"\w*", text[column - 1:]).group(0)
    if rule == "17.3" and (STDINT_CONSTANT.match(word) or word in stdint):
        return "17.3:stdint"
    return rule


def deviations():
    rules = {}
    with open(os.path.join(TOP, "tools", "gates", "misra-deviations.txt")) as f:
        for line in f:
            line = line.strip()
            if line and not line.startswith("#"):
                rule, _, reason = line.partition(" ")
                rules[rule] = reason
    return rules


def main():
    allowed = deviations()
    stdint = stdint_macros()
    sources = sorted(os.path.relpath(os.path.join(d, f), TOP)
                     for top in ("core", "fixed")
                     for d, _, files in os.walk(os.path.join(TOP, top))
                     for f in files if f.endswith(".c"))
    # --enable=style: cppcheck 2.13 and later report the addon's findings
    # (severity style) only with it; its own style findings are not MISRA
    # rules and are not counted. -U__AVR__: the AVR configuration reads
    # avr-libc's headers, which the check does not have; it differs only
    # in how DRDC_FLASH_TABLE tables are read (fixed/internal/drdc/compiler.h).
    r = subprocess.run(["cppcheck", "--addon=misra", "--enable=style",
                        "--std=c99", "-q", "-U__AVR__",
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
        rule = rule_of(m.group(1), int(m.group(2)), int(m.group(3)),
                       m.group(4), stdint)
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
