# SPDX-License-Identifier: BSD-2-Clause
"""The pose types and the JAUS bodies and scaled integers from Python,
against the committed vectors with the Unity suites' tolerances:
GeographicLib's GeoConvert and CartConvert with SciPy's rotations
(tests/geo/vectors_pose.h), the standards' field tables with exact
fractions and struct.pack (tests/jaus/vectors_jaus_pose.h,
vectors_jaus.h)."""
import struct

import numpy as np
import pytest

import drdc
from cvectors import load, tolerances

POSE = "tests/geo/vectors_pose.h"
TOL = tolerances("tests/geo/test_geo_pose.c")
M = 1 << 16
Q1 = 1 << 30


def col(rows, key, k=None):
    return np.array([r[key] if k is None else r[key][k] for r in rows])


def bam_dist(a, b):
    d = (np.asarray(a, np.int64) - np.asarray(b, np.int64)) % (1 << 32)
    return np.minimum(d, (1 << 32) - d)


def test_wmgrs_against_geoconvert():
    rows = load(POSE)["pose_mgrs_vectors"]
    lat, lon, prec = col(rows, "lat"), col(rows, "lon"), col(rows, "prec")
    q = [col(rows, "q", k) for k in range(4)]
    m = drdc.pose_wmgrs_from_w_array(lon, lat, 7 * M, *q, prec=prec)
    assert (m.status == 0).all()
    assert m.mgrs.tolist() == [r["mgrs"] for r in rows]
    assert (m.height_q47_16 == 7 * M).all()
    grid = np.stack([m.qs_q1_30, m.qx_q1_30, m.qy_q1_30, m.qz_q1_30], 1)
    want = np.array([r["q_grid"] for r in rows])
    assert np.abs(grid.astype(np.int64) - want).max() <= TOL["MGRS_Q_TOL"]
    me = drdc.pose_wemgrs_from_we_array(lon, lat, 7 * M, col(rows, "yaw"),
                                        11, 22, prec)
    assert (me.mgrs == m.mgrs).all()
    assert bam_dist(me.yaw_bam32, col(rows, "yaw_grid")).max() \
        <= TOL["MGRS_YAW_TOL"]
    assert (me.pitch_bam32 == 11).all() and (me.roll_bam32 == 22).all()
    # and back: the centre of the cell, the attitude turned to true north
    w = drdc.pose_w_from_wmgrs_array(m.mgrs, -3 * M, *q)
    assert (w.status == 0).all()
    assert np.abs(w.lat_nas - col(rows, "centre_lat")).max() \
        <= TOL["CENTRE_TOL"]
    assert np.abs(w.lon_nas - col(rows, "centre_lon")).max() \
        <= TOL["CENTRE_TOL"]
    true = np.stack([w.qs_q1_30, w.qx_q1_30, w.qy_q1_30, w.qz_q1_30], 1)
    assert np.abs(true.astype(np.int64)
                  - np.array([r["q_true"] for r in rows])).max() \
        <= TOL["MGRS_Q_TOL"]
    we = drdc.pose_we_from_wemgrs_array(m.mgrs, -3 * M, col(rows, "yaw"),
                                        33, 44)
    assert bam_dist(we.yaw_bam32, col(rows, "yaw_true")).max() \
        <= TOL["MGRS_YAW_TOL"]
    # one at a time, the same
    one = drdc.pose_wmgrs_from_w(int(lon[0]), int(lat[0]), 7 * M,
                                 *(int(x[0]) for x in q), prec=int(prec[0]))
    assert one.mgrs == rows[0]["mgrs"]
    assert tuple(one[1:]) == tuple(int(x[0]) for x in m[1:-1])


def test_local_poses_against_cartconvert():
    rows = load(POSE)["pose_local_vectors"]
    ref = [col(rows, "ref", 1), col(rows, "ref", 0), col(rows, "ref", 2)] \
        + [col(rows, "ref_e", k) for k in range(3)]
    le = [col(rows, "p", k) for k in range(3)] + [col(rows, "e", k)
                                                  for k in range(3)]
    out = drdc.pose_we_from_le_array(*ref, col(rows, "sep"), *le)
    assert (out.status == 0).all()
    assert np.abs(out.lat_nas - col(rows, "lat")).max() <= TOL["LE_NAS_TOL"]
    arc = (np.abs(out.lon_nas - col(rows, "lon")).astype(object)
           * col(rows, "cos_lat").astype(object)) >> 30
    assert max(arc) <= TOL["LE_NAS_TOL"]
    assert np.abs(out.height_q47_16 - col(rows, "height")).max() \
        <= TOL["LE_H_TOL"]
    for k, f in enumerate(("yaw_bam32", "pitch_bam32", "roll_bam32")):
        assert bam_dist(getattr(out, f), col(rows, "out_e", k)).max() \
            <= TOL["LE_ANG_TOL"]
    w = [col(rows, "lon"), col(rows, "lat"), col(rows, "height")] + \
        [col(rows, "out_e", k) for k in range(3)]
    back = drdc.pose_le_from_we_array(*ref, col(rows, "sep"), *w)
    for k, f in enumerate(("x_q15_16", "y_q15_16", "z_q15_16")):
        assert np.abs(getattr(back, f) - col(rows, "p", k)).max() \
            <= TOL["LE_P_TOL"]
    # {le} -> {l} -> {le}, and {l} relative to {W} and back
    lq = drdc.pose_l_from_le_array(*le)
    assert (lq.status == 0).all()
    again = drdc.pose_le_from_l_array(*lq[:-1])
    assert (again.x_q15_16 == le[0]).all()
    wq = drdc.quat_from_euler_array(*ref[3:])
    wref = ref[:3] + list(wq[:4])
    there = drdc.pose_w_from_l_array(*wref, col(rows, "sep"), *lq[:-1])
    assert (there.status == 0).all()
    # through the quaternion instead of the Euler angles: within the
    # bound of both against CartConvert
    assert np.abs(there.lat_nas - out.lat_nas).max() <= TOL["LE_NAS_TOL"]
    home = drdc.pose_l_from_w_array(*wref, col(rows, "sep"), *there[:-1])
    assert np.abs(home.x_q15_16 - le[0]).max() <= TOL["LE_P_TOL"]


def test_utm_poses_agree_with_geo_to_utm_and_the_convergence():
    rng = np.random.default_rng(8)
    deg = drdc.NAS_PER_DEGREE
    lat = rng.integers(-79 * deg, 83 * deg, 500)
    lon = rng.integers(-180 * deg, 180 * deg, 500)
    q = drdc.quat_from_euler_array(rng.integers(0, 1 << 32, 500),
                                   rng.integers(-(1 << 29), 1 << 29, 500),
                                   rng.integers(0, 1 << 32, 500))
    u = drdc.pose_wutm_from_w_array(lon, lat, 5 * M, *q[:4])
    assert (u.status == 0).all()
    g = drdc.geo_to_utm_array(lat, lon)
    for f in ("zone", "north", "easting_q47_16", "northing_q47_16"):
        assert (getattr(u, f) == getattr(g, f)).all()
    turned = drdc.pose_grid_from_true_array(*q[:4], g.convergence_nas)
    for f in ("qs_q1_30", "qx_q1_30", "qy_q1_30", "qz_q1_30"):
        assert (getattr(u, f) == getattr(turned, f)).all()
    back = drdc.pose_w_from_wutm_array(*u[:-1])
    assert (back.status == 0).all()
    # the easting and northing are rounded to Q47.16: half of 15 um is
    # 247 nas of latitude
    assert np.abs(back.lat_nas - lat).max() <= 250
    e = drdc.pose_weutm_from_we_array(lon, lat, 5 * M, 0, 0, 0)
    assert (bam_dist(e.yaw_bam32, drdc.pose_bam_from_convergence_array(
        -g.convergence_nas).bam32) <= 1).all()
    # errors: a status per element, 0 outputs, the scalar raises
    bad = drdc.pose_wutm_from_w_array([0, 0], [0, 91 * deg], 0, Q1, 0, 0, 0)
    assert drdc.status_name_array(bad.status).tolist() == [
        "DRDC_OK", "DRDC_E_LATITUDE"]
    assert bad.easting_q47_16[1] == 0 and bad.qs_q1_30[1] == 0
    with pytest.raises(drdc.DrdcError) as err:
        drdc.pose_wutm_from_w(0, 91 * deg, 0, Q1, 0, 0, 0)
    assert err.value.function == "drdc_pose_wutm_from_w"
    with pytest.raises(TypeError):
        drdc.pose_wutm_from_w(0, 0, 0, Q1, 0, 0)  # qz missing
    with pytest.raises(ValueError, match="qs_q1_30"):
        drdc.pose_wutm_from_w_array(0, 0, 0, 1 << 31, 0, 0, 0)
    m = drdc.pose_w_from_wmgrs_array(["38SMB4488", "x" * 40, "\u00e9"], 0,
                                     Q1, 0, 0, 0)
    assert drdc.status_name_array(m.status).tolist() == [
        "DRDC_OK", "DRDC_E_MGRS", "DRDC_E_MGRS"]


def bam(v):
    return v & 0xFFFFFFFF


def test_jaus_bodies_equal_the_field_tables():
    rows = load("tests/jaus/vectors_jaus_pose.h")["jaus_pose_pack_vectors"]
    for local in (0, 1):
        for form in (drdc.FORM_RA3, drdc.FORM_AS6009):
            sel = [r for r in rows if r["local"] == local
                   and r["form"] == form]
            if not sel:
                continue
            v = np.array([r["in"] for r in sel])
            presence = col(sel, "presence")
            stamp = col(sel, "stamp")
            # the vectors' order: position (3), position RMS, roll,
            # pitch, yaw, attitude RMS; the package's: the struct's
            args = [presence, v[:, 1], v[:, 0]] if not local else \
                [presence, v[:, 0], v[:, 1]]
            args += [v[:, 2], bam(v[:, 6]), bam(v[:, 5]), bam(v[:, 4]),
                     v[:, 3], v[:, 7], stamp]
            pack = (drdc.jaus_local_pose_pack_array if local
                    else drdc.jaus_global_pose_pack_array)
            b = pack(*args, form=form)
            assert (b.status == 0).all()
            assert b.length.tolist() == [r["length"] for r in sel]
            for r, body, n in zip(sel, b.body, b.length):
                assert bytes(body[:n]) == bytes(r["bytes"][:r["length"]])
            unpack = (drdc.jaus_local_pose_unpack_array if local
                      else drdc.jaus_global_pose_unpack_array)
            u = unpack(b.body, b.length, form)
            assert drdc.status_name_array(u.status).tolist() == [
                drdc.status_name(r["unpacked"]) for r in sel]
            o = np.array([r["out"] for r in sel])
            ok = u.status == 0
            pos = (u.lat_nas, u.lon_nas, u.height_q47_16) if not local \
                else (u.x_q15_16, u.y_q15_16, u.z_q15_16)
            for k in range(3):
                assert (pos[k][ok] == o[ok, k]).all()
            assert (u.roll_bam32[ok] == bam(o[ok, 4])).all()
            assert (u.yaw_bam32[ok] == bam(o[ok, 6])).all()
            assert (u.position_rms_q15_16[ok] == o[ok, 3]).all()
            # the scalar twins
            r = sel[0]
            one = (drdc.jaus_local_pose_pack if local
                   else drdc.jaus_global_pose_pack)(
                *(int(a[0]) for a in args), form=form)
            assert one == bytes(r["bytes"][:r["length"]])
    # a body from RA 3.x's layout by hand: presence 0x0040 (yaw only),
    # yaw an int16 over [-pi, pi] with the scale factor 2 pi / 65534, so
    # 90 degrees is 65534 / 4 = 16383.5, rounded away from zero
    body = drdc.jaus_global_pose_pack(0x40, 0, 0, 0, 1 << 30, 0, 0, 0, 0, 0,
                                      form=drdc.FORM_RA3)
    assert body == struct.pack("<Hh", 0x40, 16384)
    back = drdc.jaus_global_pose_unpack(body, form=drdc.FORM_RA3)
    assert back.presence == 0x40 and back.lat_nas == 0
    assert abs(back.yaw_bam32 - (1 << 30)) <= (1 << 32) // 65534


def test_jaus_unpack_of_any_bytes():
    rows = load("tests/jaus/vectors_jaus_pose.h")["jaus_pose_unpack_vectors"]
    for local in (0, 1):
        for form in (drdc.FORM_RA3, drdc.FORM_AS6009):
            sel = [r for r in rows if r["local"] == local
                   and r["form"] == form]
            if not sel:
                continue
            bodies = [bytes(r["bytes"][:r["length"]]) for r in sel]
            unpack = (drdc.jaus_local_pose_unpack_array if local
                      else drdc.jaus_global_pose_unpack_array)
            u = unpack(bodies, form=form)
            assert drdc.status_name_array(u.status).tolist() == [
                drdc.status_name(r["status"]) for r in sel]
            assert u.presence.tolist() == [
                r["presence"] if r["status"] == 0 else 0 for r in sel]


def test_jaus_scaled_integers():
    v = load("tests/jaus/vectors_jaus.h")
    for key, array in (("jaus_encode_vectors", drdc.jaus_scaled_encode_array),
                       ("jaus_decode_vectors",
                        drdc.jaus_scaled_decode_array)):
        rows = v[key]
        args = (col(rows, "in"), col(rows, "min"), col(rows, "max"),
                col(rows, "type"), col(rows, "form"))
        plain = array(*args)
        sat = array(*args, saturate=True)
        clamped = col(rows, "clamped") != 0
        assert (plain.status[~clamped] == 0).all()
        assert (plain.status[clamped] != 0).all()
        assert (sat.value == col(rows, "out")).all()
        assert (sat.status[clamped] == drdc.Status.DRDC_W_SATURATED).all()
        assert (plain.value[~clamped] == col(rows, "out")[~clamped]).all()
    r = drdc.jaus_scaled_range(drdc.JAUS_INT16, drdc.FORM_RA3)
    assert r == (-32767, 32767)
    assert drdc.jaus_scaled_range(drdc.JAUS_INT16, drdc.FORM_AS6009) == \
        (-32768, 32767)
    # every field: the largest body of jaus_pose.h
    assert drdc.jaus_pose_size(0x1FF) == load(
        "core/include/drdc/jaus_pose.h")["defines"]["DRDC_JAUS_POSE_BODY_MAX"]
    assert drdc.jaus_pose_size_array([0, 1, 0x1FF]).size.tolist()[:2] == \
        [2, 6]
    with pytest.raises(drdc.DrdcError):
        drdc.jaus_pose_size(0x200)
