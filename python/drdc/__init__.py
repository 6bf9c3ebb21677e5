# SPDX-License-Identifier: BSD-2-Clause
"""libdrdc-fx from Python: the firmware's exact integers on a PC.

The package calls the library itself, compiled from this checkout's
core/ and fixed/ into drdc/libdrdc.so when pip builds it
(python/build_backend.py), so every result has the bits that the host
tool build/host/drdc and the MCU firmware compute. The array functions
loop in C (python/src/batch.c) over the same public functions.

**Binding: ctypes.** It is in the standard library, needs no C compiler
when the package is imported and nothing to pin; cffi's ABI mode would
do the same with one more package, and its API mode would need a
compiler at install time for a C extension that adds nothing here (the
library's API is plain structures and integers).

**Names and formats** are the C library's, without the drdc_ prefix
(drdc_geo_to_utm -> geo_to_utm), and every fixed-point argument and
result field says its format: ``lat_nas`` (int64 nano-arcseconds,
3.6e12 per degree), ``easting_q47_16`` (int64 metres x 2^16),
``scale_q5_58``, ``s_q1_30`` (int32 x 2^30), ``yaw_bam32`` (binary angle,
2^32 per turn), UTC ``sec``/``nsec`` (POSIX seconds and nanoseconds).
The headers in core/include/drdc/ document each function's domain and
accuracy.

**Statuses.**

- Scalar functions return a namedtuple (or an int or str) and raise
  ``DrdcError`` (``.reason`` in words, ``.name``, ``.code`` = ``.number``,
  ``.function``) for a DRDC_E_* status; for a DRDC_W_* status (a
  leap-second table past its expiry) they return the result and issue a
  ``DrdcWarning`` (warnings module).
- Array functions (``*_array``) take numpy integer arrays (broadcast
  together) and return a namedtuple of arrays of the broadcast shape with
  a ``status`` array (int32, ``Status`` values): where an element's
  status is an error its outputs are 0; DRDC_OK and warnings have them
  written. They never raise for a value the library refuses.
- Arguments are checked before any call: a non-integer (float, bool,
  object arrays) raises TypeError, a value that does not fit the C
  parameter's type (int64, int32, ...) raises ValueError, so nothing
  wraps on its way into C.

**Modules beyond the functions:** ``drdc.nmea`` (sentences, lines and
whole receiver logs, UTC stitched in C), the pose types and JAUS bodies
as array functions (``pose_*``, ``jaus_*``), decimal text of the
integers as arrays (``format_*_array``, ``status_name_array``) and the
``drdc`` command (drdc/bin/drdc, the host tool).

Example (the same numbers as ``echo 50.27 -111.17 | drdc geo -u -p 4``)::

    import drdc
    u = drdc.geo_to_utm(drdc.degrees_to_nas("50.27"),
                        drdc.degrees_to_nas("-111.17"))
    # Utm(zone=12, north=True, easting_q47_16=..., northing_q47_16=..., ...)
"""
import re
from collections import namedtuple as _namedtuple
from decimal import Decimal
from fractions import Fraction

import numpy as np

from ._status import (DrdcError, DrdcWarning, Status, is_error,  # noqa: F401
                      status_name, reason)
from ._geo import (ZONE_STANDARD, ZONE_UPS, MGRS_PREC_MIN,  # noqa: F401
                   MGRS_PREC_MAX, geo_utm_zone, geo_tm_forward, geo_to_utm,
                   geo_from_utm, geo_mgrs_encode, geo_mgrs_from_utm,
                   geo_mgrs_decode, geo_to_utm_array, geo_from_utm_array,
                   geo_utm_zone_array, geo_tm_forward_array,
                   geo_mgrs_encode_array, geo_mgrs_from_utm_array,
                   geo_mgrs_decode_array)
from ._time import (time_from_civil, time_to_civil,  # noqa: F401
                    time_utc_to_gps, time_gps_to_utc, time_utc_to_tai,
                    time_tai_to_utc, time_utc_to_unix, time_unix_to_utc,
                    time_utc_to_gps_array, time_gps_to_utc_array,
                    time_utc_to_tai_array, time_tai_to_utc_array,
                    time_utc_to_unix_array, time_unix_to_utc_array,
                    time_from_civil_array, time_to_civil_array,
                    time_iso8601_format, time_iso8601_parse,
                    time_iso8601_parse_array, time_jaus_pack,
                    time_jaus_pack_array, time_jaus_to_utc,
                    time_jaus_to_utc_array)
from ._orient import (quat_from_euler, euler_from_quat,  # noqa: F401
                      quat_from_euler_array, euler_from_quat_array)
from ._units import (units_convert, units_convert_expr,  # noqa: F401
                     units_convert_array, units_convert_expr_array)
from ._format import (format_fixed_array, format_q47_16_array,  # noqa: F401
                      format_q15_16_array, format_nas_degrees_array,
                      format_bam32_degrees_array, format_utc_array,
                      status_name_array)
from ._pose import (FUNCTIONS as _POSE_FUNCTIONS,  # noqa: F401
                    POSES as _POSES)
from ._jaus import (jaus_scaled_encode, jaus_scaled_decode,  # noqa: F401
                    jaus_scaled_encode_array, jaus_scaled_decode_array,
                    jaus_scaled_range, jaus_scaled_range_array,
                    jaus_pose_size, jaus_pose_size_array,
                    jaus_global_pose_pack, jaus_global_pose_pack_array,
                    jaus_global_pose_unpack, jaus_global_pose_unpack_array,
                    jaus_local_pose_pack, jaus_local_pose_pack_array,
                    jaus_local_pose_unpack, jaus_local_pose_unpack_array,
                    JAUS_INT8, JAUS_UINT8, JAUS_INT16, JAUS_UINT16,
                    JAUS_INT32, JAUS_UINT32, FORM_RA3, FORM_AS6009)
from ._status import check as _check_status
from . import nmea  # noqa: F401  (drdc.nmea)
from ._version import VERSION as __version__


# the pose conversions of geo_pose.h (drdc/_pose.py), by name
globals().update(_POSE_FUNCTIONS)
# drdc_time_iso8601_format's array twin is the formatter of UTC arrays
time_iso8601_format_array = format_utc_array

NAS_PER_DEGREE = 3600000000000  # DRDC_NAS_PER_DEGREE
NasArrays = _namedtuple("NasArrays", "nas status")
Q47_16_ONE = 1 << 16            # 1 m in Q47.16 (and Q15.16)
Q1_30_ONE = 1 << 30             # DRDC_Q1_30_ONE
Q5_58_ONE = 1 << 58             # DRDC_Q5_58_ONE
BAM32_PER_TURN = 1 << 32        # DRDC_BAM32_PER_TURN


def _round_half_away(x):
    """A Fraction rounded to the nearest integer, ties away from zero (the
    library's rounding rule)."""
    n = abs(x.numerator) * 2 + x.denominator
    q = n // (2 * x.denominator)
    return q if x >= 0 else -q


_DECIMAL_DEGREES = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)$")
# NMEA's (d)ddmm.mmmm: 4 or 5 integer digits, the last two minutes
_DDMM = re.compile(r"[+-]?\d{2,3}[0-5]\d(\.\d*)?$")
# the widest angle the library's geodesy takes: longitudes in [-540, 540)
DDMM_DEGREES_LIMIT = 540


def _exact(value, what):
    """A decimal str, int, Decimal, Fraction or float as an exact Fraction
    (the float's binary value); a ValueError or TypeError naming `what`."""
    if isinstance(value, bool):
        raise TypeError("%s: a number or decimal text, not a bool" % what)
    if isinstance(value, str):
        text = value.strip()
        # plain decimals only: Fraction() would also take an exponent of
        # any size ("1e100000000" takes minutes) and "a/b"
        if len(text) > 40 or not _DECIMAL_DEGREES.match(text):
            raise ValueError("%s: %r is not a decimal number of at most 40 "
                             "characters" % (what, value))
        value = text
    elif isinstance(value, Decimal) and (
            not value.is_finite() or abs(value.adjusted()) > 30):
        # Fraction(Decimal("1e100000000")) would build 10^100000000
        raise ValueError("%s: %s is not a finite decimal within 10^+-30"
                         % (what, value))
    try:
        return Fraction(value)
    except (ValueError, TypeError, OverflowError) as e:
        raise type(e)("%s: %s" % (what, e)) from None


def degrees_to_nas(degrees):
    """Degrees -> nano-arcseconds (int), exactly: a decimal str ("50.27",
    up to 12 decimals exact, as drdc geo reads it), int, Decimal or
    Fraction, or a float (its exact binary value), rounded to the nearest
    nas, ties away from zero. Text in NMEA's ddmm.mmmm form whose value as
    degrees lies beyond 540 ("3854.5087") is a ValueError that names
    ddmm_to_nas(): read as degrees it would pass silently until a
    conversion refuses it far from here."""
    exact = _exact(degrees, "degrees")
    if isinstance(degrees, str) and _DDMM.match(degrees.strip()) \
            and abs(exact) > DDMM_DEGREES_LIMIT:
        # "3854.5087" is 38 degrees 54.5087 minutes to a receiver; as
        # degrees it is beyond any latitude or longitude
        raise ValueError(
            "degrees: %r is beyond %d degrees and reads as NMEA's "
            "ddmm.mmmm; ddmm_to_nas(%r, hemisphere) takes that form"
            % (degrees, DDMM_DEGREES_LIMIT, degrees.strip()))
    nas = _round_half_away(exact * NAS_PER_DEGREE)
    if not -2 ** 63 <= nas < 2 ** 63:
        raise ValueError("degrees: %s is beyond int64 nas" % degrees)
    return nas


def degrees_to_bam32(degrees):
    """Degrees -> a binary angle (int, uint32: 2^32 per turn, wrapped to
    one turn), exactly as degrees_to_nas() reads the value, rounded to
    the nearest unit, ties away from zero."""
    exact = _exact(degrees, "degrees")
    return _round_half_away(exact * BAM32_PER_TURN / 360) % BAM32_PER_TURN


def metres_to_q47_16(metres):
    """Metres -> Q47.16 (int64, 2^16 per metre), exactly as
    degrees_to_nas() reads the value, rounded to the nearest 1/65536 m,
    ties away from zero."""
    exact = _exact(metres, "metres")
    q = _round_half_away(exact * Q47_16_ONE)
    if not -2 ** 63 <= q < 2 ** 63:
        raise ValueError("metres: %s is beyond Q47.16" % metres)
    return q


def nas_to_degrees(nas):
    """Nano-arcseconds -> degrees as an exact Fraction (float(...) of it
    for plotting)."""
    return Fraction(int(nas), NAS_PER_DEGREE)


def _ddmm_sentences(texts, hemispheres):
    """GLL sentences carrying each (text, hemisphere) as their latitude
    (N, S) or longitude (E, W), the other coordinate 0, with checksums:
    the library's own parser then reads the field."""
    lines = []
    for text, h in zip(texts, hemispheres):
        if h in ("N", "S"):
            body = "GPGLL,%s,%s,00000.000,E,000000,A,A" % (text, h)
        else:
            body = "GPGLL,0000.000,N,%s,%s,000000,A,A" % (text, h)
        c = 0
        for ch in body.encode("ascii"):
            c ^= ch
        lines.append("$%s*%02X" % (body, c))
    return lines


_DDMM_FIELD = re.compile(r"\d{1,5}(\.\d{0,12})?$")


def ddmm_to_nas_array(text, hemisphere):
    """ddmm_to_nas over arrays of str (broadcast together): NasArrays of
    nas (int64) and status (the parser's: DRDC_E_SYNTAX for a malformed
    field or hemisphere, DRDC_E_MINUTE for minutes of 60 or more,
    DRDC_E_RANGE beyond 90 or 180 degrees)."""
    t, h = np.broadcast_arrays(np.asarray(text), np.asarray(hemisphere))
    if t.dtype.kind != "U" or h.dtype.kind != "U":
        raise TypeError("text and hemisphere: arrays of str")
    shape = t.shape
    flat_t, flat_h = t.ravel().tolist(), h.ravel().tolist()
    ok = [bool(_DDMM_FIELD.match(x)) and y in ("N", "S", "E", "W")
          for x, y in zip(flat_t, flat_h)]
    lines = _ddmm_sentences([x if k else "0000" for x, k in zip(flat_t, ok)],
                            [y if k else "N" for y, k in zip(flat_h, ok)])
    r = nmea.parse_array(lines, stitch=False)
    lat = [y in ("N", "S") for y in flat_h]
    nas = np.where(lat, r.lat_nas, r.lon_nas)
    status = np.where(ok, r.status, int(Status.DRDC_E_SYNTAX)).astype(
        np.int32)
    nas = np.where(status == 0, nas, 0)
    return NasArrays(nas.reshape(shape), status.reshape(shape))


def ddmm_to_nas(text, hemisphere):
    """NMEA's latitude or longitude text -> nano-arcseconds (int), exactly
    as the library's NMEA parser reads it: ddmm.mmmm (latitude,
    hemisphere "N" or "S") or dddmm.mmmm (longitude, "E" or "W"), up to
    10 decimals of minutes; south and west negative.
    ddmm_to_nas("3854.5087", "N") is 38 degrees 54.5087 minutes. Raises
    DrdcError with the parser's status and reason."""
    if not isinstance(text, str) or not isinstance(hemisphere, str):
        raise TypeError("text and hemisphere: str, as the sentence has them")
    r = ddmm_to_nas_array(np.array([text]), np.array([hemisphere]))
    _check_status(int(r.status[0]), "drdc_nmea_parse")
    return int(r.nas[0])
