# SPDX-License-Identifier: BSD-2-Clause
"""Euler <-> quaternion against the SciPy vectors of
tests/orient/vectors_orient.h, with the tolerances of
tests/orient/test_quat.c."""
import numpy as np

import drdc
from cvectors import load, tolerances

V = load("tests/orient/vectors_orient.h")
TOL = tolerances("tests/orient/test_quat.c")
SUB = V["defines"]["ORIENT_EULER_SUB"]


def angle_err(angle, ref_sub):
    """|angle - ref| in 1/SUB binary-angle units, modulo a turn."""
    m = (1 << 32) * SUB
    d = (int(angle) * SUB - ref_sub) % m
    return min(d, m - d)


def test_euler_to_quat_matches_scipy():
    rows = V["orient_euler_vectors"]
    e = np.array([r["e"] for r in rows], np.uint32)
    q = drdc.quat_from_euler_array(e[:, 0], e[:, 1], e[:, 2])
    assert (q.status == 0).all()
    got = np.stack([q.s, q.x, q.y, q.z], axis=1).astype(np.int64)
    want = np.array([r["q"] for r in rows], np.int64)
    assert np.abs(got - want).max() <= TOL["TOL_EULER_TO_QUAT"]


def test_quat_to_euler_matches_scipy():
    rows = V["orient_quat_vectors"]
    q = np.array([r["q"] for r in rows], np.int32)
    e = drdc.euler_from_quat_array(q[:, 0], q[:, 1], q[:, 2], q[:, 3])
    assert (e.status == 0).all()
    worst, checked = 0, 0
    for i, r in enumerate(rows):
        pitch = int(e.pitch[i].astype(np.int32))
        # the suite's rule: exactly in gimbal lock (roll 0) or at least
        # GIMBAL_MARGIN_BAM from it, where the oracle's angles apply
        if (1 << 30) - abs(pitch) >= TOL["GIMBAL_MARGIN_BAM"] \
                or e.roll[i] == 0:
            worst = max(worst, angle_err(e.yaw[i], r["e"][0]),
                        angle_err(e.pitch[i], r["e"][1]),
                        angle_err(e.roll[i], r["e"][2]))
            checked += 1
        assert drdc.euler_from_quat(*r["q"]) == (e.yaw[i], e.pitch[i],
                                                 e.roll[i])
    assert checked > len(rows) * 9 // 10
    assert worst <= TOL["TOL_QUAT_TO_EULER_SUB"]


def test_signed_angles_are_the_same_bits():
    # an int32 reading of a binary angle (-90 degrees) is its uint32
    a = drdc.quat_from_euler(-(1 << 30), 0, 0)
    b = drdc.quat_from_euler(3 << 30, 0, 0)
    assert a == b
    arr = drdc.quat_from_euler_array(np.array([-(1 << 30)], np.int32), 0, 0)
    assert tuple(int(x[0]) for x in arr[:4]) == a


def test_zero_quaternion_is_a_domain_error():
    e = drdc.euler_from_quat_array([0, 1 << 30], 0, 0, 0)
    assert list(e.status) == [drdc.Status.DRDC_E_DOMAIN, 0]
    assert list(e.yaw) == [0, 0]


def test_header_examples():
    # orient.h: yaw 90 degrees <-> { 759250125, 0, 0, 759250125 }
    assert drdc.quat_from_euler(1 << 30, 0, 0) == (759250125, 0, 0, 759250125)
    assert drdc.euler_from_quat(759250125, 0, 0, 759250125) == (1 << 30, 0, 0)
