# SPDX-License-Identifier: BSD-2-Clause
"""Tests of the RTEMS build path (waftools/rtems.py) through a stand-in
RTEMS prefix (tests/integration/rtems_standin.py). Run by ./waf check after the
ppc-e500 build; leaves build/rtems-standin/test-runner.elf for the harness.
"""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

from tests.integration import rtems_standin

TOP = rtems_standin.TOP


def configure(*args):
    """./waf configure in a scratch build directory; (status, output)."""
    scratch = tempfile.mkdtemp(prefix="drdc-rtems-")
    try:
        r = subprocess.run([sys.executable, os.path.join(TOP, "waf"), "configure",
                            "--out=" + os.path.join(scratch, "build")] + list(args),
                           cwd=TOP, env=dict(os.environ, WAFLOCK=".lock-waf-rtems-test"),
                           capture_output=True, text=True)
        return r.returncode, r.stdout + r.stderr
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
        lock = os.path.join(TOP, ".lock-waf-rtems-test")
        if os.path.exists(lock):
            os.remove(lock)


class StandInPrefix(unittest.TestCase):
    def test_configure_build_install_and_link(self):
        # exits non-zero (SystemExit) on any difference it finds
        rtems_standin.main()
        self.assertTrue(os.path.exists(os.path.join(
            TOP, "build", "rtems-standin", "test-runner.elf")))


class ConfigureMessages(unittest.TestCase):
    """Each missing piece of an RTEMS prefix gets its own message."""

    def setUp(self):
        self.prefix = tempfile.mkdtemp(prefix="drdc-rtems-prefix-")
        rtems_standin.make_prefix(self.prefix)

    def tearDown(self):
        shutil.rmtree(self.prefix, ignore_errors=True)

    def expect(self, message, *args):
        status, out = configure("--rtems=" + self.prefix, *args)
        self.assertNotEqual(0, status, out)
        self.assertIn(message, out)

    def test_missing_prefix(self):
        shutil.rmtree(self.prefix)
        self.expect("does not exist")

    def test_missing_pkgconfig(self):
        shutil.rmtree(os.path.join(self.prefix, "lib", "pkgconfig"))
        self.expect("has no lib/pkgconfig")

    def test_missing_share(self):
        shutil.rmtree(os.path.join(self.prefix, "share", "rtems6"))
        self.expect("has no share/rtems6")

    def test_missing_tools(self):
        shutil.rmtree(os.path.join(self.prefix, "bin"))
        self.expect("has no bin/ directory")

    def test_unknown_bsp(self):
        self.expect("powerpc/ss555 is not installed", "--rtems-bsps=powerpc/ss555")

    def test_malformed_bsp_name(self):
        self.expect("is not of the form arch/bsp", "--rtems-bsps=qoriq_e500")



class NoShadowOfTheBspHeader(unittest.TestCase):
    """RTEMS's <rtems/confdefs.h> includes the BSP's own <bsp.h>, and the
    RTEMS test-runner is compiled with bsp/, tests/ and fw/test-runner/ on
    its include path: a bsp.h in any of them takes the BSP's place, its
    shutdown handler is lost and QEMU hangs after the end of the test."""

    def test_no_bsp_h_on_the_runners_include_path(self):
        for folder in ("bsp", "bsp/rtems", "tests", "fw/test-runner"):
            self.assertFalse(os.path.exists(os.path.join(TOP, folder, "bsp.h")),
                             "%s/bsp.h would shadow the RTEMS BSP's <bsp.h>"
                             % folder)


if __name__ == "__main__":
    unittest.main()
