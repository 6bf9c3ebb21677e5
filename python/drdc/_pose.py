# SPDX-License-Identifier: BSD-2-Clause
"""The pose types of the data standard (core/include/drdc/geo_pose.h) as
array functions, the loop in C (python/src/batch_pose.c), each with its
scalar twin.

Poses are flat: each field is an argument (or a column) named with its
format, in the order of the C structure, so a namedtuple of one function
is the arguments of the next (``pose_w_from_wutm_array(*u[:-1])``):

| pose | fields |
|---|---|
| {W} | lon_nas, lat_nas, height_q47_16, qs_q1_30, qx_q1_30, qy_q1_30, qz_q1_30 |
| {We} | lon_nas, lat_nas, height_q47_16, yaw_bam32, pitch_bam32, roll_bam32 |
| {W-UTM} | zone, north, easting_q47_16, northing_q47_16, height_q47_16, qs..qz (grid north) |
| {We-UTM} | zone, north, easting_q47_16, northing_q47_16, height_q47_16, yaw..roll (grid north) |
| {W-MGRS} | mgrs, height_q47_16, qs..qz |
| {We-MGRS} | mgrs, height_q47_16, yaw..roll |
| {l} | x_q15_16, y_q15_16, z_q15_16, qs..qz |
| {le} | x_q15_16, y_q15_16, z_q15_16, yaw..roll |

The {W} 7-vector keeps the paper's order: longitude first. Local poses
and the relative conversions take a reference pose (``ref_`` before its
fields) and the geoid separation at it (``geoid_separation_q47_16``:
geoid above ellipsoid, as GGA's separation field). Array functions
return the target pose's namedtuple of arrays with a ``status``; where an
element's status is an error its outputs are 0 (mgrs "").
"""
from collections import namedtuple

import numpy as np

from . import _check
from ._geo import MGRS_SIZE, text_rows
from ._lib import lib
from ._status import Status, check

_I64 = (_check.INT64, np.int64)
_I32 = (_check.INT32, np.int32)
_BAM = (_check.BAM32, np.uint32)
_BOOL = ((0, 1), np.bool_)
_Q = [("qs_q1_30", _I32), ("qx_q1_30", _I32), ("qy_q1_30", _I32),
      ("qz_q1_30", _I32)]
_E = [("yaw_bam32", _BAM), ("pitch_bam32", _BAM), ("roll_bam32", _BAM)]
_GEO = [("lon_nas", _I64), ("lat_nas", _I64), ("height_q47_16", _I64)]
_GRID = [("zone", _I32), ("north", _BOOL), ("easting_q47_16", _I64),
         ("northing_q47_16", _I64), ("height_q47_16", _I64)]
_LOCAL = [("x_q15_16", _I32), ("y_q15_16", _I32), ("z_q15_16", _I32)]

# the rows of batch_pose.c; "mgrs" is text, carried apart from the rows
LAYOUTS = {
    "WPose": _GEO + _Q,
    "WePose": _GEO + _E,
    "WUTMPose": _GRID + _Q,
    "WeUTMPose": _GRID + _E,
    "WMGRSPose": [("mgrs", None), ("height_q47_16", _I64)] + _Q,
    "WeMGRSPose": [("mgrs", None), ("height_q47_16", _I64)] + _E,
    "LPose": _LOCAL + _Q,
    "LePose": _LOCAL + _E,
    "Quat": _Q,
}
_ZONE = ("zone", _I32, -1)
_PREC = ("prec", _I32, 5)
_SEP = ("geoid_separation_q47_16", _I64, None)
_CONV = ("convergence_nas", _I64, None)

# name: (batch_pose.c's number, inputs, output pose, C function, summary);
# an input is a pose (with a prefix) or one extra argument
CONVERSIONS = {
    "pose_wutm_from_w": (0, [("", "WPose"), _ZONE], "WUTMPose",
                         "drdc_pose_wutm_from_w",
                         "{W} -> {W-UTM}: position to UTM/UPS, attitude "
                         "turned to grid north by the convergence"),
    "pose_w_from_wutm": (1, [("", "WUTMPose")], "WPose",
                         "drdc_pose_w_from_wutm", "{W-UTM} -> {W}"),
    "pose_weutm_from_we": (2, [("", "WePose"), _ZONE], "WeUTMPose",
                           "drdc_pose_weutm_from_we", "{We} -> {We-UTM}"),
    "pose_we_from_weutm": (3, [("", "WeUTMPose")], "WePose",
                           "drdc_pose_we_from_weutm", "{We-UTM} -> {We}"),
    "pose_wmgrs_from_w": (4, [("", "WPose"), _PREC], "WMGRSPose",
                          "drdc_pose_wmgrs_from_w",
                          "{W} -> {W-MGRS} with prec digits (5: 1 m)"),
    "pose_w_from_wmgrs": (5, [("", "WMGRSPose")], "WPose",
                          "drdc_pose_w_from_wmgrs",
                          "{W-MGRS} -> {W} (the centre of the cell)"),
    "pose_wemgrs_from_we": (6, [("", "WePose"), _PREC], "WeMGRSPose",
                            "drdc_pose_wemgrs_from_we",
                            "{We} -> {We-MGRS}"),
    "pose_we_from_wemgrs": (7, [("", "WeMGRSPose")], "WePose",
                            "drdc_pose_we_from_wemgrs", "{We-MGRS} -> {We}"),
    "pose_w_from_l": (8, [("ref_", "WPose"), _SEP, ("", "LPose")], "WPose",
                      "drdc_pose_w_from_l",
                      "a local pose {l} relative to ref -> {W}"),
    "pose_l_from_w": (9, [("ref_", "WPose"), _SEP, ("", "WPose")], "LPose",
                      "drdc_pose_l_from_w",
                      "{W} -> the local pose {l} relative to ref"),
    "pose_l_from_le": (10, [("", "LePose")], "LPose", "drdc_pose_l_from_le",
                       "{le} -> {l}"),
    "pose_le_from_l": (11, [("", "LPose")], "LePose", "drdc_pose_le_from_l",
                       "{l} -> {le}"),
    "pose_we_from_le": (12, [("ref_", "WePose"), _SEP, ("", "LePose")],
                        "WePose", "drdc_pose_we_from_le",
                        "{le} relative to ref -> {We}"),
    "pose_le_from_we": (13, [("ref_", "WePose"), _SEP, ("", "WePose")],
                        "LePose", "drdc_pose_le_from_we",
                        "{We} -> {le} relative to ref"),
    "pose_grid_from_true": (14, [("", "Quat"), _CONV], "Quat",
                            "drdc_pose_grid_from_true",
                            "an attitude from true north -> from grid north"),
    "pose_true_from_grid": (15, [("", "Quat"), _CONV], "Quat",
                            "drdc_pose_true_from_grid",
                            "an attitude from grid north -> true north"),
}

POSES = {name: namedtuple(name, [f for f, _ in fields])
         for name, fields in LAYOUTS.items()}
ARRAYS = {name: namedtuple(name + "Arrays",
                           [f for f, _ in fields] + ["status"])
          for name, fields in LAYOUTS.items()}
BamArrays = namedtuple("BamArrays", "bam32 status")


def _arguments(inputs):
    """[(argument, limits, dtype, default)] of a conversion's inputs."""
    out = []
    for item in inputs:
        if len(item) == 2:
            prefix, pose = item
            out += [(prefix + f, spec, None) for f, spec in LAYOUTS[pose]]
        else:
            name, spec, default = item
            out.append((name, spec, default))
    return out


def _bind(name, arguments, args, kwargs):
    names = [a for a, _, _ in arguments]
    if len(args) > len(names):
        raise TypeError("%s takes %d arguments, not %d"
                        % (name, len(names), len(args)))
    values = dict(zip(names, args))
    for k, v in kwargs.items():
        if k not in names:
            raise TypeError("%s has no argument %s (it takes %s)"
                            % (name, k, ", ".join(names)))
        if k in values:
            raise TypeError("%s: %s given twice" % (name, k))
        values[k] = v
    for a, _, default in arguments:
        if a not in values:
            if default is None:
                raise TypeError("%s: argument %s missing" % (name, a))
            values[a] = default
    return values


def _convert(name, args, kwargs):
    which, inputs, target, _, _ = CONVERSIONS[name]
    arguments = _arguments(inputs)
    values = _bind(name, arguments, args, kwargs)
    numbers, text = [], None
    for a, spec, _ in arguments:
        if spec is None:
            text = values[a]
            continue
        limits, _dtype = spec
        v = values[a]
        if limits == (0, 1):
            v = np.asarray(v)
            if v.dtype.kind == "b":
                v = v.astype(np.int64)
        numbers.append(_check.integer_array(v, a, limits, np.int64))
    if text is not None:
        rows, width, bad, tshape = text_rows(text, "mgrs")
        numbers.append(np.zeros(tshape, np.int64))  # its shape, broadcast
    arrays, shape = _check.broadcast(*numbers)
    if text is not None:
        arrays.pop()
        rows = np.ascontiguousarray(np.broadcast_to(
            rows.reshape(tshape), shape)).ravel()
        bad = np.broadcast_to(bad.reshape(tshape), shape).ravel()
    n = arrays[0].size if arrays else 0
    k_in = len(arrays)
    data = (np.ascontiguousarray(np.stack(arrays, axis=1)) if n
            else np.zeros((0, k_in), np.int64))
    fields = LAYOUTS[target]
    numeric = [(f, spec) for f, spec in fields if spec is not None]
    k_out = len(numeric)
    out = np.zeros((n, k_out), np.int64)
    status = np.zeros(n, np.int32)
    text_out = any(spec is None for _, spec in fields)
    if text_out:
        width = MGRS_SIZE
        rows = np.zeros(n, "S%d" % width)
    elif text is None:
        rows, width = None, 0
    scratch = np.zeros(width + 1, np.uint8)
    lib.drdc_batch_pose(which, n, data.ctypes.data, k_in, out.ctypes.data,
                        k_out, None if rows is None else rows.ctypes.data,
                        width, scratch.ctypes.data, status.ctypes.data)
    if text is not None and bad.any():
        # C could not read it as the text it is: malformed MGRS
        status[bad] = Status.DRDC_E_MGRS
        out[bad] = 0
    columns, k = [], 0
    for f, spec in fields:
        if spec is None:
            columns.append(rows.astype(np.str_).reshape(shape))
            continue
        columns.append(out[:, k].astype(spec[1]).reshape(shape))
        k += 1
    return ARRAYS[target](*columns, status.reshape(shape))


def _scalar(name, result):
    """The scalar twin: Python ints (bool for north, str for mgrs) or
    DrdcError."""
    target = CONVERSIONS[name][2]
    status = int(result.status)
    check(status, CONVERSIONS[name][3])
    values = []
    for v in result[:-1]:
        v = v.item() if hasattr(v, "item") else v
        values.append(v)
    return POSES[target](*values)


def _make(name):
    which, inputs, target, c_name, summary = CONVERSIONS[name]
    names = ", ".join(a for a, _, _ in _arguments(inputs))

    def array(*args, **kwargs):
        return _convert(name, args, kwargs)

    def scalar(*args, **kwargs):
        for v in list(args) + list(kwargs.values()):
            if np.ndim(v) != 0:
                raise TypeError("%s takes one pose; %s_array takes arrays"
                                % (name, name))
        return _scalar(name, _convert(name, args, kwargs))

    array.__name__ = name + "_array"
    array.__doc__ = ("%s over arrays (broadcast together), the loop in C: "
                     "%s. Arguments: %s. Returns %sArrays (with status)."
                     % (c_name, summary, names, target))
    scalar.__name__ = name
    scalar.__doc__ = ("%s: %s. Arguments: %s. Returns %s; DrdcError for an "
                      "error status." % (c_name, summary, names, target))
    return scalar, array


FUNCTIONS = {}
for _name in CONVERSIONS:
    FUNCTIONS[_name], FUNCTIONS[_name + "_array"] = _make(_name)


def pose_bam_from_convergence_array(convergence_nas):
    """drdc_pose_bam_from_convergence over an array: the convergence as a
    binary angle (uint32), rounded to nearest; BamArrays(bam32, status),
    status always DRDC_OK."""
    c = _check.integer_array(convergence_nas, "convergence_nas",
                             _check.INT64, np.int64)
    shape = c.shape
    data = np.ascontiguousarray(c).reshape(-1, 1)
    out = np.zeros((data.shape[0], 1), np.int64)
    status = np.zeros(data.shape[0], np.int32)
    lib.drdc_batch_pose(16, data.shape[0], data.ctypes.data, 1,
                        out.ctypes.data, 1, None, 0, None,
                        status.ctypes.data)
    return BamArrays(out[:, 0].astype(np.uint32).reshape(shape),
                     status.reshape(shape))


def pose_bam_from_convergence(convergence_nas):
    """drdc_pose_bam_from_convergence: the convergence (nas) as a binary
    angle (int, uint32)."""
    v = _check.integer(convergence_nas, "convergence_nas", _check.INT64)
    return int(pose_bam_from_convergence_array(v).bam32)


FUNCTIONS["pose_bam_from_convergence"] = pose_bam_from_convergence
FUNCTIONS["pose_bam_from_convergence_array"] = \
    pose_bam_from_convergence_array
globals().update(FUNCTIONS)
