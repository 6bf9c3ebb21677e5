# SPDX-License-Identifier: BSD-2-Clause
"""`drdc nmea` (run by ./waf check): every sentence of the NMEA vectors
against the independent model of tests/ref/gen_nmea.py (pynmeagps names
the fields, fractions reads their text), formatted here from the model's
exact values; every malformation's status; one output line per input
line, whatever the input."""
import os
import random
import subprocess
import sys
import unittest
from fractions import Fraction

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from tests.integration import drdc_tool  # host, or win64 under Wine
DRDC = drdc_tool.COMMAND
sys.path.insert(0, os.path.join(TOP, "tests", "ref"))
import gen_nmea  # noqa: E402  (the vectors' model)

BEYOND_NAMES = ["hdop", "speed", "rms", "sigma_major", "sigma_minor", "sigma_lat",
                "sigma_lon", "sigma_alt", "pdop", "vdop"]


def nmea(*args, data=b""):
    return subprocess.run(DRDC + ["nmea"] + list(args), input=data, capture_output=True)


def decimal(value, decimals):
    """value (a Fraction) with `decimals` decimals, ties away from zero."""
    q = gen_nmea.round_away(value * 10 ** decimals)
    sign = "-" if q < 0 else ""
    q = abs(q)
    return "%s%d.%0*d" % (sign, q // 10 ** decimals, decimals, q % 10 ** decimals)


def expected(r):
    """The documented key=value line of a model record."""
    has = r["has"]
    H = gen_nmea.HAS
    out = ["type=%s" % r["type"][len("DRDC_NMEA_"):], "talker=%s" % r["talker"]]
    if has & H["TIME"]:
        out.append("time=%02d:%02d:%02d.%09d" % r["time"])
    if has & H["DATE"]:
        out.append("date=%04d-%02d-%02d" % (r["year"], r["month"], r["day"]))
    if has & H["ZONE"]:
        out.append("zone=%s%02d:%02d" % ("-" if r["zh"] < 0 else "+", abs(r["zh"]), r["zm"]))
    if has & H["POSITION"]:
        out.append("lat=" + decimal(Fraction(r["lat"], 3600 * 10 ** 9), 12))
        out.append("lon=" + decimal(Fraction(r["lon"], 3600 * 10 ** 9), 12))
    if has & H["QUALITY"]:
        out.append("quality=%d" % r["quality"])
    if r["mode"]:
        out.append("mode=" + r["mode"])
    if has & H["FIX_TYPE"]:
        out.append("fix=%d" % r["fix_type"])
    if has & H["SATELLITES"]:
        out.append("satellites=%d" % r["sats"])
    if r["type"] == "DRDC_NMEA_GSA" and r["sats"]:
        out.append("ids=" + ",".join(str(i) for i in r["ids"][:r["sats"]]))
    if has & H["SYSTEM"]:
        out.append("system=%d" % r["system"])

    def q16(key, v):
        out.append("%s=%s" % (key, decimal(Fraction(v, 65536), 4)))

    def angle(key, v):
        out.append("%s=%s" % (key, decimal(Fraction(v * 360, 2 ** 32), 8)))

    for key, bit in (("hdop", "HDOP"), ("pdop", "PDOP"), ("vdop", "VDOP"),
                     ("alt", "ALTITUDE"), ("sep", "SEPARATION"), ("speed", "SPEED")):
        if has & H[bit]:
            q16({"alt": "altitude", "sep": "separation"}.get(key, key), r[key])
    for key, bit, name in (("course", "COURSE", "course"),
                           ("course_m", "COURSE_MAGNETIC", "course_magnetic"),
                           ("heading", "HEADING", "heading")):
        if has & H[bit]:
            angle(name, r[key])
    g = r["gst"]
    if has & H["GST"]:
        for key, i in (("rms", 0), ("sigma_lat", 4), ("sigma_lon", 5), ("sigma_alt", 6)):
            q16(key, g[i])
    if has & H["ELLIPSE"]:
        q16("sigma_major", g[1])
        q16("sigma_minor", g[2])
        angle("orientation", g[3])
    if r["beyond"]:
        out.append("beyond=" + ",".join(n for k, n in enumerate(BEYOND_NAMES)
                                        if r["beyond"] >> k & 1))
    return " ".join(out)


NO_FIX = "DRDC_E_NO_FIX"


def expected_of_log_line(line):
    """What `drdc nmea` must print for one line of a receiver's log (the
    line without its LF): an ERROR with its status for sentences it does
    not decode and fixes the receiver marks invalid, else the model's
    record. pynmeagps checks the checksum and names the fields."""
    body = line.rstrip("\r")
    kind = body[3:6] if body.startswith("$") and len(body) > 6 else ""
    if not body.startswith("$"):
        return "DRDC_E_SYNTAX"
    if "*" not in body:
        return "DRDC_E_TRUNCATED"
    if body.startswith("$P") or kind not in gen_nmea.LAYOUT:
        return "DRDC_E_SENTENCE"
    msg, f, _ = gen_nmea.named_fields(body + "\r\n")
    mode = f.get("posMode", "")
    if ((kind == "GGA" and f["quality"] == "0")
            or (kind in ("RMC", "GLL") and f["status"] == "V")
            or (kind in ("RMC", "GLL", "VTG") and mode == "N")
            or (kind == "GNS" and set(mode) <= {"N"})
            or (kind == "GSA" and f["navMode"] == "1")
            or (kind == "THS" and f["mi"] == "V")):
        return NO_FIX
    # the required fields these logs leave empty: an instrument without a
    # heading, a receiver without a date
    if ((kind == "HDT" and not f["headingT"])
            or (kind == "ZDA" and not (f["day"] and f["month"] and f["year"]))):
        return "DRDC_E_MISSING_FIELD"
    return expected(gen_nmea.model(body + "\r\n")[0])


class NmeaCommand(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.corpus = gen_nmea.corpus()
        cls.models = [gen_nmea.model(s) for s in cls.corpus]

    @staticmethod
    def lines(texts):
        return b"".join(t.encode("latin-1").rstrip(b"\r\n") + b"\n" for t in texts)

    def test_every_vector_decodes_as_the_model_says(self):
        r = nmea(data=self.lines(self.corpus))
        self.assertEqual(0, r.returncode, r.stdout)
        got = r.stdout.decode().splitlines()
        self.assertEqual(len(self.corpus), len(got))
        for text, (model, _), line in zip(self.corpus, self.models, got):
            self.assertEqual(expected(model), line, text)

    def test_strict_refuses_what_the_standard_does(self):
        r = nmea("--strict", data=self.lines(self.corpus))
        self.assertEqual(1, r.returncode)
        got = r.stdout.decode().splitlines()
        self.assertEqual(len(self.corpus), len(got))
        refused = 0
        for text, (model, strict), line in zip(self.corpus, self.models, got):
            if strict == "DRDC_OK":
                self.assertEqual(expected(model), line, text)
            else:
                self.assertTrue(line.startswith("ERROR: ") and line.endswith("(%s)" % strict),
                                (text, line))
                refused += 1
        self.assertGreaterEqual(refused, 10)
        # the 87-character GGA of a survey receiver
        long_gga = gen_nmea.sentence("GPGGA,172814.0,3723.46587704,N,12202.26957864,W,2,6,"
                                     "1.2,18.893,M,-25.669,M,2.0,0031")
        self.assertEqual(87, len(long_gga.rstrip("\r\n")))
        self.assertIn(b"(DRDC_E_OVERLONG)", nmea("--strict", data=self.lines([long_gga])).stdout)
        self.assertIn(b"type=GGA", nmea(data=self.lines([long_gga])).stdout)

    def test_raw_prints_the_library_integers(self):
        s = gen_nmea.sentence(gen_nmea.CORPUS[0])
        model, _ = gen_nmea.model(s)
        out = nmea("--raw", data=self.lines([s])).stdout.decode().split()
        self.assertIn("lat=%d" % model["lat"], out)
        self.assertIn("lon=%d" % model["lon"], out)
        self.assertIn("altitude=%d" % model["alt"], out)
        self.assertIn("hdop=%d" % model["hdop"], out)

    def test_malformations_give_their_status(self):
        # as the lines of a file: the text up to its own LF, if any
        rows = [(t[:-1] if t.endswith("\n") else t, st) for t, st, flags in gen_nmea.bad()
                if flags == 0 and "\n" not in t[:-1]]
        r = nmea(data=b"".join(t.encode("latin-1") + b"\n" for t, _ in rows))
        self.assertEqual(1, r.returncode)
        got = r.stdout.decode().splitlines()
        self.assertEqual(len(rows), len(got))
        for (text, status), line in zip(rows, got):
            if "\x00" in text:  # the tool's own wording, for every command
                self.assertEqual("ERROR: NUL byte in the line", line)
                continue
            self.assertTrue(line.startswith("ERROR: ") and line.endswith("(%s)" % status),
                            (text, line))

    def test_one_line_out_per_line_in_whatever_the_input(self):
        rng = random.Random(23)
        lines = [b"x" * 100000, b"", b"\r", b"$" + b"," * 5000 + b"*00",
                 gen_nmea.sentence(gen_nmea.CORPUS[0]).encode().rstrip(b"\n") * 3]
        for _ in range(300):
            n = rng.choice([0, 1, 5, 80, 127, 128, 129, 300])
            lines.append(bytes(rng.choice(range(256)) for _ in range(n)).replace(b"\n", b""))
        r = nmea(data=b"".join(l + b"\n" for l in lines))
        self.assertEqual(1, r.returncode)
        self.assertEqual(len(lines), r.stdout.count(b"\n"))
        self.assertEqual(b"", r.stderr)

    def test_real_logs_line_for_line(self):
        logs = os.path.join(TOP, "tests", "nmea", "logs")
        paths = sorted(os.path.join(d, f) for d, _, files in os.walk(logs)
                       for f in files if f.endswith((".log", ".nmea")))
        self.assertEqual(5, len(paths))
        decoded = 0
        for path in paths:
            with open(path, "rb") as f:
                data = f.read()
            lines = data.split(b"\n")
            if lines[-1] == b"":
                lines.pop()
            r = nmea(data=data)
            got = r.stdout.decode().splitlines()
            self.assertEqual(len(lines), len(got), path)
            for line, out in zip(lines, got):
                want = expected_of_log_line(line.decode("latin-1"))
                if want.startswith("DRDC_"):
                    self.assertTrue(out.startswith("ERROR: ") and out.endswith("(%s)" % want),
                                    (path, line, out))
                else:
                    self.assertEqual(want, out, (path, line))
                    decoded += 1
        self.assertGreater(decoded, 2500)

    def test_keep_going_exits_0_on_a_real_log(self):
        # a real log holds sentences without a fix and sentences not
        # decoded here: --keep-going writes the same lines and exits 0, so
        # subprocess.run(check=True) works; without it the status is 1
        path = os.path.join(TOP, "tests", "nmea", "logs", "nmea-0.8.0",
                            "nmea1-first-3000.log")
        with open(path, "rb") as f:
            data = f.read()
        plain = nmea(data=data)
        going = subprocess.run(DRDC + ["nmea", "--keep-going"], input=data,
                               capture_output=True, check=True)
        self.assertEqual(1, plain.returncode)
        self.assertEqual(plain.stdout, going.stdout)
        self.assertIn(b"ERROR: ", going.stdout)
        self.assertIn(b"type=GGA", going.stdout)
        # still 2 for a usage error, whatever else is given
        self.assertEqual(2, nmea("--keep-going", "--bogus").returncode)
        # with --strict and --raw as well
        r = nmea("--keep-going", "--strict", "--raw", data=data)
        self.assertEqual(0, r.returncode)
        self.assertEqual(nmea("--strict", "--raw", data=data).stdout, r.stdout)

    def test_help_and_usage(self):
        r = nmea("--help")
        self.assertEqual(0, r.returncode)
        for word in (b"--strict", b"--raw", b"--keep-going", b"key=value",
                     b"beyond", b"Exit status"):
            self.assertIn(word, r.stdout)
        r = nmea("--bogus")
        self.assertEqual(2, r.returncode)
        top = subprocess.run(DRDC + ["--help"], capture_output=True)
        self.assertIn(b"nmea", top.stdout)


if __name__ == "__main__":
    unittest.main()
