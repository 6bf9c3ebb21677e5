# SPDX-License-Identifier: BSD-2-Clause
"""The installed tree, as a firmware team gets it: './waf install' of every
configured target into one prefix (under a scratch DESTDIR), each target
in its own lib/<target>/ with its own lib/pkgconfig/drdc-<target>.pc, so
that none overwrites another; a program outside the tree built from that
prefix alone with pkg-config, whose results equal the drdc tool's; and
the examples/ of every firmware target, built by their Makefiles from the
prefix and run under QEMU.
Run by ./waf check after every target is built.
"""
import glob
import os
import shutil
import subprocess
import sys
import tempfile
import unittest
from fractions import Fraction

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from waftools.targets import TARGETS as ALL_TARGETS
from waftools.targets import with_role

# The targets ./waf install installs (a row with its ABI flags; the test
# builds are left out).
TARGETS = [n for n, t in ALL_TARGETS.items() if t.get("abi") is not None]

# LAT LON in degrees: Baghdad, Sydney, Norway's zone 32, DRDC Suffield
POINTS = [("33.3", "44.4"), ("-33.9", "151.2"), ("60.5", "5.3"),
          ("50.27", "-111.17")]
NAS_PER_DEGREE = 3600000000000


class Prefix:
    """The scratch DESTDIR that ./waf install filled, one for the module."""
    destdir = None
    prefix = None


def setUpModule():
    # each target by name: a tree configured with --rtems installs its BSPs
    # on a bare './waf install'
    Prefix.destdir = tempfile.mkdtemp(prefix="drdc-install-")
    r = subprocess.run([sys.executable, os.path.join(TOP, "waf")]
                       + ["install_" + t for t in TARGETS]
                       + ["--destdir=" + Prefix.destdir],
                       cwd=TOP, capture_output=True, text=True)
    if r.returncode != 0:
        raise AssertionError("./waf install failed:\n" + r.stdout + r.stderr)
    # the configured --prefix, wherever it is, under the destdir
    pcs = glob.glob(os.path.join(Prefix.destdir, "**", "lib", "pkgconfig",
                                 "drdc-host.pc"), recursive=True)
    if len(pcs) != 1:
        raise AssertionError("no single drdc-host.pc under %s: %s"
                             % (Prefix.destdir, pcs))
    Prefix.prefix = os.path.dirname(os.path.dirname(os.path.dirname(pcs[0])))


def pkg_config(target, *what):
    """pkg-config of drdc-<target> in the installed prefix, as words, its
    -I and -L folders normalised. The tree sits under the destdir, not
    where configure's --prefix says: the .pc files must find it from
    their own place."""
    env = dict(os.environ, PKG_CONFIG_PATH=os.path.join(
        Prefix.prefix, "lib", "pkgconfig"))
    words = subprocess.run(["pkg-config", "drdc-" + target] + list(what),
                           env=env, check=True, capture_output=True,
                           text=True).stdout.split()
    return [w[:2] + os.path.normpath(w[2:]) if w[:2] in ("-I", "-L") else w
            for w in words]


def tearDownModule():
    shutil.rmtree(Prefix.destdir, ignore_errors=True)


class InstalledTree(unittest.TestCase):
    def setUp(self):
        self.destdir = Prefix.destdir
        self.prefix = Prefix.prefix

    def test_every_target_has_its_own_library_and_pc(self):
        for target in TARGETS:
            t = ALL_TARGETS[target]
            abi = t["abi"]
            lib = os.path.join(self.prefix, "lib", target, "libdrdc.a")
            self.assertTrue(os.path.exists(lib), lib)
            out = subprocess.run([t["cross"] + "objdump", "-f", lib],
                                 check=True, capture_output=True,
                                 text=True).stdout
            self.assertIn("file format " + t["object_format"], out)
            # the include folder alone: the library's ABI flags are not
            # imposed on the user's code, they are a variable to read
            self.assertEqual(["-I" + os.path.join(self.prefix, "include")],
                             pkg_config(target, "--cflags"), target)
            self.assertEqual(abi, pkg_config(target,
                                             "--variable=abi_cflags"), target)
            libs = pkg_config(target, "--libs")
            self.assertEqual(["-L" + os.path.dirname(lib), "-ldrdc"],
                             libs[:2], target)
            for flag in abi:
                self.assertNotIn(flag, libs, target)
            if "arm_arch" in t:
                attrs = subprocess.run(["arm-none-eabi-readelf", "-A", lib],
                                       check=True, capture_output=True,
                                       text=True).stdout
                archs = {l.split(":", 1)[1].strip() for l in attrs.splitlines()
                         if l.strip().startswith("Tag_CPU_arch:")}
                self.assertEqual({t["arm_arch"]}, archs, target)
        # freestanding PowerPC links libgcc for 64-bit division
        self.assertIn("-lgcc", pkg_config("ppc-e500", "--libs"))

    def test_headers_and_the_documents_they_cite(self):
        headers = sorted(os.path.basename(h) for pattern in
                         ("fixed/include/drdc/*.h", "core/include/drdc/*.h")
                         for h in glob.glob(os.path.join(TOP, pattern)))
        installed = sorted(h for h in os.listdir(os.path.join(
            self.prefix, "include", "drdc")) if h.endswith(".h"))
        self.assertEqual(headers, installed)
        docs = os.path.join(self.prefix, "share", "doc", "drdc")
        for h in headers:
            for d in ("fixed", "core"):
                path = os.path.join(TOP, d, "include", "drdc", h)
                if not os.path.exists(path):
                    continue
                with open(path) as f:
                    text = f.read()
                for word in text.replace("(", " ").replace(")", " ").split():
                    if word.startswith("docs/") and word.rstrip(".,;:") \
                            .endswith(".md"):
                        cited = os.path.join(docs, word.rstrip(".,;:"))
                        self.assertTrue(os.path.exists(cited),
                                        "%s cites %s" % (h, word))

    def test_the_cxx_headers_with_the_c_headers(self):
        headers = sorted(os.path.basename(h) for h in
                         glob.glob(os.path.join(TOP, "cxx/include/drdc/*.hpp")))
        installed = sorted(h for h in os.listdir(os.path.join(
            self.prefix, "include", "drdc")) if h.endswith(".hpp"))
        self.assertEqual(["drdc.hpp", "drdc_ostream.hpp"], headers)
        self.assertEqual(headers, installed)

    def test_a_cxx_program_outside_the_tree(self):
        """examples/cxx/pose.cpp from the prefix alone (tests/integration/test_cxx.py
        checks what it prints)."""
        exe = os.path.join(self.destdir, "client-cxx")
        subprocess.run(["g++", "-std=c++17", "-Wall", "-Wextra", "-Werror",
                        "-pedantic",
                        os.path.join(TOP, "examples", "cxx", "pose.cpp"),
                        "-o", exe] + pkg_config("host", "--cflags", "--libs"),
                       check=True)
        out = subprocess.run([exe], check=True, capture_output=True,
                             text=True).stdout
        mgrs = subprocess.run([os.path.join(self.prefix, "bin", "drdc"), "geo",
                               "-m", "-p", "0"], input="50.27 -111.17\n",
                              check=True, capture_output=True,
                              text=True).stdout
        self.assertIn("MGRS " + mgrs, out)

    def test_a_program_outside_the_tree_equals_the_drdc_tool(self):
        exe = os.path.join(self.destdir, "client")
        subprocess.run(["gcc", "-std=c99", "-Wall", "-Werror",
                        os.path.join(TOP, "tests", "install", "client.c"),
                        "-o", exe] + pkg_config("host", "--cflags", "--libs"),
                       check=True)
        nas = "".join("%d %d\n" % tuple(Fraction(x) * NAS_PER_DEGREE
                                        for x in p) for p in POINTS)
        got = subprocess.run([exe], input=nas, check=True,
                             capture_output=True, text=True).stdout.splitlines()
        tool = os.path.join(self.prefix, "bin", "drdc")
        deg = "".join("%s %s\n" % p for p in POINTS)
        want = subprocess.run([tool, "geo", "-u", "-p", "3"], input=deg,
                              check=True, capture_output=True,
                              text=True).stdout.splitlines()
        for g, w in zip(got, want):
            zone, east, north = w.split()
            self.assertEqual("%s %s %s" % (zone, east.replace(".", ""),
                                           north.replace(".", "")), g)
        self.assertEqual(len(POINTS), len(got))
        self.assertEqual(len(POINTS), len(want))


# Each firmware target of examples/: its folder and the machine that runs
# it (its row's "examples").
EXAMPLES = {n: ALL_TARGETS[n]["examples"] for n in with_role("examples")}


class Examples(unittest.TestCase):
    """examples/: built with make from the installed prefix alone (the
    module's tree), run on the host and under QEMU; every
    firmware prints exactly the host's text, whose values equal the drdc
    tool's."""

    def setUp(self):
        self.destdir = Prefix.destdir
        self.prefix = Prefix.prefix

    def make(self, folder, out, *args):
        subprocess.run(["make", "-s", "-C", self.destdir, "-f",
                        os.path.join(TOP, "examples", folder, "Makefile"),
                        "PREFIX=" + self.prefix, "OUT=" + out] + list(args),
                       check=True)

    def host_text(self):
        exe = os.path.join(self.destdir, "example-host")
        self.make("host", exe)
        return subprocess.run([exe], check=True, capture_output=True,
                              text=True).stdout

    def test_host_example_equals_the_drdc_tool(self):
        lines = dict(l.split(" ", 1) for l in self.host_text().splitlines())
        tool = os.path.join(self.prefix, "bin", "drdc")

        def drdc(stdin, *args):
            return subprocess.run([tool] + list(args), input=stdin,
                                  check=True, capture_output=True,
                                  text=True).stdout.strip()
        # the sentence's position, 5016.20000 N 11110.20000 W, in degrees
        self.assertEqual(drdc("50.27 -111.17\n", "geo", "-u", "-p", "3"),
                         lines["UTM"])
        self.assertEqual(drdc("50.27 -111.17\n", "geo", "-m", "-p", "0"),
                         lines["MGRS"])
        week, tow = drdc(lines["UTC"] + "\n", "time", "--from", "utc",
                         "--to", "gps").split()
        self.assertEqual("%s %s" % (week, tow.split(".")[0]), lines["GPS"])

    def test_windows_example_prints_the_hosts_text(self):
        """The README's "On Windows": examples/host built by mingw-w64
        from the installed win64 library, run under Wine; its lines end
        in CR LF, as Windows's text mode writes them."""
        sys.path.insert(0, TOP)
        from qemu import harness
        want = self.host_text()
        exe = os.path.join(self.destdir, "example-win64.exe")
        self.make("host", exe, "TARGET=win64",
                  "CC=x86_64-w64-mingw32-gcc-win32")
        data, status, killed = harness.boot("wine64", exe, 10, 60, 1 << 16)
        self.assertIsNone(killed)
        self.assertEqual(0, status)
        self.assertEqual(want.count("\n"), data.count(b"\r\n"))
        self.assertEqual(want, data.decode("ascii").replace("\r\n", "\n"))

    def test_cortex_m0_linked_in_steps_is_thumb1_throughout(self):
        """Compile with the ABI variable and --cflags, link with the ABI
        variable and --libs: every input of the image, libgcc's 64-bit
        division included, must be armv6-m."""
        here = os.path.join(TOP, "examples")
        objects = []
        for src in ("common/pose_report.c", "cortex-m/platform.c"):
            obj = os.path.join(self.destdir, os.path.basename(src) + ".o")
            subprocess.run(["arm-none-eabi-gcc", "-std=c99", "-O2", "-c",
                            "-I" + os.path.join(here, "common")]
                           + pkg_config("arm-cm0", "--variable=abi_cflags")
                           + pkg_config("arm-cm0", "--cflags")
                           + [os.path.join(here, src), "-o", obj], check=True)
            objects.append(obj)
        image = os.path.join(self.destdir, "steps-arm-cm0.elf")
        subprocess.run(["arm-none-eabi-gcc", "-nostartfiles",
                        "--specs=nano.specs", "--specs=nosys.specs",
                        "-Wl,--gc-sections", "-T",
                        os.path.join(here, "cortex-m", "link.ld")] + objects
                       + pkg_config("arm-cm0", "--variable=abi_cflags")
                       + pkg_config("arm-cm0", "--libs") + ["-o", image],
                       check=True)
        attrs = subprocess.run(["arm-none-eabi-readelf", "-A", image],
                               check=True, capture_output=True,
                               text=True).stdout
        self.assertIn("Tag_CPU_arch: v6S-M", attrs)
        self.assertNotIn("Tag_ARM_ISA_use: Yes", attrs)

    def test_firmware_examples_print_the_hosts_text(self):
        sys.path.insert(0, TOP)
        from qemu import harness
        want = self.host_text()
        for target, (folder, profile) in EXAMPLES.items():
            image = os.path.join(self.destdir, "example-%s.elf" % target)
            self.make(folder, image, "TARGET=" + target)
            data, status, killed = harness.boot(profile, image, 10, 60,
                                                1 << 16)
            got = data.decode("ascii", "replace").replace("\r", "")
            self.assertIsNone(killed, target)
            self.assertIn(status, (0, None), target)
            self.assertEqual(want, got, target)


if __name__ == "__main__":
    unittest.main()
