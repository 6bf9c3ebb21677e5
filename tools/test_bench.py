# SPDX-License-Identifier: BSD-2-Clause
"""Tests of the benchmark guard of tools/bench.py (run by ./waf check)."""
import copy
import json
import os
import tempfile
import unittest

from tools import bench, footprint

REPORT = {
    "functions": [{"function": "drdc_f", "target": "arm-cm3", "cycles": 100.0}],
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
        new["functions"][0]["cycles"] = 105.0
        self.assertTrue(self.check(new))

    def test_six_percent_more_cycles_fails(self):
        new = copy.deepcopy(REPORT)
        new["functions"][0]["cycles"] = 106.0
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
        new["footprint"]["arm-cm3"]["linked"]["sections"]["text"] = 36 * 1024 - 1000
        self.assertTrue(self.check(new))

    def test_demo_over_its_budget_fails(self):
        new = copy.deepcopy(REPORT)
        new["footprint"]["arm-cm3"]["linked"]["sections"]["text"] = 36 * 1024 - 999
        self.assertFalse(self.check(new))

    def test_unbounded_stack_fails(self):
        new = copy.deepcopy(REPORT)
        new["footprint"]["arm-cm3"]["stack"]["drdc_f"] = {
            "bytes": None, "recursion": "drdc_f -> drdc_f"}
        self.assertFalse(self.check(new))


class WorstStack(unittest.TestCase):
    """tools/footprint.py's depth: frames add up along calls, but a sibling
    (tail) call runs after its caller's frame is gone."""
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


if __name__ == "__main__":
    unittest.main()
