# SPDX-License-Identifier: BSD-2-Clause
"""The package computes the bits of the host build: build/host/drdc (geo,
time) and build/host/accuracy-sample (raw integers of the transverse
Mercator, the UTM reverse and Euler angles), on random inputs.

They need `./waf build_host`; without it these tests are skipped, unless
DRDC_REQUIRE_HOST_TOOLS is set (./waf check sets it), when they fail."""
import datetime
import os
import subprocess
from fractions import Fraction

import numpy as np
import pytest

import drdc
from cvectors import TOP

BUILD = os.environ.get("DRDC_HOST_BUILD", os.path.join(TOP, "build", "host"))
DEG = drdc.NAS_PER_DEGREE
N = 400


def tool(name):
    path = os.path.join(BUILD, name)
    if not os.access(path, os.X_OK):
        message = "%s not built (./waf build_host)" % path
        if os.environ.get("DRDC_REQUIRE_HOST_TOOLS"):
            pytest.fail(message)
        pytest.skip(message)
    return path


def run(args, lines):
    r = subprocess.run(args, input="".join(l + "\n" for l in lines),
                       capture_output=True, text=True, timeout=120)
    out = r.stdout.splitlines()
    assert len(out) == len(lines), r.stderr
    return out


def nano_degrees_text(k):
    """k * 1e-9 degree as decimal text, exactly."""
    sign = "-" if k < 0 else ""
    return "%s%d.%09d" % (sign, abs(k) // 10**9, abs(k) % 10**9)


def q16_text(v):
    """A Q47.16 value as its exact decimal (16 decimals)."""
    return "%d.%016d" % (v >> 16, (v & 0xFFFF) * 5**16)


def q16_rounded(v, decimals):
    """A positive Q47.16 value rounded half to even to decimals (as drdc
    geo prints)."""
    k = round(Fraction(v * 10**decimals, 1 << 16))
    return "%d.%0*d" % (k // 10**decimals, decimals, k % 10**decimals)


def dms_to_nas(text):
    """drdc geo -d -p 8: 50d16'12.000000000"N -> nas (9 decimals of a
    second are 1 nas)."""
    d, rest = text.split("d")
    m, rest = rest.split("'")
    s = rest[:-2]
    nas = int(d) * DEG + int(m) * 60 * 10**9 + int(s.replace(".", ""))
    return -nas if rest[-1] in "SW" else nas


@pytest.fixture(scope="module")
def points():
    rng = np.random.default_rng(20261126)
    lat = rng.integers(-80 * 10**9, 84 * 10**9, N)
    lon = rng.integers(-180 * 10**9, 180 * 10**9, N)
    return lat, lon


def test_utm_as_drdc_geo_prints_it(points):
    lat, lon = points
    lines = ["%s %s" % (nano_degrees_text(a), nano_degrees_text(b))
             for a, b in zip(lat.tolist(), lon.tolist())]
    out = run([tool("drdc"), "geo", "-u", "-p", "4"], lines)
    u = drdc.geo_to_utm_array(lat * 3600, lon * 3600)
    assert (u.status == 0).all()
    for i, line in enumerate(out):
        # GeoConvert writes the zone with two digits
        ours = "%02d%s %s %s" % (u.zone[i], "n" if u.north[i] else "s",
                                 q16_rounded(int(u.easting_q47_16[i]), 4),
                                 q16_rounded(int(u.northing_q47_16[i]), 4))
        assert line == ours, lines[i]


def test_utm_reverse_bits_equal_drdc_geo(points):
    lat, lon = points
    u = drdc.geo_to_utm_array(lat * 3600, lon * 3600)
    lines = ["%d%s %s %s" % (u.zone[i], "n" if u.north[i] else "s",
                             q16_text(int(u.easting_q47_16[i])),
                             q16_text(int(u.northing_q47_16[i])))
             for i in range(N)]
    out = run([tool("drdc"), "geo", "-d", "-p", "8"], lines)
    g = drdc.geo_from_utm_array(u.zone, u.north, u.easting_q47_16,
                                u.northing_q47_16)
    for i, line in enumerate(out):
        a, b = line.split()
        assert (dms_to_nas(a), dms_to_nas(b)) == (g.lat_nas[i],
                                                   g.lon_nas[i]), lines[i]


def test_raw_integers_equal_the_accuracy_sampler(points):
    lat, lon = points
    rng = np.random.default_rng(7)
    dlon = rng.integers(-4 * 10**9, 4 * 10**9, N) * 3600
    q = rng.integers(-(1 << 30), 1 << 30, (N, 4))
    u = drdc.geo_to_utm_array(lat * 3600, lon * 3600)
    lines = (["tmfwd %d %d" % (a * 3600, d) for a, d in zip(lat.tolist(),
                                                            dlon.tolist())]
             + ["utmrev %d %s %d %d" % (u.zone[i], "N" if u.north[i] else "S",
                                        u.easting_q47_16[i],
                                        u.northing_q47_16[i])
                for i in range(N)]
             + ["euler %d %d %d %d" % tuple(row) for row in q.tolist()])
    out = run([tool("accuracy-sample")], lines)
    for i in range(N):
        t = drdc.geo_tm_forward(int(lat[i]) * 3600, int(dlon[i]))
        assert out[i] == "%d %d %d" % t[:3], lines[i]
        g = drdc.geo_from_utm(int(u.zone[i]), bool(u.north[i]),
                              int(u.easting_q47_16[i]),
                              int(u.northing_q47_16[i]))
        assert out[N + i] == "%d %d" % g[:2], lines[N + i]
        e = drdc.euler_from_quat(*q[i].tolist())
        assert out[2 * N + i] == "%d %d %d" % e, lines[2 * N + i]


def test_gps_time_as_drdc_time_prints_it():
    rng = np.random.default_rng(11)
    # 1980-01-06 .. 2026-01-01, before the built-in table's expiry
    sec = rng.integers(315964800, 1767225600, N)
    nsec = rng.integers(0, 10**9, N)
    epoch = datetime.datetime(1970, 1, 1)
    lines = [(epoch + datetime.timedelta(seconds=int(s)))
             .strftime("%Y-%m-%dT%H:%M:%S") + ".%09dZ" % n
             for s, n in zip(sec.tolist(), nsec.tolist())]
    # and the leap second of 2016 (23:59:60.5 is sec of 23:59:59 + 1.5e9)
    lines.append("2016-12-31T23:59:60.500000000Z")
    sec = np.append(sec, 1483228799)
    nsec = np.append(nsec, 1500000000)
    out = run([tool("drdc"), "time", "--from", "utc", "--to", "gps"], lines)
    g = drdc.time_utc_to_gps_array(sec, nsec)
    assert (g.status == 0).all()
    for i, line in enumerate(out):
        assert line == "%d %d.%09d" % (g.week[i], g.tow[i], g.nsec[i]), \
            lines[i]
