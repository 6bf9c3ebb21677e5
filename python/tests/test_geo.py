# SPDX-License-Identifier: BSD-2-Clause
"""Geodesy against the GeographicLib vectors of tests/geo/ (the Unity
suite's, with its tolerances from tests/geo/test_geo_utm.c), through the
array entry points and the scalar ones."""
import numpy as np
import pytest

import drdc
from cvectors import load, tolerances

GEO = "tests/geo/vectors_geo.h"
TOL = tolerances("tests/geo/test_geo_utm.c")
TURN = 360 * drdc.NAS_PER_DEGREE


def column(rows, name):
    return np.array([r[name] for r in rows], dtype=np.int64)


def lon_dist(a, b):
    """|a - b| of longitudes in nas, modulo 360 degrees (as the suite)."""
    d = np.abs(a - b)
    return np.where(d > TURN // 2, TURN - d, d)


@pytest.mark.parametrize("table,rev,forced,with_scale", [
    ("geo_random_vectors", "geo_random_rev", False, False),
    ("geo_edge_vectors", "geo_edge_rev", False, True),
    ("geo_forced_vectors", "geo_forced_rev", True, True),
])
def test_utm_forward_and_reverse_arrays(table, rev, forced, with_scale):
    rows, back = load(GEO)[table], load(GEO)[rev]
    zone = column(rows, "zone") if forced else drdc.ZONE_STANDARD
    u = drdc.geo_to_utm_array(column(rows, "lat"), column(rows, "lon"), zone)
    assert (u.status == 0).all()
    assert (u.zone == column(rows, "zone")).all()
    assert (u.north == (column(rows, "north") != 0)).all()
    assert np.abs(u.easting_q47_16 - column(rows, "easting")).max() \
        <= TOL["EN_TOL"]
    assert np.abs(u.northing_q47_16 - column(rows, "northing")).max() \
        <= TOL["EN_TOL"]
    assert lon_dist(u.convergence_nas, column(rows, "convergence")).max() \
        <= TOL["CONV_TOL"]
    assert np.abs(u.scale_q5_58 - column(rows, "scale")).max() \
        <= TOL["SCALE_TOL"]

    g = drdc.geo_from_utm_array(column(rows, "zone"), column(rows, "north"),
                                column(rows, "easting"),
                                column(rows, "northing"),
                                with_scale=with_scale)
    assert (g.status == 0).all()
    # convergence and scale only when asked for: the same position
    plain = drdc.geo_from_utm_array(column(rows, "zone"),
                                    column(rows, "north"),
                                    column(rows, "easting"),
                                    column(rows, "northing"))
    assert plain.convergence_nas is None and plain.scale_q5_58 is None
    assert (plain.lat_nas == g.lat_nas).all()
    assert (plain.lon_nas == g.lon_nas).all()
    assert np.abs(g.lat_nas - column(back, "lat")).max() <= TOL["LATLON_TOL"]
    assert lon_dist(g.lon_nas, column(back, "lon")).max() \
        <= TOL["LATLON_TOL"]
    if with_scale:
        utm = column(rows, "zone") != 0  # UPS: see the suite's comment
        assert lon_dist(g.convergence_nas[utm],
                        column(rows, "convergence")[utm]).max() \
            <= TOL["REV_CONV_TOL"]
        assert np.abs(g.scale_q5_58[utm] - column(rows, "scale")[utm]).max() \
            <= TOL["REV_SCALE_TOL"]


def test_scalar_calls_give_the_array_bits():
    rows = load(GEO)["geo_edge_vectors"][::37]
    lat, lon = column(rows, "lat"), column(rows, "lon")
    a = drdc.geo_to_utm_array(lat, lon)
    for i, r in enumerate(rows):
        u = drdc.geo_to_utm(r["lat"], r["lon"])
        assert u == tuple(int(x[i]) if x.dtype != bool else bool(x[i])
                          for x in a[:6])
        g = drdc.geo_from_utm(u.zone, u.north, u.easting_q47_16,
                              u.northing_q47_16)
        assert abs(g.lat_nas - r["lat"]) < drdc.NAS_PER_DEGREE // 3600


def test_tm_forward_beyond_the_zones():
    worst = {"en": 0, "conv": 0, "scale": 0}
    for r in load(GEO)["geo_tm_vectors"]:
        t = drdc.geo_tm_forward(r["lat"], r["dlon"])
        worst["en"] = max(worst["en"], abs(t.x_q47_16 - r["x"]),
                          abs(t.y_q47_16 - r["y"]))
        worst["conv"] = max(worst["conv"], abs(t.convergence_nas
                                               - r["convergence"]))
        worst["scale"] = max(worst["scale"], abs(t.scale_q5_58 - r["scale"]))
    assert worst["en"] <= TOL["EN_TOL"]
    assert worst["conv"] <= TOL["CONV_TOL"]
    assert worst["scale"] <= TOL["TM_SCALE_TOL"]


MGRS = "tests/geo/vectors_mgrs.h"


def within_last_digit(got, want):
    """Same text but for one unit of the last digit of the easting or the
    northing digits (the suite's allowance near a 1 um boundary)."""
    if len(got) != len(want):
        return False
    head = len(got) - 2 * ((len(got) - len(got.rstrip("0123456789"))) // 2)
    digits = (len(got) - head) // 2
    if got[:head] != want[:head] or digits == 0:
        return False
    pairs = [(got[head:head + digits], want[head:head + digits]),
             (got[head + digits:], want[head + digits:])]
    return all(abs(int(a) - int(b)) <= 1 for a, b in pairs)


def test_mgrs_encode_every_precision():
    v = load(MGRS)
    first = v["defines"]["MGRS_PREC_FIRST"]
    near = tolerances("tests/geo/test_geo_mgrs.c")["MGRS_NEAR_NM"]
    rows = v["mgrs_enc_vectors"]
    lat, lon = column(rows, "lat"), column(rows, "lon")
    for k in range(v["defines"]["MGRS_PRECS"]):
        m = drdc.geo_mgrs_encode_array(lat, lon, first + k)
        assert (m.status == 0).all()
        for got, r in zip(m.text.tolist(), rows):
            want = r["text"][k]
            if got != want:
                assert r["near_nm"] <= near, (got, want)
                assert within_last_digit(got, want), (got, want)


def test_mgrs_decode_statuses_and_centres():
    for r in load(MGRS)["mgrs_dec_vectors"]:
        if r["status"] != 0:
            with pytest.raises(drdc.DrdcError) as e:
                drdc.geo_mgrs_decode(r["text"])
            assert e.value.code == r["status"], r["text"]
            continue
        d = drdc.geo_mgrs_decode(r["text"])
        assert d.centre == (r["zone"], r["north"] != 0, r["easting"],
                            r["northing"]), r["text"]


def test_mgrs_decode_array_gives_the_vectors():
    rows = load(MGRS)["mgrs_dec_vectors"]
    d = drdc.geo_mgrs_decode_array(np.array([r["text"] for r in rows]))
    assert list(d.status) == [r["status"] for r in rows]
    ok = d.status == 0
    for name, field in (("zone", "zone"), ("easting_q47_16", "easting"),
                        ("northing_q47_16", "northing")):
        assert (getattr(d, name)[ok] == column(rows, field)[ok]).all()
    assert (d.north[ok] == (column(rows, "north")[ok] != 0)).all()
    bad = drdc.geo_mgrs_decode_array(["38SMB4414084706", "38SMB\x0044",
                                      "38SMB44140847\u00e9"])
    assert list(bad.status) == [0, drdc.Status.DRDC_E_MGRS,
                                drdc.Status.DRDC_E_MGRS]
    assert bad.prec[0] == 5


def test_header_examples():
    # geo.h and geo_mgrs.h: lat 10, lon 20 -> 34n 390 399.2275 1 105 578.5892
    u = drdc.geo_to_utm(drdc.degrees_to_nas(10), drdc.degrees_to_nas(20))
    assert (u.zone, u.north) == (34, True)
    assert round(u.easting_q47_16 / 65536, 4) == 390399.2275
    assert round(u.northing_q47_16 / 65536, 4) == 1105578.5892
    assert drdc.geo_mgrs_encode(drdc.degrees_to_nas("33.3"),
                                drdc.degrees_to_nas("44.4"), 5) \
        == "38SMB4414084706"
    assert drdc.geo_utm_zone(60 * drdc.NAS_PER_DEGREE,
                             5 * drdc.NAS_PER_DEGREE) == 32
