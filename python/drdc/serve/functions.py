# SPDX-License-Identifier: BSD-2-Clause
"""The functions the service exposes: for each, its inputs and outputs with
their fixed-point formats, its accuracy as the C header documents it (and
which header), and how /v1/eval calls the package's array function.

The accuracy texts summarise the @retval/Accuracy paragraphs of
core/include/drdc/*.h; when a header's measured bound changes, change the
line here too (test_serve.py checks that every header named exists)."""
from collections import namedtuple

import drdc

# C parameter types of the inputs, with the integer range that fits them
# (the package's own checks refuse anything else; these bounds give the
# service's error message and the OpenAPI document's minimum/maximum)
RANGES = {
    "int64": (-(1 << 63), (1 << 63) - 1),
    "int32": (-(1 << 31), (1 << 31) - 1),
    "uint32": (0, (1 << 32) - 1),
    "bam32": (-(1 << 31), (1 << 32) - 1),
    "bool": (0, 1),
}

# kind: "int" (an integer per element, or one integer for all), "text"
# (a string per element), "scalar-int" / "scalar-text" (one value for the
# whole batch)
Arg = namedtuple("Arg", "name kind ctype format default")
Out = namedtuple("Out", "name ctype format")
Function = namedtuple("Function",
                      "name c_name header summary inputs outputs accuracy "
                      "call")

NAS = "int64 nano-arcseconds, 3.6e12 per degree"
Q47_16 = "Q47.16 metres (int64, 2^16 = 1 m)"
Q5_58 = "Q5.58 (int64, 2^58 = 1.0)"
Q1_30 = "Q1.30 (int32, 2^30 = 1.0)"
BAM32 = "binary angle (2^32 per turn; uint32, an int32 reading accepted)"
BAM32_OUT = "binary angle (uint32, 2^32 per turn)"
SEC = "UTC: POSIX seconds (86 400 a day), int64"
NSEC = "nanoseconds, int32 (1e9..2e9-1 during a leap second)"
ZONE = "int32: UTM zone 1..60, 0 for UPS"
NORTH = "hemisphere: 1 (true) north, 0 south"
MGRS_TEXT = "MGRS text, ASCII (\"12UVA8788568665\")"


def _time_arrays(function, in_names):
    def call(a):
        return function(*(a[n] for n in in_names))
    return call


def _units(function, from_name, to_name):
    def call(a):
        return function(a["raw"], a["from_frac"], a[from_name],
                        a["to_frac"], a[to_name])
    return call


GEO_H = "core/include/drdc/geo.h"
MGRS_H = "core/include/drdc/geo_mgrs.h"
SCALES_H = "core/include/drdc/time_scales.h"
ORIENT_H = "core/include/drdc/orient.h"
UNITS_H = "core/include/drdc/units.h"
TIME_EXACT = ("exact integer arithmetic to the nanosecond; checked against "
              "ERFA at every leap second")

UTM_OUTPUTS = [Out("zone", "int32", ZONE), Out("north", "bool", NORTH),
               Out("easting_q47_16", "int64", Q47_16),
               Out("northing_q47_16", "int64", Q47_16)]
UTC_OUTPUTS = [Out("sec", "int64", SEC), Out("nsec", "int32", NSEC)]

FUNCTIONS = [
    Function(
        "geo_to_utm", "drdc_geo_to_utm", GEO_H,
        "geographic -> UTM/UPS (as GeoConvert -u), in the standard zone or "
        "a forced one",
        [Arg("lat_nas", "int", "int64", NAS + ", [-90, 90] degrees", None),
         Arg("lon_nas", "int", "int64", NAS, None),
         Arg("zone", "int", "int32",
             "-1 the standard zone, 0 forces UPS, 1..60 a UTM zone", -1)],
        UTM_OUTPUTS + [Out("convergence_nas", "int64", NAS),
                       Out("scale_q5_58", "int64", Q5_58)],
        "easting and northing within 1 LSB (15 um) of GeoConvert -p 9 in "
        "UTM and UPS; convergence within 1 nas (2.8e-13 degree); scale "
        "within 307 LSB of Q5.58 (1.1e-15); 24 694 points",
        lambda a: drdc.geo_to_utm_array(a["lat_nas"], a["lon_nas"],
                                        a["zone"])),
    Function(
        "geo_from_utm", "drdc_geo_from_utm", GEO_H,
        "UTM/UPS -> geographic, with the meridian convergence and the "
        "point scale",
        [Arg("zone", "int", "int32", ZONE, None),
         Arg("north", "int", "bool", NORTH, None),
         Arg("easting_q47_16", "int", "int64", Q47_16, None),
         Arg("northing_q47_16", "int", "int64", Q47_16, None)],
        [Out("lat_nas", "int64", NAS), Out("lon_nas", "int64", NAS),
         Out("convergence_nas", "int64", NAS),
         Out("scale_q5_58", "int64", Q5_58)],
        "latitude and longitude within 1 nas (2.8e-13 degree) of GeoConvert "
        "-p 9; convergence within 2 079 nas and scale within 25 141 LSB of "
        "the forward values at the unrounded point",
        lambda a: drdc.geo_from_utm_array(a["zone"], a["north"],
                                          a["easting_q47_16"],
                                          a["northing_q47_16"],
                                          with_scale=True)),
    Function(
        "geo_mgrs_encode", "drdc_geo_mgrs_encode", MGRS_H,
        "MGRS of a point (as GeoConvert -m), prec digits per coordinate",
        [Arg("lat_nas", "int", "int64", NAS, None),
         Arg("lon_nas", "int", "int64", NAS, None),
         Arg("prec", "int", "int32", "digits per coordinate, -1..11 "
             "(5 is 1 m)", 5)],
        [Out("text", "string", MGRS_TEXT)],
        "digits truncate the exact easting and northing; equal to "
        "GeoConvert -m except within nanometres of a 1 um boundary "
        "(6 063 points x 13 precisions)",
        lambda a: drdc.geo_mgrs_encode_array(a["lat_nas"], a["lon_nas"],
                                             a["prec"])),
    Function(
        "geo_mgrs_decode", "drdc_geo_mgrs_decode", MGRS_H,
        "MGRS text -> the centre of its cell in UTM/UPS and its precision",
        [Arg("text", "text", "string", MGRS_TEXT, None)],
        UTM_OUTPUTS + [Out("prec", "int32", "digits per coordinate")],
        "exact up to the Q47.16 rounding of cells finer than 1 m (to "
        "nearest)",
        lambda a: drdc.geo_mgrs_decode_array(a["text"])),
    Function(
        "time_utc_to_gps", "drdc_time_utc_to_gps", SCALES_H,
        "UTC -> GPS full week, time of week and nanoseconds",
        [Arg("sec", "int", "int64", SEC, None),
         Arg("nsec", "int", "int32", NSEC, 0)],
        [Out("week", "int32", "GPS full week since 1980-01-06"),
         Out("tow", "int32", "seconds of the week"),
         Out("nsec", "int32", "nanoseconds")],
        TIME_EXACT,
        _time_arrays(drdc.time_utc_to_gps_array, ("sec", "nsec"))),
    Function(
        "time_gps_to_utc", "drdc_time_gps_to_utc", SCALES_H,
        "GPS full week, time of week -> UTC",
        [Arg("week", "int", "int32", "GPS full week", None),
         Arg("tow", "int", "int32", "seconds of the week, 0..604 799",
             None),
         Arg("nsec", "int", "int32", "nanoseconds, 0..999 999 999", 0)],
        UTC_OUTPUTS, TIME_EXACT,
        _time_arrays(drdc.time_gps_to_utc_array, ("week", "tow", "nsec"))),
    Function(
        "time_utc_to_tai", "drdc_time_utc_to_tai", SCALES_H,
        "UTC -> TAI seconds since 1958-01-01",
        [Arg("sec", "int", "int64", SEC, None),
         Arg("nsec", "int", "int32", NSEC, 0)],
        [Out("sec", "int64", "TAI seconds since 1958-01-01"),
         Out("nsec", "int32", "nanoseconds")],
        TIME_EXACT,
        _time_arrays(drdc.time_utc_to_tai_array, ("sec", "nsec"))),
    Function(
        "time_tai_to_utc", "drdc_time_tai_to_utc", SCALES_H,
        "TAI seconds since 1958-01-01 -> UTC",
        [Arg("sec", "int", "int64", "TAI seconds since 1958-01-01", None),
         Arg("nsec", "int", "int32", "nanoseconds", 0)],
        UTC_OUTPUTS, TIME_EXACT,
        _time_arrays(drdc.time_tai_to_utc_array, ("sec", "nsec"))),
    Function(
        "time_utc_to_unix", "drdc_time_utc_to_unix", SCALES_H,
        "UTC -> Unix seconds (a leap second maps to the next midnight)",
        [Arg("sec", "int", "int64", SEC, None),
         Arg("nsec", "int", "int32", NSEC, 0)],
        [Out("sec", "int64", "Unix seconds"),
         Out("nsec", "int32", "nanoseconds")],
        "exact; checked against Python's calendar.timegm",
        _time_arrays(drdc.time_utc_to_unix_array, ("sec", "nsec"))),
    Function(
        "time_unix_to_utc", "drdc_time_unix_to_utc", SCALES_H,
        "Unix seconds -> UTC (never a leap second)",
        [Arg("sec", "int", "int64", "Unix seconds", None),
         Arg("nsec", "int", "int32", "nanoseconds", 0)],
        UTC_OUTPUTS, "exact; checked against Python's calendar.timegm",
        _time_arrays(drdc.time_unix_to_utc_array, ("sec", "nsec"))),
    Function(
        "quat_from_euler", "drdc_quat_from_euler", ORIENT_H,
        "Z-Y-X Euler angles (yaw, pitch, roll) -> unit quaternion, scalar "
        "first",
        [Arg("yaw_bam32", "int", "bam32", BAM32, None),
         Arg("pitch_bam32", "int", "bam32", BAM32, None),
         Arg("roll_bam32", "int", "bam32", BAM32, None)],
        [Out(n, "int32", Q1_30) for n in ("s", "x", "y", "z")],
        "max 2 LSB of Q1.30 per part against SciPy (20 256 orientations)",
        lambda a: drdc.quat_from_euler_array(a["yaw_bam32"],
                                             a["pitch_bam32"],
                                             a["roll_bam32"])),
    Function(
        "euler_from_quat", "drdc_euler_from_quat", ORIENT_H,
        "a non-zero quaternion (q / |q| is used) -> Z-Y-X Euler angles",
        [Arg(n, "int", "int32", Q1_30, None)
         for n in ("s_q1_30", "x_q1_30", "y_q1_30", "z_q1_30")],
        [Out(n, "uint32", BAM32_OUT) for n in ("yaw", "pitch", "roll")],
        "max 1.125 binary-angle units (9.4e-8 degree) from SciPy when "
        "|pitch| is 0.001 degree or more from 90 degrees (20 249 cases)",
        lambda a: drdc.euler_from_quat_array(a["s_q1_30"], a["x_q1_30"],
                                             a["y_q1_30"], a["z_q1_30"])),
    Function(
        "units_convert", "drdc_units_convert", UNITS_H,
        "raw / 2^from_frac in a unit of the table -> raw of to_unit with "
        "to_frac fraction bits",
        [Arg("raw", "int", "int64", "int64, real value raw / 2^from_frac",
             None),
         Arg("from_frac", "scalar-int", "uint32", "fraction bits, 0..62",
             None),
         Arg("from_unit", "scalar-text", "string",
             "a unit of the table (GNU units' names: \"ft\", \"knot\")",
             None),
         Arg("to_frac", "scalar-int", "uint32", "fraction bits, 0..62",
             None),
         Arg("to_unit", "scalar-text", "string", "a unit of the table",
             None)],
        [Out("value", "int64", "int64, real value / 2^to_frac")],
        "correctly rounded (<= 0.5 LSB; units with pi add 2.5e-17 "
        "relative); 2 251 vectors equal to GNU units 2.22",
        _units(drdc.units_convert_array, "from_unit", "to_unit")),
    Function(
        "units_convert_expr", "drdc_units_convert_expr", UNITS_H,
        "as units_convert, for unit expressions (\"km/h\", \"kg m/s^2\")",
        [Arg("raw", "int", "int64", "int64, real value raw / 2^from_frac",
             None),
         Arg("from_frac", "scalar-int", "uint32", "fraction bits, 0..62",
             None),
         Arg("from_expr", "scalar-text", "string", "a unit expression",
             None),
         Arg("to_frac", "scalar-int", "uint32", "fraction bits, 0..62",
             None),
         Arg("to_expr", "scalar-text", "string", "a unit expression", None)],
        [Out("value", "int64", "int64, real value / 2^to_frac")],
        "correctly rounded (<= 0.5 LSB) for exact factors; otherwise "
        "within 0.5 LSB plus the factors' relative error (below 1e-12)",
        _units(drdc.units_convert_expr_array, "from_expr", "to_expr")),
]

BY_NAME = {f.name: f for f in FUNCTIONS}

# one request's "inputs" per function, for the page and the OpenAPI
# document: the README's and the headers' own examples where they have one
EXAMPLES = {
    "geo_to_utm": {"lat_nas": [180972000000000, 36000000000000],
                   "lon_nas": [-400212000000000, 72000000000000]},
    "geo_from_utm": {"zone": [12], "north": [1],
                     "easting_q47_16": [31974289408],
                     "northing_q47_16": [364942508032]},
    "geo_mgrs_encode": {"lat_nas": [180972000000000],
                        "lon_nas": [-400212000000000], "prec": 5},
    "geo_mgrs_decode": {"text": ["12UVA8788568665"]},
    "time_utc_to_gps": {"sec": [1795453201], "nsec": 0},
    "time_gps_to_utc": {"week": [2446], "tow": [61219], "nsec": 0},
    "time_utc_to_tai": {"sec": [1795453201], "nsec": 0},
    "time_tai_to_utc": {"sec": [2173834638], "nsec": 0},
    "time_utc_to_unix": {"sec": [1795453201], "nsec": 0},
    "time_unix_to_utc": {"sec": [1795453201], "nsec": 0},
    "quat_from_euler": {"yaw_bam32": [1073741824], "pitch_bam32": [0],
                        "roll_bam32": [0]},
    "euler_from_quat": {"s_q1_30": [759250125], "x_q1_30": [0],
                        "y_q1_30": [0], "z_q1_30": [759250125]},
    "units_convert": {"raw": [65536], "from_frac": 16, "from_unit": "ft",
                      "to_frac": 16, "to_unit": "m"},
    "units_convert_expr": {"raw": [100], "from_frac": 0,
                           "from_expr": "km/h", "to_frac": 16,
                           "to_expr": "m/s"},
}


# What a person may type instead of an input's integer: the quantity's
# name (the key of {"degrees": "50.27"}), its unit, and how the text
# becomes the integer (exactly, as the package's degrees_to_nas() does).
# A "utc" sec also sets the nsec beside it.
QUANTITIES = {
    NAS: ("degrees", "deg", drdc.degrees_to_nas),
    NAS + ", [-90, 90] degrees": ("degrees", "deg", drdc.degrees_to_nas),
    BAM32: ("degrees", "deg", drdc.degrees_to_bam32),
    Q47_16: ("metres", "m", drdc.metres_to_q47_16),
    SEC: ("utc", "ISO 8601 UTC", drdc.time_iso8601_parse),
}


def _fixed(frac, decimals, unit=""):
    def show(a, outputs):
        text = drdc.format_fixed_array(a, frac, decimals)
        return [t + unit for t in text.tolist()]
    return show


def _utc(a, outputs):
    return drdc.format_utc_array(a, outputs["nsec"]).text.tolist()


# How an output is shown to a person beside its integer: exact decimal
# text with its unit, by the output's format (drdc's formatters).
DISPLAYS = {
    NAS: lambda a, o: [t + " deg" for t in
                       drdc.format_nas_degrees_array(a).tolist()],
    Q47_16: _fixed(16, None, " m"),
    Q5_58: _fixed(58, 18),
    Q1_30: _fixed(30, 10),
    BAM32_OUT: lambda a, o: [t + " deg" for t in
                             drdc.format_bam32_degrees_array(a).tolist()],
    SEC: _utc,
}


def quantity(arg):
    """(name, unit, convert) of what may stand for an input, or None."""
    return QUANTITIES.get(arg.format)


def describe(f):
    """The JSON description of one function (GET /v1/functions)."""
    return {
        "name": f.name,
        "c_function": f.c_name,
        "header": f.header,
        "summary": f.summary,
        "inputs": [dict({"name": a.name, "type": a.ctype,
                         "format": a.format,
                         "per_element": a.kind in ("int", "text")},
                        **({"default": a.default}
                           if a.default is not None else {}),
                        **({"quantity": {"name": quantity(a)[0],
                                         "unit": quantity(a)[1]}}
                           if quantity(a) else {}))
                   for a in f.inputs],
        "outputs": [{"name": o.name, "type": o.ctype, "format": o.format}
                    for o in f.outputs]
        + [{"name": "status", "type": "int32",
            "format": "drdc_status_t: 0 DRDC_OK; where it is an error "
                      "(DRDC_E_*) the element's outputs are 0"}],
        "accuracy": f.accuracy,
        "example": EXAMPLES[f.name],
    }
