# SPDX-License-Identifier: BSD-2-Clause
"""Time scales against the ERFA vectors of tests/time/vectors_time.h:
every leap second since 1972 (the specials) and 10 000 random instants
drawn with the C suite's own generator, through the array entry points
and the scalar ones."""
import warnings

import numpy as np
import pytest

import drdc
from cvectors import load, tolerances

V = load("tests/time/vectors_time.h")
C = tolerances("tests/time/test_time_scales.c")  # GPS_EPOCH_TAI, NS, DAY
TAI_EPOCH_TO_UNIX = 378691200  # DRDC_TIME_TAI_EPOCH_TO_UNIX, time_scales.h
WEEK = 604800
EXPIRED = int(drdc.Status.DRDC_W_LEAP_EXPIRED)


def expected(sec, nsec, tai_utc):
    """TAI, GPS and Unix of a UTC instant with the oracle's TAI-UTC (the
    vectors' tai_excess, which counts the leap second itself in 23:59:60)."""
    tai = sec + TAI_EPOCH_TO_UNIX + tai_utc
    gps = tai - C["GPS_EPOCH_TAI"]
    # POSIX has no 23:59:60: it is 00:00:00 of the next day
    unix = sec + nsec // C["NS"]
    return tai, (gps // WEEK, gps % WEEK), unix, nsec % C["NS"]


def expected_status(sec):
    """DRDC_W_LEAP_EXPIRED on and after the IERS file's expiry day, as the
    C suite expects."""
    expiry = V["defines"]["LEAP_ORACLE_EXPIRY_DAY"]
    return EXPIRED if sec // C["DAY"] >= expiry else 0


def random_instants():
    """The C suite's draws: the same LCG, seed and span (vectors_time.h)."""
    d = V["defines"]
    state = d["RANDOM_SEED"]
    out = []
    for _ in V["random_dates"]:
        draws = []
        for _ in range(2):
            state = (state * d["LCG_MUL"] + d["LCG_ADD"]) % (1 << 64)
            draws.append(state >> 32)
        a, b = draws
        out.append((d["RANDOM_START"] + ((a * d["RANDOM_SPAN"]) >> 32),
                    (b * C["NS"]) >> 32))
    return out


def test_specials_every_leap_second():
    rows = V["time_specials"]
    sec = np.array([r["utc_sec"] for r in rows], np.int64)
    nsec = np.array([r["nsec"] for r in rows], np.int64)
    tai = drdc.time_utc_to_tai_array(sec, nsec)
    gps = drdc.time_utc_to_gps_array(sec, nsec)
    unix = drdc.time_utc_to_unix_array(sec, nsec)
    for i, r in enumerate(rows):
        want_tai, (week, tow), want_unix, ns = expected(
            r["utc_sec"], r["nsec"], r["tai_excess"])
        status = expected_status(r["utc_sec"])
        assert tai.status[i] == status, r
        assert (tai.sec[i], tai.nsec[i]) == (want_tai, ns), r
        assert (unix.sec[i], unix.nsec[i]) == (want_unix, ns), r
        if want_tai >= C["GPS_EPOCH_TAI"]:
            assert gps.status[i] == status
            assert (gps.week[i], gps.tow[i], gps.nsec[i]) == (week, tow, ns)
            with warnings.catch_warnings():
                # past the expiry the scalar call warns; the result stands
                warnings.simplefilter("ignore", drdc.DrdcWarning)
                back = drdc.time_gps_to_utc(week, tow, ns)
            assert back == (r["utc_sec"], r["nsec"]), r
        else:
            assert gps.status[i] == drdc.Status.DRDC_E_RANGE
        civil = drdc.time_to_civil(r["utc_sec"], r["nsec"])
        assert civil == (r["year"], r["month"], r["day"], r["hour"],
                         r["minute"], r["second"], r["nsec"] % C["NS"])
        assert drdc.time_from_civil(*civil) == (r["utc_sec"], r["nsec"])
    back = drdc.time_tai_to_utc_array(tai.sec, tai.nsec)
    assert (back.sec == sec).all() and (back.nsec == nsec).all()


def test_random_instants_match_erfa():
    drawn = random_instants()
    sec = np.array([s for s, _ in drawn], np.int64)
    nsec = np.array([n for _, n in drawn], np.int64)
    flags = V["random_tai_utc"]
    tai = drdc.time_utc_to_tai_array(sec, nsec)
    gps = drdc.time_utc_to_gps_array(sec, nsec)
    for i, (s, n) in enumerate(drawn):
        want_tai, (week, tow), _, ns = expected(s, n, flags[i] & 0x7F)
        # the vector's flag: past the IERS file's expiry, a warning
        want_status = EXPIRED if flags[i] & 0x80 else 0
        assert tai.status[i] == want_status
        assert (tai.sec[i], tai.nsec[i]) == (want_tai, ns)
        if want_tai >= C["GPS_EPOCH_TAI"]:
            assert gps.status[i] == want_status
            assert (gps.week[i], gps.tow[i], gps.nsec[i]) == (week, tow, ns)
    # and back: the UTC of each GPS time is the instant drawn
    ok = gps.status != drdc.Status.DRDC_E_RANGE
    back = drdc.time_gps_to_utc_array(gps.week[ok], gps.tow[ok], gps.nsec[ok])
    assert (back.sec == sec[ok]).all() and (back.nsec == nsec[ok]).all()


def test_scalar_warning_past_the_expiry_returns_the_result():
    # 2100-01-01: past any leap-second table's expiry
    t = drdc.time_from_civil(2100, 1, 1)
    with pytest.warns(drdc.DrdcWarning) as w:
        g = drdc.time_utc_to_gps(*t)
    assert w[0].message.name == "DRDC_W_LEAP_EXPIRED"
    assert g.week > 6000
    with warnings.catch_warnings():
        warnings.simplefilter("error", drdc.DrdcWarning)
        with pytest.raises(drdc.DrdcWarning):
            drdc.time_utc_to_gps(*t)


def test_header_examples():
    # time_scales.h: 2016-12-31T23:59:60 -> TAI 1861920036; GPS week 1024
    assert drdc.time_utc_to_tai(1483228799, 1000000000).sec == 1861920036
    assert drdc.time_to_civil(*drdc.time_gps_to_utc(1024, 0))[:6] \
        == (1999, 8, 21, 23, 59, 47)
    assert drdc.time_from_civil(2016, 12, 31, 23, 59, 60, 500000000) \
        == (1483228799, 1500000000)
