# SPDX-License-Identifier: BSD-2-Clause
"""UTC <-> TAI / GPS / Unix vectors across leap seconds.

Oracles, all independent of this project's code:
  - ERFA (pyerfa): eraDat for TAI-UTC, eraDtf2d + eraUtctai for UTC -> TAI
    at the leap seconds themselves (ERFA's UTC days may have 86 401 s),
    eraTaiutc + eraD2dtf for GPS week rollovers (GPS = TAI - 19 s);
  - the IERS Leap_Second.dat of the pinned astropy-iers-data package: the
    table of leap seconds and the expiry date ("File expires on ...");
  - Python's datetime and calendar.timegm: civil dates and POSIX seconds.

Random instants are drawn by a 64-bit LCG that the C suite repeats (so
their inputs take no flash); the table holds only the oracle's answers:
the civil date (16 bits) and TAI-UTC with an "expired" flag (8 bits).
"""
import calendar
import datetime
import os
import re
import warnings

import astropy_iers_data
import erfa

EPOCH = datetime.date(1970, 1, 1)
MJD_1970 = 40587
JD_1958 = 2436204.5           # 1958-01-01T00:00:00 as a Julian date
TAI_EPOCH_TO_UNIX = 378691200  # 4383 days from 1958-01-01 to 1970-01-01
RANDOM_COUNT = 10000
RANDOM_SEED = 20161231
RANDOM_START = calendar.timegm((1972, 1, 1, 0, 0, 0))
RANDOM_SPAN = calendar.timegm((2100, 1, 1, 0, 0, 0)) - RANDOM_START
LCG_MUL = 6364136223846793005
LCG_ADD = 1442695040888963407
MASK64 = (1 << 64) - 1
MONTHS = {m: i for i, m in enumerate(
    "January February March April May June July August September October "
    "November December".split(), 1)}


def _leap_second_dat():
    """(days since 1970, TAI-UTC) of each step, and the expiry day."""
    path = os.path.join(os.path.dirname(astropy_iers_data.__file__), "data",
                        "Leap_Second.dat")
    text = open(path).read()
    m = re.search(r"File expires on\s+(\d+)\s+(\w+)\s+(\d{4})", text)
    expiry = datetime.date(int(m.group(3)), MONTHS[m.group(2)], int(m.group(1)))
    rows = []
    for line in text.splitlines():
        f = line.split()
        if line.startswith("#") or len(f) != 5:
            continue
        mjd, off = float(f[0]), int(f[4])
        if mjd >= 41317:  # 1972-01-01: integer offsets from here on
            rows.append((int(mjd) - MJD_1970, off))
    return rows, (expiry - EPOCH).days


def _dat(d):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return int(erfa.dat(d.year, d.month, d.day, 0.0))


def _tai_seconds(y, mo, d, h, mi, s):
    """TAI seconds since 1958-01-01 of a whole UTC second, by ERFA."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        u1, u2 = erfa.dtf2d("UTC", y, mo, d, h, mi, float(s))
        t1, t2 = erfa.utctai(u1, u2)
    # t1 is the date part (exact); the sum keeps ~1e-6 s: round to integer
    return int(round(((float(t1) - JD_1958) + float(t2)) * 86400.0))


def _utc_of_tai(tai):
    """UTC civil fields of whole TAI seconds since 1958, by ERFA."""
    days, sod = divmod(tai, 86400)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        u1, u2 = erfa.taiutc(JD_1958 + days, sod / 86400.0)
        y, mo, d, hmsf = erfa.d2dtf("UTC", 0, u1, u2)
    return int(y), int(mo), int(d), int(hmsf[0]), int(hmsf[1]), int(hmsf[2])


def _row(y, mo, d, h, mi, s, ns, note):
    """A special instant: UTC civil -> drdc_time_t, TAI (ERFA)."""
    if s == 60:
        utc = calendar.timegm((y, mo, d, h, mi, 59))
        nsec = ns + 1000000000
    else:
        utc = calendar.timegm((y, mo, d, h, mi, s))
        nsec = ns
    tai = _tai_seconds(y, mo, d, h, mi, s)
    return (utc, tai, nsec, y, mo, d, h, mi, s, note)


def _specials(leaps):
    rows = []
    # every leap second: the second before, at, and after, at both ends
    for day, _ in leaps[1:]:
        last = EPOCH + datetime.timedelta(days=day - 1)
        nxt = EPOCH + datetime.timedelta(days=day)
        y, mo, d = last.year, last.month, last.day
        for s, ns in ((59, 0), (59, 999999999), (60, 0), (60, 500000000),
                      (60, 999999999)):
            rows.append(_row(y, mo, d, 23, 59, s, ns, "leap second"))
        rows.append(_row(nxt.year, nxt.month, nxt.day, 0, 0, 0, 0, "after leap"))
    # the GPS epoch and every week rollover, defined on the GPS side
    gps_epoch_tai = (datetime.date(1980, 1, 6) - datetime.date(1958, 1, 1)).days * 86400 + 19
    for week, tow, ns in ((0, 0, 0), (1023, 604799, 999999999), (1024, 0, 0),
                          (1024, 1, 0), (2047, 604799, 999999999), (2048, 0, 0),
                          (2048, 1, 0)):
        y, mo, d, h, mi, s = _utc_of_tai(gps_epoch_tai + week * 604800 + tow)
        rows.append(_row(y, mo, d, h, mi, s, ns, "gps week %d" % week))
    # every year end 1972..2100 and the month ends of a few years
    for y in range(1972, 2101):
        rows.append(_row(y - 1, 12, 31, 23, 59, 59, 999999999, "year end"))
        rows.append(_row(y, 1, 1, 0, 0, 0, 0, "year start"))
    for y in (1980, 2000, 2024, 2025, 2100):
        for mo in range(1, 12):
            last = calendar.monthrange(y, mo)[1]
            rows.append(_row(y, mo, last, 23, 59, 59, 999999999, "month end"))
            rows.append(_row(y, mo + 1, 1, 0, 0, 0, 0, "month start"))
    # integer TAI-UTC starts 1972-01-01; one row per instant
    unique = {}
    for r in rows:
        if (r[3], r[4], r[5]) >= (1972, 1, 1):
            unique.setdefault((r[0], r[2]), r)
    return [unique[k] for k in sorted(unique)]


def _lcg(state):
    state = (state * LCG_MUL + LCG_ADD) & MASK64
    return state, state >> 32


def _random(expiry_day):
    state = RANDOM_SEED
    dates, offs = [], []
    for _ in range(RANDOM_COUNT):
        state, a = _lcg(state)
        state, _b = _lcg(state)  # nanoseconds: drawn by the C suite too
        sec = RANDOM_START + ((a * RANDOM_SPAN) >> 32)
        date = EPOCH + datetime.timedelta(days=sec // 86400)
        dates.append(((date.year - 1972) << 9) | (date.month << 5) | date.day)
        expired = (date - EPOCH).days >= expiry_day
        offs.append(_dat(date) | (0x80 if expired else 0))
    return dates, offs


def _wrap(values, per_line, fmt):
    lines = []
    for i in range(0, len(values), per_line):
        lines.append("  " + ", ".join(fmt % v for v in values[i:i + per_line]) + ",")
    return "\n".join(lines)


def generate():
    leaps, expiry_day = _leap_second_dat()
    # The IERS file and ERFA's own table must agree on every step.
    for day, off in leaps:
        assert _dat(EPOCH + datetime.timedelta(days=day)) == off, (day, off)
        assert _dat(EPOCH + datetime.timedelta(days=day - 1)) == off - 1 or day == 730
    specials = _specials(leaps)
    dates, offs = _random(expiry_day)
    # packed to 16 bytes a row: UTC seconds as uint32 (1972..2106), and
    # ERFA's TAI as its excess over UTC + 378691200 s (TAI-UTC, plus 1
    # in a leap second), which fits an int8
    for r in specials:
        assert 0 <= r[0] < 2 ** 32 and 0 <= r[1] - r[0] - TAI_EPOCH_TO_UNIX < 128, r
    special_rows = "\n".join(
        "  { %du, %d, %d, %d, %d, %d, %d, %d, %d }, /* %s */"
        % (utc, ns, y, mo, d, h, mi, s, tai - utc - TAI_EPOCH_TO_UNIX, note)
        for utc, tai, ns, y, mo, d, h, mi, s, note in specials)
    text = """/* SPDX-License-Identifier: BSD-2-Clause */
/* Generated by tests/ref/gen_time_scales.py: UTC <-> TAI/GPS/Unix from
 * ERFA (pyerfa %s), the IERS Leap_Second.dat of astropy-iers-data %s and
 * Python's datetime/calendar. Do not edit; run tools/generate.py. */
#ifndef VECTORS_TIME_H
#define VECTORS_TIME_H

#include <stdint.h>

/* The IERS table: first day (since 1970) of each TAI-UTC value, and the
 * day the file expires. */
#define LEAP_ORACLE_EXPIRY_DAY %d
static const int32_t leap_oracle[][2] = {
%s
};

/* Special instants: UTC as drdc_time_t {utc_sec, nsec} (nsec >= 1e9 in
 * 23:59:60), its civil fields, and TAI seconds since 1958 by ERFA as
 * utc_sec + 378691200 + tai_excess (with nsec %% 1e9 nanoseconds). */
struct time_special {
  uint32_t utc_sec;
  int32_t nsec;
  int16_t year;
  uint8_t month, day, hour, minute, second;
  int8_t tai_excess;
};

static const struct time_special time_specials[] = {
%s
};

/* Random instants: the C suite draws them with the same LCG. */
#define RANDOM_SEED UINT64_C(%d)
#define RANDOM_START INT64_C(%d)
#define RANDOM_SPAN UINT64_C(%d)
#define LCG_MUL UINT64_C(%d)
#define LCG_ADD UINT64_C(%d)
/* civil date: (year - 1972) << 9 | month << 5 | day */
static const uint16_t random_dates[%d] = {
%s
};
/* TAI-UTC by eraDat; bit 7 set when on or after the expiry day */
static const uint8_t random_tai_utc[%d] = {
%s
};

#endif
""" % (erfa.__version__, astropy_iers_data.__version__, expiry_day,
       _wrap(["{ %d, %d }" % r for r in leaps], 4, "%s"), special_rows,
       RANDOM_SEED, RANDOM_START, RANDOM_SPAN, LCG_MUL, LCG_ADD,
       RANDOM_COUNT, _wrap(dates, 10, "%d"), RANDOM_COUNT,
       _wrap(offs, 16, "%d"))
    return {"tests/time/vectors_time.h": text}
