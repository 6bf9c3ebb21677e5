# SPDX-License-Identifier: BSD-2-Clause
"""JAUS out (and in): scaled integers (core/include/drdc/jaus_scaled.h)
and the Report Global Pose and Report Local Pose message bodies
(jaus_pose.h), array functions with the loop in C
(python/src/batch_jaus.c) and their scalar twins.

Scaled integers: a real value's raw integer in any fixed-point format
(nas, Q47.16, ...) within [min, max] <-> the integer of a JAUS field of
`type` (JAUS_INT8 .. JAUS_UINT32) in `form` (FORM_RA3: Reference
Architecture 3.x, FORM_AS6009: the JSIDL scaled_range); one rounding to
nearest, ties away from zero.

Pose bodies: the fields of drdc_jaus_global_pose_t / local_pose_t, flat
and named with their formats: ``presence`` (DRDC_JAUS_PV_* bits), then
``lon_nas, lat_nas, height_q47_16`` (global) or ``x_q15_16, y_q15_16,
z_q15_16`` (local), ``yaw_bam32, pitch_bam32, roll_bam32``,
``position_rms_q15_16``, ``attitude_rms_bam32``, ``time_stamp`` (a JAUS
time stamp, time_jaus_pack()). Only the fields whose presence bit is set
are packed; unpacking gives 0 for the others. A body travels as bytes,
little-endian as on the wire: arrays of bodies as BodyArrays(body (n,
30) uint8, length, status); the scalar pack returns bytes.
"""
from collections import namedtuple

import numpy as np

from . import _check
from ._lib import lib
from ._status import check

JAUS_INT8, JAUS_UINT8, JAUS_INT16, JAUS_UINT16, JAUS_INT32, JAUS_UINT32 = \
    range(6)  # drdc_jaus_type_t
FORM_RA3, FORM_AS6009 = 0, 1  # drdc_jaus_form_t
PV_LATITUDE, PV_LONGITUDE, PV_ALTITUDE = 0x1, 0x2, 0x4
PV_X, PV_Y, PV_Z = 0x1, 0x2, 0x4
PV_POSITION_RMS, PV_ROLL, PV_PITCH, PV_YAW = 0x8, 0x10, 0x20, 0x40
PV_ATTITUDE_RMS, PV_TIME_STAMP, PV_ALL = 0x80, 0x100, 0x1FF
ID_REPORT_GLOBAL_POSE, ID_REPORT_LOCAL_POSE = 0x4402, 0x4403
BODY_MAX = 30  # DRDC_JAUS_POSE_BODY_MAX

ValueArrays = namedtuple("ValueArrays", "value status")
RangeArrays = namedtuple("RangeArrays", "ilo ihi status")
Range = namedtuple("Range", "ilo ihi")
SizeArrays = namedtuple("SizeArrays", "size status")
BodyArrays = namedtuple("BodyArrays", "body length status")

_I64 = (_check.INT64, np.int64)
_I32 = (_check.INT32, np.int32)
_BAM = (_check.BAM32, np.uint32)
_U32 = (_check.UINT32, np.uint32)
_U16 = ((0, 0xFFFF), np.uint16)
_GLOBAL = [("presence", _U16), ("lon_nas", _I64), ("lat_nas", _I64),
           ("height_q47_16", _I64), ("yaw_bam32", _BAM),
           ("pitch_bam32", _BAM), ("roll_bam32", _BAM),
           ("position_rms_q15_16", _I32), ("attitude_rms_bam32", _BAM),
           ("time_stamp", _U32)]
_LOCAL = [("presence", _U16), ("x_q15_16", _I32), ("y_q15_16", _I32),
          ("z_q15_16", _I32)] + _GLOBAL[4:]
GlobalPose = namedtuple("GlobalPose", [f for f, _ in _GLOBAL])
LocalPose = namedtuple("LocalPose", [f for f, _ in _LOCAL])
GlobalPoseArrays = namedtuple("GlobalPoseArrays",
                              GlobalPose._fields + ("status",))
LocalPoseArrays = namedtuple("LocalPoseArrays",
                             LocalPose._fields + ("status",))
_FUNCTIONS = ("drdc_jaus_scaled_encode", "drdc_jaus_scaled_encode_sat",
              "drdc_jaus_scaled_decode", "drdc_jaus_scaled_decode_sat")


def _scaled(which, values, name, minimum, maximum, type_, form):
    (v, lo, hi, t, f), shape = _check.broadcast(
        _check.integer_array(values, name, _check.INT64, np.int64),
        _check.integer_array(minimum, "minimum", _check.INT64, np.int64),
        _check.integer_array(maximum, "maximum", _check.INT64, np.int64),
        _check.integer_array(type_, "type", _check.INT32, np.int32),
        _check.integer_array(form, "form", _check.INT32, np.int32))
    out = np.zeros(v.size, np.int64)
    status = np.zeros(v.size, np.int32)
    lib.drdc_batch_jaus_scaled(which, v.size, *(a.ctypes.data for a in (
        v, lo, hi, t, f, out, status)))
    return ValueArrays(out.reshape(shape), status.reshape(shape))


def jaus_scaled_encode_array(value, minimum, maximum, type_, form,
                             saturate=False):
    """drdc_jaus_scaled_encode (or _sat) over arrays (broadcast together):
    ValueArrays of the field's integer (int64) and status."""
    return _scaled(1 if saturate else 0, value, "value", minimum, maximum,
                   type_, form)


def jaus_scaled_decode_array(integer, minimum, maximum, type_, form,
                             saturate=False):
    """drdc_jaus_scaled_decode (or _sat) over arrays: ValueArrays of the
    real value's raw integer and status."""
    return _scaled(3 if saturate else 2, integer, "integer", minimum,
                   maximum, type_, form)


def _one(function, which, *args):
    for v in args:
        if np.ndim(v) != 0:
            raise TypeError("one value each; the _array functions take "
                            "arrays")
    r = function(*args)
    check(int(r.status), _FUNCTIONS[which])
    return int(r.value)


def jaus_scaled_encode(value, minimum, maximum, type_, form, saturate=False):
    """drdc_jaus_scaled_encode (_sat with saturate=True): the integer of a
    JAUS field (int)."""
    return _one(lambda *a: jaus_scaled_encode_array(*a, saturate=saturate),
                1 if saturate else 0, value, minimum, maximum, type_, form)


def jaus_scaled_decode(integer, minimum, maximum, type_, form,
                       saturate=False):
    """drdc_jaus_scaled_decode (_sat with saturate=True): the real value's
    raw integer (int)."""
    return _one(lambda *a: jaus_scaled_decode_array(*a, saturate=saturate),
                3 if saturate else 2, integer, minimum, maximum, type_, form)


def jaus_scaled_range_array(type_, form):
    """drdc_jaus_scaled_range over arrays: RangeArrays of the integer range
    [ilo, ihi] of each field type in each form, and status."""
    (t, f), shape = _check.broadcast(
        _check.integer_array(type_, "type", _check.INT32, np.int32),
        _check.integer_array(form, "form", _check.INT32, np.int32))
    ilo, ihi = np.zeros(t.size, np.int64), np.zeros(t.size, np.int64)
    status = np.zeros(t.size, np.int32)
    lib.drdc_batch_jaus_scaled_range(t.size, *(a.ctypes.data for a in (
        t, f, ilo, ihi, status)))
    return RangeArrays(ilo.reshape(shape), ihi.reshape(shape),
                       status.reshape(shape))


def jaus_scaled_range(type_, form):
    """drdc_jaus_scaled_range: Range(ilo, ihi) of a field type in a form."""
    r = jaus_scaled_range_array(_check.integer(type_, "type", _check.INT32),
                                _check.integer(form, "form", _check.INT32))
    check(int(r.status), "drdc_jaus_scaled_range")
    return Range(int(r.ilo), int(r.ihi))


def jaus_pose_size_array(presence):
    """drdc_jaus_pose_size over an array of presence vectors: SizeArrays
    of the body's length in bytes and status."""
    p = _check.integer_array(presence, "presence", (0, 0xFFFF), np.uint16)
    shape = p.shape
    flat = np.ascontiguousarray(p).ravel()
    size = np.zeros(flat.size, np.int64)
    status = np.zeros(flat.size, np.int32)
    lib.drdc_batch_jaus_pose_size(flat.size, flat.ctypes.data,
                                  size.ctypes.data, status.ctypes.data)
    return SizeArrays(size.reshape(shape), status.reshape(shape))


def jaus_pose_size(presence):
    """drdc_jaus_pose_size: a body's length in bytes (int)."""
    r = jaus_pose_size_array(_check.integer(presence, "presence",
                                            (0, 0xFFFF)))
    check(int(r.status), "drdc_jaus_pose_size")
    return int(r.size)


def _form(form):
    return _check.integer(form, "form", _check.INT32)


def _pack(local, fields, args, kwargs, form):
    names = [f for f, _ in fields]
    values = dict(zip(names, args))
    values.update(kwargs)
    missing = [n for n in names if n not in values]
    extra = [n for n in values if n not in names]
    if missing or extra or len(args) > len(names):
        raise TypeError("the body's fields are %s (missing %s, unknown %s)"
                        % (", ".join(names), ", ".join(missing) or "none",
                           ", ".join(extra) or "none"))
    arrays, shape = _check.broadcast(*(
        _check.integer_array(values[n], n, spec[0], np.int64)
        for n, spec in fields))
    n = arrays[0].size
    data = (np.ascontiguousarray(np.stack(arrays, axis=1)) if n
            else np.zeros((0, len(fields)), np.int64))
    body = np.zeros((n, BODY_MAX), np.uint8)
    length = np.zeros(n, np.int64)
    status = np.zeros(n, np.int32)
    lib.drdc_batch_jaus_pose_pack(local, n, data.ctypes.data, _form(form),
                                  body.ctypes.data, length.ctypes.data,
                                  status.ctypes.data)
    return BodyArrays(body.reshape(shape + (BODY_MAX,)),
                      length.reshape(shape), status.reshape(shape))


def jaus_global_pose_pack_array(*args, form=FORM_AS6009, **kwargs):
    """drdc_jaus_global_pose_pack over arrays (the body's fields, broadcast
    together): BodyArrays of the bodies (n, 30 bytes; `length` of each
    are the body), length and status."""
    return _pack(0, _GLOBAL, args, kwargs, form)


def jaus_local_pose_pack_array(*args, form=FORM_AS6009, **kwargs):
    """drdc_jaus_local_pose_pack over arrays: BodyArrays."""
    return _pack(1, _LOCAL, args, kwargs, form)


def _body_rows(body, length):
    """Bodies as rows of bytes: a (n, w) uint8 array with lengths, or a
    sequence of bytes objects (length None)."""
    if length is None:
        if isinstance(body, (bytes, bytearray)):
            raise TypeError("body: a sequence of bodies; the scalar unpack "
                            "takes one")
        items = [bytes(b) for b in body]
        width = max([len(b) for b in items] + [1])
        rows = np.zeros((len(items), width), np.uint8)
        for i, b in enumerate(items):
            rows[i, :len(b)] = np.frombuffer(b, np.uint8)
        lengths = np.array([len(b) for b in items], np.int64)
        return rows, lengths, (len(items),)
    rows = np.asarray(body)
    if rows.dtype != np.uint8 or rows.ndim < 1:
        raise TypeError("body: a uint8 array of bodies (..., width)")
    shape = rows.shape[:-1]
    rows = np.ascontiguousarray(rows.reshape(-1, rows.shape[-1]))
    lengths = _check.integer_array(length, "length", (0, rows.shape[1]),
                                   np.int64)
    lengths = np.ascontiguousarray(np.broadcast_to(lengths, shape)).ravel()
    return rows, lengths, shape


def _unpack(local, body, length, form, result, fields):
    rows, lengths, shape = _body_rows(body, length)
    n = rows.shape[0]
    out = np.zeros((n, len(fields)), np.int64)
    status = np.zeros(n, np.int32)
    lib.drdc_batch_jaus_pose_unpack(local, n, rows.ctypes.data,
                                    rows.shape[1], lengths.ctypes.data,
                                    _form(form), out.ctypes.data,
                                    status.ctypes.data)
    return result(*(out[:, k].astype(spec[1]).reshape(shape)
                    for k, (_, spec) in enumerate(fields)),
                  status.reshape(shape))


def jaus_global_pose_unpack_array(body, length=None, form=FORM_AS6009):
    """drdc_jaus_global_pose_unpack over bodies: a sequence of bytes, or a
    uint8 array (..., width) with the `length` of each:
    GlobalPoseArrays."""
    return _unpack(0, body, length, form, GlobalPoseArrays, _GLOBAL)


def jaus_local_pose_unpack_array(body, length=None, form=FORM_AS6009):
    """drdc_jaus_local_pose_unpack over bodies: LocalPoseArrays."""
    return _unpack(1, body, length, form, LocalPoseArrays, _LOCAL)


def _scalar_pack(local, function, args, kwargs, form):
    for v in list(args) + list(kwargs.values()):
        if np.ndim(v) != 0:
            raise TypeError("one body; the _array functions take arrays")
    r = _pack(local, _LOCAL if local else _GLOBAL, args, kwargs, form)
    check(int(r.status), function)
    return bytes(r.body[:int(r.length)])


def jaus_global_pose_pack(*args, form=FORM_AS6009, **kwargs):
    """drdc_jaus_global_pose_pack: the body's fields -> its bytes."""
    return _scalar_pack(0, "drdc_jaus_global_pose_pack", args, kwargs, form)


def jaus_local_pose_pack(*args, form=FORM_AS6009, **kwargs):
    """drdc_jaus_local_pose_pack: the body's fields -> its bytes."""
    return _scalar_pack(1, "drdc_jaus_local_pose_pack", args, kwargs, form)


def _scalar_unpack(local, function, body, form, pose):
    if not isinstance(body, (bytes, bytearray, memoryview)):
        raise TypeError("body: bytes, not %s" % type(body).__name__)
    r = _unpack(local, [bytes(body)], None, form,
                LocalPoseArrays if local else GlobalPoseArrays,
                _LOCAL if local else _GLOBAL)
    check(int(r.status[0]), function)
    return pose(*(int(a[0]) for a in r[:-1]))


def jaus_global_pose_unpack(body, form=FORM_AS6009):
    """drdc_jaus_global_pose_unpack: a body's bytes -> GlobalPose."""
    return _scalar_unpack(0, "drdc_jaus_global_pose_unpack", body, form,
                          GlobalPose)


def jaus_local_pose_unpack(body, form=FORM_AS6009):
    """drdc_jaus_local_pose_unpack: a body's bytes -> LocalPose."""
    return _scalar_unpack(1, "drdc_jaus_local_pose_unpack", body, form,
                          LocalPose)
