# SPDX-License-Identifier: BSD-2-Clause
"""Tests of the host tool build/host/drdc (run by ./waf check)."""
import os
import re
import subprocess
import unittest

DRDC = os.path.join(os.environ.get("DRDC_BUILD", "build"), "host", "drdc")
TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(*args):
    return subprocess.run([DRDC] + list(args), capture_output=True, text=True)


class Tool(unittest.TestCase):
    def test_version_is_the_library_version(self):
        with open(os.path.join(TOP, "core/include/drdc/version.h")) as f:
            header = f.read()
        version = re.search(r'DRDC_VERSION_STRING "([^"]+)"', header).group(1)
        r = run("--version")
        self.assertEqual(0, r.returncode)
        self.assertEqual("drdc %s\n" % version, r.stdout)

    def test_help_names_the_options(self):
        r = run("--help")
        self.assertEqual(0, r.returncode)
        self.assertIn("--version", r.stdout)

    def test_unknown_command_is_an_error(self):
        r = run("no-such-command")
        self.assertEqual(2, r.returncode)
        self.assertIn("unknown command", r.stderr)


if __name__ == "__main__":
    unittest.main()
