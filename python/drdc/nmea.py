# SPDX-License-Identifier: BSD-2-Clause
"""NMEA 0183 in (core/include/drdc/nmea.h): one sentence, a sequence of
lines or a whole receiver log, decoded by the library's parser into its
integers, with each fix's UTC instant stitched in C exactly as
drdc_nmea_utc() does.

    from drdc import nmea
    s = nmea.parse("$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,"
                   "545.4,M,46.9,M,,*47")
    s.lat_nas                       # 173222280000000
    log = nmea.read_log("receiver.log")   # a DataFrame with pandas, else
                                          # NmeaArrays of numpy columns

**Columns** (the fields of drdc_nmea_t, named with their format):
``status`` (the parser's, int32), ``type`` ("GGA", "" where refused),
``talker``, ``has`` and ``beyond`` (DRDC_NMEA_HAS_* / BEYOND_* bits),
``hour``, ``minute``, ``second`` (60 in a leap second), ``nsec``,
``lat_nas``, ``lon_nas``, ``altitude_q47_16``, ``separation_q47_16``,
``quality``, ``satellites``, ``hdop_q15_16``, ``pdop_q15_16``,
``vdop_q15_16``, ``speed_q15_16`` (m/s), ``course_bam32``,
``course_magnetic_bam32``, ``heading_bam32``, ``mode``, ``fix_type``,
``system_id``, ``satellite_ids`` (12 a row), ``year``, ``month``,
``day``, ``zone_hours``, ``zone_minutes``, ``rms_q15_16``,
``sigma_major_q15_16``, ``sigma_minor_q15_16``, ``orientation_bam32``,
``sigma_lat_q15_16``, ``sigma_lon_q15_16``, ``sigma_alt_q15_16``; then
``utc_sec``, ``utc_nsec`` and ``utc_status`` (the stitched instant) and
``line`` (1-based). Where a line's status is an error its row is 0 but
for ``status``, ``utc_status`` and ``line``. A field the sentence does
not carry is 0: ``has`` tells which are there.

**Dating.** A sentence with a time of day (GGA, RMC, GNS, GLL, ZDA,
GST) is dated by the last RMC or ZDA before it in the lines, whatever
talker sent it, the date of an RMC without a fix included
(drdc_nmea_parse_date()); sentences before the first date by the first
one after them. The instant is drdc_nmea_utc()'s: the sentence's time of
day on the day, among the date and the days before and after, nearest
to the dated sentence's time. ``utc_status`` is that call's status; where
there is no instant it is the line's own status (refused), or
DRDC_E_MISSING_FIELD (no time of day: VTG, HDT, THS, GSA; or no date in
the lines at all).

**Lines** are those of the `drdc` tool: they end at LF; the LF and one
CR before it are no part of the sentence; a last line without LF is a
line. Every other byte is the parser's to judge (a NUL or a byte above
0x7E: DRDC_E_CHARACTER)."""
import ctypes
from collections import namedtuple

import numpy as np

from ._lib import Nmea, NmeaColumns, Time, _COLUMN_POINTERS, lib
from ._status import DrdcError, Status, check

STRICT = 0x1  # DRDC_NMEA_STRICT
LENGTH_MAX = 128  # DRDC_NMEA_LENGTH_MAX
GSA_IDS = 12  # DRDC_NMEA_GSA_IDS
# drdc_nmea_type_t, in nmea.h's order (DRDC_NMEA_GGA = 0 ...)
TYPES = ("GGA", "RMC", "GNS", "ZDA", "GST", "GLL", "VTG", "HDT", "THS",
         "GSA")
HAS = {"POSITION": 0x01, "ALTITUDE": 0x02, "SEPARATION": 0x04,
       "SATELLITES": 0x08, "HDOP": 0x10, "SPEED": 0x20, "COURSE": 0x40,
       "DATE": 0x80, "ZONE": 0x100, "GST": 0x200, "ELLIPSE": 0x400,
       "TIME": 0x800, "QUALITY": 0x1000, "HEADING": 0x2000,
       "COURSE_MAGNETIC": 0x4000, "FIX_TYPE": 0x8000, "PDOP": 0x10000,
       "VDOP": 0x20000, "SYSTEM": 0x40000}  # DRDC_NMEA_HAS_*

# (column, C field of drdc_nmea_t / the column structure, numpy dtype)
_FIELDS = [
    ("type", "type", np.int8), ("talker", "talker", "U2"),
    ("has", "has", np.uint32), ("beyond", "beyond", np.uint32),
    ("hour", "hour", np.int32), ("minute", "minute", np.int32),
    ("second", "second", np.int32), ("nsec", "nsec", np.int32),
    ("lat_nas", "latitude", np.int64), ("lon_nas", "longitude", np.int64),
    ("altitude_q47_16", "altitude", np.int64),
    ("separation_q47_16", "separation", np.int64),
    ("quality", "quality", np.int32), ("satellites", "satellites", np.int32),
    ("hdop_q15_16", "hdop", np.int32), ("pdop_q15_16", "pdop", np.int32),
    ("vdop_q15_16", "vdop", np.int32), ("speed_q15_16", "speed", np.int32),
    ("course_bam32", "course", np.uint32),
    ("course_magnetic_bam32", "course_magnetic", np.uint32),
    ("heading_bam32", "heading", np.uint32), ("mode", "mode", "U8"),
    ("fix_type", "fix_type", np.int32), ("system_id", "system_id", np.int32),
    ("satellite_ids", "satellite_ids", np.uint16),
    ("year", "year", np.int32), ("month", "month", np.int32),
    ("day", "day", np.int32), ("zone_hours", "zone_hours", np.int32),
    ("zone_minutes", "zone_minutes", np.int32),
    ("rms_q15_16", "rms", np.int32),
    ("sigma_major_q15_16", "sigma_major", np.int32),
    ("sigma_minor_q15_16", "sigma_minor", np.int32),
    ("orientation_bam32", "orientation", np.uint32),
    ("sigma_lat_q15_16", "sigma_latitude", np.int32),
    ("sigma_lon_q15_16", "sigma_longitude", np.int32),
    ("sigma_alt_q15_16", "sigma_altitude", np.int32),
]
FIELDS = tuple(name for name, _, _ in _FIELDS)
Sentence = namedtuple("Sentence", FIELDS)
NmeaArrays = namedtuple("NmeaArrays", ("status",) + FIELDS + (
    "utc_sec", "utc_nsec", "utc_status", "line"))
Utc = namedtuple("Utc", "sec nsec")


def _flags(strict):
    return STRICT if strict else 0


def _text(line):
    """A sentence's bytes: str (encoded so that a non-ASCII character stays
    one the parser refuses) or bytes."""
    if isinstance(line, str):
        return line.encode("utf-8", "surrogatepass")
    if isinstance(line, (bytes, bytearray, memoryview)):
        return bytes(line)
    raise TypeError("line: a str or bytes, not %s" % type(line).__name__)


def _line(line):
    """The sentence of one line: its LF and one CR before it taken off."""
    raw = _text(line)
    if raw.endswith(b"\n"):
        raw = raw[:-1]
    if raw.endswith(b"\r"):
        raw = raw[:-1]
    return raw


def _sentence(r):
    return Sentence(
        TYPES[r.type], r.talker.decode("ascii"), r.has, r.beyond,
        r.time.hour, r.time.minute, r.time.second, r.time.nsec,
        r.latitude, r.longitude, r.altitude, r.separation, r.quality,
        r.satellites, r.hdop, r.pdop, r.vdop, r.speed, r.course,
        r.course_magnetic, r.heading, r.mode.decode("ascii"), r.fix_type,
        r.system_id, tuple(r.satellite_ids), r.year, r.month, r.day,
        r.zone_hours, r.zone_minutes, r.rms, r.sigma_major, r.sigma_minor,
        r.orientation, r.sigma_latitude, r.sigma_longitude,
        r.sigma_altitude)


def _record(s):
    """A Sentence (or a row of NmeaArrays) back as the C record, for
    drdc_nmea_utc()."""
    r = Nmea()
    r.type = TYPES.index(s.type) if s.type in TYPES else 0
    r.has = int(s.has)
    r.time.hour, r.time.minute = int(s.hour), int(s.minute)
    r.time.second, r.time.nsec = int(s.second), int(s.nsec)
    r.year, r.month, r.day = int(s.year), int(s.month), int(s.day)
    return r


def parse(line, strict=False):
    """drdc_nmea_parse_with(): one sentence (str or bytes, from `$`; a line
    end of LF or CR LF is taken off first) -> Sentence. Raises DrdcError
    with the reason `drdc nmea` gives ("checksum does not match")."""
    raw = _line(line)
    r = Nmea()
    check(lib.drdc_nmea_parse_with(raw, len(raw), _flags(strict),
                                   ctypes.byref(r)), "drdc_nmea_parse")
    return _sentence(r)


def parse_date(line, strict=False):
    """drdc_nmea_parse_date(): the time of day and date of an RMC, whatever
    its status (V or mode N too), or of a ZDA -> Sentence with only those
    (and a ZDA's zone); DrdcError otherwise (DRDC_E_SENTENCE for a
    sentence without a date)."""
    raw = _line(line)
    r = Nmea()
    check(lib.drdc_nmea_parse_date(raw, len(raw), _flags(strict),
                                   ctypes.byref(r)), "drdc_nmea_parse_date")
    return _sentence(r)


def utc(dated, sentence):
    """drdc_nmea_utc(): the UTC instant of `sentence`'s time of day on the
    date of `dated` (a Sentence of an RMC or ZDA, from parse() or
    parse_date()) -> Utc(sec, nsec)."""
    t = Time()
    check(lib.drdc_nmea_utc(None, ctypes.byref(_record(dated)),
                            ctypes.byref(_record(sentence)),
                            ctypes.byref(t)), "drdc_nmea_utc")
    return Utc(t.sec, t.nsec)


# ---- arrays: the loop in C ----

def _joined(lines):
    """The lines as one buffer and the bounds of each: (bytes, starts,
    ends)."""
    if isinstance(lines, (str, bytes, bytearray)):
        raise TypeError("lines: a sequence of lines (str or bytes), not one "
                        "%s; parse() takes one sentence" % type(lines).__name__)
    if isinstance(lines, np.ndarray):
        if lines.dtype.kind not in "USO":
            raise TypeError("lines: an array of str or bytes, not dtype %s"
                            % lines.dtype)
        lines = lines.ravel().tolist()
    elif not isinstance(lines, (list, tuple)):
        lines = list(lines)
    n = len(lines)
    try:
        text = "".join(lines)
        ascii_only = text.isascii()
        raw = text.encode("ascii") if ascii_only else None
    except TypeError:
        try:
            raw = b"".join(lines)
            ascii_only = True
        except TypeError:
            raise TypeError("lines: every line a str, or every line "
                            "bytes") from None
    if not ascii_only:
        # a character beyond ASCII: its own bytes (the parser refuses
        # them), so the byte lengths differ from the characters'
        pieces = [_text(x) for x in lines]
        raw = b"".join(pieces)
        lengths = np.fromiter(map(len, pieces), np.int64, n)
    else:
        lengths = np.fromiter(map(len, lines), np.int64, n)
    ends = np.cumsum(lengths, dtype=np.int64)
    starts = ends - lengths
    return raw, starts, ends


def _parse_buffer(raw, starts, ends, strict, stitch):
    n = starts.size
    cols = {}
    for name, field, dtype in _FIELDS:
        if name == "satellite_ids":
            cols[field] = np.zeros((n, GSA_IDS), dtype)
        else:
            cols[field] = np.zeros(n, dtype)
    cols["status"] = np.zeros(n, np.int32)
    if stitch:
        cols["utc_sec"] = np.zeros(n, np.int64)
        cols["utc_nsec"] = np.zeros(n, np.int32)
        cols["utc_status"] = np.zeros(n, np.int32)
    c = NmeaColumns(**{k: (cols[k].ctypes.data if k in cols else None)
                       for k in _COLUMN_POINTERS})
    buf = np.frombuffer(raw, np.uint8) if raw else np.zeros(1, np.uint8)
    lib.drdc_batch_nmea_parse(buf.ctypes.data, n, starts.ctypes.data,
                              ends.ctypes.data, _flags(strict),
                              ctypes.byref(c))
    names = np.array(TYPES + ("",))
    out = {"status": cols["status"]}
    for name, field, dtype in _FIELDS:
        a = cols[field]
        if name == "type":
            a = names[a]  # -1: the last, ""
        out[name] = a
    if stitch:
        out["utc_sec"] = cols["utc_sec"]
        out["utc_nsec"] = cols["utc_nsec"]
        out["utc_status"] = cols["utc_status"]
    else:
        out["utc_sec"] = out["utc_nsec"] = out["utc_status"] = None
    out["line"] = np.arange(1, n + 1, dtype=np.int64)
    return NmeaArrays(**out)


def parse_array(lines, strict=False, stitch=True):
    """drdc_nmea_parse_with() over a sequence of lines (str or bytes; a list,
    a tuple, a numpy array or any iterable), the loop in C: NmeaArrays,
    one row and one status per line (the module's columns), every sentence
    type the library decodes. With `stitch`, each sentence's UTC instant
    is dated as the module says (utc_sec, utc_nsec, utc_status); without,
    those three are None. Never raises for a line the parser refuses."""
    raw, starts, ends = _joined(lines)
    return _parse_buffer(raw, starts, ends, strict, stitch)


def parse_bytes(data, strict=False, stitch=True):
    """parse_array() of the lines of one buffer (a log's bytes): the lines
    are found in C, as the `drdc` tool reads them."""
    data = bytes(data)
    n = lib.drdc_batch_line_count(data, len(data))
    starts = np.zeros(n, np.int64)
    ends = np.zeros(n, np.int64)
    lib.drdc_batch_line_bounds(data, len(data), n, starts.ctypes.data,
                               ends.ctypes.data)
    return _parse_buffer(data, starts, ends, strict, stitch)


def _pandas():
    try:
        import pandas
    except ImportError:
        return None
    return pandas


def to_frame(arrays):
    """NmeaArrays as a pandas DataFrame: one column each, satellite_ids as
    satellite_id_01 .. satellite_id_12."""
    pandas = _pandas()
    if pandas is None:
        raise ImportError("drdc.nmea.to_frame needs pandas: pip install "
                          "'drdc[pandas]'")
    columns = {}
    for name, a in arrays._asdict().items():
        if a is None:
            continue
        if name == "satellite_ids":
            for k in range(GSA_IDS):
                columns["satellite_id_%02d" % (k + 1)] = a[:, k]
        else:
            columns[name] = a
    return pandas.DataFrame(columns, copy=False)


def read_log(path, strict=False, as_frame=None):
    """A receiver log (a file of NMEA lines) -> its columns, UTC stitched
    in C: a pandas DataFrame (to_frame()) when pandas is installed, else
    NmeaArrays of numpy columns; as_frame=True requires pandas, False
    gives NmeaArrays either way."""
    with open(path, "rb") as f:
        data = f.read()
    arrays = parse_bytes(data, strict=strict)
    if as_frame is False or (as_frame is None and _pandas() is None):
        return arrays
    return to_frame(arrays)


__all__ = ["parse", "parse_date", "utc", "parse_array", "parse_bytes",
           "read_log", "to_frame", "Sentence", "NmeaArrays", "TYPES", "HAS",
           "STRICT", "DrdcError", "Status"]
