# SPDX-License-Identifier: BSD-2-Clause
"""Reference vectors of the pose conversions {W} <-> {W-MGRS},
{We} <-> {We-MGRS} and {le} <-> {We} (core/geo/grid_pose.c, local_pose.c).

Oracles: GeographicLib 2.1.2 (Debian `geographiclib-tools`): `GeoConvert
-m -p P` (MGRS text), `GeoConvert -c -p 9` (convergence, 1e-13 degree) at
the point and at the MGRS cell's centre, `GeoConvert -p 9` (the centre,
1e-14 degree), `CartConvert -l LAT0 LON0 H0 -r -p 9` (local East-North-Up
-> geodetic); SciPy's Rotation for the attitudes (turns about the down
axis, Z-Y-X Euler angles, compositions), in double on the exact integer
inputs, rounded to nearest (Q1.30, binary angles, nas, Q47.16).

MGRS rows: 500 random points (UTM and both UPS caps) at random precisions
-1..11 with random attitudes; the reverse rows use the cell's centre
(`GeoConvert -u -p 9` of the text) rounded to Q47.16 as the library holds
it. Local rows: 20 reference poses of random
attitude (pitch within +-80 degrees), geoid separations within +-100 m,
20 local poses each within 20 km; compositions with |pitch| > 80 degrees
are skipped (Euler angles ill-conditioned near gimbal lock)."""
import math
import random
import subprocess
from decimal import Decimal, ROUND_HALF_UP

import numpy
from scipy.spatial.transform import Rotation

NAS_DEG = 3600 * 10 ** 9
Q30 = 1 << 30
TURN = 1 << 32


def rnd(d):
    d = Decimal(d)  # a float converts exactly
    q = abs(d).quantize(Decimal(1), rounding=ROUND_HALF_UP)
    return int(q) if d >= 0 else -int(q)


def nas(text):
    return rnd(Decimal(text) * NAS_DEG)


def q16(text):
    return rnd(Decimal(text) * 65536)


def deg(n):
    return "{:f}".format(Decimal(n) / NAS_DEG)


def m16(v):
    return "{:f}".format(Decimal(v) / 65536)


def run(args, lines):
    out = subprocess.run(args, input="\n".join(lines) + "\n", text=True,
                         capture_output=True, check=True).stdout.splitlines()
    if len(out) != len(lines) or any(o.startswith("ERROR") for o in out):
        raise SystemExit("%s failed" % " ".join(args))
    return out


def lit(v):
    return "INT64_C(%d)" % v


def bam_of_rad(r):
    """radians -> binary angle (2^32 per turn), nearest, modulo a turn"""
    return rnd(float(r * TURN / (2 * math.pi))) % TURN


def rad_of_bam(b):
    s = b - TURN if b >= TURN // 2 else b
    return s * 2 * math.pi / TURN


def quat_rot(q):
    # scalar-first integers -> Rotation (SciPy is scalar-last)
    return Rotation.from_quat([q[1], q[2], q[3], q[0]])


def turned(q, gamma_deg):
    """q_z(gamma) * q of the exact integer quaternion q (|q| kept: q is
    within 2^-29 of unit length), the sign of q_z(gamma) with
    cos(gamma/2) >= 0 as the library's half angle in [-90, 90] degrees"""
    r = Rotation.from_euler("z", gamma_deg, degrees=True) * quat_rot(q)
    norm = math.sqrt(sum(a * a for a in q)) / Q30
    x, y, z, s = r.as_quat()
    # the product's sign: that of the Hamilton product with c >= 0
    h = math.radians(gamma_deg) / 2
    c, sn = math.cos(h), math.sin(h)
    ref = [c * q[0] - sn * q[3], c * q[1] - sn * q[2],
           c * q[2] + sn * q[1], c * q[3] + sn * q[0]]
    v = [s, x, y, z]
    if sum(a * b for a, b in zip(v, ref)) < 0:
        v = [-a for a in v]
    return [rnd(float(a * norm * Q30)) for a in v]


def random_quat(rng):
    r = Rotation.from_euler("ZYX", [rng.uniform(-180, 180),
                                    rng.uniform(-89, 89),
                                    rng.uniform(-180, 180)], degrees=True)
    x, y, z, s = r.as_quat()
    return [rnd(float(a * Q30)) for a in (s, x, y, z)]


def mgrs_rows(rng):
    pts = []
    for i in range(500):
        if i % 10 == 0:
            lat = rng.randrange(84 * NAS_DEG, 90 * NAS_DEG, 3600)
        elif i % 10 == 1:
            lat = rng.randrange(-90 * NAS_DEG + 3600, -80 * NAS_DEG, 3600)
        else:
            lat = rng.randrange(-80 * NAS_DEG, 84 * NAS_DEG, 3600)
        lon = rng.randrange(-180 * NAS_DEG, 180 * NAS_DEG, 3600)
        prec = rng.randrange(-1, 12)
        pts.append((lat, lon, prec))
    lines = ["%s %s" % (deg(a), deg(b)) for a, b, _ in pts]
    conv = run(["GeoConvert", "-c", "-p", "9"], lines)
    texts = [run(["GeoConvert", "-m", "-p", str(p - 5)], [l])[0]
             for l, (_, _, p) in zip(lines, pts)]
    # the cell's centre rounded to Q47.16 as the library holds it, then
    # its position and convergence
    utm = []
    for o in run(["GeoConvert", "-u", "-p", "9"], texts):
        z, e, n = o.split()
        utm.append("%s %s %s" % (z, m16(q16(e)), m16(q16(n))))
    centre = run(["GeoConvert", "-p", "9"], utm)
    cconv = run(["GeoConvert", "-c", "-p", "9"], utm)
    rows = []
    for (lat, lon, prec), text, cv, ce, cc in zip(pts, texts, conv, centre,
                                                  cconv):
        q = random_quat(rng)
        yaw = rng.randrange(TURN)
        gamma = float(cv.split()[0])
        gamma_c = float(cc.split()[0])
        q_grid = turned(q, -gamma)
        q_true = turned(q, gamma_c)
        yaw_grid = (yaw - bam_of_rad(math.radians(gamma))) % TURN
        yaw_true = (yaw + bam_of_rad(math.radians(gamma_c))) % TURN
        clat, clon = ce.split()
        rows.append("  { %s, %s, %d, \"%s\", { %s }, { %s }, { %s }, %du, %du, "
                    "%du, %s, %s }," % (
                        lit(lat), lit(lon), prec, text,
                        ", ".join(str(v) for v in q),
                        ", ".join(str(v) for v in q_grid),
                        ", ".join(str(v) for v in q_true),
                        yaw, yaw_grid, yaw_true, lit(nas(clat)),
                        lit(nas(clon))))
    return rows


def euler_bam(r):
    yaw, pitch, roll = r.as_euler("ZYX")
    return [bam_of_rad(a) for a in (yaw, pitch, roll)]


def random_euler(rng):
    return [rng.randrange(TURN),
            rng.randrange(-(80 * TURN) // 360, (80 * TURN) // 360) % TURN,
            rng.randrange(TURN)]


def local_rows(rng):
    rows = []
    refs = []
    for _ in range(20):
        lat0 = rng.randrange(-85 * NAS_DEG, 85 * NAS_DEG, 3600)
        lon0 = rng.randrange(-180 * NAS_DEG, 180 * NAS_DEG, 3600)
        h0 = rng.randrange(-100 * 65536, 5000 * 65536)
        sep = rng.randrange(-100 * 65536, 100 * 65536)
        refs.append((lat0, lon0, h0, sep, random_euler(rng)))
    for lat0, lon0, h0, sep, e0 in refs:
        r0 = Rotation.from_euler("ZYX", [rad_of_bam(a) for a in e0])
        pts = []
        while len(pts) < 20:
            p = [rng.randrange(-20000 * 65536, 20000 * 65536)
                 for _ in range(3)]
            e = random_euler(rng)
            r = Rotation.from_euler("ZYX", [rad_of_bam(a) for a in e])
            out_e = euler_bam(r0 * r)
            pitch = rad_of_bam(out_e[1])
            if abs(pitch) > math.radians(80):
                continue
            ned = r0.apply(numpy.array(p, dtype=float) / 65536)
            pts.append((p, e, out_e,
                        (float(ned[1]), float(ned[0]), -float(ned[2]))))
        out = run(["CartConvert", "-l", deg(lat0), deg(lon0), m16(h0 + sep),
                   "-r", "-p", "9"],
                  ["%r %r %r" % enu for _, _, _, enu in pts])
        for (p, e, oe, _), o in zip(pts, out):
            lat, lon, h = o.split()
            rows.append("  { { %s }, { %du, %du, %du }, %s, { %s }, "
                        "{ %du, %du, %du }, %s, %s, %s, %d, "
                        "{ %du, %du, %du } }," % (
                            ", ".join(lit(v) for v in (lat0, lon0, h0)),
                            e0[0], e0[1], e0[2], lit(sep),
                            ", ".join(str(v) for v in p),
                            e[0], e[1], e[2], lit(nas(lat)), lit(nas(lon)),
                            lit(q16(h) - sep),
                            rnd(math.cos(math.radians(float(lat))) * Q30),
                            oe[0], oe[1], oe[2]))
    return rows


def generate():
    rng = random.Random(2026)
    mgrs = mgrs_rows(rng)
    local = local_rows(rng)
    text = """/* SPDX-License-Identifier: BSD-2-Clause */
/* Generated by tests/ref/gen_geo_pose.py from GeographicLib 2.1.2
 * GeoConvert and CartConvert and SciPy's Rotation. Do not edit; run
 * tools/generate.py. */
#ifndef VECTORS_POSE_H
#define VECTORS_POSE_H

#include <stdint.h>

/* {W} at lat, lon (nas) with attitude q and yaw -> {W-MGRS} at prec:
 * the text, q turned to grid north, yaw - gamma; the text with q (and
 * yaw) taken as grid-north attitude -> {W}: q turned by the convergence
 * at the cell's centre, yaw + that convergence, the centre (nas) */
struct pose_mgrs_vector {
  int64_t lat;
  int64_t lon;
  int32_t prec;
  char mgrs[28];
  int32_t q[4];
  int32_t q_grid[4];
  int32_t q_true[4];
  uint32_t yaw;
  uint32_t yaw_grid;
  uint32_t yaw_true;
  int64_t centre_lat;
  int64_t centre_lon;
};

/* reference {We} (lat0, lon0, h0 MSL; yaw, pitch, roll), geoid
 * separation, {le} (x, y, z Q15.16; angles) -> {We} (lat, lon nas,
 * MSL height Q47.16, angles) */
struct pose_local_vector {
  int64_t ref[3];
  uint32_t ref_e[3];
  int64_t sep;
  int32_t p[3];
  uint32_t e[3];
  int64_t lat;
  int64_t lon;
  int64_t height;
  int32_t cos_lat;  /* cos(lat), Q1.30: longitude error to arc length */
  uint32_t out_e[3];
};

static const struct pose_mgrs_vector pose_mgrs_vectors[%d] = {
%s
};

static const struct pose_local_vector pose_local_vectors[%d] = {
%s
};

#endif
""" % (len(mgrs), "\n".join(mgrs), len(local), "\n".join(local))
    return {"tests/geo/vectors_pose.h": text}
