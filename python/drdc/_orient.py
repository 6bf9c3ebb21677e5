# SPDX-License-Identifier: BSD-2-Clause
"""Orientation (core/include/drdc/orient.h): quaternions scalar first,
each part Q1.30 (int32, 2^30 = 1.0); Z-Y-X Euler angles [yaw, pitch,
roll] as binary angles (uint32, 2^32 per turn; an int32 reading gives
[-180, 180) degrees, and either is accepted as input)."""
import ctypes
from collections import namedtuple

import numpy as np

from . import _check
from ._lib import Euler, Quat, lib
from ._status import check

QuatQ1_30 = namedtuple("QuatQ1_30", "s x y z")
EulerBam32 = namedtuple("EulerBam32", "yaw pitch roll")
QuatArrays = namedtuple("QuatArrays", "s x y z status")
EulerArrays = namedtuple("EulerArrays", "yaw pitch roll status")


def quat_from_euler(yaw_bam32, pitch_bam32, roll_bam32):
    """drdc_quat_from_euler: Z-Y-X angles -> unit quaternion, Q1.30 parts."""
    e = Euler(*(_check.integer(v, n, _check.BAM32) & 0xFFFFFFFF for v, n in
                ((yaw_bam32, "yaw_bam32"), (pitch_bam32, "pitch_bam32"),
                 (roll_bam32, "roll_bam32"))))
    q = Quat()
    check(lib.drdc_quat_from_euler(ctypes.byref(e), ctypes.byref(q)),
          "drdc_quat_from_euler")
    return QuatQ1_30(q.s, q.x, q.y, q.z)


def euler_from_quat(s_q1_30, x_q1_30, y_q1_30, z_q1_30):
    """drdc_euler_from_quat: a non-zero quaternion (q / |q| is used) ->
    Z-Y-X angles as uint32 binary angles."""
    q = Quat(*(_check.integer(v, n, _check.INT32) for v, n in
               ((s_q1_30, "s_q1_30"), (x_q1_30, "x_q1_30"),
                (y_q1_30, "y_q1_30"), (z_q1_30, "z_q1_30"))))
    e = Euler()
    check(lib.drdc_euler_from_quat(ctypes.byref(q), ctypes.byref(e)),
          "drdc_euler_from_quat")
    return EulerBam32(e.yaw, e.pitch, e.roll)


# ---- arrays: one status per element, outputs 0 where it is an error ----

def quat_from_euler_array(yaw_bam32, pitch_bam32, roll_bam32):
    """drdc_quat_from_euler over arrays (broadcast together): QuatArrays
    of s, x, y, z (int32, Q1.30) and status (int32)."""
    angles, shape = _check.broadcast(*(
        _check.integer_array(v, n, _check.BAM32, np.int64).astype(np.uint32)
        for v, n in ((yaw_bam32, "yaw_bam32"), (pitch_bam32, "pitch_bam32"),
                     (roll_bam32, "roll_bam32"))))
    outs = [np.zeros(angles[0].size, np.int32) for _ in range(5)]
    lib.drdc_batch_quat_from_euler(angles[0].size, *(a.ctypes.data for a in
                                                     angles + outs))
    return QuatArrays(*(a.reshape(shape) for a in outs))


def euler_from_quat_array(s_q1_30, x_q1_30, y_q1_30, z_q1_30):
    """drdc_euler_from_quat over arrays (broadcast together): EulerArrays
    of yaw, pitch, roll (uint32 binary angles) and status (int32;
    DRDC_E_DOMAIN for a zero quaternion)."""
    parts, shape = _check.broadcast(*(
        _check.integer_array(v, n, _check.INT32, np.int32)
        for v, n in ((s_q1_30, "s_q1_30"), (x_q1_30, "x_q1_30"),
                     (y_q1_30, "y_q1_30"), (z_q1_30, "z_q1_30"))))
    n = parts[0].size
    angles = [np.zeros(n, np.uint32) for _ in range(3)]
    status = np.zeros(n, np.int32)
    lib.drdc_batch_euler_from_quat(n, *(a.ctypes.data for a in
                                        parts + angles + [status]))
    return EulerArrays(*(a.reshape(shape) for a in angles + [status]))
