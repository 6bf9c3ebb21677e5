# SPDX-License-Identifier: BSD-2-Clause
"""Tests of the benchmark guard of tools/gates/bench.py (run by ./waf check)."""
import copy
import io
import json
import os
import tempfile
import unittest
from unittest import mock

from tools.gates import bench, footprint

REPORT = {
    "toolchain": {"arm-cm3": "arm-none-eabi-gcc 12.2.1"},
    "functions": [{"function": "drdc_f", "target": "arm-cm3", "instructions": 100.0}],
    "footprint": {"arm-cm3": {"library": {"text": 1000, "rodata": 100, "data": 0,
                                          "bss": 0},
                              "stack": {"drdc_f": {"bytes": 200}},
                              "linked": {"image": "fw/demo/demo", "sections": {
                                  "text": 30000, "rodata": 1000, "data": 0,
                                  "bss": 0}}}},
}


class Guard(unittest.TestCase):
    def check(self, new):
        with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
            json.dump(REPORT, f)
        try:
            return bench.check(new, f.name)
        finally:
            os.remove(f.name)

    def test_same_report_passes(self):
        self.assertTrue(self.check(copy.deepcopy(REPORT)))

    def test_five_percent_more_cycles_passes(self):
        new = copy.deepcopy(REPORT)
        new["functions"][0]["instructions"] = 105.0
        self.assertTrue(self.check(new))

    def test_six_percent_more_cycles_fails(self):
        new = copy.deepcopy(REPORT)
        new["functions"][0]["instructions"] = 106.0
        self.assertFalse(self.check(new))

    def test_six_percent_more_flash_fails(self):
        new = copy.deepcopy(REPORT)
        new["footprint"]["arm-cm3"]["library"]["text"] = 1066
        self.assertFalse(self.check(new))

    def test_stack_at_the_limit_passes(self):
        new = copy.deepcopy(REPORT)
        new["footprint"]["arm-cm3"]["stack"]["drdc_f"]["bytes"] = 512
        self.assertTrue(self.check(new))

    def test_stack_over_the_limit_fails(self):
        new = copy.deepcopy(REPORT)
        new["footprint"]["arm-cm3"]["stack"]["drdc_f"]["bytes"] = 520
        self.assertFalse(self.check(new))

    def test_demo_at_its_budget_passes(self):
        new = copy.deepcopy(REPORT)
        budget = footprint.LINKED_BUDGET["arm-cm3"]
        new["footprint"]["arm-cm3"]["linked"]["sections"]["text"] = budget - 1000
        self.assertTrue(self.check(new))

    def test_demo_over_its_budget_fails(self):
        new = copy.deepcopy(REPORT)
        budget = footprint.LINKED_BUDGET["arm-cm3"]
        new["footprint"]["arm-cm3"]["linked"]["sections"]["text"] = budget - 999
        self.assertFalse(self.check(new))

    def test_unbounded_stack_fails(self):
        new = copy.deepcopy(REPORT)
        new["footprint"]["arm-cm3"]["stack"]["drdc_f"] = {
            "bytes": None, "recursion": "drdc_f -> drdc_f"}
        self.assertFalse(self.check(new))

    def test_another_compiler_is_reported_not_guarded(self):
        new = copy.deepcopy(REPORT)
        new["toolchain"]["arm-cm3"] = "arm-none-eabi-gcc 14.2.1"
        new["functions"][0]["instructions"] = 130.0
        new["footprint"]["arm-cm3"]["stack"]["drdc_f"]["bytes"] = 520
        with mock.patch("sys.stdout", io.StringIO()) as out:
            self.assertTrue(self.check(new))
        text = out.getvalue()
        self.assertIn("Reported, not guarded", text)
        self.assertIn("reported: drdc_f on arm-cm3: 130.0 instructions", text)
        self.assertIn("reported: drdc_f on arm-cm3: worst-case stack 520", text)

    def test_the_same_compiler_is_guarded(self):
        new = copy.deepcopy(REPORT)
        new["functions"][0]["instructions"] = 130.0
        with mock.patch("sys.stdout", io.StringIO()):
            self.assertFalse(self.check(new))


class BaselineCheck(unittest.TestCase):
    """A double baseline that does not compute what the library computes
    (beyond the library's documented accuracy) fails the bench."""
    CONSOLE = ("BENCH-CHECK quat_mul worst=500 limit=501 unit=milli-LSB ok\n"
               "BENCH-CHECK utm_forward.xy worst=90000 limit=15269 unit=nm FAIL\n")

    def test_a_check_beyond_its_limit_fails(self):
        checks = [m for m in
                  (bench.CHECK_RE.match(l) for l in self.CONSOLE.splitlines())]
        self.assertTrue(all(checks))
        report = {"baseline_checks": {"arm-cm3": [
            {"name": m.group(1), "worst": int(m.group(2)), "limit": int(m.group(3)),
             "unit": m.group(4), "ok": m.group(5) == "ok"} for m in checks]}}
        self.assertEqual(["utm_forward.xy on arm-cm3: worst 90000 nm, limit 15269"],
                         bench.failed_checks(report))

    def test_checks_within_their_limits_pass(self):
        report = {"baseline_checks": {"arm-cm3": [
            {"name": "quat_mul", "worst": 500, "limit": 501, "unit": "x", "ok": True}]}}
        self.assertEqual([], bench.failed_checks(report))


class WorstStack(unittest.TestCase):
    """tools/gates/footprint.py's depth: frames add up along calls, but a
    sibling (tail) call runs after its caller's frame is gone; a call
    through a pointer reaches every function whose address is taken."""
    FRAMES = {"drdc_f": 40, "g": 24, "h": 64, "leaf": 8}
    EDGES = {"drdc_f": {"g", "h", "__divdi3"}, "g": {"leaf"}, "h": {"leaf"}}

    def test_calls_add_frames(self):
        depth, outside = footprint.worst_stack("drdc_f", self.FRAMES, self.EDGES)
        self.assertEqual(depth, 40 + 64 + 8)
        self.assertEqual(outside, {"__divdi3"})

    def test_sibling_call_does_not_add_the_callers_frame(self):
        tails = {("drdc_f", "h")}
        depth, _ = footprint.worst_stack("drdc_f", self.FRAMES, self.EDGES, tails)
        self.assertEqual(depth, max(40 + 24 + 8, 64 + 8))

    def test_recursion_is_reported(self):
        with self.assertRaises(RecursionError):
            footprint.worst_stack("g", {"g": 8}, {"g": {"g"}})

    def test_a_call_through_a_pointer_reaches_every_address_taken(self):
        edges = footprint.resolve_indirect(
            dict(self.EDGES, drdc_f={footprint.INDIRECT}), {"g", "h"})
        depth, outside = footprint.worst_stack("drdc_f", self.FRAMES, edges)
        self.assertEqual(depth, 40 + 64 + 8)
        self.assertEqual(outside, set())

    def test_a_call_through_a_pointer_without_targets_stays_outside(self):
        edges = footprint.resolve_indirect(
            {"drdc_f": {footprint.INDIRECT}}, set())
        _, outside = footprint.worst_stack("drdc_f", self.FRAMES, edges)
        self.assertEqual(outside, {footprint.INDIRECT})


if __name__ == "__main__":
    unittest.main()
