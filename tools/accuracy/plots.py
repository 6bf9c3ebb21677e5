#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Error plots of docs/accuracy.md: the library's results (the host
sampler, tools/accuracy/sample.c, bit-identical to the firmware builds)
against independent oracles over whole domains.

  fx-sincos.png   sin, cos of binary angles vs mpmath, full circle
  fx-atan2.png    atan2 on the circle of radius 2^30 vs mpmath
  tm-forward.png  transverse Mercator (UTM's k0) position error over a
                  zone and 500 km beyond vs GeographicLib's
                  TransverseMercatorProj -s (same Krueger series)
  tm-reverse.png  the inverse, from the rounded forward grid
  euler.png       Euler angles of quaternions near gimbal lock vs SciPy

Run by `./waf docs`; writes PNGs into docs/img/ and prints the maxima the
plots show so that docs/accuracy.md can quote them.

usage: plots.py SAMPLER OUTDIR
"""
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import mpmath  # noqa: E402
import numpy as np  # noqa: E402
from scipy.spatial.transform import Rotation  # noqa: E402

Q30 = 1 << 30
Q16 = 1 << 16
NAS_PER_DEG = 3600 * 10**9
BAM_TURN = 1 << 32
DPI = 80


def sample(sampler, requests):
    """The library's answers, one list of ints (or None) per request."""
    out = subprocess.run([sampler], input="".join(r + "\n" for r in requests),
                         capture_output=True, text=True, check=True).stdout
    lines = out.splitlines()
    assert len(lines) == len(requests), "sampler answered %d of %d" % (
        len(lines), len(requests))
    return [None if l.startswith("ERR") else [int(v) for v in l.split()]
            for l in lines]


def save(fig, outdir, name):
    fig.tight_layout()
    fig.savefig(outdir / name, dpi=DPI, metadata={"Software": None})
    plt.close(fig)


def plot_sincos(sampler, outdir):
    """Every 2^16-th binary angle: 65 536 points around the circle."""
    mpmath.mp.dps = 30
    angles = [k << 16 for k in range(1 << 16)]
    ours = sample(sampler, ["sincos %d" % a for a in angles])
    err_s, err_c = [], []
    for a, (s, c) in zip(angles, ours):
        x = mpmath.mpf(a) * 2 * mpmath.pi / BAM_TURN
        err_s.append(float(s - mpmath.sin(x) * Q30))
        err_c.append(float(c - mpmath.cos(x) * Q30))
    deg = np.array(angles) * 360.0 / BAM_TURN
    fig, ax = plt.subplots(figsize=(9, 3.4))
    ax.plot(deg, err_s, ",", color="tab:blue", label="sin")
    ax.plot(deg, err_c, ",", color="tab:orange", label="cos")
    ax.axhline(2, color="grey", ls="--", lw=0.8)
    ax.axhline(-2, color="grey", ls="--", lw=0.8, label="issue bound 2 LSB")
    ax.set_xlim(0, 360)
    ax.set_xticks(range(0, 361, 45))
    ax.set_xlabel("angle (degrees)")
    ax.set_ylabel("error (LSB of Q1.30)")
    ax.set_title("drdc_fx_sin_bam32 / cos_bam32 minus exact (mpmath), "
                 "65 536 angles")
    ax.legend(loc="upper right", markerscale=20, fontsize=8)
    save(fig, outdir, "fx-sincos.png")
    return max(map(abs, err_s + err_c))


def plot_atan2(sampler, outdir):
    """Points on the circle of radius 2^30 (the Q1.30 unit circle)."""
    mpmath.mp.dps = 30
    n = 1 << 16
    pts = []
    for k in range(n):
        t = mpmath.mpf(k) * 2 * mpmath.pi / n
        pts.append((int(mpmath.nint(mpmath.sin(t) * Q30)),
                    int(mpmath.nint(mpmath.cos(t) * Q30))))
    ours = sample(sampler, ["atan2 %d %d" % p for p in pts])
    deg, err = [], []
    for (y, x), (a,) in zip(pts, ours):
        exact = mpmath.atan2(y, x) / (2 * mpmath.pi) * BAM_TURN
        e = (a - exact) % BAM_TURN  # binary angles wrap
        if e > BAM_TURN / 2:
            e -= BAM_TURN
        err.append(float(e))
        deg.append(float(exact) * 360.0 / BAM_TURN)
    fig, ax = plt.subplots(figsize=(9, 3.4))
    ax.plot(deg, err, ",", color="tab:blue")
    ax.axhline(4, color="grey", ls="--", lw=0.8, label="issue bound 4 LSB")
    ax.axhline(-4, color="grey", ls="--", lw=0.8)
    ax.set_xlim(-180, 180)
    ax.set_xticks(range(-180, 181, 45))
    ax.set_xlabel("atan2(y, x) (degrees)")
    ax.set_ylabel("error (binary-angle LSB)")
    ax.set_title("drdc_fx_atan2_bam32 minus exact (mpmath), 65 536 points "
                 "of radius 2^30")
    ax.legend(loc="upper right", fontsize=8)
    save(fig, outdir, "fx-atan2.png")
    return max(map(abs, err))


def geographiclib(args, lines):
    out = subprocess.run(["TransverseMercatorProj", "-s", "-k", "0.9996",
                          "-p", "9"] + args, input="".join(lines),
                         capture_output=True, text=True, check=True).stdout
    return [l.split() for l in out.splitlines()]


def _dec(q, bits):
    """Q format integer as its exact decimal string."""
    sign = "-" if q < 0 else ""
    q = abs(q)
    whole, frac = divmod(q * 10**bits, 1 << bits)
    assert frac == 0  # 2^-bits has exactly `bits` decimals
    s = str(whole).rjust(bits + 1, "0")
    return sign + s[:-bits] + "." + s[-bits:]


def tm_grid():
    """Latitudes -80..84 every degree, longitudes from the central
    meridian -7.5..7.5 every 0.25 degree: the zone (+-3) and up to
    500 km beyond it at the equator."""
    lats = np.arange(-80, 85, 1)
    dlons = np.arange(-7.5, 7.5001, 0.25)
    return lats, dlons


def plot_tm(sampler, outdir):
    lats, dlons = tm_grid()
    pts = [(int(la * NAS_PER_DEG), int(round(dl * 4)) * NAS_PER_DEG // 4)
           for la in lats for dl in dlons]
    ours = sample(sampler, ["tmfwd %d %d" % p for p in pts])
    # the grid's degrees are multiples of 1/4: exact in decimal
    ref = geographiclib([], ["%r %r\n" % (la / NAS_PER_DEG,
                                          dl / NAS_PER_DEG)
                             for la, dl in pts])
    fwd = np.full((len(lats), len(dlons)), np.nan)
    rev_req, rev_idx, rev_ref_in = [], [], []
    for i, (p, o, r) in enumerate(zip(pts, ours, ref)):
        if o is None:
            continue
        x, y, _ = o
        dx = x / Q16 - float(r[0])
        dy = y / Q16 - float(r[1])
        fwd.flat[i] = np.hypot(dx, dy) * 1e6
        north = y >= 0
        rev_req.append("utmrev 31 %s %d %d" % (
            "N" if north else "S", x + 500000 * Q16,
            y if north else y + 10000000 * Q16))
        rev_idx.append(i)
        rev_ref_in.append("%s %s\n" % (_dec(x, 16), _dec(y, 16)))
    rev_ours = sample(sampler, rev_req)
    rev_ref = geographiclib(["-r"], rev_ref_in)
    rev = np.full(fwd.shape, np.nan)
    cos_lat = np.cos(np.radians(lats))
    for i, o, r in zip(rev_idx, rev_ours, rev_ref):
        if o is None:
            continue
        lat, lon = o
        dlat = (lat - float(r[0]) * NAS_PER_DEG)
        dlon = (lon - 3 * NAS_PER_DEG - float(r[1]) * NAS_PER_DEG)
        # metres on the ground: 1 nas of latitude is 30.9 um
        rev.flat[i] = np.hypot(dlat, dlon * cos_lat[i // len(dlons)])
    refused = sum(o is None for o in rev_ours)
    for name, data, label, title, note in (
            ("tm-forward.png", fwd,
             "position error (um); the Q47.16 rounding alone: <= 10.8",
             "drdc_geo_tm_forward (k0 0.9996) minus TransverseMercatorProj "
             "-s", ""),
            ("tm-reverse.png", rev, "error on the ground (nas = 30.9 um)",
             "drdc_geo_from_utm (zone 31) of the rounded forward grid minus "
             "TransverseMercatorProj -s -r",
             "\nblank: easting beyond UTM's 0..1000 km, refused "
             "(DRDC_E_EASTING)")):
        fig, ax = plt.subplots(figsize=(9, 5))
        im = ax.pcolormesh(dlons, lats, data, shading="nearest",
                           cmap="viridis")
        ax.axvline(-3, color="white", lw=0.8)
        ax.axvline(3, color="white", lw=0.8)
        ax.set_xlabel("longitude from the central meridian (degrees); "
                      "white lines: zone edges" + note)
        ax.set_ylabel("latitude (degrees)")
        ax.set_title(title, fontsize=10)
        fig.colorbar(im, ax=ax, label=label)
        save(fig, outdir, name)
    return np.nanmax(fwd), np.nanmax(rev), refused


def plot_euler(sampler, outdir):
    """Quaternions (rounded to Q1.30) with pitch 1e-3..90 degrees from
    the lock, random yaw and roll; SciPy's ZYX angles of the same
    integers are the oracle."""
    rng = np.random.default_rng(20261122)
    n = 4000
    dist = 10 ** rng.uniform(-3, np.log10(90), n)  # degrees from the lock
    sign = rng.choice([-1, 1], n)
    eul = np.column_stack([rng.uniform(-180, 180, n), sign * (90 - dist),
                           rng.uniform(-180, 180, n)])
    xyzw = Rotation.from_euler("ZYX", eul, degrees=True).as_quat()
    qi = np.rint(xyzw * Q30).astype(np.int64)
    ours = sample(sampler, ["euler %d %d %d %d" % (q[3], q[0], q[1], q[2])
                            for q in qi])
    ref = Rotation.from_quat(qi.astype(np.float64)).as_euler("ZYX",
                                                             degrees=True)
    err = []
    for o, r in zip(ours, ref):
        d = (np.array(o) * 360.0 / BAM_TURN - r + 180) % 360 - 180
        err.append(np.max(np.abs(d)))
    err = np.array(err)
    fig, ax = plt.subplots(figsize=(9, 3.6))
    ax.loglog(dist, err, ".", ms=2)
    ax.axhline(1e-7, color="grey", ls="--", lw=0.8,
               label="issue bound 1e-7 degree")
    ax.set_xlabel("pitch distance from +-90 degrees (degrees)")
    ax.set_ylabel("max |error| of yaw, pitch, roll (degrees)")
    ax.set_title("drdc_euler_from_quat minus SciPy as_euler('ZYX') of the "
                 "same Q1.30 quaternion, %d random" % n, fontsize=10)
    ax.legend(loc="upper right", fontsize=8)
    save(fig, outdir, "euler.png")
    return float(err.max())


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    sampler, outdir = argv[1], Path(argv[2])
    outdir.mkdir(parents=True, exist_ok=True)
    print("sin/cos: max %.3f LSB" % plot_sincos(sampler, outdir))
    print("atan2: max %.3f LSB" % plot_atan2(sampler, outdir))
    fwd, rev, refused = plot_tm(sampler, outdir)
    print("tm forward: max %.2f um; reverse: max %.3f nas, %d points "
          "beyond UTM's easting limits refused" % (fwd, rev, refused))
    print("euler near lock: max %.3g degree" % plot_euler(sampler, outdir))


if __name__ == "__main__":
    main(sys.argv)
