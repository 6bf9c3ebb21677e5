# SPDX-License-Identifier: BSD-2-Clause
"""Decimal text of the library's integers, an array at a time, the loop
in C (python/src/batch_format.c, batch_time.c): for a CSV or a report
that shows the firmware's exact numbers.

- format_q47_16_array (metres), format_fixed_array (any Q format):
  drdc_fx_format(), the exact value by default (16 decimals hold any
  Q47.16 or Q15.16 value exactly; trailing zeros left off), or rounded to
  `decimals`, ties away from zero;
- format_nas_degrees_array: nano-arcseconds as degrees, correctly rounded
  (12 decimals by default, as `drdc nmea` writes latitude and longitude;
  13 decimals give the nas back exactly through degrees_to_nas());
- format_bam32_degrees_array: binary angles as degrees in [0, 360)
  (8 decimals by default, as `drdc nmea` writes course and heading);
- format_utc_array: ISO 8601 UTC (drdc_time_iso8601_format(); 9 digits,
  truncated, so exact to the nanosecond, 23:59:60 in a leap second);
- status_name_array: the DRDC_* name of every status of an array.

Each returns a numpy str array of its input's shape; an element the
library refuses (a UTC instant out of range) is "" (format_utc_array:
also its status, in a FormattedArrays)."""
from collections import namedtuple

import numpy as np

from . import _check
from ._lib import lib
from ._status import Status, status_name

ISO8601_SIZE = 31        # DRDC_TIME_ISO8601_SIZE
FX_FORMAT_MAX = 40       # DRDC_FX_FORMAT_MAX
DEGREES_WIDTH = 48       # batch_format.c's row
DECIMALS_MAX = 18
FormattedArrays = namedtuple("FormattedArrays", "text status")


def _text(rows, shape):
    return rows.astype(np.str_).reshape(shape)


def _decimals(decimals, lo=0):
    d = _check.integer(decimals, "decimals", _check.INT32)
    if not lo <= d <= DECIMALS_MAX:
        raise ValueError("decimals = %d: %d..%d" % (d, lo, DECIMALS_MAX))
    return d


def format_fixed_array(raw, frac_bits, decimals=None):
    """raw / 2^frac_bits as decimal text (drdc_fx_format()): exactly
    (decimals None: frac_bits decimals, trailing zeros and a bare point
    left off; frac_bits 0..18) or rounded to `decimals` (0..18), ties away
    from zero."""
    f = _check.integer(frac_bits, "frac_bits", (0, 60))
    if decimals is None:
        if f > DECIMALS_MAX:
            raise ValueError("frac_bits = %d: an exact text needs %d "
                             "decimals, at most %d are written; give "
                             "decimals" % (f, f, DECIMALS_MAX))
        d = -1
    else:
        d = _decimals(decimals)
    v = _check.integer_array(raw, "raw", _check.INT64, np.int64)
    shape = v.shape
    flat = np.ascontiguousarray(v).ravel()
    rows = np.zeros(flat.size, "S%d" % FX_FORMAT_MAX)
    status = np.zeros(flat.size, np.int32)
    lib.drdc_batch_format_fixed(flat.size, flat.ctypes.data, f, d,
                                rows.ctypes.data, FX_FORMAT_MAX,
                                status.ctypes.data)
    return _text(rows, shape)


def format_q47_16_array(q47_16, decimals=None):
    """Q47.16 metres (easting, northing, heights) as decimal metres:
    format_fixed_array(q47_16, 16, decimals); exact by default."""
    return format_fixed_array(q47_16, 16, decimals)


def format_q15_16_array(q15_16, decimals=None):
    """Q15.16 (local metres, speeds in m/s, dilutions of precision) as
    decimal text: format_fixed_array(q15_16, 16, decimals)."""
    return format_fixed_array(q15_16, 16, decimals)


def format_nas_degrees_array(nas, decimals=12):
    """Nano-arcseconds as decimal degrees (nas / 3.6e12), correctly
    rounded to `decimals` (0..18), ties away from zero, "-" only before a
    text that is not zero."""
    d = _decimals(decimals)
    v = _check.integer_array(nas, "nas", _check.INT64, np.int64)
    shape = v.shape
    flat = np.ascontiguousarray(v).ravel()
    rows = np.zeros(flat.size, "S%d" % DEGREES_WIDTH)
    status = np.zeros(flat.size, np.int32)
    lib.drdc_batch_format_nas_degrees(flat.size, flat.ctypes.data, d,
                                      rows.ctypes.data, status.ctypes.data)
    return _text(rows, shape)


def format_bam32_degrees_array(bam32, decimals=8):
    """Binary angles (2^32 per turn; uint32, or its int32 reading) as
    decimal degrees in [0, 360), correctly rounded, ties up."""
    d = _decimals(decimals)
    v = _check.integer_array(bam32, "bam32", _check.BAM32, np.int64)
    v = v.astype(np.uint32)
    shape = v.shape
    flat = np.ascontiguousarray(v).ravel()
    rows = np.zeros(flat.size, "S%d" % DEGREES_WIDTH)
    status = np.zeros(flat.size, np.int32)
    lib.drdc_batch_format_bam32_degrees(flat.size, flat.ctypes.data, d,
                                        rows.ctypes.data, status.ctypes.data)
    return _text(rows, shape)


def format_utc_array(sec, nsec=0, digits=9):
    """UTC instants (sec, nsec, broadcast together) as ISO 8601 text,
    "2016-12-31T23:59:60.500000000Z" (drdc_time_iso8601_format(), `digits`
    0..9 of the second, truncated): FormattedArrays(text, status); "" where
    the status is an error."""
    g = _check.integer(digits, "digits", _check.INT32)
    (s, n), shape = _check.broadcast(
        _check.integer_array(sec, "sec", _check.INT64, np.int64),
        _check.integer_array(nsec, "nsec", _check.INT32, np.int32))
    rows = np.zeros(s.size, "S%d" % ISO8601_SIZE)
    status = np.zeros(s.size, np.int32)
    lib.drdc_batch_time_iso8601_format(s.size, s.ctypes.data, n.ctypes.data,
                                       g, rows.ctypes.data,
                                       status.ctypes.data)
    return FormattedArrays(_text(rows, shape), status.reshape(shape))


_NAMES = None


def status_name_array(status):
    """The name of each status of an integer array ("DRDC_OK",
    "DRDC_E_NO_FIX"; "DRDC_E_?" for a value that is no status), as a
    numpy str array of its shape."""
    global _NAMES
    if _NAMES is None:
        _NAMES = np.array([status_name(int(s)) for s in Status]
                          + ["DRDC_E_?"])
    a = _check.integer_array(status, "status", _check.INT64, np.int64)
    unknown = len(_NAMES) - 1
    index = np.where((a >= 0) & (a < unknown), a, unknown)
    return _NAMES[index]
