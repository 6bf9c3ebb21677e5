# SPDX-License-Identifier: BSD-2-Clause
"""Tests of the QEMU harness: the verdict rules on made-up consoles, and
real images (qemu/selftest.c) on every target that must be judged pass,
failure, hang, crash, flood, fake summary and never-started.

Run by ./waf check after the images are built (build/<target>/qemu/).
"""
import os
import subprocess
import sys
import time
import unittest

from qemu import harness
from waftools.targets import TARGETS as ALL_TARGETS
from waftools.targets import with_role

BUILD = os.environ.get("DRDC_BUILD", "build")
# target: (its machine, the ending of its programs), for each target whose
# row says selftest
TARGETS = {n: (ALL_TARGETS[n]["machine"], ALL_TARGETS[n]["ext"])
           for n in with_role("selftest")}
# Short limits so the hang tests take seconds; each verdict must come
# within the limit plus a small margin.
INACTIVITY = 2.0
MAX_BYTES = 200000

GOOD = (b"*** BEGIN OF TEST x ***\n"
        b"t.c:1:test_a:PASS\n"
        b"t.c:2:test_b:PASS\n"
        b"\n-----------------------\n2 Tests 0 Failures 0 Ignored \nOK\n"
        b"*** END OF TEST x ***\n")


class JudgeRules(unittest.TestCase):
    """The rules, on consoles written here."""

    def judge(self, data, status=0, profile="host"):
        return harness.judge(profile, "img", data, status, None)

    def test_good_console_passes(self):
        v = self.judge(GOOD)
        self.assertTrue(v.passed, v.reasons)
        self.assertEqual(2, v.count("PASS"))

    def test_garbage_byte_fails(self):
        v = self.judge(GOOD.replace(b"test_b", b"test\xffb"))
        self.assertFalse(v.passed)
        self.assertIn("garbage", " ".join(v.reasons))

    def test_summary_that_disagrees_with_the_lines_fails(self):
        v = self.judge(GOOD.replace(b"2 Tests", b"3 Tests"))
        self.assertIn("does not match", " ".join(v.reasons))

    def test_missing_end_marker_fails(self):
        v = self.judge(GOOD.replace(b"*** END OF TEST x ***\n", b""))
        self.assertIn("END OF TEST", " ".join(v.reasons))

    def test_wrong_exit_status_fails_where_it_means_something(self):
        self.assertFalse(self.judge(GOOD, status=3).passed)
        self.assertTrue(self.judge(GOOD, status=3, profile="ppc-e500").passed)

    def test_sanitizer_report_is_a_crash(self):
        v = self.judge(GOOD + b"x.c:3:5: runtime error: signed integer overflow\n")
        self.assertIn("crash", " ".join(v.reasons))

    def test_conformance_digest_is_read(self):
        v = self.judge(GOOD.replace(b"t.c:1:", b"*** GOLDEN DIGEST: 0x0123abcd\nt.c:1:"))
        self.assertTrue(v.passed, v.reasons)
        self.assertEqual("0x0123abcd", v.digest)

    def test_failed_test_counts_once(self):
        v = self.judge(GOOD.replace(b"test_b:PASS", b"test_b:FAIL: Expected 1 Was 2")
                       .replace(b"0 Failures", b"1 Failures").replace(b"\nOK\n", b"\nFAIL\n"),
                       status=1)
        self.assertFalse(v.passed)
        self.assertEqual(1, v.test_failures)


class WineRelay(unittest.TestCase):
    """qemu/wine.py hands on a program's output until the program ends,
    even while a process it started (as Wine's services do) holds the
    pipe open: the harness must not wait for that process."""

    def test_output_ends_with_the_program(self):
        here = os.path.dirname(os.path.abspath(__file__))
        script = ("import os, sys; sys.path.insert(0, %r); import wine; "
                  "sys.exit(wine.run_relayed(['sh', '-c', 'echo out; "
                  "echo err >&2; (sleep 20) & exit 3'], dict(os.environ)))"
                  % here)
        t0 = time.monotonic()
        r = subprocess.run([sys.executable, "-c", script],
                           capture_output=True, timeout=60)
        self.assertLess(time.monotonic() - t0, 10.0)
        self.assertEqual(3, r.returncode)
        self.assertEqual(b"out\n", r.stdout)
        self.assertEqual(b"err\n", r.stderr)


class SelfTestImages(unittest.TestCase):
    """Real images on each target."""

    @classmethod
    def setUpClass(cls):
        # a new Wine prefix takes 8 s and more: made before any verdict
        # is timed, whichever test runs first
        for profile, _ in TARGETS.values():
            harness.prepare(profile)

    def run_kind(self, target, kind):
        profile, ext = TARGETS[target]
        image = os.path.join(BUILD, target, "qemu", "selftest-%s%s" % (kind, ext))
        self.assertTrue(os.path.exists(image), image)
        t0 = time.monotonic()
        v = harness.run_image(profile, image, inactivity=INACTIVITY,
                              timeout=30.0, max_bytes=MAX_BYTES)
        return v, time.monotonic() - t0

    def check_all(self, kind, passed, reason, failures):
        for target in TARGETS:
            with self.subTest(target=target):
                v, seconds = self.run_kind(target, kind)
                self.assertEqual(passed, v.passed, v.reasons)
                if reason:
                    self.assertTrue(any(r.startswith(reason) for r in v.reasons),
                                    v.reasons)
                self.assertEqual(failures, v.test_failures)
                self.assertLess(seconds, INACTIVITY + 5.0)

    def test_passing_image_passes(self):
        self.check_all("pass", True, None, 0)

    def test_failing_image_fails_with_its_test(self):
        self.check_all("fail", False, "test failures: 1", 1)

    def test_hanging_image_fails_within_the_inactivity_limit(self):
        self.check_all("hang", False, "hang:", 1)

    def test_crashing_image_is_reported_as_a_crash(self):
        self.check_all("crash", False, "crash:", 1)

    def test_flooding_image_is_stopped(self):
        self.check_all("flood", False, "console flood", 1)

    def test_fake_summary_then_crash_fails(self):
        self.check_all("fake-summary", False, "crash:", 1)

    def test_image_that_never_starts_fails(self):
        self.check_all("silent", False, "hang:", 1)


if __name__ == "__main__":
    unittest.main()
