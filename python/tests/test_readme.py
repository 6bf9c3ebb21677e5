# SPDX-License-Identifier: BSD-2-Clause
"""README's receiver-log-to-CSV example, run as written on every committed
real log, and every value of its CSV checked: UTC against Python's
calendar (the nearest-day rule worked out here), GPS week and time of
week against `drdc time`, latitude and longitude against `drdc nmea` and
the NMEA vectors' model (pynmeagps locates the fields), UTM against
`drdc geo -u` (rounded as it rounds) and GeographicLib's GeoConvert
(within the Unity suite's 1 LSB), MGRS against `drdc geo -m`."""
import csv
import datetime
import os
import re
import shutil
import subprocess
import sys
from fractions import Fraction

import pytest

from cvectors import TOP, tolerances
from test_host_tool import tool
from test_nmea import LOG_FILES, LOGS, reference_utc, tool_lines

sys.path.insert(0, os.path.join(TOP, "tests", "ref"))
import gen_nmea  # noqa: E402

EXAMPLE_LOG = "tests/nmea/logs/rtklib-2.4.3/ubx_20080526.nmea"


def example():
    """README's Python block that reads a log."""
    with open(os.path.join(TOP, "README.md")) as f:
        text = f.read()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    code = [b for b in blocks if "nmea.read_log" in b]
    assert len(code) == 1
    return text, code[0]


def run_example(log, work):
    _, code = example()
    assert EXAMPLE_LOG in code
    script = os.path.join(work, "example.py")
    with open(script, "w") as f:
        f.write(code.replace(EXAMPLE_LOG, log))
    env = dict(os.environ)
    subprocess.run([sys.executable, script], cwd=work, env=env, check=True,
                   timeout=120)
    with open(os.path.join(work, "fixes.csv"), newline="") as f:
        return list(csv.DictReader(f))


def geoconvert():
    path = shutil.which("GeoConvert")
    if path is None:
        if os.environ.get("DRDC_REQUIRE_HOST_TOOLS"):
            pytest.fail("GeoConvert is missing (geographiclib-tools)")
        pytest.skip("no GeoConvert")
    return path


def dms(field, hemisphere):
    """An NMEA (d)ddmm.mmmm field as exact DMS text for drdc geo and
    GeoConvert: degrees, then the minutes as they are."""
    point = field.index(".") if "." in field else len(field)
    return "%sd%s'%s" % (field[:point - 2], field[point - 2:], hemisphere)


def half_even(value, decimals):
    q = round(value * 10 ** decimals)  # Fraction: half to even
    return "%d.%0*d" % (q // 10 ** decimals, decimals, q % 10 ** decimals)


def lines_of(args, lines):
    r = subprocess.run(args, input="".join(l + "\n" for l in lines),
                       capture_output=True, text=True, timeout=120)
    out = r.stdout.splitlines()
    assert len(out) == len(lines), r.stderr
    return out


@pytest.mark.parametrize("path", LOG_FILES,
                         ids=lambda p: os.path.relpath(p, LOGS))
def test_readme_example_on_a_real_log(path, tmp_path):
    pytest.importorskip("pandas")
    rows = run_example(path, str(tmp_path))
    with open(path, "rb") as f:
        texts = f.read().decode("latin-1").splitlines()
    tool_out = tool_lines(path)
    plain = subprocess.run([tool("drdc"), "nmea", "--keep-going"],
                           stdin=open(path, "rb"), capture_output=True,
                           text=True).stdout.splitlines()
    utc = reference_utc(list(zip(tool_out, texts)))
    fixes = [i for i, line in enumerate(tool_out)
             if line.startswith("type=GGA") and i in utc]
    assert len(rows) == len(fixes)
    if not rows:
        return  # a log without a dated fix (receivers before their fix)
    # UTC: the calendar's instant, as ISO 8601 with 9 decimals
    for row, i in zip(rows, fixes):
        sec, ns = utc[i]
        d = datetime.datetime(1970, 1, 1) + datetime.timedelta(seconds=sec)
        assert row["utc"] == d.strftime("%Y-%m-%dT%H:%M:%S") + ".%09dZ" % ns
    # GPS week and time of week: drdc time
    gps = lines_of([tool("drdc"), "time", "--from", "utc", "--to", "gps"],
                   [r["utc"] for r in rows])
    for row, line in zip(rows, gps):
        week, tow = line.split()
        whole, frac = tow.split(".")
        assert (row["gps_week"], row["gps_tow_s"], row["gps_nsec"]) == (
            week, whole, str(int(frac)))
    # latitude and longitude: drdc nmea's text, and the model's exact nas
    points = []
    for row, i in zip(rows, fixes):
        fields = dict(kv.split("=", 1) for kv in plain[i].split())
        assert (row["lat_deg"], row["lon_deg"]) == (fields["lat"],
                                                    fields["lon"])
        _, f, _ = gen_nmea.named_fields(texts[i].rstrip("\r") + "\r\n")
        lat = gen_nmea.angle(f["lat"], f["NS"])
        lon = gen_nmea.angle(f["lon"], f["EW"])
        half = Fraction(1, 2 * 10 ** 12)
        assert abs(Fraction(row["lat_deg"]) - Fraction(lat, 3600 * 10 ** 9)) \
            <= half
        assert abs(Fraction(row["lon_deg"]) - Fraction(lon, 3600 * 10 ** 9)) \
            <= half
        points.append("%s %s" % (dms(f["lat"], f["NS"]),
                                 dms(f["lon"], f["EW"])))
    # UTM: drdc geo rounds the same integers half to even; GeoConvert's
    # within 1 LSB of Q47.16
    en_tol = Fraction(tolerances("tests/geo/test_geo_utm.c")["EN_TOL"],
                      1 << 16)
    ours = lines_of([tool("drdc"), "geo", "-u", "-p", "4"], points)
    ref = lines_of([geoconvert(), "-u", "-p", "9"], points)
    for row, line, g in zip(rows, ours, ref):
        zone = "%d%s" % (int(row["utm_zone"]), row["utm_hemisphere"].lower())
        e, n = Fraction(row["easting_m"]), Fraction(row["northing_m"])
        assert (e * 65536).denominator == 1  # exactly the Q47.16 value
        assert line == "%s %s %s" % (zone, half_even(e, 4), half_even(n, 4))
        gz, ge, gn = g.split()
        assert gz.lstrip("0") == zone
        assert abs(e - Fraction(ge)) <= en_tol
        assert abs(n - Fraction(gn)) <= en_tol
    # MGRS to 1 m: drdc geo -m
    mgrs = lines_of([tool("drdc"), "geo", "-m", "-p", "0"], points)
    assert [r["mgrs"] for r in rows] == mgrs


def test_readme_shows_the_examples_first_row(tmp_path):
    pytest.importorskip("pandas")
    text, _ = example()
    rows = run_example(os.path.join(TOP, EXAMPLE_LOG), str(tmp_path))
    with open(os.path.join(str(tmp_path), "fixes.csv")) as f:
        head = f.read().splitlines()[:2]
    for line in head:
        assert "    " + line in text
    assert len(rows) > 200
