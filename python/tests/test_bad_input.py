# SPDX-License-Identifier: BSD-2-Clause
"""Bad input never crashes, hangs or wraps: non-integers are refused with
TypeError, values beyond the C type with ValueError, values the library
refuses with DrdcError (scalars) or a status (arrays)."""
import os
import subprocess

import numpy as np
import pytest

import drdc
from cvectors import TOP

DEG = drdc.NAS_PER_DEGREE


@pytest.mark.parametrize("value", [1.5, np.float64(2.0), "10", None, True,
                                   np.bool_(False), 1j])
def test_scalar_non_integers_are_type_errors(value):
    with pytest.raises(TypeError):
        drdc.geo_to_utm(value, 0)


@pytest.mark.parametrize("value", [1 << 63, -(1 << 63) - 1, 1 << 100])
def test_scalar_beyond_int64_is_a_value_error(value):
    with pytest.raises(ValueError, match="lat_nas"):
        drdc.geo_to_utm(value, 0)


def test_int32_arguments_do_not_wrap():
    # 2^32 + 12 would be zone 12 after a silent wrap
    with pytest.raises(ValueError, match="zone"):
        drdc.geo_to_utm(50 * DEG, -111 * DEG, (1 << 32) + 12)
    with pytest.raises(ValueError, match="yaw_bam32"):
        drdc.quat_from_euler(1 << 32, 0, 0)
    with pytest.raises(ValueError, match="from_frac"):
        drdc.units_convert(1, -1, "m", 0, "m")


def test_library_statuses_become_drdc_errors():
    with pytest.raises(drdc.DrdcError) as e:
        drdc.geo_to_utm(91 * DEG, 0)
    assert (e.value.code, e.value.name, e.value.function) == (
        drdc.Status.DRDC_E_LATITUDE, "DRDC_E_LATITUDE", "drdc_geo_to_utm")
    with pytest.raises(drdc.DrdcError) as e:
        drdc.geo_to_utm(0, 0, 61)
    assert e.value.name == "DRDC_E_ZONE"
    with pytest.raises(drdc.DrdcError) as e:
        drdc.time_gps_to_utc(0, 604800)
    assert e.value.name == "DRDC_E_TIME_OF_WEEK"
    with pytest.raises(drdc.DrdcError) as e:
        drdc.geo_mgrs_encode(0, 0, 12)
    assert e.value.name == "DRDC_E_RANGE"


@pytest.mark.parametrize("text", ["", "Q", "99ZZZ", "38SMB44140847066",
                                  "38SMB" + "1" * 40, "38smb4414084706 "])
def test_mgrs_text_errors(text):
    with pytest.raises(drdc.DrdcError):
        drdc.geo_mgrs_decode(text)


def test_mgrs_text_that_c_cannot_carry():
    with pytest.raises(ValueError):
        drdc.geo_mgrs_decode("38SMB\x004414084706")
    with pytest.raises(ValueError):
        drdc.geo_mgrs_decode("38SMB44140847\u00e9")
    with pytest.raises(TypeError):
        drdc.geo_mgrs_decode(b"38SMB4414084706")


@pytest.mark.parametrize("array", [np.array([1.0, 2.0]),
                                   np.array([True, False]),
                                   np.array(["1", "2"]),
                                   np.array([1, None], dtype=object),
                                   [1 << 64]])
def test_array_non_integers_are_type_errors(array):
    with pytest.raises(TypeError, match="lat_nas"):
        drdc.geo_to_utm_array(array, 0)


def test_array_beyond_the_c_type_names_the_element():
    a = np.array([0, 5, (1 << 63) + 7], np.uint64)
    with pytest.raises(ValueError, match=r"lat_nas\[2\]"):
        drdc.geo_to_utm_array(a, 0)
    with pytest.raises(ValueError, match=r"zone\[1\]"):
        drdc.geo_to_utm_array(0, 0, np.array([1, 1 << 40]))


def test_array_shapes_broadcast_or_refuse():
    u = drdc.geo_to_utm_array(np.full((2, 3), 10 * DEG), 20 * DEG)
    assert u.easting_q47_16.shape == (2, 3) and (u.status == 0).all()
    with pytest.raises(ValueError, match="shapes"):
        drdc.geo_to_utm_array(np.zeros(3, np.int64), np.zeros(4, np.int64))
    empty = drdc.geo_to_utm_array(np.zeros(0, np.int64), 0)
    assert empty.status.shape == (0,)


def test_random_garbage_gives_statuses_only():
    """Any int64 lat/lon: a documented status per element, outputs 0 where
    it is an error, no crash."""
    rng = np.random.default_rng(20261126)
    lat = rng.integers(-(1 << 63), (1 << 63) - 1, 20000, dtype=np.int64,
                       endpoint=True)
    lon = rng.integers(-(1 << 63), (1 << 63) - 1, 20000, dtype=np.int64,
                       endpoint=True)
    lat[:5] = [-(1 << 63), (1 << 63) - 1, 90 * DEG, -90 * DEG, 0]
    lon[:5] = [-(1 << 63), (1 << 63) - 1, 540 * DEG, -540 * DEG,
               540 * DEG - 1]
    u = drdc.geo_to_utm_array(lat, lon)
    allowed = {0, drdc.Status.DRDC_E_LATITUDE, drdc.Status.DRDC_E_LONGITUDE}
    assert set(np.unique(u.status).tolist()) <= allowed
    bad = u.status != 0
    assert (u.easting_q47_16[bad] == 0).all()
    g = drdc.geo_from_utm_array(rng.integers(-5, 70, 20000), 1,
                                lat >> 8, lon >> 8)
    assert set(np.unique(g.status).tolist()) <= {
        0, drdc.Status.DRDC_E_ZONE, drdc.Status.DRDC_E_EASTING,
        drdc.Status.DRDC_E_NORTHING}
    t = drdc.time_utc_to_gps_array(lat, rng.integers(-(1 << 31), 1 << 31,
                                                     20000))
    assert set(np.unique(t.status).tolist()) <= {
        0, drdc.Status.DRDC_W_LEAP_EXPIRED, drdc.Status.DRDC_E_RANGE,
        drdc.Status.DRDC_E_NANOSECOND, drdc.Status.DRDC_E_SECOND}
    q = drdc.euler_from_quat_array(*(rng.integers(-(1 << 31), 1 << 31, 20000)
                                     for _ in range(4)))
    assert set(np.unique(q.status).tolist()) <= {0}


def test_degrees_to_nas_is_exact():
    # 1e-9 degree is 3600 nas
    assert drdc.degrees_to_nas("50.270008333") == 50 * DEG + 270008333 * 3600
    assert drdc.degrees_to_nas("-111.169986667") \
        == -(111 * DEG + 169986667 * 3600)
    assert drdc.degrees_to_nas(10) == 10 * DEG
    assert drdc.degrees_to_nas("0.0000000000005") == 2  # 1.8 nas, to 2
    assert drdc.degrees_to_nas("-0.000000000000125") == 0  # -0.45 nas
    with pytest.raises(ValueError):
        drdc.degrees_to_nas("north")
    with pytest.raises(TypeError):
        drdc.degrees_to_nas(True)


def test_degrees_to_nas_refuses_huge_text_at_once():
    """Only plain decimals: an exponent would make Fraction build a power
    of ten of that many digits (1e100000000 took minutes)."""
    import time
    from decimal import Decimal
    t0 = time.monotonic()
    for bad in ["1e100000000", "1/3", "1" * 41, "0x10", "--1", "1.2.3", ""]:
        with pytest.raises(ValueError):
            drdc.degrees_to_nas(bad)
    for bad in [Decimal("1e100000000"), Decimal("NaN"), Decimal("-Infinity")]:
        with pytest.raises(ValueError):
            drdc.degrees_to_nas(bad)
    assert time.monotonic() - t0 < 1.0
    # beyond int64 nas (2.56e9 degrees) is refused, not wrapped
    with pytest.raises(ValueError):
        drdc.degrees_to_nas("2600000000")
    assert drdc.degrees_to_nas("+.5") == DEG // 2
    assert drdc.degrees_to_nas(Decimal("-1.25")) == -(5 * DEG) // 4


def test_errors_carry_the_reason_drdc_prints():
    """DrdcError: the words `drdc time` prints on its ERROR line for the
    same refusal, the status's name and number; for functions whose
    `drdc` messages quote the input, the status's meaning as status.h
    says it."""
    from test_host_tool import tool
    r = subprocess.run([tool("drdc"), "time", "--from", "utc", "--to", "gps"],
                       input="2017-02-30T00:00:00Z\n", capture_output=True,
                       text=True)
    with pytest.raises(drdc.DrdcError) as e:
        drdc.time_from_civil(2017, 2, 30)
    assert r.stdout.strip() == "ERROR: %s (%s)" % (e.value.reason,
                                                   e.value.name)
    assert (e.value.name, e.value.number) == ("DRDC_E_DAY",
                                              int(drdc.Status.DRDC_E_DAY))
    assert str(e.value) == "drdc_time_from_civil: %s (DRDC_E_DAY, %d)" % (
        e.value.reason, e.value.number)
    with pytest.raises(drdc.DrdcError) as e:
        drdc.geo_to_utm(91 * DEG, 0)
    assert e.value.reason == "a latitude outside [-90, 90] degrees"
    with open(os.path.join(TOP, "fixed/include/drdc/status.h")) as f:
        assert "/**< a latitude outside [-90, 90] degrees */" in f.read()
