# SPDX-License-Identifier: BSD-2-Clause
"""The library in a firmware team's own CMake project (./waf check):

- CMakeLists.txt builds the same objects as waf (the host's libdrdc.a);
- examples/cortex-m, the example firmware, with CMake and its toolchain
  file: a Cortex-M4F build through find_package() of an install of the
  table's targets and through add_subdirectory() of the source tree; a
  softfp and a Cortex-M7 build through find_package() of custom variants
  (./waf configure --variant); each runs under QEMU and prints exactly
  what the host's example prints;
- a variant whose ABI does not fit stops CMake's configure with a
  message naming both ABIs.
The installs are made here, the table's targets from the main build and
the custom variants by a waf build of their own (its own lock file).
"""
import collections
import glob
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

from qemu import harness

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = os.path.join(TOP, "build")
EXAMPLE = os.path.join(TOP, "examples", "cortex-m")
TOOLCHAIN = os.path.join(EXAMPLE, "arm-none-eabi.cmake")
M4F = "-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16"
M4_SOFTFP = "-mcpu=cortex-m4 -mthumb -mfloat-abi=softfp -mfpu=fpv4-sp-d16"
M7 = "-mcpu=cortex-m7 -mthumb -mfloat-abi=hard -mfpu=fpv5-d16"


class Installs:
    tmp = None
    table = None     # prefix of host, arm-cm3, arm-cm4f
    custom = None    # prefix of the custom variants m7 and m4-softfp


def run(cmd, **kw):
    r = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        raise AssertionError("%s failed:\n%s%s" % (" ".join(cmd), r.stdout,
                                                   r.stderr))
    return r.stdout


def setUpModule():
    Installs.tmp = tempfile.mkdtemp(prefix="drdc-cmake-")
    waf = [sys.executable, os.path.join(TOP, "waf")]
    Installs.table = os.path.join(Installs.tmp, "table")
    run(waf + ["install_host", "install_arm-cm3", "install_arm-cm4f",
               "--destdir=" + Installs.table], cwd=TOP)
    Installs.table = os.path.dirname(os.path.dirname(os.path.dirname(
        glob.glob(os.path.join(Installs.table, "**", "lib", "pkgconfig",
                               "drdc-host.pc"), recursive=True)[0])))
    Installs.custom = os.path.join(Installs.tmp, "custom")
    env = dict(os.environ, WAFLOCK=".lock-waf-cmake-test")
    env.pop("CC", None)
    env.pop("CFLAGS", None)
    run(waf + ["configure", "--out=" + os.path.join(Installs.tmp, "build"),
               "--prefix=" + Installs.custom, "--with-targets=arm-cm4f",
               "--variant", "m7=arm-cm4f:" + M7,
               "--variant", "m4-softfp=arm-cm4f:" + M4_SOFTFP], cwd=TOP,
        env=env)
    run(waf + ["install_m7", "install_m4-softfp"], cwd=TOP, env=env)


def tearDownModule():
    shutil.rmtree(Installs.tmp, ignore_errors=True)
    lock = os.path.join(TOP, ".lock-waf-cmake-test")
    if os.path.exists(lock):
        os.remove(lock)


def host_text():
    exe = os.path.join(Installs.tmp, "example-host")
    run(["make", "-s", "-C", Installs.tmp, "-f",
         os.path.join(TOP, "examples", "host", "Makefile"),
         "PREFIX=" + Installs.table, "OUT=" + exe])
    return run([exe])


def configure(name, flags, *defines):
    """cmake's configure of examples/cortex-m for the core of flags: its
    build folder, or the CompletedProcess where it failed."""
    build = os.path.join(Installs.tmp, name)
    r = subprocess.run(["cmake", "-S", EXAMPLE, "-B", build,
                        "-DCMAKE_TOOLCHAIN_FILE=" + TOOLCHAIN,
                        "-DCMAKE_BUILD_TYPE=Release",
                        "-DCORTEX_M_FLAGS=" + flags] + list(defines),
                       capture_output=True, text=True)
    return build if r.returncode == 0 else r


class CMake(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.host = host_text()

    def firmware(self, name, flags, machine, *defines):
        build = configure(name, flags, *defines)
        self.assertIsInstance(build, str, getattr(build, "stderr", ""))
        run(["cmake", "--build", build, "-j", "2"])
        image = os.path.join(build, "example.elf")
        data, status, killed = harness.boot(machine, image, 10, 60, 1 << 16)
        self.assertIsNone(killed)
        self.assertEqual(0, status)
        self.assertEqual(self.host, data.decode("ascii"))
        return build

    def test_cmake_builds_the_objects_waf_builds(self):
        build = os.path.join(Installs.tmp, "host-lib")
        run(["cmake", "-S", TOP, "-B", build, "-DCMAKE_BUILD_TYPE=Release"])
        run(["cmake", "--build", build, "-j", "2"])
        made = collections.Counter(
            os.path.basename(p)[:-len(".o")] for p in glob.glob(
                os.path.join(build, "CMakeFiles", "drdc.dir", "**", "*.c.o"),
                recursive=True))
        members = run(["ar", "t", os.path.join(BUILD, "host", "libdrdc.a")])
        waf = collections.Counter(m[:-len(".1.o")] for m in members.split())
        self.assertEqual(waf, made)

    def test_cortex_m4f_through_find_package(self):
        self.firmware("m4f-installed", M4F, "arm-cm4f",
                      "-DCMAKE_PREFIX_PATH=" + Installs.table)

    def test_cortex_m4f_through_add_subdirectory(self):
        self.firmware("m4f-source", M4F, "arm-cm4f", "-DDRDC_SOURCE_DIR=" + TOP)

    def test_custom_softfp_variant(self):
        self.firmware("m4-softfp", M4_SOFTFP, "arm-cm4f",
                      "-DCMAKE_PREFIX_PATH=" + Installs.custom)

    def test_custom_cortex_m7_variant(self):
        self.firmware("m7", M7, "arm-cm7",
                      "-DCMAKE_PREFIX_PATH=" + Installs.custom)

    def test_a_variant_of_another_abi_stops_configure(self):
        r = configure("mismatch", M4_SOFTFP,
                      "-DCMAKE_PREFIX_PATH=" + Installs.table,
                      "-DDRDC_VARIANT=arm-cm4f")
        self.assertNotIsInstance(r, str)
        text = " ".join(r.stderr.split())
        self.assertIn("variant arm-cm4f was built for Arm v7-M Thumb-2, "
                      "hard-float ABI", text)
        self.assertIn("this project compiles for Arm v7-M Thumb-2, "
                      "soft-float ABI", text)


if __name__ == "__main__":
    unittest.main()
