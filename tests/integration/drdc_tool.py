# SPDX-License-Identifier: BSD-2-Clause
"""The drdc program that the tool tests (tests/integration/test_drdc.py,
tests/integration/test_drdc_nmea.py, tests/integration/geo_parity.py) run: the host's, or the
Windows one under Wine.

  DRDC_TARGET  host (default): build/host/drdc
               win64: build/win64/drdc.exe through qemu/wine.py
  DRDC_BUILD   the build directory (default build/ of the source tree)

On Windows drdc writes its lines in text mode, each ending in CR LF as
GeoConvert's do there (tools/drdc/main.c); the tests compare lines, and
lf_text() checks that every line of such output ends so.
"""
import os
import sys

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = os.environ.get("DRDC_BUILD", os.path.join(TOP, "build"))
TARGET = os.environ.get("DRDC_TARGET", "host")

if TARGET == "host":
    COMMAND = [os.path.join(BUILD, "host", "drdc")]
    NEWLINE = b"\n"
elif TARGET == "win64":
    COMMAND = [sys.executable, os.path.join(TOP, "qemu", "wine.py"),
               os.path.join(BUILD, "win64", "drdc.exe")]
    NEWLINE = b"\r\n"
else:
    raise SystemExit("DRDC_TARGET: %r is neither host nor win64" % TARGET)


def lf_text(out):
    """The bytes of drdc's standard output with LF line ends; raises
    AssertionError where a line does not end in NEWLINE."""
    if NEWLINE == b"\n":
        return out
    if out.count(b"\n") != out.count(NEWLINE):
        raise AssertionError("a line of %s does not end in CR LF: %r"
                             % (TARGET, out[:200]))
    return out.replace(NEWLINE, b"\n")
