# SPDX-License-Identifier: BSD-2-Clause
"""Reference vectors of core/orient/: quaternions, Euler Z-Y-X angles,
rotation matrices, axis-angle, rotation of vectors, slerp.

Oracles: scipy.spatial.transform.Rotation (SciPy 1.17, double precision)
for every rotation conversion; exact Python integers for the quaternion
product (its correctly rounded value); mpmath at 40 digits for rotating
Q47.16 vectors (beyond double's 53 bits). Conventions: scalar-first
quaternions, R = Rz(yaw) Ry(pitch) Rx(roll) = SciPy's intrinsic 'ZYX'.

To fit the Cortex-M3 flash (256 KiB for every suite of every module)
the tables are small: about 55 KiB on host and PowerPC, and only the
first rows of each (boundary cases first, 2.5 KiB) on Cortex-M3;
inputs are the exact integers the library receives, outputs are the
oracle rounded to the library's format, except Euler angles, which are
stored in 1/16 binary-angle units (int64) so the tests can measure
errors below one binary-angle unit. The tests add tens of thousands of
in-test random cases checked by exact identities (round trips, unit
norm, exact products): consistency checks, named as such there.
"""
import math
import random

import mpmath
import numpy as np
from scipy.spatial.transform import Rotation as R

mpmath.mp.dps = 40

TURN = 1 << 32
ONE = 1 << 30
SUB = 16  # sub-units of a binary angle in the Euler reference columns
I32_MIN, I32_MAX = -(1 << 31), (1 << 31) - 1


def rnd(x):
    """Nearest integer, ties away from zero (float, mpf or Fraction)."""
    if x >= 0:
        return int(math.floor(x + 0.5)) if isinstance(x, float) else \
            int(mpmath.floor(x + mpmath.mpf(1) / 2))
    return -rnd(-x)


def signed(a):
    a %= TURN
    return a - TURN if a >= TURN // 2 else a


def rad(a):
    return signed(a) * 2.0 * math.pi / TURN


def q30(v):
    return [rnd(float(x) * ONE) for x in v]


def euler_sub(angles):
    """Radians [yaw, pitch, roll] -> 1/16 binary-angle units, signed."""
    return [rnd(a / (2 * math.pi) * TURN * SUB) for a in angles]


def rot_of_q(qi):
    return R.from_quat(np.array(qi, dtype=float), scalar_first=True)


def half_angle_q(e):
    """Sign convention of drdc_quat_from_euler: signed half angles."""
    y, p, r = (rad(a) / 2 for a in e)
    cy, sy, cp, sp, cr, sr = (math.cos(y), math.sin(y), math.cos(p),
                              math.sin(p), math.cos(r), math.sin(r))
    return [cy * cp * cr + sy * sp * sr, cy * cp * sr - sy * sp * cr,
            cy * sp * cr + sy * cp * sr, sy * cp * cr - cy * sp * sr]


def match_sign(q, ref):
    return q if sum(a * b for a, b in zip(q, ref)) >= 0 else [-a for a in q]


def c_rows(rows):
    return "\n".join("  { " + ", ".join(
        "{ " + ", ".join(_lit(x) for x in f) + " }" if isinstance(f, list)
        else _lit(f) for f in r) + " }," for r in rows)


def _lit(x):
    if x == I32_MIN:
        return "INT32_MIN"
    if abs(x) >= (1 << 31):
        return "INT64_C(%d)" % x
    return "%d" % x


# ------------------------------------------------------------------ Euler
def euler_inputs(rng):
    e = []
    q90 = ONE  # 90 degrees
    special_yaw = [0, 1, TURN - 1, TURN // 2, TURN // 2 - 1, TURN // 2 + 1,
                   q90, 3 * q90, 12345678, TURN - 12345678]
    special_pitch = [0, q90, TURN - q90, q90 - 1, TURN - q90 + 1, 1,
                     TURN - 1, q90 - 20000, TURN - q90 + 20000]
    for y in special_yaw:
        for p in special_pitch[:5]:
            e.append([y, p, special_yaw[(y >> 3) % len(special_yaw)]])
    for p in special_pitch:
        e.append([rng.randrange(TURN), p, rng.randrange(TURN)])
    while len(e) < 256:
        e.append([rng.randrange(TURN), rng.randint(-q90, q90) % TURN,
                  rng.randrange(TURN)])
    return e


def euler_rows(rng):
    rows = []
    for e in euler_inputs(rng):
        rot = R.from_euler("ZYX", [rad(a) for a in e])
        q = match_sign(list(rot.as_quat(scalar_first=True)), half_angle_q(e))
        m = rot.as_matrix()
        rows.append([list(e), q30(q), [x for row in m for x in q30(row)]])
    return rows


# ------------------------------------------------------ quaternion -> Euler
def quat_inputs(rng):
    """Random unit quaternions at several lengths, yaw +-180 degrees, and
    pitch near (but at least 0.001 degree from) +-90 degrees, and exactly
    at +-90 degrees (gimbal lock: roll 0 on both sides)."""
    qs = []
    rots = R.random(200, random_state=rng.randrange(1 << 30))
    scales = [1.0, 1.0, 1.0, 1.9, 0.999, 1e-3, 3e-7]
    randoms = [q30(q * scales[i % len(scales)])
               for i, q in enumerate(rots.as_quat(scalar_first=True))]
    # tiny integer quaternions (near zero) and the largest ones
    qs += [[1, 0, 0, 0], [0, 0, 0, -1], [3, -1, 2, 1], [1, 1, 1, 1],
           [I32_MAX, 5, -7, 11], [I32_MIN, I32_MAX, I32_MIN, I32_MAX],
           [-5, I32_MIN, 3, 0]]
    for deg in [0.0011, 0.002, 0.01, 0.5, 5.0]:
        for sgn in (1, -1):
            p = sgn * (90 - deg)
            for _ in range(3):
                e = [rng.uniform(-180, 180), p, rng.uniform(-180, 180)]
                qs.append(q30(R.from_euler("ZYX", e, degrees=True)
                              .as_quat(scalar_first=True)))
    for y in [180.0, -180.0, 179.9999, -179.9999]:
        qs.append(q30(R.from_euler("ZYX", [y, rng.uniform(-80, 80),
                                           rng.uniform(-180, 180)],
                                   degrees=True).as_quat(scalar_first=True)))
    # exact gimbal lock: the quaternion parts are symmetric, cos(pitch) = 0
    for y in [0.0, 30.0, -150.0, 180.0]:
        for p in (90.0, -90.0):
            qs.append(q30(R.from_euler("ZYX", [y, p, 0.0], degrees=True)
                          .as_quat(scalar_first=True)))
    # the first 48 (kept on Cortex-M3): every kind of boundary, then random
    first = qs[:7] + qs[7:37:3] + qs[37:]
    rest = [q for q in qs if q not in first]
    return first + randoms[:48 - len(first)] + rest + randoms[48 - len(first):]


def quat_rows(rng):
    rows = []
    for qi in quat_inputs(rng):
        rot = rot_of_q(qi)
        m = rot.as_matrix()
        if math.hypot(m[0, 0], m[1, 0]) < 2.0 ** -24:
            # gimbal lock (cos pitch below the library's threshold, and
            # below SciPy's 1e-7 rad): roll 0, yaw = atan2(-R12, R22)
            pitch = math.atan2(-m[2, 0], math.hypot(m[0, 0], m[1, 0]))
            ang = [math.atan2(-m[0, 1], m[1, 1]), pitch, 0.0]
        else:
            ang = list(rot.as_euler("ZYX"))
        rows.append([list(qi), euler_sub(ang),
                     [x for row in m for x in q30(row)]])
    return rows


# ---------------------------------------------------- matrix -> quaternion
def dcm_rows(rng):
    randoms = list(R.random(96, random_state=rng.randrange(1 << 30)))
    rots = []
    # 180-degree rotations: about the axes, diagonals and random axes
    axes = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [1, 0, 1], [0, 1, 1],
            [1, 1, 1], [-1, 2, 3], [1e-5, 1, 0]]
    axes += [list(rng.uniform(-1, 1) for _ in range(3)) for _ in range(15)]
    for a in axes:
        a = np.array(a, dtype=float)
        rots.append(R.from_rotvec(a / np.linalg.norm(a) * math.pi))
    # near 180 degrees and near 0
    for ang in [math.pi - 1e-6, math.pi - 1e-3, 1e-6, 0.0]:
        a = np.array([rng.uniform(-1, 1) for _ in range(3)])
        rots.append(R.from_rotvec(a / np.linalg.norm(a) * ang))
    rots = rots[:9] + rots[-4:] + rots[9:-4] + randoms
    rows = []
    for rot in rots:
        m = [x for row in rot.as_matrix() for x in q30(row)]
        mf = np.array(m, dtype=float).reshape(3, 3) / ONE
        q = R.from_matrix(mf).as_quat(scalar_first=True)
        k = int(np.argmax(np.abs(q)))
        if q[k] < 0:
            q = -q
        rows.append([m, q30(q)])
    return rows


# ---------------------------------------------------- exact products
def exact_mul(a, b):
    s0, x0, y0, z0 = a
    s1, x1, y1, z1 = b
    p = [s0 * s1 - x0 * x1 - y0 * y1 - z0 * z1,
         s0 * x1 + x0 * s1 + y0 * z1 - z0 * y1,
         s0 * y1 - x0 * z1 + y0 * s1 + z0 * x1,
         s0 * z1 + x0 * y1 - y0 * x1 + z0 * s1]
    out = []
    for v in p:
        r = (abs(v) + (1 << 29)) >> 30
        out.append(r if v >= 0 else -r)
    ok = all(I32_MIN <= v <= I32_MAX for v in out)
    return out, ok


def mul_rows(rng):
    rows = []
    rots = R.random(48, random_state=rng.randrange(1 << 30))
    qs = [q30(q) for q in rots.as_quat(scalar_first=True)]
    pairs = [(qs[i], qs[i + 1]) for i in range(0, 40, 2)]
    # non-unit, large and overflowing operands
    big = [[I32_MAX, I32_MAX, 0, 0], [I32_MIN, 0, 0, 0], [ONE, ONE, ONE, ONE],
           [I32_MIN, I32_MIN, I32_MIN, I32_MIN], [ONE + 7, -ONE, 3, 1 << 29],
           [1, -1, 1, -1], [0, 0, 0, 0]]
    for a in big:
        for b in big[:4] + [qs[0]]:
            pairs.append((a, b))
    pairs = pairs[20:] + pairs[:20]
    for a, b in pairs:
        out, ok = exact_mul(a, b)
        rows.append([list(a), list(b), out if ok else [0, 0, 0, 0],
                     0 if ok else 3])
    return rows


# ---------------------------------------------------- rotate vectors
def rotate_rows(rng):
    rows = []
    rots = R.random(48, random_state=rng.randrange(1 << 30))
    for i, q in enumerate(rots.as_quat(scalar_first=True)):
        qi = q30(q * (1.0 if i % 3 else 0.75))
        mag = [1.0, 100.0, 5000.0, 18000.0][i % 4]
        v = [rnd(rng.uniform(-mag, mag) * 65536) for _ in range(3)]
        out = rot_of_q(qi).apply(np.array(v, dtype=float) / 65536) * 65536
        # global vector: mpmath, exact rotation matrix of the integers
        gm = [1e3, 6.4e6, 4.2e7, 1e11][i % 4]
        g = [rnd(rng.uniform(-gm, gm) * 65536) for _ in range(3)]
        qm = [mpmath.mpf(c) for c in qi]
        n2 = sum(c * c for c in qm)
        s, x, y, z = qm
        mm = [[s*s + x*x - y*y - z*z, 2*(x*y - s*z), 2*(x*z + s*y)],
              [2*(x*y + s*z), s*s - x*x + y*y - z*z, 2*(y*z - s*x)],
              [2*(x*z - s*y), 2*(y*z + s*x), s*s - x*x - y*y + z*z]]
        gout = [rnd(sum(mm[r][c] * g[c] for c in range(3)) / n2)
                for r in range(3)]
        rows.append([qi, v, [rnd(float(o)) for o in out], g, gout])
    return rows


# ------------------------------- correctly rounded rotation, mul edges
def exact_rotate(q, v):
    """round(P(q) v / |q|^2) with Python integers: R(q / |q|) = P / |q|^2
    is rational, so this is the exact rotation, rounded to nearest, ties
    away from zero; None when a part is outside int32."""
    s, x, y, z = q
    n2 = s * s + x * x + y * y + z * z
    p = [[s*s + x*x - y*y - z*z, 2*(x*y - s*z), 2*(x*z + s*y)],
         [2*(x*y + s*z), s*s - x*x + y*y - z*z, 2*(y*z - s*x)],
         [2*(x*z - s*y), 2*(y*z + s*x), s*s - x*x - y*y + z*z]]
    out = []
    for row in p:
        num = sum(a * b for a, b in zip(row, v))
        r = (2 * abs(num) + n2) // (2 * n2)
        out.append(r if num >= 0 else -r)
    return out if all(I32_MIN <= o <= I32_MAX for o in out) else None


def guard_bits_rotate(q, v):
    """The former method (each term p v 2^6 / |q|^2 rounded, the sum
    rounded): up to 3/128 LSB off, so sometimes on the wrong side."""
    s, x, y, z = q
    n2 = s * s + x * x + y * y + z * z
    p = [[s*s + x*x - y*y - z*z, 2*(x*y - s*z), 2*(x*z + s*y)],
         [2*(x*y + s*z), s*s - x*x + y*y - z*z, 2*(y*z - s*x)],
         [2*(x*z - s*y), 2*(y*z + s*x), s*s - x*x - y*y + z*z]]

    def rdiv(a, b):
        r = (2 * abs(a) + b) // (2 * b)
        return r if a >= 0 else -r
    return [rdiv(sum(rdiv(a * b * 64, n2) for a, b in zip(row, v)), 64)
            for row in p]


def scale_up(q):
    """q 2^k with the largest part in (2^29, 2^30]: the same rotation."""
    m = max(abs(c) for c in q)
    k = 0
    while (m << (k + 1)) <= ONE:
        k += 1
    return [c << k for c in q]


def rotate_exact_rows(rng):
    """Quaternions with parts in [-1, 1] (the library's rotation is the
    exact one there), any length down to 1 LSB, any int32 vector: exact
    halves (ties, both signs) first, then cases the former guard-bit
    method rounded the wrong way, overflow, boundaries, random."""
    rows = []
    wrong = []
    while len(wrong) < 8:
        q = scale_up([rng.randint(-ONE, ONE) for _ in range(4)])
        v = [rng.randint(I32_MIN, I32_MAX) >> rng.randrange(0, 16)
             for _ in range(3)]
        e = exact_rotate(q, v)
        if e is not None and e != guard_bits_rotate(q, v):
            wrong.append([q, v])
    rows += wrong
    rows += [[[ONE, 0, 0, 0], [I32_MAX, I32_MIN, 1]],
             [[-ONE, 0, 0, 0], [I32_MIN, I32_MAX, -1]],
             [[0, ONE, 0, 0], [5, I32_MIN, I32_MIN]],
             [[1, 0, 0, 1], [I32_MIN, 0, 7]],
             [[1, 0, 0, 0], [-3, 2, 1]],
             [[ONE, ONE, ONE, ONE], [I32_MAX, I32_MAX, I32_MAX]],
             [[ONE, -ONE, 3, 1], [I32_MIN, I32_MIN, I32_MIN]],
             [[1, 1, 1, 1], [I32_MIN, I32_MIN, 0]]]
    while len(rows) < 64:
        e = rng.randrange(0, 31)
        q = [rng.randint(-(1 << e), 1 << e) for _ in range(4)]
        if not any(q):
            continue
        v = [rng.randint(I32_MIN, I32_MAX) >> rng.randrange(0, 31)
             for _ in range(3)]
        rows.append([q, v])
    out = []
    for q, v in rows:
        e = exact_rotate(q, v)
        out.append([list(q), list(v), e if e is not None else [0, 0, 0],
                    0 if e is not None else 3])
    return out


def mul_edge_rows():
    """Products with parts at exactly +-1.0 and one LSB inside or beyond:
    the edge between the unchecked and the checked sums."""
    edge = [ONE, -ONE, ONE - 1, -ONE + 1, ONE + 1, -ONE - 1, 0, 1]
    rows = []
    for i, a0 in enumerate(edge):
        for j, b0 in enumerate(edge):
            a = [a0, edge[(i + 3) % 8], edge[(i + 5) % 8], edge[(i + 6) % 8]]
            b = [b0, edge[(j + 1) % 8], edge[(j + 2) % 8], edge[(j + 7) % 8]]
            out, ok = exact_mul(a, b)
            rows.append([a, b, out if ok else [0, 0, 0, 0], 0 if ok else 3])
    return rows


# ---------------------------------------------------- axis-angle, slerp
def axis_rows(rng):
    rows = []
    for i in range(48):
        axis = [rnd(rng.uniform(-1, 1) * ONE * [1, 1e-4, 1.5][i % 3])
                for _ in range(3)]
        ang = [0, 1, TURN // 2, TURN // 2 - 1, ONE][i] if i < 5 else \
            rng.randrange(TURN)
        a = np.array(axis, dtype=float)
        rot = R.from_rotvec(a / np.linalg.norm(a) * rad(ang))
        q = list(rot.as_quat(scalar_first=True))
        h = rad(ang) / 2  # signed half angle: sign convention of the library
        q = match_sign(q, [math.cos(h)] + list(a / np.linalg.norm(a)
                                                * math.sin(h)))
        rows.append([axis, ang, q30(q)])
    return rows


def slerp_rows(rng):
    rows = []
    rots = R.random(96, random_state=rng.randrange(1 << 30))
    qs = [q30(q) for q in rots.as_quat(scalar_first=True)]
    from scipy.spatial.transform import Slerp
    for i in range(48):
        a, b = qs[2 * i], qs[2 * i + 1]
        if i % 8 == 1:
            b = [-c for c in a]  # q near -q: the same orientation
        if i % 8 == 2:
            b = [a[0] + 3, a[1] - 2, a[2], a[3] + 1]  # nearly equal
        t = [0, ONE, ONE // 2][i] if i < 3 else rng.randrange(ONE + 1)
        ra, rb = rot_of_q(a), rot_of_q(b)
        qa = ra.as_quat(scalar_first=True)
        qb = rb.as_quat(scalar_first=True)
        if np.dot(qa, qb) < 0:  # shorter arc, as the library
            qb = -qb
        sl = Slerp([0.0, 1.0], R.from_quat(np.array([qa, qb]),
                                           scalar_first=True))
        q = sl([t / ONE]).as_quat(scalar_first=True)[0]
        # slerp keeps the hemisphere of a
        q = match_sign(list(q), list(qa))
        rows.append([a, b, t, q30(q)])
    return rows


HEADER = """/* SPDX-License-Identifier: BSD-2-Clause */
/* Generated by tests/ref/gen_orient_quat.py from SciPy %s
 * (scipy.spatial.transform.Rotation), exact integers and mpmath.
 * Do not edit; run tools/generate.py. */
#ifndef VECTORS_ORIENT_H
#define VECTORS_ORIENT_H

#include <stdint.h>

#include "orient_test_util.h"

/* Sub-units of a binary angle in the Euler reference columns. */
#define ORIENT_EULER_SUB %d

/* Euler [yaw, pitch, roll] -> quaternion and matrix (SciPy 'ZYX'). */
struct orient_euler_vector {
  uint32_t e[3];
  int32_t q[4];
  int32_t m[9];
};

/* Quaternion (any length) -> Euler (1/16 binary-angle units, signed) and
 * matrix (Q1.30). */
struct orient_quat_vector {
  int32_t q[4];
  int64_t e[3];
  int32_t m[9];
};

/* Matrix -> quaternion (largest part positive). */
struct orient_dcm_vector {
  int32_t m[9];
  int32_t q[4];
};

/* Exact quaternion products; status 3 = DRDC_E_OVERFLOW. */
struct orient_mul_vector {
  int32_t a[4];
  int32_t b[4];
  int32_t p[4];
  int32_t status;
};

/* Rotation of a Q15.16 and a Q47.16 vector. */
struct orient_rotate_vector {
  int32_t q[4];
  int32_t v[3];
  int32_t out[3];
  int64_t g[3];
  int64_t gout[3];
};

/* Rotation of a Q15.16 vector, exact (Python integers) and rounded to
 * nearest, ties away from zero; status 3 = DRDC_E_OVERFLOW. */
struct orient_rotate_exact_vector {
  int32_t q[4];
  int32_t v[3];
  int32_t out[3];
  int32_t status;
};

/* Axis (any length) and angle -> quaternion. */
struct orient_axis_vector {
  int32_t axis[3];
  uint32_t angle;
  int32_t q[4];
};

/* slerp(a, b, t), t in Q1.30. */
struct orient_slerp_vector {
  int32_t a[4];
  int32_t b[4];
  int32_t t;
  int32_t q[4];
};
"""


def table(ctype, name, rows, small):
    """Boundary cases first, then random ones (`small` is where the random
    rows start; every target runs every row)."""
    del small
    return "static const struct %s %s[] = {\n%s\n};\n" % (ctype, name, c_rows(rows))


def generate():
    import scipy
    rng = random.Random(20261122)
    parts = [HEADER % (scipy.__version__, SUB),
             table("orient_euler_vector", "orient_euler_vectors",
                   euler_rows(rng), 6),
             table("orient_quat_vector", "orient_quat_vectors",
                   quat_rows(rng), 8),
             table("orient_dcm_vector", "orient_dcm_vectors", dcm_rows(rng),
                   10),
             table("orient_mul_vector", "orient_mul_vectors", mul_rows(rng),
                   6),
             table("orient_rotate_vector", "orient_rotate_vectors",
                   rotate_rows(rng), 2),
             table("orient_axis_vector", "orient_axis_vectors",
                   axis_rows(rng), 4),
             table("orient_slerp_vector", "orient_slerp_vectors",
                   slerp_rows(rng), 3),
             table("orient_rotate_exact_vector", "orient_rotate_exact_vectors",
                   rotate_exact_rows(random.Random(20261123)), 0),
             table("orient_mul_vector", "orient_mul_edge_vectors",
                   mul_edge_rows(), 0),
             "\n#endif\n"]
    return {"tests/orient/vectors_orient.h": "\n".join(parts),
            "tests/orient/vectors_orient_random.h": generate_random()}


# ------------------------------------------------- 20 000 random (host, PPC)
RANDOM_SEED = 0x1D2C3B4A
RANDOM_COUNT = 20000
PITCH_MAX = 1061811576  # 89 degrees in binary-angle units (rounded up)


def xorshift32(x):
    x ^= (x << 13) & 0xFFFFFFFF
    x ^= x >> 17
    x ^= (x << 5) & 0xFFFFFFFF
    return x


def random_eulers():
    """The same sequence as orient_random_euler() in tests/orient/: yaw and
    roll uniform, pitch uniform in [-89, 89] degrees."""
    x = RANDOM_SEED
    out = []
    for _ in range(RANDOM_COUNT):
        x = xorshift32(x)
        y = x
        x = xorshift32(x)
        p = (x % (2 * PITCH_MAX + 1)) - PITCH_MAX
        x = xorshift32(x)
        out.append([y, p % TURN, x])
    return out


def extra_rows(rng):
    """angle_between, nlerp and axis-angle of a quaternion (host, PPC)."""
    rots = R.random(400, random_state=rng.randrange(1 << 30))
    qs = [q30(q) for q in rots.as_quat(scalar_first=True)]
    rows = []
    for i in range(200):
        a, b = qs[2 * i], qs[2 * i + 1]
        if i % 10 == 1:
            b = [-c for c in a]                      # q vs -q: angle 0
        elif i % 10 == 2:
            b = [a[0] + 5, a[1] - 3, a[2] + 1, a[3]]  # tiny angle
        elif i % 10 == 3:
            b = [-a[1], a[0], -a[3], a[2]]            # exactly 180 degrees
        t = rng.randrange(ONE + 1)
        ra, rb = rot_of_q(a), rot_of_q(b)
        ang = (ra.inv() * rb).magnitude()
        qa = ra.as_quat(scalar_first=True)
        qb = rb.as_quat(scalar_first=True)
        if np.dot(qa, qb) < 0:
            qb = -qb
        # nlerp of the normalised inputs: both are unit to 1e-9 already
        qn = (1 - t / ONE) * np.array(a, float) / ONE + \
            (t / ONE) * np.array(b if np.dot(a, b) >= 0 else
                                 [-c for c in b], float) / ONE
        qn = qn / np.linalg.norm(qn)
        rv = ra.as_rotvec()
        th = np.linalg.norm(rv)
        axis = rv / th if th > 0 else np.array([1.0, 0, 0])
        rows.append("  { { %s }, { %s }, %d, %s, { %s }, { %s }, %s }," % (
            ", ".join(str(c) for c in a), ", ".join(str(c) for c in b), t,
            _lit(rnd(ang / (2 * math.pi) * TURN * SUB)),
            ", ".join(str(c) for c in q30(qn)),
            ", ".join(str(c) for c in q30(axis)),
            _lit(rnd(th / (2 * math.pi) * TURN * SUB))))
    return rows


def generate_random():
    es = random_eulers()
    rad3 = np.array([[rad(a) for a in e] for e in es])
    rots = R.from_euler("ZYX", rad3)
    qf = rots.as_quat(scalar_first=True)
    qrows = []
    drows = []
    for e, q in zip(es, qf):
        q = match_sign(list(q), half_angle_q(e))
        qi = q30(q)
        ang = rot_of_q(qi).as_euler("ZYX")
        sub = euler_sub(ang)
        d = []
        for a, s in zip(e, sub):
            m = TURN * SUB
            v = (s - signed(a) * SUB) % m
            v = v - m if v >= m // 2 else v
            assert -32768 <= v <= 32767
            d.append(v)
        qrows.append(", ".join(str(c) for c in qi) + ",")
        drows.append(", ".join(str(c) for c in d) + ",")
    import scipy
    text = """/* SPDX-License-Identifier: BSD-2-Clause */
/* Generated by tests/ref/gen_orient_quat.py from SciPy %s: %d random
 * Euler angles (the xorshift32 sequence of orient_random_euler(), seed
 * 0x%08X; pitch within +-89 degrees) -> quaternion (Q1.30, rounded), and
 * the Euler angles of that exact integer quaternion as the difference
 * from the input in 1/%d binary-angle units. Host and PowerPC only (the
 * Cortex-M3 flash cannot hold it). Do not edit; run tools/generate.py.
 */
#ifndef VECTORS_ORIENT_RANDOM_H
#define VECTORS_ORIENT_RANDOM_H

#include <stdint.h>

#define ORIENT_RANDOM_COUNT %du
#define ORIENT_RANDOM_SEED UINT32_C(0x%08X)
#define ORIENT_RANDOM_PITCH_MAX UINT32_C(%d)

/* 4 parts per case: s, x, y, z */
static const int32_t orient_random_q[%d] = {
%s
};

/* 3 differences per case: yaw, pitch, roll */
static const int16_t orient_random_euler_delta[%d] = {
%s
};

/* angle between a and b (1/16 units), nlerp(a, b, t), axis and angle of
 * a (SciPy as_rotvec; angle in 1/16 units). */
struct orient_extra_vector {
  int32_t a[4];
  int32_t b[4];
  int32_t t;
  int64_t angle;
  int32_t nlerp[4];
  int32_t axis[3];
  int64_t rot_angle;
};

static const struct orient_extra_vector orient_extra_vectors[] = {
%s
};

#endif
""" % (scipy.__version__, RANDOM_COUNT, RANDOM_SEED, SUB, RANDOM_COUNT,
       RANDOM_SEED, PITCH_MAX, 4 * RANDOM_COUNT,
       "\n".join(qrows), 3 * RANDOM_COUNT, "\n".join(drows),
       "\n".join(extra_rows(random.Random(5))))
    return text
