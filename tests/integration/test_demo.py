# SPDX-License-Identifier: BSD-2-Clause
"""The demo firmware against the host tool and an exact model (./waf check).

The demo (fw/demo) prints, per epoch, what a pose node computes from its
scripted NMEA sentences and IMU quaternions. Checked here:
- PowerPC e500, Cortex-M3 and RISC-V rv32 print exactly what the host
  build prints;
- UTC -> GPS week and time of week equal `drdc time --from utc --to gps`;
- yaw, pitch, roll equal `drdc attitude --from quat --to euler` for the
  same Q1.30 quaternions;
- longitude and latitude equal the NMEA text's degrees and minutes,
  computed with Python's fractions;
- UTM zone, easting, northing and the MGRS square equal `drdc geo -u` and
  `drdc geo -m` (GeoConvert's format, itself diffed against GeoConvert in
  test_drdc.py), and the convergence equals `drdc geo -c` within the
  resolution of the Q1.30 attitude it is measured on;
- the JAUS Report Global Pose body (AS6009) equals bytes built here with
  struct.pack('<...') from the standard's field table: latitude and
  longitude from the NMEA text (fractions), the height as the text rounded
  to Q47.16 (as nmea.h documents), roll, pitch and yaw from the image's
  Q1.30 quaternions with Python's math, the time stamp from the sentence's
  time and the RMC date.
"""
import fractions
import math
import os
import re
import struct
import subprocess
import unittest

from qemu import harness
from waftools.targets import TARGETS, with_role

BUILD = os.environ.get("DRDC_BUILD", "build")
TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DRDC = os.path.join(BUILD, "host", "drdc")
# The demo of each target whose row says demo_check, the host's first
DEMO_TARGETS = with_role("demo_check")


def console(target):
    t = TARGETS[target]
    image = os.path.join(BUILD, target, "fw", "demo", "demo" + t["ext"])
    data, status, killed = harness.boot(t["machine"], image, 10, 60, 1 << 20)
    assert not killed, killed
    text = data.decode("ascii").replace("\r", "")
    return text.split(": GNSS", 1)[1]  # after the line naming the board


def tool(*args, stdin):
    r = subprocess.run([DRDC] + list(args), input=stdin, capture_output=True,
                       text=True, check=True)
    return r.stdout.split("\n")


def demo_source():
    with open(os.path.join(TOP, "fw", "demo", "main.c")) as f:
        return f.read()


class Demo(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.host = console("host")

    def test_every_target_prints_the_same_bits(self):
        self.assertIn("ppc-e500", DEMO_TARGETS)
        for target in DEMO_TARGETS:
            self.assertEqual(self.host, console(target), target)

    def test_gps_time_matches_the_host_tool(self):
        found = re.findall(r"UTC   (\S+)   GPS week (\d+) TOW (\d+)", self.host)
        self.assertEqual(4, len(found))
        out = tool("time", "--from", "utc", "--to", "gps",
                   stdin="".join(u + "\n" for u, _, _ in found))
        for (utc, week, tow), line in zip(found, out):
            self.assertEqual("%s %s.000000000" % (week, tow), line, utc)

    def test_euler_matches_the_host_tool(self):
        quats = re.findall(r"\{ (-?\d+), (-?\d+), (-?\d+), (-?\d+) \}, /\* yaw",
                           demo_source())
        self.assertEqual(4, len(quats))
        lines = "".join(" ".join("%.15f" % (int(v) / 2 ** 30) for v in q) + "\n"
                        for q in quats)
        want = tool("attitude", "--from", "quat", "--to", "euler", stdin=lines)
        got = re.findall(r"yaw (\S+) pitch (\S+) roll (\S+) deg", self.host)
        for g, w in zip(got, want):
            for a, b in zip(g, w.split()):
                self.assertAlmostEqual(float(a), float(b), delta=1.01e-8)

    def test_position_is_the_nmea_text_exactly(self):
        sentences = re.findall(r'"\$GNGGA,[^,]*,(\d\d)(\d\d\.\d+),N,(\d\d\d)(\d\d\.\d+),W',
                               demo_source())
        got = re.findall(r"lon (\S+) lat (\S+) deg", self.host)
        self.assertEqual(4, len(sentences))
        for (lad, lam, lod, lom), (lon, lat) in zip(sentences, got):
            want_lat = int(lad) + fractions.Fraction(lam) / 60
            want_lon = -(int(lod) + fractions.Fraction(lom) / 60)
            self.assertEqual(round(want_lat * 10 ** 9), round(fractions.Fraction(lat) * 10 ** 9))
            self.assertEqual(round(want_lon * 10 ** 9), round(fractions.Fraction(lon) * 10 ** 9))

    def test_heading_is_the_hdt_and_ths_text(self):
        """The true heading of the epochs that carry HDT or THS: the
        sentence's degrees rounded to a binary angle (2^32 per turn), then
        printed with 8 decimals; the IMU yaw beside it is the {We} yaw."""
        f = fractions.Fraction
        src = demo_source()
        sent = re.findall(r'"\$(GN)(HDT|THS),([0-9.]+),[TA]\*', src)
        got = re.findall(r"GNSS  heading (\S+) deg true \((\w+)\), IMU yaw - heading (\S+) deg",
                         self.host)
        yaws = re.findall(r"yaw (\S+) pitch", self.host)
        epochs = self.host.split("epoch ")[1:]
        self.assertEqual(2, len(sent))
        self.assertEqual(2, len(got))
        with_heading = [i for i, e in enumerate(epochs) if "GNSS  heading" in e]
        self.assertEqual([1, 3], with_heading)
        for (talker, kind, deg), (heading, name, diff), i in zip(sent, got, with_heading):
            self.assertEqual(talker + kind, name)
            bam = math.floor(f(deg) * 2 ** 32 / 360 + f(1, 2))
            want = f(bam * 360, 2 ** 32)
            self.assertLessEqual(abs(f(heading) - want), f(1, 2 * 10 ** 8))
            # both printed values are rounded to 1e-8 deg
            self.assertLessEqual(abs(f(yaws[i]) - f(heading) - f(diff)), f(2, 10 ** 8))

    def test_jaus_body_is_the_standard_bytes(self):
        """AS6009: ScaleFactor = (max - min) / (2^n - 1), Bias = min,
        unsigned fields; presence 0x0177 (latitude, longitude, altitude,
        roll, pitch, yaw, time stamp), little-endian."""
        f = fractions.Fraction

        def scaled(real, lo, hi, bits):
            x = (f(real) - lo) / (f(hi) - lo) * ((1 << bits) - 1)
            return math.floor(x + f(1, 2))  # real >= lo: ties away from zero

        def angle(radians, bits=16):
            """The integers the library may send: the correct rounding,
            or either neighbour of a tie closer than the library's
            documented quaternion -> Euler error (9.4e-8 degree = 1.7e-5
            of a step) plus double rounding."""
            x = (radians + math.pi) / (2 * math.pi) * ((1 << bits) - 1)
            if abs(x - math.floor(x) - 0.5) > 2e-5:
                return {math.floor(x + 0.5)}
            return {math.floor(x), math.floor(x) + 1}

        src = demo_source()
        gga = re.findall(r'"\$GNGGA,(\d\d)(\d\d)(\d\d)\.\d+,(\d\d)(\d\d\.\d+),N,'
                         r'(\d\d\d)(\d\d\.\d+),W,\d,\d+,[^,]*,([^,]*),M', src)
        date = re.findall(r'"\$GNRMC,[^,]*,A,[^,]*,N,[^,]*,W,[^,]*,[^,]*,(\d\d)\d{4},', src)
        quats = re.findall(r"\{ (-?\d+), (-?\d+), (-?\d+), (-?\d+) \}, /\* yaw", src)
        got = re.findall(r"Report Global Pose body \(AS6009\) ([0-9a-f]+)", self.host)
        self.assertEqual(4, len(gga))
        self.assertEqual(4, len(got))
        ties = 0
        for (hh, mm, ss, lad, lam, lod, lom, alt), day, q, hexed in zip(gga, date, quats, got):
            lat = int(lad) + f(lam) / 60
            lon = -(int(lod) + f(lom) / 60)
            height = f(math.floor(f(alt) * 65536 + f(1, 2)), 65536)
            s, x, y, z = (int(v) / 2 ** 30 for v in q)
            n = math.sqrt(s * s + x * x + y * y + z * z)
            s, x, y, z = s / n, x / n, y / n, z / n
            yaw = math.atan2(2 * (s * z + x * y), 1 - 2 * (y * y + z * z))
            pitch = math.asin(2 * (s * y - z * x))
            roll = math.atan2(2 * (s * x + y * z), 1 - 2 * (x * x + y * y))
            stamp = (int(day) << 27) | (int(hh) << 22) | (int(mm) << 16) | (int(ss) << 10)
            fields = struct.unpack("<HIIIHHHI", bytes.fromhex(hexed))
            self.assertEqual(24 * 2, len(hexed))
            self.assertEqual((0x0177, scaled(lat, -90, 90, 32), scaled(lon, -180, 180, 32),
                              scaled(height, -10000, 35000, 32)), fields[:4])
            for got_angle, want_angles in zip(fields[4:7], (angle(roll), angle(pitch),
                                                            angle(yaw))):
                self.assertIn(got_angle, want_angles)
                ties += len(want_angles) > 1
            self.assertEqual(stamp, fields[7])
        # the scripted attitudes are whole and half degrees; 48 degrees of
        # yaw is a tie of the 16-bit field (228 x 65535 / 360 = 41505.5)
        self.assertLessEqual(ties, 1)

if __name__ == "__main__":
    unittest.main()


class DemoGeodesy(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.host = console("host")
        cls.points = ["%s %s" % (lat, lon) for lon, lat in
                      re.findall(r"lon (\S+) lat (\S+) deg", cls.host)]

    def test_utm_matches_drdc_geo(self):
        got = re.findall(r"UTM   (\d+[ns]) (\S+) (\S+) m", self.host)
        want = tool("geo", "-u", "-p", "3", stdin="".join(p + "\n" for p in self.points))
        self.assertEqual(4, len(got))
        for g, w in zip(got, want):
            self.assertEqual(" ".join(g), w)

    def test_mgrs_matches_drdc_geo(self):
        got = re.findall(r"MGRS  (\S+)", self.host)
        want = tool("geo", "-m", "-p", "0", stdin="".join(p + "\n" for p in self.points))
        self.assertEqual(4, len(got))
        self.assertEqual(got, want[:4])

    def test_convergence_matches_drdc_geo(self):
        got = [float(c) for c in re.findall(r"convergence (\S+) deg", self.host)]
        want = tool("geo", "-c", "-p", "6", stdin="".join(p + "\n" for p in self.points))
        self.assertEqual(4, len(got))
        for g, w in zip(got, want):
            # the demo measures it between two Q1.30 attitudes: 2e-7 deg
            self.assertAlmostEqual(g, float(w.split()[0]), delta=2e-7)
