# SPDX-License-Identifier: BSD-2-Clause
"""waf tool: the conformance digest's own programs (tests/golden), for the
variant being built.

- A target with golden_parts (AVR): fw/golden-part/<part>.elf, one image
  per part of the digest, for a board whose memory holds one module's
  tables at a time (avr-gcc copies the const tables not marked
  DRDC_FLASH_TABLE into RAM).
- host: fw/golden-trace/golden-trace, the reference records of the digest
  (it writes tests/golden/golden_expected.c), and
  fw/test-runner/test-runner-broken, a port with drdc_geo_to_utm one LSB
  off (GOLDEN_BREAK_TO_UTM) whose log python/tests/test_conformance.py
  judges.
"""
from waftools import images
from waftools.targets import role

# The parts of the digest: function, its file, the name the runner prints.
GOLDEN_PARTS = [
    ("golden_time", "golden_time.c", "time"),
    ("golden_time_scales", "golden_time.c", "time scales"),
    ("golden_fixed", "golden_fixed.c", "fixed"),
    ("golden_orient", "golden_orient.c", "orient"),
    ("golden_interop", "golden_interop.c", "interop"),
    ("golden_geo", "golden_geo.c", "geo"),
    ("golden_poses", "golden_poses.c", "poses and JAUS bodies"),
]


def build(bld):
    if role(bld.variant, "golden_parts"):
        parts(bld)
    if bld.variant == "host":
        trace(bld)


def parts(bld):
    for k, (part, source, name) in enumerate(GOLDEN_PARTS):
        images.image(bld, "fw/golden-part/" + part,
                     ["fw/golden-part/main.c", "tests/golden/golden.c",
                      "tests/golden/" + source],
                     "libdrdc bsp", idx=200 + k, includes=["tests/golden"],
                     # no trace labels: their strings would take RAM
                     defines=["GOLDEN_PART=" + part, 'GOLDEN_NAME="%s"' % name,
                              "GOLDEN_TRACE=0"])


def trace(bld):
    parts_ = [n for n in images.glob(bld, "tests/golden/golden*.c")
              if n.name != "golden_expected.c"]
    bld.program(source=["fw/golden-trace/main.c"] + parts_,
                target="fw/golden-trace/golden-trace", use="libdrdc",
                cflags=images.ours(bld.env), includes=["tests/golden"],
                install_path=None, idx=400)
    images.image(bld, "fw/test-runner/test-runner-broken",
                 [bld.path.find_node("tests/golden/golden_geo.c")],
                 "runner-suites libdrdc unity bsp", includes=["tests"],
                 idx=401, defines=["GOLDEN_BREAK_TO_UTM=1"])
