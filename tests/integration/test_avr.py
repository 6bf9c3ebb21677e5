# SPDX-License-Identifier: BSD-2-Clause
"""The conformance digest where int has 16 bits (./waf check): each part
of it (tests/golden), built alone for an AVR ATmega2560
(build/avr/fw/golden-part/<part>.elf: avr-gcc copies the const tables
not marked DRDC_FLASH_TABLE into the part's 8 KiB of RAM, so one
module's tables at a time), runs under
simavr and must print the very line the host's test runner prints for
that part. A width assumption in the library (a 32-bit value through an
unsigned int) changes the part's digest: before the clz fix of
fixed/sqrt.c, fixed/trig_impl.h and core/orient, the fixed, orient and
geo parts differed here."""
import os
import re
import subprocess
import unittest

from qemu import harness
from waftools.golden import GOLDEN_PARTS

BUILD = os.environ.get("DRDC_BUILD", "build")
PARTS = [part for part, _, _ in GOLDEN_PARTS]
LINE = re.compile(r"golden digest of ([A-Za-z ]+): (0x[0-9a-f]{8})")


def host_lines():
    runner = os.path.join(BUILD, "host", "fw", "test-runner", "test-runner")
    out = subprocess.run([runner], capture_output=True, text=True).stdout
    return dict(LINE.findall(out))


def avr_line(part):
    image = os.path.join(BUILD, "avr", "fw", "golden-part", part + ".elf")
    # simavr prints what USART0 sends (with colour codes), and ends when
    # the image sleeps with interrupts off
    r = subprocess.run(harness.command("avr", image), capture_output=True,
                       timeout=600)
    text = (r.stdout + r.stderr).decode("ascii", "replace")
    return LINE.findall(text)


class GoldenPartsOnAvr(unittest.TestCase):
    def test_every_part_prints_the_hosts_digest(self):
        want = host_lines()
        self.assertEqual(len(PARTS), len(want))
        for part in PARTS:
            got = avr_line(part)
            self.assertEqual(1, len(got), part)
            name, digest = got[0]
            self.assertEqual(want[name], digest, part)
            print("avr %-22s %s (host %s)" % (name, digest, want[name]))


# the tables marked DRDC_FLASH_TABLE (fixed/internal/drdc/compiler.h)
FLASH_TABLES = ("drdc__fx_sin_q31", "drdc__fx_atan_nodes",
                "drdc__fx_sqrt_seed")


class FlashTablesOnAvr(unittest.TestCase):
    def test_flash_tables_are_where_lpm_reaches(self):
        """pgm_read_*() is LPM, which reads the first 64 KiB of flash
        only; the linker puts .progmem first, and the largest part links
        115 KB: each table must still start and end below 0x10000."""
        seen = 0
        for part in PARTS:
            image = os.path.join(BUILD, "avr", "fw", "golden-part",
                                 part + ".elf")
            out = subprocess.run(["avr-nm", "-S", image], check=True,
                                 capture_output=True, text=True).stdout
            for line in out.split("\n"):
                fields = line.split()
                if len(fields) == 4 and fields[3] in FLASH_TABLES:
                    self.assertIn(fields[2], ("t", "T", "r", "R"), line)
                    end = int(fields[0], 16) + int(fields[1], 16)
                    self.assertLessEqual(end, 0x10000, (part, line))
                    seen += 1
        self.assertGreater(seen, 6)


if __name__ == "__main__":
    unittest.main()
