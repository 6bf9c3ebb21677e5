# SPDX-License-Identifier: BSD-2-Clause
"""The C++ layer, cxx/include/drdc/drdc.hpp, beyond its Unity suite (./waf check).

The Unity suite (tests/cxx, fw/cxx-runner) runs with every other image
under qemu/harness.py. Checked here, with the compilers configure found
for each target of CXX_TARGETS (build/c4che/<target>_cache.py):
- the C++ demo (fw/demo-cxx) prints exactly what the C demo (fw/demo)
  prints, on the host with g++ and clang++, under ASan and UBSan, and
  on Cortex-M3, M0 and RISC-V rv32 under QEMU (the C demo itself is checked against
  independent references by tests/integration/test_demo.py);
- the wrapper's quaternion product costs at most 5 % more instructions
  per call than the C call drdc_quat_mul() (fw/bench-cxx under QEMU
  -icount on Cortex-M3);
- literals are compile-time only: a literal beyond its type, with an
  exponent or hexadecimal does not compile; no C++ object of a bare-metal
  target calls a soft-float helper;
- value_or_throw() exists only with exceptions: with -fno-exceptions a
  program that calls it does not compile;
- the README's C++ example is examples/cxx/pose.cpp, warning-free with
  each host compiler, and prints UTC, GPS time, the quaternion, UTM and
  MGRS equal to the host tool drdc.
"""
import ast
import glob
import os
import re
import subprocess
import tempfile
import unittest

from qemu import harness
from tools.gates import bench

BUILD = os.environ.get("DRDC_BUILD", "build")
TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DRDC = os.path.join(BUILD, "host", "drdc")
WARNINGS = ["-std=c++17", "-Wall", "-Wextra", "-pedantic", "-Werror"]
INCLUDES = ["-I" + os.path.join(TOP, d, "include")
            for d in ("cxx", "core", "fixed")]
# the Cortex-M3 slack over the C call, instructions per call
BENCH_LIMIT = 1.05


def configured(target):
    """The variables configure stored for a target."""
    env = {}
    with open(os.path.join(BUILD, "c4che", target + "_cache.py")) as f:
        for line in f:
            name, sep, value = line.partition(" = ")
            if sep:
                env[name.strip()] = ast.literal_eval(value.strip())
    return env


def host_compilers():
    """(name, command) of each host C++ compiler, g++ first."""
    env = configured("host")
    return [("g++", env["CXX"])] + [(name, env[var])
                                    for name, var in env["CXX_OTHERS"]]


def console(profile, image):
    data, status, killed = harness.boot(profile, image, 10, 60, 1 << 20)
    assert not killed, killed
    assert status == 0, (image, status)
    return data.decode("ascii").replace("\r", "")


def tool(*args, stdin):
    return subprocess.run([DRDC] + list(args), input=stdin, check=True,
                          capture_output=True, text=True).stdout.split("\n")


class Compilers(unittest.TestCase):
    def test_every_host_compiler_was_found(self):
        # configure skips a missing one (a tree for the host alone);
        # ./waf check configures every target and needs them all
        self.assertEqual(["g++", "clang++"],
                         [name for name, _ in host_compilers()])


def cxx_targets():
    """The targets configure set up a C++ compiler for (CXX_TARGETS)."""
    names = []
    for path in sorted(os.listdir(os.path.join(BUILD, "c4che"))):
        if not path.endswith("_cache.py"):
            continue
        target = path[:-len("_cache.py")]
        if target and "CXX" in configured(target):
            names.append(target)
    return names


class Demo(unittest.TestCase):
    def test_cxx_demo_prints_what_the_c_demo_prints(self):
        targets = cxx_targets()
        self.assertTrue({"host", "arm-cm3"} <= set(targets), targets)
        for target in targets:
            env = configured(target)
            profile, ext = env["CXX_QEMU"], env["CXX_EXT"]
            names = ["demo-cxx"] + ["demo-cxx-" + n
                                    for n, _ in env.get("CXX_OTHERS", [])]
            c = console(profile, os.path.join(BUILD, target, "fw", "demo",
                                              "demo" + ext))
            self.assertIn("epoch 4", c)
            for name in names:
                cxx = console(profile, os.path.join(BUILD, target, "fw",
                                                    "demo-cxx", name + ext))
                self.assertEqual(c, cxx, "%s %s" % (target, name))


class Bench(unittest.TestCase):
    def test_wrapper_product_within_5_percent_of_the_c_call(self):
        image = os.path.join(BUILD, "arm-cm3", "fw", "bench-cxx",
                             "bench-cxx.elf")
        cases, _, _ = bench.run_target(BUILD, "arm-cm3", image=image)
        c = cases[("drdc", "quat_mul")]["instructions"]
        cxx = cases[("cxx", "quat_mul")]["instructions"]
        print("\ncxx: quat_mul on Cortex-M3: C call %.1f, drdc::Quat * %.1f "
              "instructions per call (%+.1f %%)" % (c, cxx, 100 * (cxx / c - 1)))
        self.assertGreater(c, 50)  # the product itself was timed
        self.assertLessEqual(cxx, c * BENCH_LIMIT)


def compile_snippet(compiler, body, extra=()):
    """Compile a program that includes drdc.hpp; the compiler's result."""
    with tempfile.TemporaryDirectory() as tmp:
        src = os.path.join(tmp, "snippet.cpp")
        with open(src, "w") as f:
            f.write("#include <drdc/drdc.hpp>\nusing namespace drdc::literals;\n"
                    "int main()\n{\n%s\n  return 0;\n}\n" % body)
        return subprocess.run(compiler + WARNINGS + INCLUDES + list(extra)
                              + ["-fsyntax-only", src],
                              capture_output=True, text=True)


class CompileTime(unittest.TestCase):
    BAD_LITERALS = {
        "drdc::LocalLength x = 32768_m; (void)x;": "range of Q15.16",
        "drdc::LocalLength x = -32768.00001_m; (void)x;": "range of Q15.16",
        "drdc::Length x = 1e3_m; (void)x;": "no exponent",
        "drdc::Angle a = 0x10_deg; (void)a;": "no exponent",
        "drdc::Angle a = 12345678901234567890_deg; (void)a;": "19 digits",
        "drdc::GeoAngle a = 9999999_deg; (void)a;": "range of drdc_nas_t",
        "drdc::LocalLength x = 010_m; (void)x;": "octal",
        "drdc::Angle a = 0'7.5_deg; (void)a;": "octal",
    }

    def test_bad_literals_do_not_compile(self):
        for name, compiler in host_compilers():
            ok = compile_snippet(compiler, "  drdc::LocalLength x = -32768_m;"
                                 " drdc::Length h = 0.5_m;"
                                 " drdc::Length z = 0_m;"
                                 " (void)x; (void)h; (void)z;")
            self.assertEqual(0, ok.returncode, ok.stderr)
            for body, message in self.BAD_LITERALS.items():
                r = compile_snippet(compiler, "  " + body)
                self.assertNotEqual(0, r.returncode, "%s: %s" % (name, body))
                self.assertIn(message, r.stderr, "%s: %s" % (name, body))

    def test_the_example_of_drdc_hpp_compiles(self):
        with open(os.path.join(TOP, "cxx", "include", "drdc", "drdc.hpp")) as f:
            head = f.read().split("@file", 1)[1].split("*/", 1)[0]
        body = "\n".join(l[len(" *   "):] for l in head.splitlines()
                         if l.startswith(" *     "))
        self.assertIn("drdc::to_quat", body)
        for name, compiler in host_compilers():
            r = compile_snippet(compiler, body)
            self.assertEqual(0, r.returncode, "%s: %s" % (name, r.stderr))

    def test_units_do_not_mix(self):
        for name, compiler in host_compilers():
            for body in ("drdc::Angle a = 1.5_m; (void)a;",
                         "drdc::Length l = 1.5_deg; (void)l;",
                         "drdc::GeoAngle g = 50; (void)g;",
                         "drdc::Length l = 754; (void)l;",
                         "drdc::Angle a = 1.5; (void)a;"):
                r = compile_snippet(compiler, "  " + body)
                self.assertNotEqual(0, r.returncode, "%s: %s" % (name, body))
            ok = compile_snippet(compiler, "  drdc::Angle a = 90_deg;"
                                 " drdc::GeoAngle g = -90_deg;"
                                 " drdc::Length l = -1.5_m;"
                                 " (void)a; (void)g; (void)l;")
            self.assertEqual(0, ok.returncode, ok.stderr)

    def test_value_or_throw_needs_exceptions(self):
        body = "  (void)drdc::Quat().normalized().value_or_throw();"
        for name, compiler in host_compilers():
            self.assertEqual(0, compile_snippet(compiler, body).returncode)
            r = compile_snippet(compiler, body, ["-fno-exceptions"])
            self.assertNotEqual(0, r.returncode, name)
            self.assertIn("value_or_throw", r.stderr, name)

    def test_cxx_objects_call_no_floating_point_helper(self):
        # libgcc's soft-float routines (__adddf3, __floatsidf, __fixdfsi,
        # __aeabi_dadd, __aeabi_f2d, ...): what float or double in the
        # C++ code, literals included, would call on these FPU-less cores
        helper = re.compile(r"^__(aeabi_[df]\w+|(add|sub|mul|div|neg)[sdt]f3"
                            r"|(eq|ne|lt|le|gt|ge|unord|cmp)[sdt]f2"
                            r"|float\w*[sdt]f|fix(uns)?[sdt]f\w+"
                            r"|extend\w+|trunc[sdt]f\w+)$")
        bare_metal = [t for t in cxx_targets() if configured(t)["CXX_EXT"]]
        self.assertIn("arm-cm3", bare_metal)
        for target in bare_metal:
            nm = configured(target)["NM"]
            objects = [o for d in ("cxx-runner", "demo-cxx", "bench-cxx")
                       for o in glob.glob(os.path.join(BUILD, target, "fw",
                                                       d, "*.cpp.*.o"))]
            self.assertGreaterEqual(len(objects), 2, target)
            for obj in objects:
                undefined = subprocess.run(nm + ["-u", obj], check=True,
                                           capture_output=True,
                                           text=True).stdout.split()
                calls = {u for u in undefined if helper.match(u)}
                self.assertEqual(set(), calls, obj)
            # the check bites: a double product in the same compile calls
            # one
            env = configured(target)
            with tempfile.TemporaryDirectory() as tmp:
                # unoptimised too: the literals are constants by the
                # language, not by the optimiser's folding
                demo = os.path.join(tmp, "demo-O0.o")
                subprocess.run(env["CXX"] + env["ARCH"] + INCLUDES
                               + ["-I" + os.path.join(TOP, "bsp"), "-O0",
                                  "-std=c++17", "-fno-exceptions", "-fno-rtti",
                                  "-c", os.path.join(TOP, "fw", "demo-cxx",
                                                     "main.cpp"), "-o", demo],
                               check=True)
                undefined = subprocess.run(nm + ["-u", demo], check=True,
                                           capture_output=True,
                                           text=True).stdout.split()
                self.assertEqual(set(), {u for u in undefined
                                         if helper.match(u)}, target)
                bait = os.path.join(tmp, "bait.cpp")
                with open(bait, "w") as f:
                    f.write("double bait(double a, int b) { return a * b; }\n")
                subprocess.run(env["CXX"] + env["ARCH"] + ["-O2", "-c", bait,
                                                           "-o", bait + ".o"],
                               check=True)
                undefined = subprocess.run(nm + ["-u", bait + ".o"],
                                           check=True, capture_output=True,
                                           text=True).stdout.split()
            self.assertTrue({u for u in undefined if helper.match(u)},
                            "%s: %s" % (target, undefined))

def readme_example():
    """The C++ block of README.md's "From C++" section."""
    with open(os.path.join(TOP, "README.md")) as f:
        text = f.read()
    section = text.split("\n## From C++\n", 1)[1].split("\n## ", 1)[0]
    return section.split("```cpp\n", 1)[1].split("```\n", 1)[0]


class Example(unittest.TestCase):
    def test_readme_shows_the_example_file(self):
        with open(os.path.join(TOP, "examples", "cxx", "pose.cpp")) as f:
            self.assertEqual(f.read(), readme_example())

    def test_example_prints_what_the_host_tool_computes(self):
        lib = os.path.join(BUILD, "host", "libdrdc.a")
        src = os.path.join(TOP, "examples", "cxx", "pose.cpp")
        for name, compiler in host_compilers():
            with tempfile.TemporaryDirectory() as tmp:
                exe = os.path.join(tmp, "pose")
                subprocess.run(compiler + WARNINGS + INCLUDES
                               + [src, lib, "-o", exe], check=True)
                out = subprocess.run([exe], check=True, capture_output=True,
                                     text=True).stdout
            lines = dict(l.split(" ", 1) for l in out.splitlines())
            utc = lines["UTC"]
            self.assertEqual("2026-11-22T17:00:00.000000000Z", utc, name)
            week, tow = tool("time", "--from", "utc", "--to", "gps",
                             stdin=utc + "\n")[0].split()
            self.assertEqual("week %s tow %s" % (week, tow), lines["GPS"])
            quat = tool("attitude", "--from", "euler", "--to", "quat",
                        stdin="46.5 2.2 -0.8\n")[0].split()
            got = lines["q"].strip("[]").split()
            for g, w in zip(got, quat):
                # 9 decimals of the same Q1.30 value the tool prints with 10
                self.assertLessEqual(abs(float(g) - float(w)), 0.6e-9, name)
            self.assertEqual(4, len(got))
            self.assertEqual(tool("geo", "-u", "-p", "3",
                                  stdin="50.27 -111.17\n")[0],
                             lines["UTM"])
            self.assertEqual(tool("geo", "-m", "-p", "0",
                                  stdin="50.27 -111.17\n")[0],
                             lines["MGRS"])
            self.assertIn("10 m ahead", out)


if __name__ == "__main__":
    unittest.main()
