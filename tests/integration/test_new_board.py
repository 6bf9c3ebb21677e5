# SPDX-License-Identifier: BSD-2-Clause
"""Adding a board is one row of waftools/targets.py and a folder
bsp/<board>/ (README, "Adding a board"), shown here: in a copy of the
tree, a board "scratch-cm3" whose folder is a copy of bsp/arm-cm3/ and
whose row is a Cortex-M3 row naming it is configured and built, and its
test runner passes every Unity test under QEMU with the digest of every
other image. Run by ./waf check after every target is built (about a
minute: one more target's library and suites).
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

from qemu import harness

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = os.environ.get("DRDC_BUILD", "build")
# The row a maintainer adds: everything a Cortex-M3 row says, its own board.
ROW = '''
TARGETS["scratch-cm3"] = dict(
    ARM_NEWLIB, bsp="scratch-cm3",
    arch=["-mcpu=cortex-m3", "-mthumb", "-mfloat-abi=soft",
          "--specs=nano.specs"],
    abi=["-mcpu=cortex-m3", "-mthumb", "-mfloat-abi=soft"])
'''


def copy_tree(dest):
    """The tree as it is (tracked files and new ones git does not ignore)
    and the set-up's .deps/ (a link: nothing is downloaded again)."""
    files = subprocess.run(["git", "ls-files", "-z", "--cached", "--others",
                            "--exclude-standard"], cwd=TOP, check=True,
                           capture_output=True).stdout.decode().split("\0")
    for rel in filter(None, files):
        src = os.path.join(TOP, rel)
        if not os.path.isfile(src):
            continue  # deleted in the working tree
        os.makedirs(os.path.dirname(os.path.join(dest, rel)), exist_ok=True)
        shutil.copy2(src, os.path.join(dest, rel))
    os.symlink(os.path.join(TOP, ".deps"), os.path.join(dest, ".deps"))


def digest(build):
    runner = os.path.join(build, "host", "fw", "test-runner", "test-runner")
    out = subprocess.run([runner], capture_output=True, text=True).stdout
    return re.search(r"\*\*\* GOLDEN DIGEST: (0x[0-9a-f]{8})", out).group(1)


class NewBoard(unittest.TestCase):
    def test_one_row_and_a_folder_make_a_target(self):
        with tempfile.TemporaryDirectory(prefix="drdc-board-") as tree:
            copy_tree(tree)
            shutil.copytree(os.path.join(tree, "bsp", "arm-cm3"),
                            os.path.join(tree, "bsp", "scratch-cm3"))
            with open(os.path.join(tree, "waftools", "targets.py"), "a") as f:
                f.write(ROW)
            waf = [sys.executable, os.path.join(tree, "waf")]
            for args in (["configure", "--with-targets=scratch-cm3"],
                         ["build_scratch-cm3"]):
                r = subprocess.run(waf + args, cwd=tree, capture_output=True,
                                   text=True)
                self.assertEqual(0, r.returncode, r.stdout[-3000:] + r.stderr)
            image = os.path.join(tree, "build", "scratch-cm3", "fw",
                                 "test-runner", "test-runner.elf")
            v = harness.run_image("arm-cm3", image, inactivity=10,
                                  timeout=300, max_bytes=8 << 20,
                                  label="scratch-cm3")
            self.assertTrue(v.passed, v.reasons)
            self.assertGreater(v.count("PASS"), 200)
            self.assertEqual(digest(BUILD), v.digest)


if __name__ == "__main__":
    unittest.main()
