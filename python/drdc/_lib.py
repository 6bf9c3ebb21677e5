# SPDX-License-Identifier: BSD-2-Clause
"""libdrdc.so through ctypes: the C structures and the prototypes of the
functions the package calls, copied from the public headers
(core/include/drdc/, fixed/include/drdc/). A field or argument type here
must be the header's exactly, or the call reads the wrong bits."""
import ctypes
import os

HERE = os.path.dirname(os.path.abspath(__file__))

LIBRARY = os.path.join(HERE, "libdrdc.so")
if not os.path.exists(LIBRARY):
    raise ImportError("%s is missing: import the installed package (pip "
                      "install ./python builds it), not the source folder"
                      % LIBRARY)
lib = ctypes.CDLL(LIBRARY)

status_t = ctypes.c_int  # drdc_status_t, an enum: int on every ABI here
nas_t = ctypes.c_int64
q47_16_t = ctypes.c_int64
q5_58_t = ctypes.c_int64
q1_30_t = ctypes.c_int32
bam32_t = ctypes.c_uint32


class GeoUtm(ctypes.Structure):
    """drdc_geo_utm_t (geo.h)"""
    _fields_ = [("zone", ctypes.c_int32), ("north", ctypes.c_bool),
                ("easting", q47_16_t), ("northing", q47_16_t)]


class Time(ctypes.Structure):
    """drdc_time_t (types.h)"""
    _fields_ = [("sec", ctypes.c_int64), ("nsec", ctypes.c_int32)]


class TimeCount(ctypes.Structure):
    """drdc_time_count_t (time_scales.h)"""
    _fields_ = [("sec", ctypes.c_int64), ("nsec", ctypes.c_int32)]


class TimeGps(ctypes.Structure):
    """drdc_time_gps_t (time_scales.h)"""
    _fields_ = [("week", ctypes.c_int32), ("tow", ctypes.c_int32),
                ("nsec", ctypes.c_int32)]


class TimeCivil(ctypes.Structure):
    """drdc_time_civil_t (time.h)"""
    _fields_ = [(n, ctypes.c_int32) for n in
                ("year", "month", "day", "hour", "minute", "second", "nsec")]


class Quat(ctypes.Structure):
    """drdc_quat_t (orient.h)"""
    _fields_ = [(n, q1_30_t) for n in ("s", "x", "y", "z")]


class Euler(ctypes.Structure):
    """drdc_euler_t (orient.h)"""
    _fields_ = [(n, bam32_t) for n in ("yaw", "pitch", "roll")]


class UnitsExpr(ctypes.Structure):
    """drdc_units_expr_t (units.h)"""
    _fields_ = [("dimension", ctypes.c_int8 * 6),
                ("factor_num", ctypes.c_int64), ("factor_den", ctypes.c_int64),
                ("offset_num", ctypes.c_int64), ("offset_den", ctypes.c_int64),
                ("rounded", ctypes.c_uint8)]


class NmeaTod(ctypes.Structure):
    """drdc_nmea_tod_t (nmea.h)"""
    _fields_ = [(n, ctypes.c_int32) for n in
                ("hour", "minute", "second", "nsec")]


class Nmea(ctypes.Structure):
    """drdc_nmea_t (nmea.h)"""
    _fields_ = [("type", ctypes.c_int), ("talker", ctypes.c_char * 3),
                ("has", ctypes.c_uint32), ("beyond", ctypes.c_uint32),
                ("time", NmeaTod),
                ("latitude", nas_t), ("longitude", nas_t),
                ("altitude", q47_16_t), ("separation", q47_16_t),
                ("quality", ctypes.c_int32), ("satellites", ctypes.c_int32),
                ("hdop", ctypes.c_int32), ("pdop", ctypes.c_int32),
                ("vdop", ctypes.c_int32), ("speed", ctypes.c_int32),
                ("course", bam32_t), ("course_magnetic", bam32_t),
                ("heading", bam32_t), ("mode", ctypes.c_char * 8),
                ("fix_type", ctypes.c_int32), ("system_id", ctypes.c_int32),
                ("satellite_ids", ctypes.c_uint16 * 12),
                ("year", ctypes.c_int32), ("month", ctypes.c_int32),
                ("day", ctypes.c_int32), ("zone_hours", ctypes.c_int32),
                ("zone_minutes", ctypes.c_int32), ("rms", ctypes.c_int32),
                ("sigma_major", ctypes.c_int32),
                ("sigma_minor", ctypes.c_int32), ("orientation", bam32_t),
                ("sigma_latitude", ctypes.c_int32),
                ("sigma_longitude", ctypes.c_int32),
                ("sigma_altitude", ctypes.c_int32)]


_COLUMN_POINTERS = [
    "status", "type", "talker", "has", "beyond", "hour", "minute", "second",
    "nsec", "latitude", "longitude", "altitude", "separation", "quality",
    "satellites", "hdop", "pdop", "vdop", "speed", "course",
    "course_magnetic", "heading", "mode", "fix_type", "system_id",
    "satellite_ids", "year", "month", "day", "zone_hours", "zone_minutes",
    "rms", "sigma_major", "sigma_minor", "orientation", "sigma_latitude",
    "sigma_longitude", "sigma_altitude", "utc_sec", "utc_nsec",
    "utc_status"]


class NmeaColumns(ctypes.Structure):
    """drdc_batch_nmea_columns_t (python/src/batch_nmea.c): the data
    address of each output column, in the C structure's order"""
    _fields_ = [(n, ctypes.c_void_p) for n in _COLUMN_POINTERS]


P = ctypes.POINTER
_void_p = ctypes.c_void_p  # const drdc_unit_t * and const leap state *

PROTOTYPES = {
    "drdc_status_name": (ctypes.c_char_p, [status_t]),
    # geo.h, geo_mgrs.h
    "drdc_geo_utm_zone": (status_t, [nas_t, nas_t, P(ctypes.c_int32)]),
    "drdc_geo_tm_forward": (status_t, [nas_t, nas_t, P(q47_16_t), P(q47_16_t),
                                       P(nas_t), P(q5_58_t)]),
    "drdc_geo_to_utm": (status_t, [nas_t, nas_t, ctypes.c_int32, P(GeoUtm),
                                   P(nas_t), P(q5_58_t)]),
    "drdc_geo_from_utm": (status_t, [P(GeoUtm), P(nas_t), P(nas_t), P(nas_t),
                                     P(q5_58_t)]),
    "drdc_geo_mgrs_encode": (status_t, [nas_t, nas_t, ctypes.c_int32,
                                        ctypes.c_char_p, ctypes.c_size_t]),
    "drdc_geo_mgrs_from_utm": (status_t, [P(GeoUtm), ctypes.c_int32,
                                          ctypes.c_char_p, ctypes.c_size_t]),
    "drdc_geo_mgrs_decode": (status_t, [ctypes.c_char_p, P(GeoUtm), P(GeoUtm),
                                        P(ctypes.c_int32)]),
    # time.h, time_scales.h (leap state: always NULL, the built-in one)
    "drdc_time_from_civil": (status_t, [_void_p, P(TimeCivil), P(Time)]),
    "drdc_time_to_civil": (status_t, [_void_p, P(Time), P(TimeCivil)]),
    "drdc_time_utc_to_tai": (status_t, [_void_p, P(Time), P(TimeCount)]),
    "drdc_time_tai_to_utc": (status_t, [_void_p, P(TimeCount), P(Time)]),
    "drdc_time_utc_to_gps": (status_t, [_void_p, P(Time), P(TimeGps)]),
    "drdc_time_gps_to_utc": (status_t, [_void_p, P(TimeGps), P(Time)]),
    "drdc_time_utc_to_unix": (status_t, [_void_p, P(Time), P(TimeCount)]),
    "drdc_time_unix_to_utc": (status_t, [P(TimeCount), P(Time)]),
    # nmea.h
    "drdc_nmea_parse_with": (status_t, [ctypes.c_char_p, ctypes.c_size_t,
                                        ctypes.c_uint32, P(Nmea)]),
    "drdc_nmea_parse_date": (status_t, [ctypes.c_char_p, ctypes.c_size_t,
                                        ctypes.c_uint32, P(Nmea)]),
    "drdc_nmea_utc": (status_t, [_void_p, P(Nmea), P(Nmea), P(Time)]),
    # orient.h
    "drdc_quat_from_euler": (status_t, [P(Euler), P(Quat)]),
    "drdc_euler_from_quat": (status_t, [P(Quat), P(Euler)]),
    # units.h
    "drdc_units_find": (status_t, [ctypes.c_char_p, ctypes.c_size_t,
                                   P(_void_p)]),
    "drdc_units_convert": (status_t, [ctypes.c_int64, ctypes.c_uint, _void_p,
                                      ctypes.c_uint, _void_p,
                                      P(ctypes.c_int64)]),
    "drdc_units_parse": (status_t, [ctypes.c_char_p, ctypes.c_size_t,
                                    P(UnitsExpr)]),
    "drdc_units_convert_expr": (status_t, [ctypes.c_int64, ctypes.c_uint,
                                           P(UnitsExpr), ctypes.c_uint,
                                           P(UnitsExpr), P(ctypes.c_int64)]),
}

# python/src/batch.c: n, then contiguous arrays (c_void_p: their data
# addresses) and, for units, the formats and the unit or expression
_a = ctypes.c_void_p
_n = ctypes.c_size_t
PROTOTYPES.update({
    "drdc_batch_geo_to_utm": (None, [_n] + [_a] * 10),
    "drdc_batch_geo_from_utm": (None, [_n] + [_a] * 9),
    "drdc_batch_time_utc_to_gps": (None, [_n] + [_a] * 6),
    "drdc_batch_time_gps_to_utc": (None, [_n] + [_a] * 6),
    "drdc_batch_time_count": (None, [ctypes.c_int32, _n] + [_a] * 5),
    "drdc_batch_quat_from_euler": (None, [_n] + [_a] * 8),
    "drdc_batch_euler_from_quat": (None, [_n] + [_a] * 8),
    "drdc_batch_units_convert": (None, [_n, _a, ctypes.c_uint, _a,
                                        ctypes.c_uint, _a, _a, _a]),
    "drdc_batch_units_convert_expr": (None, [_n, _a, ctypes.c_uint,
                                             P(UnitsExpr), ctypes.c_uint,
                                             P(UnitsExpr), _a, _a]),
})
_c = ctypes.c_char_p
_i32 = ctypes.c_int32
_u32 = ctypes.c_uint32
PROTOTYPES.update({
    # batch_geo.c
    "drdc_batch_geo_utm_zone": (None, [_n] + [_a] * 4),
    "drdc_batch_geo_tm_forward": (None, [_n] + [_a] * 7),
    "drdc_batch_geo_mgrs_encode": (None, [_n] + [_a] * 5),
    "drdc_batch_geo_mgrs_from_utm": (None, [_n] + [_a] * 7),
    "drdc_batch_geo_mgrs_decode": (None, [_n, _a, _n] + [_a] * 7),
    # batch_time.c
    "drdc_batch_time_from_civil": (None, [_n] + [_a] * 4),
    "drdc_batch_time_to_civil": (None, [_n] + [_a] * 4),
    "drdc_batch_time_iso8601_format": (None, [_n, _a, _a, _i32, _a, _a]),
    "drdc_batch_time_iso8601_parse": (None, [_n, _a, _n] + [_a] * 4),
    "drdc_batch_time_jaus_pack": (None, [_n] + [_a] * 4),
    "drdc_batch_time_jaus_to_utc": (None, [_n] + [_a] * 6),
    # batch_format.c
    "drdc_batch_format_fixed": (None, [_n, _a, _u32, _i32, _a, _n, _a]),
    "drdc_batch_format_nas_degrees": (None, [_n, _a, _i32, _a, _a]),
    "drdc_batch_format_bam32_degrees": (None, [_n, _a, _i32, _a, _a]),
    # batch_pose.c
    "drdc_batch_pose": (None, [_i32, _n, _a, _n, _a, _n, _a, _n, _a, _a]),
    # batch_jaus.c
    "drdc_batch_jaus_scaled": (None, [_i32, _n] + [_a] * 7),
    "drdc_batch_jaus_scaled_range": (None, [_n] + [_a] * 5),
    "drdc_batch_jaus_pose_size": (None, [_n] + [_a] * 3),
    "drdc_batch_jaus_pose_pack": (None, [_i32, _n, _a, _i32, _a, _a, _a]),
    "drdc_batch_jaus_pose_unpack": (None, [_i32, _n, _a, _n, _a, _i32, _a,
                                           _a]),
    # batch_nmea.c
    "drdc_batch_line_count": (ctypes.c_size_t, [_a, _n]),
    "drdc_batch_line_bounds": (None, [_a, _n, _n, _a, _a]),
    "drdc_batch_nmea_parse": (None, [_a, _n, _a, _a, _u32, _a]),
    # tools/drdc/reasons.c: the tool's words for a status
    "drdc_tool_nmea_reason": (_c, [status_t]),
    "drdc_tool_time_reason": (_c, [status_t]),
})
# drdc_batch_time_count's conversions, in batch.c's order
COUNT_CONVERSIONS = ("utc_to_tai", "tai_to_utc", "utc_to_unix",
                     "unix_to_utc")

for _name, (_restype, _argtypes) in PROTOTYPES.items():
    _f = getattr(lib, _name)
    _f.restype = _restype
    _f.argtypes = _argtypes
