# SPDX-License-Identifier: BSD-2-Clause
"""Tests of the benchmark guard of tools/bench.py (run by ./waf check)."""
import copy
import json
import os
import tempfile
import unittest

from tools import bench

REPORT = {
    "functions": [{"function": "drdc_f", "target": "arm-cm3", "cycles": 100.0}],
    "footprint": {"arm-cm3": {"library": {"text": 1000, "rodata": 100, "data": 0,
                                          "bss": 0}}},
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


if __name__ == "__main__":
    unittest.main()
