# SPDX-License-Identifier: BSD-2-Clause
"""Random vectors over the whole documented domain of the orientation
and kinematics bounds: DH chains of 1-16 links (both conventions, link
lengths from one Q15.16 step to the format's limit, any joint values),
slerp and nlerp of quaternions of every length the headers accept
(near-identical, near-opposite and near-quarter-turn pairs included),
axis and angle of any non-zero quaternion (near the identity included).

Oracles, independent of the library: numpy float64 for DH chains (the
textbook products of elementary matrices, as gen_orient_dh.py; 1e-16
relative is 1e-7 LSB of Q1.30 and 3e-12 m at 32 km), mpmath at 40
digits for the quaternion functions, exact Python integers for every
sign decision (the slerp and nlerp arcs). Inputs are the exact integers
the library receives.

tools/accuracy/orient_bounds.py draws 12 000+ cases per function from
the same generators and measures the bounds docs/accuracy.md states;
the committed tables here are a few hundred rows per function, which
the unit tests check with those bounds as tolerances.
"""
import math
import random

import mpmath
import numpy as np

mpmath.mp.dps = 40

ONE = 1 << 30
TURN = 1 << 32
SUB = 16  # sub-units of a binary angle in the angle columns
POS_SUB = 1 << 24  # position sub-units per metre
I32_MIN, I32_MAX = -(1 << 31), (1 << 31) - 1
# Partial translations this close to +-32768 m may go either way (the
# library's own roundings); such chains are left out of both sides.
EDGE_MARGIN_M = 0.001
REV, PRI = 0, 1


def rnd(x):
    """Nearest integer, ties away from zero (float or mpf)."""
    if x < 0:
        return -rnd(-x)
    if isinstance(x, float):
        return int(math.floor(x + 0.5))
    return int(mpmath.floor(x + mpmath.mpf(1) / 2))


def signed32(v):
    v %= TURN
    return v - TURN if v >= TURN // 2 else v


def rad(b):
    return signed32(b) * 2 * math.pi / TURN


# ------------------------------------------------------------ DH chains
SPECIAL = [0, ONE, 2 * ONE, 3 * ONE, 1, TURN - 1, ONE + 1, ONE - 1]


def _angle(rng):
    if rng.random() < 0.25:
        return rng.choice(SPECIAL)
    return rng.randrange(TURN)


def _length(rng, scale):
    """A signed Q15.16 length, log-uniform from one step to `scale`."""
    if rng.random() < 0.2:
        return 0
    mag = int(2.0 ** rng.uniform(0, math.log2(scale)))
    return mag if rng.random() < 0.5 else -mag


def random_chain(rng, n=None):
    """(convention, [(a, alpha, d, theta, type)], [q]) with lengths from
    one step to the Q15.16 limit: small arms (up to 2 m per link), any
    scale spread so the chain mostly stays in range, and links up to the
    limit (most of those chains overflow on the way)."""
    n = n if n is not None else rng.randint(1, 16)
    kind = rng.random()
    if kind < 0.4:
        scale = 2 << 16
    elif kind < 0.85:
        scale = 2.0 ** rng.uniform(1, 31 - math.log2(n))
    else:
        scale = float(I32_MAX)
    links, qs = [], []
    for _ in range(n):
        ty = PRI if rng.random() < 0.25 else REV
        a, d = _length(rng, scale), _length(rng, scale)
        links.append((a, _angle(rng), d, _angle(rng), ty))
        if ty == REV:
            qs.append(signed32(_angle(rng)))
        else:
            q = _length(rng, scale)
            qs.append(max(I32_MIN - d, min(I32_MAX - d, q)))
    return (rng.randrange(2), links, qs)


def chain_request(ch):
    cv, links, qs = ch
    return "%d %d %s" % (cv, len(links), " ".join(
        "%d %d %d %d %d %d" % (l + (q,)) for l, q in zip(links, qs)))


def _rx(t):
    c, s = math.cos(t), math.sin(t)
    return np.array([[1, 0, 0, 0], [0, c, -s, 0], [0, s, c, 0], [0, 0, 0, 1.0]])


def _rz(t):
    c, s = math.cos(t), math.sin(t)
    return np.array([[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1.0]])


def _tr(x, z):
    m = np.eye(4)
    m[0, 3] = x
    m[2, 3] = z
    return m


def dh_oracle(ch):
    """Exact (float64) 4x4 base-to-tool transform and the largest
    |part| of any partial translation T1 ... Tk, in metres."""
    cv, links, qs = ch
    t = np.eye(4)
    worst = 0.0
    for (a, al, d, th, ty), q in zip(links, qs):
        theta = rad(th + (q if ty == REV else 0))
        dd = (d + (q if ty == PRI else 0)) / 65536.0
        if cv == 1:
            t = t @ _rx(rad(al)) @ _tr(a / 65536.0, 0) @ _rz(theta) @ \
                _tr(0, dd)
        else:
            t = t @ _rz(theta) @ _tr(0, dd) @ _tr(a / 65536.0, 0) @ \
                _rx(rad(al))
        worst = max(worst, float(np.max(np.abs(t[:3, 3]))))
    return t, worst


def chain_span(ch):
    """Sum of the links' lengths sqrt(a^2 + d^2), metres."""
    _, links, qs = ch
    return sum(math.hypot(a, d + (q if ty == PRI else 0)) / 65536.0
               for (a, _, d, _, ty), q in zip(links, qs))


# ----------------------------------------------------------- quaternions
def _direction(rng):
    while True:
        v = [rng.gauss(0, 1) for _ in range(4)]
        n = math.sqrt(sum(x * x for x in v))
        if n > 1e-6:
            return [x / n for x in v]


def _quat_of_length(rng, length):
    while True:
        q = [max(I32_MIN, min(I32_MAX, rnd(x * length)))
             for x in _direction(rng)]
        if any(q):
            return q


def random_quat(rng, unit=False):
    """Unit (Q1.30-rounded) or of any length from 1 LSB to the int32
    limit (log-uniform), any int32 parts."""
    if unit or rng.random() < 0.5:
        return _quat_of_length(rng, ONE)
    return _quat_of_length(rng, 2.0 ** rng.uniform(0, 31.9))


def _near(rng, q, sign):
    """sign q plus a perturbation of a few to a few thousand LSB."""
    k = 2.0 ** rng.uniform(0, 12)
    return [max(I32_MIN, min(I32_MAX, sign * c + rnd(rng.gauss(0, k))))
            for c in q]


def _quarter(rng, q):
    """A quaternion whose exact dot with q is within a few LSB^2 of 0:
    an orthogonal direction plus a tiny multiple of q."""
    o = [-q[1], q[0], -q[3], q[2]]
    if rng.random() < 0.5:
        o = [-q[2], q[3], q[0], -q[1]]
    scale = 2.0 ** rng.uniform(-2, 0.9)
    o = [max(I32_MIN, min(I32_MAX, rnd(c * scale))) for c in o]
    j = rng.randrange(4)
    o[j] = max(I32_MIN, min(I32_MAX, o[j] + rng.randint(-3, 3)))
    return o


def _t(rng):
    r = rng.random()
    if r < 0.1:
        return rng.choice([0, ONE, ONE // 2, 1, ONE - 1])
    return rng.randrange(ONE + 1)


def quat_pairs(rng, count):
    out = []
    for i in range(count):
        a = random_quat(rng)
        kind = i % 6
        if kind == 0:
            b = random_quat(rng)
        elif kind == 1:
            b = _near(rng, a, 1)    # nearly equal
        elif kind == 2:
            b = _near(rng, a, -1)   # nearly opposite: the same rotation
        elif kind == 3:
            b = _quarter(rng, a)    # dot near 0: the arc is a close call
        else:
            b = random_quat(rng, unit=True)
        out.append(a + b + [_t(rng)])
    return out


def _dot_sign(a, b):
    d = sum(x * y for x, y in zip(a, b))
    return (d > 0) - (d < 0)


def _unit(v):
    n = mpmath.sqrt(sum(mpmath.mpf(x) ** 2 for x in v))
    return [mpmath.mpf(x) / n for x in v]


def slerp_cases(rng, count):
    return quat_pairs(rng, count)


def slerp_oracle(c):
    """a (a^-1 b')^t with b' = -b when the exact a . b < 0, Q1.30 units."""
    a, b, t = c[0:4], c[4:8], mpmath.mpf(c[8]) / ONE
    if not any(a) or not any(b):
        return None
    na, nb = _unit(a), _unit(b)
    if _dot_sign(a, b) < 0:
        nb = [-x for x in nb]
    dif = mpmath.sqrt(sum((x - y) ** 2 for x, y in zip(na, nb)))
    sm = mpmath.sqrt(sum((x + y) ** 2 for x, y in zip(na, nb)))
    th = 2 * mpmath.atan2(dif, sm)
    if th == 0:
        return [x * ONE for x in na]
    wa = mpmath.sin((1 - t) * th) / mpmath.sin(th)
    wb = mpmath.sin(t * th) / mpmath.sin(th)
    return [(wa * x + wb * y) * ONE for x, y in zip(na, nb)]


def nlerp_cases(rng, count):
    return quat_pairs(rng, count)


def nlerp_oracle(c):
    """normalize((1 - t) a + t b'), a and b as given (non-unit ones weigh
    by their length), b' = -b when the exact a . b < 0; None when zero."""
    a, b, t = c[0:4], c[4:8], c[8]
    sb = -1 if _dot_sign(a, b) < 0 else 1
    u = [(ONE - t) * x + sb * t * y for x, y in zip(a, b)]  # exact, Q30
    if not any(u):
        return None
    return [x * ONE for x in _unit(u)]


def axang_cases(rng, count):
    out = []
    for i in range(count):
        q = random_quat(rng)
        if i % 4 == 1:
            # near the identity (or its negative): a tiny vector part
            k = 2.0 ** rng.uniform(0, 10)
            q[1:] = [rnd(rng.gauss(0, k)) for _ in range(3)]
            if not any(q[1:]):
                q[1] = 1
        elif i % 4 == 2:
            # near 180 degrees: a tiny scalar part, either sign
            q[0] = rnd(rng.gauss(0, 2.0 ** rng.uniform(0, 10)))
        out.append(q)
    return out


def axang_oracle(q):
    """[axis x, y, z (Q1.30), angle (binary-angle units)]:
    angle 2 atan2(|v|, |s|), axis v / |v| signed with s."""
    if not any(q):
        return None
    s, v = q[0], q[1:]
    vn = mpmath.sqrt(sum(mpmath.mpf(x) ** 2 for x in v))
    if vn == 0:
        return [ONE, 0, 0, 0]
    ang = 2 * mpmath.atan2(vn, abs(s)) / (2 * mpmath.pi) * TURN
    sg = -1 if s < 0 else 1
    return [sg * mpmath.mpf(x) / vn * ONE for x in v] + [ang]


# --------------------------------------------------- committed vectors
def _dh_rows(rng, count):
    """Chains in range (no partial translation within EDGE_MARGIN_M of
    the edge): flat links, then per chain its convention, first link,
    link count, rotation (Q1.30), position (2^-24 m) and span (2^-16 m,
    rounded up) for the length-dependent tolerance."""
    links, rows = [], []
    while len(rows) < count:
        ch = random_chain(rng)
        t, worst = dh_oracle(ch)
        if worst >= 32768 - EDGE_MARGIN_M:
            continue
        first = len(links)
        for l, q in zip(ch[1], ch[2]):
            links.append("  { { %d, UINT32_C(%d), %d, UINT32_C(%d), %s }, %d },"
                         % (l[0], l[1], l[2], l[3],
                            "DRDC_JOINT_PRISMATIC" if l[4] else
                            "DRDC_JOINT_REVOLUTE", q))
        r = [rnd(float(x) * ONE) for x in t[:3, :3].ravel()]
        p = [rnd(float(x) * POS_SUB) for x in t[:3, 3]]
        span = int(math.ceil(chain_span(ch) * 65536))
        rows.append("  { %d, %d, %d, { %s }, { %s }, INT64_C(%d) }," % (
            ch[0], first, len(ch[1]), ", ".join(str(x) for x in r),
            ", ".join("INT64_C(%d)" % x for x in p), span))
    return links, rows


def _overflow_rows(rng, links, count):
    """Chains whose partial translation leaves +-32768 m by more than
    EDGE_MARGIN_M (half of them ending back in range): appended to the
    flat links; per chain its convention, first link and link count."""
    rows = []
    back = 0
    while len(rows) < count:
        ch = random_chain(rng)
        t, worst = dh_oracle(ch)
        if worst < 32768 + EDGE_MARGIN_M:
            continue
        ends_in = float(np.max(np.abs(t[:3, 3]))) < 32768 - EDGE_MARGIN_M
        if not ends_in and back < len(rows) - back:
            continue  # keep half of them coming back
        back += ends_in
        first = len(links)
        for l, q in zip(ch[1], ch[2]):
            links.append("  { { %d, UINT32_C(%d), %d, UINT32_C(%d), %s }, %d },"
                         % (l[0], l[1], l[2], l[3],
                            "DRDC_JOINT_PRISMATIC" if l[4] else
                            "DRDC_JOINT_REVOLUTE", q))
        rows.append("  { %d, %d, %d, %d }," % (ch[0], first, len(ch[1]),
                                               1 if ends_in else 0))
    return rows


def _quat_rows(cases, oracle, angle):
    rows = []
    for c in cases:
        e = oracle(c)
        if e is None:
            continue
        if angle:
            vals = [rnd(x) for x in e[:3]]
            rows.append("  { { %s }, { %s }, INT64_C(%d) }," % (
                ", ".join(str(x) for x in c), ", ".join(str(x) for x in vals),
                rnd(e[3] * SUB)))
        else:
            rows.append("  { { %s }, { %s }, %d, { %s } }," % (
                ", ".join(str(x) for x in c[0:4]),
                ", ".join(str(x) for x in c[4:8]), c[8],
                ", ".join(str(rnd(x)) for x in e)))
    return rows


def generate():
    rng = random.Random(28)
    links, dh = _dh_rows(rng, 160)
    slerp = _quat_rows(slerp_cases(rng, 360), slerp_oracle, False)
    nlerp = _quat_rows(nlerp_cases(rng, 360), nlerp_oracle, False)
    axang = _quat_rows(axang_cases(rng, 360), axang_oracle, True)
    overflow = _overflow_rows(random.Random(29), links, 40)
    text = """/* SPDX-License-Identifier: BSD-2-Clause */
/* Generated by tests/ref/gen_orient_bounds.py: random DH chains (numpy %s
 * float64 oracle) and quaternion interpolation and axis-angle cases
 * (mpmath %s, 40 digits; exact integer dot products for the arcs) over
 * the documented domains. Do not edit; run tools/generate.py. */
#ifndef VECTORS_ORIENT_BOUNDS_H
#define VECTORS_ORIENT_BOUNDS_H

#include <stdint.h>

#include <drdc/orient_kinematics.h>

/* Sub-units per metre of the DH positions, per binary angle of angles */
#define BOUNDS_POS_SUB %d
#define BOUNDS_ANGLE_SUB %d

struct bounds_link {
  drdc_dh_link_t link;
  int32_t q;
};

/* A chain: convention, links[first .. first + n - 1], rotation (Q1.30,
 * rounded), position (2^-24 m, rounded), sum of the link lengths
 * sqrt(a^2 + d^2) (Q15.16 m, rounded up). */
struct bounds_chain {
  int32_t convention;
  int32_t first;
  int32_t n;
  int32_t r[9];
  int64_t t[3];
  int64_t span;
};

/* A chain whose partial translation leaves +-32768 m on the way (by
 * more than a millimetre): links[first .. first + n - 1]; back is 1 when
 * its final translation is in range again. */
struct bounds_overflow {
  int32_t convention;
  int32_t first;
  int32_t n;
  int32_t back;
};

/* interp(a, b, t) -> q (Q1.30, rounded). */
struct bounds_interp {
  int32_t a[4];
  int32_t b[4];
  int32_t t;
  int32_t q[4];
};

/* q -> axis (Q1.30, rounded) and angle (1/16 binary-angle units). */
struct bounds_axang {
  int32_t q[4];
  int32_t axis[3];
  int64_t angle;
};

static const struct bounds_link bounds_links[] = {
%s
};

static const struct bounds_chain bounds_chains[] = {
%s
};

static const struct bounds_overflow bounds_overflows[] = {
%s
};

static const struct bounds_interp bounds_slerp[] = {
%s
};

static const struct bounds_interp bounds_nlerp[] = {
%s
};

static const struct bounds_axang bounds_axang[] = {
%s
};

#endif
""" % (np.__version__, mpmath.__version__, POS_SUB, SUB, "\n".join(links),
       "\n".join(dh), "\n".join(overflow), "\n".join(slerp), "\n".join(nlerp), "\n".join(axang))
    return {"tests/orient/vectors_orient_bounds.h": text}
