# SPDX-License-Identifier: BSD-2-Clause
"""waf tool: what ./waf check runs after building every target, one table
of steps (title, Python arguments, extra environment) run in order by one
runner; the first failing step stops the check. README's list of the
steps ("What ./waf check runs") follows this table, item for item
(tests/integration/test_setup.py compares them).

The last step runs the Unity test runner of every target under its
machine, and the harness's "N passed, M failed" is the check's last line.
"""
import logging
import os
import time

from waflib import Logs

from waftools import commands, cxx_layer, toolchains
from waftools.targets import TARGETS

OUT = commands.OUT


def intcheck_args(run):
    return (["tools/gates/intcheck.py", "--build", OUT, "--all"]
            + ["%s:%s:%s" % (n, t["isa"], t["cross"])
               for n, t in TARGETS.items() if t.get("isa")])


def symcheck_args(run):
    return (["tools/gates/symcheck.py", "--build", OUT]
            + ["%s:%s" % (n, t["cross"]) for n, t in TARGETS.items()])


def rtems_args(run):
    top = run.all_envs[""]
    return (["tests/integration/rtems_qemu.py"]
            + (["--prefix", top.RTEMS_PREFIX, "--tools", top.RTEMS_TOOLS]
               if top.RTEMS_PREFIX else []))


def unity_args(run):
    """The harness over every target's test runner, the C++ layer's
    runners, the runner linked against the RTEMS stand-in's installed
    library and, when it was built, the RTEMS 6 application."""
    images = ["%s=%s:%s" % (n, t["machine"], os.path.join(
        OUT, n, "fw/test-runner/test-runner" + t["ext"]))
        for n, t in TARGETS.items() if t.get("images", True)]
    images += cxx_layer.runner_images(run.all_envs, OUT)
    images.append("rtems-standin=ppc-e500:" + os.path.join(
        OUT, "rtems-standin", "test-runner.elf"))
    real = os.path.join(OUT, "rtems-real", "image.txt")
    if os.path.exists(real):
        with open(real) as f:
            images.append("rtems=rtems-qoriq_e500:" + f.read().strip())
    # what the results were computed with, in the summary
    note = toolchains.summary([run.all_envs[n]
                               for n in run.all_envs[""].TARGETS])
    return (["qemu/harness.py", "run", "--junit-dir",
             os.path.join(OUT, "reports"), "--note", note] + images)


def unit_tests(*modules):
    return ["-m", "unittest", "-q"] + list(modules)


def files(args):
    """The project's files a step runs: its scripts and its unittest
    modules as paths."""
    if callable(args):
        return list(args.runs)
    found = [a for a in args if a.endswith(".py")]
    found += [m.replace(".", "/") + ".py" for m in args
              if m.startswith(("tests.", "qemu."))]
    return found


intcheck_args.runs = ("tools/gates/intcheck.py",)
symcheck_args.runs = ("tools/gates/symcheck.py",)
rtems_args.runs = ("tests/integration/rtems_qemu.py",)
unity_args.runs = ("qemu/harness.py",)

# (title, Python arguments or a function of the run context that returns
# them, extra environment)
STEPS = [
    ("set-up: no Debian version pin, README's tables true",
     unit_tests("tests.integration.test_setup"), {}),
    ("library tables and reference vectors regenerate identically",
     ["tools/generate.py", "--check"], {}),
    ("integer-only check of core/ and fixed/", intcheck_args, {}),
    ("C sources laid out as .clang-format says",
     ["tools/gates/formatcheck.py"], {}),
    ("every external name of libdrdc.a starts with drdc_", symcheck_args, {}),
    ("API reference: Doxygen without a warning",
     ["tools/gates/doxygen.py"], {}),
    ("bad-input catalogue docs/bad-input.md up to date",
     ["tools/gates/badinput.py", "--check"], {}),
    ("fuzz corpora replay without a finding",
     ["tools/gates/fuzz.py", "--build", OUT, "--replay"], {}),
    ("MISRA C:2012 of core/ and fixed/ (cppcheck)",
     ["tools/gates/misra.py"], {}),
    ("instructions and flash within 5 % of docs/performance.json",
     ["tools/gates/bench.py", "--build", OUT, "--check",
      "docs/performance.json"], {}),
    ("QEMU harness judges its own test images",
     unit_tests("qemu.test_harness"), {}),
    ("host tool drdc, the demo against it, the benchmark guard",
     unit_tests("tests.integration.test_drdc",
                "tests.integration.test_drdc_nmea",
                "tests.integration.test_demo", "tests.integration.test_bench"),
     {}),
    ("Python package: pip install ./python and pytest against the vectors",
     ["python/check.py", "--build", OUT], {}),
    ("drdc.exe (win64) under Wine: the tool's tests",
     unit_tests("tests.integration.test_drdc",
                "tests.integration.test_drdc_nmea"), {"DRDC_TARGET": "win64"}),
    ("C++ layer: demo equals C demo, hot path within 5 %, example",
     unit_tests("tests.integration.test_cxx"), {}),
    ("16-bit int: every digest part on an AVR under simavr",
     unit_tests("tests.integration.test_avr"), {}),
    ("installed tree: every target side by side, a client of it",
     unit_tests("tests.integration.test_install"), {}),
    ("CMake: the same objects, firmware through find_package and "
     "add_subdirectory, custom variants, an ABI mismatch refused",
     unit_tests("tests.integration.test_cmake"), {}),
    ("a new board: one row and a folder build a target that passes",
     unit_tests("tests.integration.test_new_board"), {}),
    ("RTEMS build path through a stand-in prefix",
     unit_tests("tests.integration.test_rtems"), {}),
    ("RTEMS 6 (real): configure, build, install, QEMU image",
     rtems_args, {}),
    ("Unity suites on every target", unity_args, {}),
]


class RunChecks(commands.Run):
    """(internal) run the checks and the Unity suites of every target"""
    cmd = "run_checks"
    python = True

    def run(self):
        for k, (title, args, env) in enumerate(STEPS):
            Logs.pprint("CYAN", "== " + title)
            start = time.monotonic()
            if callable(args):
                args = args(self)
            if commands.run_python(self, args, env) != 0:
                self.fatal("check failed: " + title)
            if k < len(STEPS) - 1:
                Logs.pprint("CYAN", "   (%.0f s)" % (time.monotonic() - start))
        # The harness's "N passed, M failed" stays the last line: CI reads
        # it; waf's own "finished successfully" would follow it.
        Logs.log.setLevel(logging.WARNING)
