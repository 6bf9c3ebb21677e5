# SPDX-License-Identifier: BSD-2-Clause
"""Time (core/include/drdc/time.h, time_scales.h): UTC is the hub. A UTC
instant is (sec, nsec): POSIX-style seconds since 1970 counting 86 400 a
day, and nanoseconds, nsec in [1e9, 2e9) during a leap second (23:59:60
is written as 23:59:59 plus 1e9 ns). Every call uses the library's
built-in leap-second table (the C functions' leap argument NULL)."""
import ctypes
from collections import namedtuple

import numpy as np

from . import _check
from ._lib import (COUNT_CONVERSIONS, Time, TimeCivil, TimeCount, TimeGps,
                   lib)
from ._status import check

Utc = namedtuple("Utc", "sec nsec")
Count = namedtuple("Count", "sec nsec")
Gps = namedtuple("Gps", "week tow nsec")
Civil = namedtuple("Civil", "year month day hour minute second nsec")
UtcArrays = namedtuple("UtcArrays", "sec nsec status")
CountArrays = namedtuple("CountArrays", "sec nsec status")
GpsArrays = namedtuple("GpsArrays", "week tow nsec status")


def _utc(sec, nsec):
    return Time(_check.integer(sec, "sec", _check.INT64),
                _check.integer(nsec, "nsec", _check.INT32))


def _count(sec, nsec):
    return TimeCount(_check.integer(sec, "sec", _check.INT64),
                     _check.integer(nsec, "nsec", _check.INT32))


def time_from_civil(year, month, day, hour=0, minute=0, second=0, nsec=0):
    """drdc_time_from_civil: broken-down UTC (second 60 in a leap second)
    -> Utc(sec, nsec)."""
    fields = dict(year=year, month=month, day=day, hour=hour, minute=minute,
                  second=second, nsec=nsec)
    c = TimeCivil(**{k: _check.integer(v, k, _check.INT32)
                     for k, v in fields.items()})
    t = Time()
    check(lib.drdc_time_from_civil(None, ctypes.byref(c), ctypes.byref(t)),
          "drdc_time_from_civil")
    return Utc(t.sec, t.nsec)


def time_to_civil(sec, nsec=0):
    """drdc_time_to_civil: a UTC instant -> Civil(year, ..., second, nsec)."""
    t, c = _utc(sec, nsec), TimeCivil()
    check(lib.drdc_time_to_civil(None, ctypes.byref(t), ctypes.byref(c)),
          "drdc_time_to_civil")
    return Civil(c.year, c.month, c.day, c.hour, c.minute, c.second, c.nsec)


def _scalar(function, make_in, args, out_type, result):
    a = make_in(*args)
    out = out_type()
    check(getattr(lib, function)(None, ctypes.byref(a), ctypes.byref(out)),
          function)
    return result(out)


def time_utc_to_gps(sec, nsec=0):
    """drdc_time_utc_to_gps: UTC -> Gps(week, tow, nsec), full week."""
    return _scalar("drdc_time_utc_to_gps", _utc, (sec, nsec), TimeGps,
                   lambda g: Gps(g.week, g.tow, g.nsec))


def time_gps_to_utc(week, tow, nsec=0):
    """drdc_time_gps_to_utc: GPS full week, time of week (s) -> Utc."""
    g = TimeGps(_check.integer(week, "week", _check.INT32),
                _check.integer(tow, "tow", _check.INT32),
                _check.integer(nsec, "nsec", _check.INT32))
    t = Time()
    check(lib.drdc_time_gps_to_utc(None, ctypes.byref(g), ctypes.byref(t)),
          "drdc_time_gps_to_utc")
    return Utc(t.sec, t.nsec)


def time_utc_to_tai(sec, nsec=0):
    """drdc_time_utc_to_tai: UTC -> TAI seconds since 1958-01-01, Count."""
    return _scalar("drdc_time_utc_to_tai", _utc, (sec, nsec), TimeCount,
                   lambda c: Count(c.sec, c.nsec))


def time_tai_to_utc(sec, nsec=0):
    """drdc_time_tai_to_utc: TAI seconds since 1958-01-01 -> Utc."""
    return _scalar("drdc_time_tai_to_utc", _count, (sec, nsec), Time,
                   lambda t: Utc(t.sec, t.nsec))


def time_utc_to_unix(sec, nsec=0):
    """drdc_time_utc_to_unix: UTC -> Unix seconds, Count (a leap second
    maps to the next midnight, as POSIX)."""
    return _scalar("drdc_time_utc_to_unix", _utc, (sec, nsec), TimeCount,
                   lambda c: Count(c.sec, c.nsec))


def time_unix_to_utc(sec, nsec=0):
    """drdc_time_unix_to_utc: Unix seconds -> Utc (never a leap second)."""
    a, t = _count(sec, nsec), Time()
    check(lib.drdc_time_unix_to_utc(ctypes.byref(a), ctypes.byref(t)),
          "drdc_time_unix_to_utc")
    return Utc(t.sec, t.nsec)


# ---- arrays: one status per element, outputs 0 where it is an error ----

def _count_array(which, sec, nsec, result):
    """One of batch.c's (seconds, nanoseconds) conversions over arrays."""
    (s, n), shape = _check.broadcast(
        _check.integer_array(sec, "sec", _check.INT64, np.int64),
        _check.integer_array(nsec, "nsec", _check.INT32, np.int32))
    out_sec = np.zeros(s.size, np.int64)
    out_nsec = np.zeros(s.size, np.int32)
    status = np.zeros(s.size, np.int32)
    lib.drdc_batch_time_count(COUNT_CONVERSIONS.index(which), s.size,
                              *(a.ctypes.data for a in
                                (s, n, out_sec, out_nsec, status)))
    return result(*(a.reshape(shape) for a in (out_sec, out_nsec, status)))


def time_utc_to_gps_array(sec, nsec=0):
    """drdc_time_utc_to_gps over arrays (broadcast together): GpsArrays of
    week, tow, nsec and status (int32)."""
    (s, n), shape = _check.broadcast(
        _check.integer_array(sec, "sec", _check.INT64, np.int64),
        _check.integer_array(nsec, "nsec", _check.INT32, np.int32))
    outs = [np.zeros(s.size, np.int32) for _ in range(4)]
    lib.drdc_batch_time_utc_to_gps(s.size, *(a.ctypes.data for a in
                                             [s, n] + outs))
    return GpsArrays(*(a.reshape(shape) for a in outs))


def time_gps_to_utc_array(week, tow, nsec=0):
    """drdc_time_gps_to_utc over arrays (broadcast together): UtcArrays."""
    (w, t, n), shape = _check.broadcast(
        _check.integer_array(week, "week", _check.INT32, np.int32),
        _check.integer_array(tow, "tow", _check.INT32, np.int32),
        _check.integer_array(nsec, "nsec", _check.INT32, np.int32))
    sec = np.zeros(w.size, np.int64)
    ns = np.zeros(w.size, np.int32)
    status = np.zeros(w.size, np.int32)
    lib.drdc_batch_time_gps_to_utc(w.size, *(a.ctypes.data for a in
                                             (w, t, n, sec, ns, status)))
    return UtcArrays(sec.reshape(shape), ns.reshape(shape),
                     status.reshape(shape))


def time_utc_to_tai_array(sec, nsec=0):
    """drdc_time_utc_to_tai over arrays: CountArrays (sec int64)."""
    return _count_array("utc_to_tai", sec, nsec, CountArrays)


def time_tai_to_utc_array(sec, nsec=0):
    """drdc_time_tai_to_utc over arrays: UtcArrays (sec int64)."""
    return _count_array("tai_to_utc", sec, nsec, UtcArrays)


def time_utc_to_unix_array(sec, nsec=0):
    """drdc_time_utc_to_unix over arrays: CountArrays (sec int64)."""
    return _count_array("utc_to_unix", sec, nsec, CountArrays)


def time_unix_to_utc_array(sec, nsec=0):
    """drdc_time_unix_to_utc over arrays: UtcArrays (sec int64)."""
    return _count_array("unix_to_utc", sec, nsec, UtcArrays)


CivilArrays = namedtuple("CivilArrays", Civil._fields + ("status",))
StampArrays = namedtuple("StampArrays", "stamp status")
ISO8601_SIZE = 31  # DRDC_TIME_ISO8601_SIZE


def time_from_civil_array(year, month, day, hour=0, minute=0, second=0,
                          nsec=0):
    """drdc_time_from_civil over arrays (broadcast together): UtcArrays of
    sec (int64), nsec (int32) and status."""
    fields, shape = _check.broadcast(*(
        _check.integer_array(v, k, _check.INT32, np.int32) for k, v in (
            ("year", year), ("month", month), ("day", day), ("hour", hour),
            ("minute", minute), ("second", second), ("nsec", nsec))))
    n = fields[0].size
    civil = np.ascontiguousarray(np.stack(fields, axis=1)) if n else \
        np.zeros((0, 7), np.int32)
    sec = np.zeros(n, np.int64)
    ns = np.zeros(n, np.int32)
    status = np.zeros(n, np.int32)
    lib.drdc_batch_time_from_civil(n, civil.ctypes.data, sec.ctypes.data,
                                   ns.ctypes.data, status.ctypes.data)
    return UtcArrays(sec.reshape(shape), ns.reshape(shape),
                     status.reshape(shape))


def time_to_civil_array(sec, nsec=0):
    """drdc_time_to_civil over arrays: CivilArrays of year, month, day,
    hour, minute, second, nsec (int32) and status."""
    (s, n), shape = _check.broadcast(
        _check.integer_array(sec, "sec", _check.INT64, np.int64),
        _check.integer_array(nsec, "nsec", _check.INT32, np.int32))
    civil = np.zeros((s.size, 7), np.int32)
    status = np.zeros(s.size, np.int32)
    lib.drdc_batch_time_to_civil(s.size, s.ctypes.data, n.ctypes.data,
                                 civil.ctypes.data, status.ctypes.data)
    return CivilArrays(*(civil[:, k].reshape(shape) for k in range(7)),
                       status.reshape(shape))


def time_iso8601_format(sec, nsec=0, digits=9):
    """drdc_time_iso8601_format: a UTC instant as ISO 8601 text,
    "2016-12-31T23:59:60.500000000Z" (digits 0..9, truncated)."""
    from ._format import format_utc_array
    r = format_utc_array(_check.integer(sec, "sec", _check.INT64),
                         _check.integer(nsec, "nsec", _check.INT32), digits)
    check(int(r.status), "drdc_time_iso8601_format")
    return str(r.text)


def time_iso8601_parse_array(text):
    """drdc_time_iso8601_parse over an array of str: UtcArrays (an element
    beyond ASCII or holding a NUL: DRDC_E_SYNTAX)."""
    from ._geo import text_rows
    from ._status import Status
    rows, width, bad, shape = text_rows(text, "text")
    n = rows.size
    sec = np.zeros(n, np.int64)
    ns = np.zeros(n, np.int32)
    status = np.zeros(n, np.int32)
    scratch = ctypes.create_string_buffer(width + 1)
    lib.drdc_batch_time_iso8601_parse(n, rows.ctypes.data, width, scratch,
                                      sec.ctypes.data, ns.ctypes.data,
                                      status.ctypes.data)
    if bad.any():
        status[bad] = Status.DRDC_E_SYNTAX
        sec[bad] = 0
        ns[bad] = 0
    return UtcArrays(sec.reshape(shape), ns.reshape(shape),
                     status.reshape(shape))


def time_iso8601_parse(text):
    """drdc_time_iso8601_parse: "2016-12-31T23:59:60.5Z" -> Utc."""
    if not isinstance(text, str):
        raise TypeError("text: a str, not %s" % type(text).__name__)
    r = time_iso8601_parse_array(np.array([text]))
    check(int(r.status[0]), "drdc_time_iso8601_parse")
    return Utc(int(r.sec[0]), int(r.nsec[0]))


def time_jaus_pack_array(sec, nsec=0):
    """drdc_time_jaus_pack over arrays: StampArrays of the JAUS time stamp
    (uint32: day, hour, minute, second, milliseconds) and status."""
    (s, n), shape = _check.broadcast(
        _check.integer_array(sec, "sec", _check.INT64, np.int64),
        _check.integer_array(nsec, "nsec", _check.INT32, np.int32))
    stamp = np.zeros(s.size, np.uint32)
    status = np.zeros(s.size, np.int32)
    lib.drdc_batch_time_jaus_pack(s.size, s.ctypes.data, n.ctypes.data,
                                  stamp.ctypes.data, status.ctypes.data)
    return StampArrays(stamp.reshape(shape), status.reshape(shape))


def time_jaus_pack(sec, nsec=0):
    """drdc_time_jaus_pack: a UTC instant -> its JAUS time stamp (int)."""
    r = time_jaus_pack_array(_check.integer(sec, "sec", _check.INT64),
                             _check.integer(nsec, "nsec", _check.INT32))
    check(int(r.status), "drdc_time_jaus_pack")
    return int(r.stamp)


def time_jaus_to_utc_array(stamp, ref_sec, ref_nsec=0):
    """drdc_time_jaus_to_utc over arrays: the full UTC instant of each JAUS
    time stamp, month and year from a reference instant within half a
    month: UtcArrays."""
    (st, rs, rn), shape = _check.broadcast(
        _check.integer_array(stamp, "stamp", _check.UINT32, np.uint32),
        _check.integer_array(ref_sec, "ref_sec", _check.INT64, np.int64),
        _check.integer_array(ref_nsec, "ref_nsec", _check.INT32, np.int32))
    sec = np.zeros(st.size, np.int64)
    ns = np.zeros(st.size, np.int32)
    status = np.zeros(st.size, np.int32)
    lib.drdc_batch_time_jaus_to_utc(st.size, st.ctypes.data, rs.ctypes.data,
                                    rn.ctypes.data, sec.ctypes.data,
                                    ns.ctypes.data, status.ctypes.data)
    return UtcArrays(sec.reshape(shape), ns.reshape(shape),
                     status.reshape(shape))


def time_jaus_to_utc(stamp, ref_sec, ref_nsec=0):
    """drdc_time_jaus_to_utc: a JAUS time stamp and a reference -> Utc."""
    r = time_jaus_to_utc_array(_check.integer(stamp, "stamp", _check.UINT32),
                               _check.integer(ref_sec, "ref_sec",
                                              _check.INT64),
                               _check.integer(ref_nsec, "ref_nsec",
                                              _check.INT32))
    check(int(r.status), "drdc_time_jaus_to_utc")
    return Utc(int(r.sec), int(r.nsec))
