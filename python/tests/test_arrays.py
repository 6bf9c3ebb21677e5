# SPDX-License-Identifier: BSD-2-Clause
"""Every scalar function of the package has an _array twin whose loop
runs in C (one ctypes call per array, whatever its length), with the
scalar's bits; the new twins against their independent oracles (the
GeographicLib MGRS vectors, Python's calendar and datetime, exact
fractions for the decimal text); status names as arrays."""
import calendar
import datetime
import inspect
from fractions import Fraction

import numpy as np
import pytest

import drdc
from drdc import _format, _geo, _jaus, _orient, _pose, _time, _units
from cvectors import load, tolerances

DEG = drdc.NAS_PER_DEGREE
# helpers of the package that are no function of the library: text
# conversions in Python's exact arithmetic, and the status helpers
NOT_LIBRARY = {"degrees_to_nas", "degrees_to_bam32", "metres_to_q47_16",
               "nas_to_degrees", "is_error", "reason",
               "status_name"}


def test_every_scalar_function_has_an_array_twin():
    public = {n for n, f in vars(drdc).items()
              if callable(f) and not n.startswith("_")
              and not inspect.isclass(f)}
    scalars = {n for n in public if not n.endswith("_array")}
    missing = sorted(n for n in scalars - NOT_LIBRARY
                     if n + "_array" not in public)
    assert missing == []
    assert "status_name_array" in public
    # the modules' too
    assert {"parse_array", "parse_bytes"} <= set(vars(drdc.nmea))


class Counting:
    """The ctypes library, counting the calls of its functions."""

    def __init__(self, lib):
        self.lib = lib
        self.calls = 0

    def __getattr__(self, name):
        f = getattr(self.lib, name)

        def counted(*args):
            self.calls += 1
            return f(*args)
        return counted


# (array function, arguments for 1000 elements)
N = 1000
RNG = np.random.default_rng(5)
LAT = RNG.integers(-80 * DEG, 84 * DEG, N)
LON = RNG.integers(-180 * DEG, 180 * DEG, N)
SEC = RNG.integers(0, 4 * 10**9, N)
U = drdc.geo_to_utm_array(LAT, LON)
TWINS = [
    ("geo_to_utm_array", (LAT, LON)),
    ("geo_from_utm_array", tuple(U[:4])),
    ("geo_utm_zone_array", (LAT, LON)),
    ("geo_tm_forward_array", (LAT, LON // 60)),
    ("geo_mgrs_encode_array", (LAT, LON)),
    ("geo_mgrs_from_utm_array", tuple(U[:4])),
    ("geo_mgrs_decode_array", (drdc.geo_mgrs_encode_array(LAT, LON).text,)),
    ("time_from_civil_array", (2000 + SEC % 50, 1 + SEC % 12, 1 + SEC % 28)),
    ("time_to_civil_array", (SEC,)),
    ("time_utc_to_gps_array", (SEC,)),
    ("time_gps_to_utc_array", (SEC % 3000, SEC % 604800)),
    ("time_utc_to_tai_array", (SEC,)),
    ("time_tai_to_utc_array", (SEC,)),
    ("time_utc_to_unix_array", (SEC,)),
    ("time_unix_to_utc_array", (SEC,)),
    ("time_iso8601_parse_array",
     (drdc.format_utc_array(SEC).text,)),
    ("time_jaus_pack_array", (SEC,)),
    ("time_jaus_to_utc_array", (drdc.time_jaus_pack_array(SEC).stamp, SEC)),
    ("quat_from_euler_array", (SEC, SEC // 3, SEC // 7)),
    ("euler_from_quat_array", ((1 << 30) - SEC % 1000, SEC % 1000, 0, 0)),
    ("units_convert_array", (SEC, 16, "ft", 16, "m")),
    ("units_convert_expr_array", (SEC, 0, "km/h", 16, "m/s")),
    ("format_q47_16_array", (SEC,)),
    ("format_nas_degrees_array", (LAT,)),
    ("format_bam32_degrees_array", (SEC,)),
    ("format_utc_array", (SEC,)),
    ("pose_wutm_from_w_array", (LON, LAT, SEC, 1 << 30, 0, 0, 0)),
    ("pose_wmgrs_from_w_array", (LON, LAT, SEC, 1 << 30, 0, 0, 0)),
    ("pose_le_from_l_array", (SEC % 1000, 0, 0, 1 << 30, 0, 0, 0)),
    ("pose_bam_from_convergence_array", (LAT // 1000,)),
    ("jaus_scaled_encode_array", (LAT, -90 * DEG, 90 * DEG,
                                  drdc.JAUS_INT32, drdc.FORM_AS6009)),
    ("jaus_global_pose_pack_array", (0x7F, LON, LAT, SEC, SEC, SEC, SEC, 0,
                                     0, 0)),
    ("ddmm_to_nas_array", (np.array(["3854.5087"] * N), np.array(["N"] * N))),
]
MODULES = [_format, _geo, _jaus, _orient, _pose, _time, _units, drdc.nmea]


@pytest.mark.parametrize("name,args", TWINS, ids=[t[0] for t in TWINS])
def test_array_functions_loop_in_c(monkeypatch, name, args):
    counting = Counting(drdc._lib.lib)
    for m in MODULES:
        monkeypatch.setattr(m, "lib", counting)
    r = getattr(drdc, name)(*args)
    # one call, or a handful (a unit looked up, a table of names): never
    # one per element
    assert 1 <= counting.calls <= 4, counting.calls
    status = r.status if hasattr(r, "status") else None
    if status is not None:
        assert status.shape == (N,)


def scalar_equals_array(scalar, array, argsets):
    """scalar(*args) == each field of array(*columns)[i] (its status
    DRDC_OK)."""
    columns = [np.array(c) for c in zip(*argsets)]
    a = array(*columns)
    assert (a.status == 0).all()
    for i, args in enumerate(argsets):
        s = scalar(*args)
        s = s if isinstance(s, tuple) else (s,)
        got = tuple(x[i].item() if hasattr(x[i], "item") else x[i]
                    for x in a[:len(s)])
        assert got == tuple(s), (args, got, s)


def test_scalars_give_the_array_bits():
    pts = list(zip(LAT[:40].tolist(), LON[:40].tolist()))
    scalar_equals_array(drdc.geo_utm_zone, drdc.geo_utm_zone_array, pts)
    scalar_equals_array(drdc.geo_tm_forward, drdc.geo_tm_forward_array,
                        [(a, b // 60) for a, b in pts])
    scalar_equals_array(drdc.geo_mgrs_encode, drdc.geo_mgrs_encode_array,
                        [(a, b, p) for (a, b), p in zip(pts, range(-1, 12)
                                                        )])
    utm = [tuple(int(x) if x.dtype != bool else bool(x) for x in
                 (U.zone[i], U.north[i], U.easting_q47_16[i],
                  U.northing_q47_16[i])) for i in range(30)]
    scalar_equals_array(drdc.geo_mgrs_from_utm, drdc.geo_mgrs_from_utm_array,
                        [u + (i % 12,) for i, u in enumerate(utm)])
    civil = [(1972 + k, 1 + k % 12, 1 + k % 28, k % 24, k % 60, k % 60,
              k * 7919) for k in range(40)]
    scalar_equals_array(drdc.time_from_civil, drdc.time_from_civil_array,
                        civil)
    scalar_equals_array(drdc.time_to_civil, drdc.time_to_civil_array,
                        [(s, 0) for s in SEC[:40].tolist()])
    scalar_equals_array(drdc.time_jaus_pack, drdc.time_jaus_pack_array,
                        [(s, 0) for s in SEC[:40].tolist()])
    g = drdc.geo_from_utm_array(*U[:4], with_scale=True)
    for i in range(20):
        s = drdc.geo_from_utm(*utm[i], with_scale=True)
        assert s == (g.lat_nas[i], g.lon_nas[i], g.convergence_nas[i],
                     g.scale_q5_58[i])
        assert drdc.geo_from_utm(*utm[i])[:2] == s[:2]


def test_mgrs_arrays_equal_the_geographiclib_vectors():
    enc = load("tests/geo/vectors_mgrs.h")["mgrs_enc_vectors"]
    near = tolerances("tests/geo/test_geo_mgrs.c")["MGRS_NEAR_NM"]
    lat = np.array([r["lat"] for r in enc])
    lon = np.array([r["lon"] for r in enc])
    for k, prec in enumerate(range(-1, 12)):
        a = drdc.geo_mgrs_encode_array(lat, lon, prec)
        assert (a.status == 0).all()
        for r, text in zip(enc, a.text.tolist()):
            # GeoConvert's double may differ within nanometres of a 1 um
            # boundary, as the Unity suite allows
            assert text == r["text"][k] or r["near_nm"] <= near
    # from the Q47.16 position: the same 100 km square, but for points
    # within a millimetre of a band's or a square's edge, where the
    # rounding of the position may cross it
    u = drdc.geo_to_utm_array(lat, lon)
    b = drdc.geo_mgrs_from_utm_array(*u[:4], 0)
    assert (b.status == 0).all()
    mm = DEG // 3600 // 30 // 1000  # nas of a millimetre, about
    # distance to the nearest band edge (-80 + 8k degrees)
    band = np.abs((lat + 84 * DEG) % (8 * DEG) - 4 * DEG)
    square = 100000 * 65536
    edge_e = np.minimum(u.easting_q47_16 % square,
                        square - u.easting_q47_16 % square)
    edge_n = np.minimum(u.northing_q47_16 % square,
                        square - u.northing_q47_16 % square)
    far = (band > mm) & (edge_e > 66) & (edge_n > 66)  # 66 / 2^16: 1 mm
    got, want = np.array(b.text), np.array([r["text"][1] for r in enc])
    assert far.sum() > 0.95 * len(enc)
    assert (got[far] == want[far]).all()


def test_time_arrays_against_the_calendar():
    rng = np.random.default_rng(3)
    days = rng.integers(0, 100 * 365, 500)
    seconds = rng.integers(0, 86400, 500)
    sec = days * 86400 + seconds
    c = drdc.time_to_civil_array(sec, 123)
    for i in range(500):
        d = datetime.datetime(1970, 1, 1) + datetime.timedelta(
            seconds=int(sec[i]))
        assert (c.year[i], c.month[i], c.day[i], c.hour[i], c.minute[i],
                c.second[i], c.nsec[i]) == (d.year, d.month, d.day, d.hour,
                                            d.minute, d.second, 123)
    back = drdc.time_from_civil_array(*c[:7])
    assert (back.sec == sec).all() and (back.nsec == 123).all()
    # the leap second at the end of 2016, and 30 February
    leap = drdc.time_from_civil_array(2016, 12, 31, 23, 59, [60, 60],
                                      [0, 5])
    assert leap.sec.tolist() == [calendar.timegm((2016, 12, 31, 23, 59,
                                                  59))] * 2
    assert leap.nsec.tolist() == [10**9, 10**9 + 5]
    bad = drdc.time_from_civil_array(2017, 2, 30)
    assert drdc.status_name_array(bad.status).item() == "DRDC_E_DAY"
    assert bad.sec == 0


def test_iso8601_text_against_datetime():
    rng = np.random.default_rng(4)
    sec = rng.integers(0, 4 * 10**9, 300)
    nsec = rng.integers(0, 10**9, 300)
    t = drdc.format_utc_array(sec, nsec)
    assert (t.status == 0).all()
    for s, n, text in zip(sec.tolist(), nsec.tolist(), t.text.tolist()):
        d = datetime.datetime(1970, 1, 1) + datetime.timedelta(seconds=s)
        assert text == d.strftime("%Y-%m-%dT%H:%M:%S") + ".%09dZ" % n
    back = drdc.time_iso8601_parse_array(t.text)
    assert (back.sec == sec).all() and (back.nsec == nsec).all()
    leap = drdc.format_utc_array(1483228799, 1500000000, 3)
    assert leap.text.item() == "2016-12-31T23:59:60.500Z"
    assert drdc.time_iso8601_format(1483228799, 1500000000) == \
        "2016-12-31T23:59:60.500000000Z"
    assert drdc.time_iso8601_parse("2016-12-31T23:59:60.5Z") == \
        (1483228799, 1500000000)
    out = drdc.format_utc_array([0, 0], [0, -1])
    assert out.text.tolist()[1] == ""
    assert drdc.status_name_array(out.status).tolist() == [
        "DRDC_OK", "DRDC_E_NANOSECOND"]
    bad = drdc.time_iso8601_parse_array(np.array(["2017-02-30T00:00:00Z",
                                                  "x", "\u00e9"]))
    assert drdc.status_name_array(bad.status).tolist() == [
        "DRDC_E_DAY", "DRDC_E_SYNTAX", "DRDC_E_SYNTAX"]


def exact_decimal(value, decimals):
    """A Fraction with `decimals` decimals, ties away from zero."""
    q = value * 10**decimals
    n = (abs(q.numerator) * 2 + q.denominator) // (2 * q.denominator)
    text = "%d.%0*d" % (n // 10**decimals, decimals, n % 10**decimals) \
        if decimals else "%d" % n
    return ("-" if q < 0 and n else "") + text


def test_decimal_text_is_exact():
    rng = np.random.default_rng(6)
    q47 = np.concatenate([rng.integers(-(1 << 62), 1 << 62, 400),
                          [0, 1, -1, 1 << 16, -(1 << 63), (1 << 63) - 1,
                           32768, -32768]])
    text = drdc.format_q47_16_array(q47).tolist()
    for v, t in zip(q47.tolist(), text):
        # the exact value: parsing the text gives it back
        assert Fraction(t) == Fraction(v, 1 << 16), (v, t)
        assert not (("." in t) and t.endswith("0")), t
    assert drdc.format_q47_16_array([32768, 65536, -98304]).tolist() == \
        ["0.5", "1", "-1.5"]
    for d in (0, 3, 4, 9):
        for v, t in zip(q47.tolist()[:100],
                        drdc.format_q47_16_array(q47[:100], d).tolist()):
            assert t == exact_decimal(Fraction(v, 1 << 16), d)
    nas = np.concatenate([rng.integers(-(1 << 63), (1 << 63) - 1, 400),
                          [0, 1, -1, 18, -18, DEG, -(1 << 63)]])
    for d in (0, 9, 12, 13, 18):
        for v, t in zip(nas.tolist(),
                        drdc.format_nas_degrees_array(nas, d).tolist()):
            assert t == exact_decimal(Fraction(v, DEG), d), (v, d)
    # 13 decimals give the nas back (within the angles degrees_to_nas
    # takes as text: up to 540 degrees in NMEA's ddmm shape)
    small = rng.integers(-540 * DEG, 540 * DEG, 400)
    back = [drdc.degrees_to_nas(t) for t in
            drdc.format_nas_degrees_array(small, 13).tolist()]
    assert back == small.tolist()
    bam = rng.integers(0, 1 << 32, 300)
    for v, t in zip(bam.tolist(),
                    drdc.format_bam32_degrees_array(bam).tolist()):
        assert t == exact_decimal(Fraction(v * 360, 1 << 32), 8)
    assert drdc.format_bam32_degrees_array(-(1 << 30)).item() == \
        "270.00000000"
    with pytest.raises(ValueError):
        drdc.format_nas_degrees_array(0, 19)
    with pytest.raises(ValueError):
        drdc.format_fixed_array(0, 30)  # exact needs 30 decimals
    assert drdc.format_fixed_array(1 << 29, 30, 3).item() == "0.500"


def test_status_names_as_arrays():
    codes = np.array([[0, 24], [31, 1000], [-1, 29]])
    names = drdc.status_name_array(codes)
    assert names.shape == (3, 2)
    assert names.tolist() == [["DRDC_OK", "DRDC_E_CHECKSUM"],
                              ["DRDC_E_LATITUDE", "DRDC_E_?"],
                              ["DRDC_E_?", "DRDC_E_NO_FIX"]]
    for s in drdc.Status:
        assert drdc.status_name_array(int(s)).item() == s.name
