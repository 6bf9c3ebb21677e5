#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Symbol check: every external symbol that a libdrdc.a defines starts with
drdc_ (public names drdc_<module>_..., internal ones drdc__<module>_...),
so no application symbol can silently replace one of the library's, or
clash with it.

  symcheck.py --build DIR TARGET:NM_PREFIX...
        for each target: build/TARGET/libdrdc.a must pass, and the bait
        library (tests/symcheck/symbol_bait.c) must be caught.

The compiler may add its own external names for the library's objects,
which are judged by the name of the object they stand for:
AddressSanitizer's ODR indicators (GCC's __odr_asan.<object>, clang's
__odr_asan_gen_<object>), and on Windows x86-64 mingw-w64 GCC's pointers
to data of other objects (.refptr.<object>: a COMDAT pointer each object
that reads the data shares, which the linker's pseudo-relocations fill
in). clang's AddressSanitizer (19 and later) also defines one name of its
own in every object, ___asan_globals_registered: a hidden flag its
module constructor sets, which stands for no object of the library.
"""
import os
import subprocess
import sys

PREFIX = "drdc_"
INSTRUMENTATION = ("__odr_asan.", "__odr_asan_gen_", ".refptr.")
SANITIZER_NAMES = {"___asan_globals_registered"}


def defined_externals(nm, path):
    """(member, name) of every external symbol the archive defines."""
    out = subprocess.run([nm, "-A", "-P", "-g", "--defined-only", path],
                         check=True, capture_output=True, text=True).stdout
    found = []
    # POSIX format: "ARCHIVE[MEMBER]: NAME TYPE [VALUE SIZE]"
    for line in out.splitlines():
        parts = line.split()
        if len(parts) >= 3:
            found.append((parts[0].rstrip(":"), parts[1]))
    return found


def foreign(nm, path):
    bad = []
    for member, name in defined_externals(nm, path):
        if name in SANITIZER_NAMES:
            continue
        bare = name
        for p in INSTRUMENTATION:
            if bare.startswith(p):
                bare = bare[len(p):]
        if not bare.startswith(PREFIX):
            bad.append("%s: %s" % (member, name))
    return bad


def main(argv):
    if len(argv) < 3 or argv[0] != "--build":
        sys.exit(__doc__)
    build, specs = argv[1], argv[2:]
    ok = True
    for spec in specs:
        target, _, prefix = spec.partition(":")
        nm = prefix + "nm"
        lib = os.path.join(build, target, "libdrdc.a")
        bad = foreign(nm, lib)
        print("%-10s libdrdc.a: %s" % (target, "every external name drdc_"
                                         if not bad else
                                         "%d name(s) without drdc_" % len(bad)))
        for b in bad:
            print("  " + b)
        ok &= not bad
        bait = os.path.join(build, target, "libbait-symbols.a")
        caught = foreign(nm, bait)
        print("%-10s libbait-symbols.a: %s" % (target, "caught (%s)" % ", ".join(
            c.split(": ")[1] for c in caught) if caught else "NOT caught"))
        ok &= bool(caught)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
