# SPDX-License-Identifier: BSD-2-Clause
"""JAUS Report Global Pose (4402h) and Report Local Pose (4403h) bodies.

Oracle: the field tables of the standards, written out below in real units
(degrees, metres, radians as multiples of pi), the scaled-integer formulas
with Python's fractions.Fraction, and struct.pack('<...') for the
little-endian wire:

  AS6009 (JAUS Mobility Service Set 1.0; every field an unsigned type):
    ScaleFactor = (max - min) / (2^n - 1), Bias = min.
  JAUS RA 3.x (signed types for the signed quantities):
    signed:   ScaleFactor = (max - min) / (2^n - 2), Bias = (min + max) / 2
    unsigned: as AS6009.
  Integer = round((Real - Bias) / ScaleFactor); Real = Integer x
  ScaleFactor + Bias; rounding to nearest, ties away from zero.

The library's pose types hold raw values (latitude in nano-arcseconds,
heights Q47.16 m, local lengths Q15.16 m, angles 2^32 per turn), so an
input is a raw value, its real value is exact, and a decoded real value is
rounded once to the raw format. Angles: pi radians is 2^31 binary-angle
units by definition, so pi cancels and the model is exact.

Vectors: every field of both messages and both forms at its minimum,
maximum, zero, negative, near-limit and random values, each alone and with
others; every presence vector that matters (none, all, each single bit,
random subsets); the edges of the time stamp. Then bodies of arbitrary
bytes (random and extreme integers, reserved bits, wrong lengths, the
unused RA 3.x integer, bad stamps, local positions beyond Q15.16) with the
status and the values the receiver must get.
"""
import random
import struct
from fractions import Fraction

NAS_PER_DEGREE = 3600 * 10 ** 9
Q16 = 1 << 16
BAM_PER_PI = 1 << 31  # binary angle: 2^32 per turn

# Status names, in the order unpack checks (see jaus_pose.h).
OK = "DRDC_OK"

# One field: name, real lower and upper limit, unit as raw units per real
# unit, type per form as struct code ('i' int32, 'I' uint32, 'h' int16,
# 'H' uint16), the status of an out-of-range value when packing.
DEG = Fraction(NAS_PER_DEGREE)
METRE = Fraction(Q16)
PI = Fraction(BAM_PER_PI)          # raw units per multiple of pi radians


def fields(message, form):
    ra3 = form == "DRDC_JAUS_FORM_RA3"
    s32, s16 = ("i", "h") if ra3 else ("I", "H")
    angle = [(-1, 1, PI, s16, "DRDC_E_RANGE")] * 3
    rms = [(0, 100, METRE, "I", "DRDC_E_RANGE")]
    att = [(0, 1, PI, "H", "DRDC_E_RANGE")]
    if message == "global":
        pos = [(-90, 90, DEG, s32, "DRDC_E_LATITUDE"),
               (-180, 180, DEG, s32, "DRDC_E_LONGITUDE"),
               (-10000, 35000, METRE, s32, "DRDC_E_RANGE")]
    else:
        z = (-10000, 35000) if ra3 else (-100000, 100000)
        pos = [(-100000, 100000, METRE, s32, "DRDC_E_RANGE"),
               (-100000, 100000, METRE, s32, "DRDC_E_RANGE"),
               (z[0], z[1], METRE, s32, "DRDC_E_RANGE")]
    return pos + rms + angle + att


def round_away(x):
    x = Fraction(x)
    n = (abs(x.numerator) * 2 + x.denominator) // (2 * x.denominator)
    return -n if x < 0 else n


def scaling(code, lo, hi):
    """(ilo, ihi, scale, bias) of a field, in real units."""
    bits = struct.calcsize("<" + code) * 8
    lo, hi = Fraction(lo), Fraction(hi)
    if code in "ih":
        h = (1 << (bits - 1)) - 1
        return -h, h, (hi - lo) / (2 * h), (lo + hi) / 2
    return 0, (1 << bits) - 1, (hi - lo) / ((1 << bits) - 1), lo


def encode(field, raw):
    lo, hi, unit, code, _ = field
    ilo, ihi, scale, bias = scaling(code, lo, hi)
    i = round_away((Fraction(raw) / unit - bias) / scale)
    assert ilo <= i <= ihi
    return i


def decode(field, integer):
    lo, hi, unit, code, _ = field
    _, _, scale, bias = scaling(code, lo, hi)
    return round_away((integer * scale + bias) * unit)


def stamp_of(day, hour, minute, second, msec):
    return (day << 27) | (hour << 22) | (minute << 16) | (second << 10) | msec


def stamp_status(s):
    """drdc_time_jaus_unpack's checks, in its order."""
    if (s >> 27) & 31 == 0:
        return "DRDC_E_DAY"
    if (s >> 22) & 31 > 23:
        return "DRDC_E_HOUR"
    if (s >> 16) & 63 > 59:
        return "DRDC_E_MINUTE"
    if (s >> 10) & 63 > 60:
        return "DRDC_E_SECOND"
    if s & 1023 > 999:
        return "DRDC_E_NANOSECOND"
    return OK


def to_bam(raw):
    """A signed raw angle as the library's binary angle (uint32)."""
    return raw & 0xFFFFFFFF


def from_bam(bam):
    return bam - (1 << 32) if bam >= 1 << 31 else bam


def body_bytes(message, form, presence, raw, stamp):
    """The wire bytes of valid inputs (raw values, angles signed)."""
    out = struct.pack("<H", presence)
    for bit, f in enumerate(fields(message, form)):
        if presence >> bit & 1:
            out += struct.pack("<" + f[3], encode(f, raw[bit]))
    if presence >> 8 & 1:
        out += struct.pack("<I", stamp)
    return out


def unpack_model(message, form, data):
    """(status, presence, raw values, stamp) a receiver must get."""
    if len(data) < 2:
        return "DRDC_E_TRUNCATED", 0, [0] * 8, 0
    presence = struct.unpack_from("<H", data)[0]
    if presence & ~0x1FF:
        return "DRDC_E_RANGE", 0, [0] * 8, 0
    table = fields(message, form)
    need = 2 + sum(struct.calcsize("<" + f[3]) for b, f in enumerate(table)
                   if presence >> b & 1) + (4 if presence >> 8 & 1 else 0)
    if len(data) < need:
        return "DRDC_E_TRUNCATED", 0, [0] * 8, 0
    if len(data) > need:
        return "DRDC_E_OVERLONG", 0, [0] * 8, 0
    raw, pos = [0] * 8, 2
    for bit, f in enumerate(table):
        if presence >> bit & 1:
            i = struct.unpack_from("<" + f[3], data, pos)[0]
            pos += struct.calcsize("<" + f[3])
            ilo, ihi, _, _ = scaling(f[3], f[0], f[1])
            if not ilo <= i <= ihi:
                return "DRDC_E_RANGE", 0, [0] * 8, 0
            raw[bit] = decode(f, i)
    stamp = 0
    if presence >> 8 & 1:
        stamp = struct.unpack_from("<I", data, pos)[0]
        st = stamp_status(stamp)
        if st != OK:
            return st, 0, [0] * 8, 0
    if message == "local" and any(not -(1 << 31) <= v < 1 << 31 for v in raw[:3]):
        return "DRDC_E_OVERFLOW", 0, [0] * 8, 0
    return OK, presence, raw, stamp


MESSAGES = ["global", "local"]
FORMS = ["DRDC_JAUS_FORM_RA3", "DRDC_JAUS_FORM_AS6009"]


def raw_limits(message, form, bit):
    """Smallest and largest raw input the pose type can hold in range."""
    lo, hi, unit, _, _ = fields(message, form)[bit]
    rlo, rhi = lo * unit, hi * unit
    # ceil / floor to raw values
    rlo = -((-rlo.numerator) // rlo.denominator)
    rhi = rhi.numerator // rhi.denominator
    if message == "local" and bit < 3 or bit == 3:
        rlo, rhi = max(rlo, -(1 << 31)), min(rhi, (1 << 31) - 1)   # Q15.16
    if 4 <= bit <= 6:
        rhi = min(rhi, (1 << 31) - 1)  # a binary angle stops below +pi
    return rlo, rhi


def random_raw(rng, message, form):
    return [rng.randint(*raw_limits(message, form, b)) for b in range(8)]


def random_stamp(rng):
    return stamp_of(rng.randint(1, 31), rng.randint(0, 23), rng.randint(0, 59),
                    rng.randint(0, 60), rng.randint(0, 999))


def pack_vectors(rng):
    rows = []
    for message in MESSAGES:
        for form in FORMS:
            cases = []
            # each field alone at its notable values
            for bit in range(8):
                rlo, rhi = raw_limits(message, form, bit)
                values = {rlo, rhi, rlo + 1, rhi - 1, (rlo + rhi) // 2}
                if rlo < 0 < rhi:
                    values.update([0, -1, 1, rlo // 3, rlo // 2])
                values.update(rng.randint(rlo, rhi) for _ in range(3))
                for v in sorted(values):
                    raw = [0] * 8
                    raw[bit] = v
                    cases.append((1 << bit, raw, 0))
            # the time stamp alone at its edges
            for s in (stamp_of(1, 0, 0, 0, 0), stamp_of(31, 23, 59, 60, 999),
                      stamp_of(31, 23, 59, 59, 999), stamp_of(22, 17, 0, 1, 0),
                      random_stamp(rng)):
                cases.append((0x100, [0] * 8, s))
            # presence vectors: none, all, the demo's, random subsets
            for presence in [0, 0x1FF, 0x177, 0x0FF, 0x100, 0x1F0, 0x00F] + \
                    [rng.randint(0, 0x1FF) for _ in range(24)]:
                cases.append((presence, random_raw(rng, message, form), random_stamp(rng)))
            # everything present at the limits
            for pick in (0, 1):
                raw = [raw_limits(message, form, b)[pick] for b in range(8)]
                cases.append((0x1FF, raw, random_stamp(rng)))
            for presence, raw, stamp in cases:
                raw = [v if presence >> b & 1 else 0 for b, v in enumerate(raw)]
                stamp = stamp if presence >> 8 & 1 else 0
                data = body_bytes(message, form, presence, raw, stamp)
                st, _, out, _ = unpack_model(message, form, data)
                rows.append((message, form, presence, raw, stamp, data, st, out))
    return rows


def unpack_vectors(rng):
    rows = []
    for message in MESSAGES:
        for form in FORMS:
            table = fields(message, form)
            bodies = []
            for _ in range(20):
                # random integers over each whole type, any presence
                presence = rng.randint(0, 0x1FF)
                data = struct.pack("<H", presence)
                for bit, f in enumerate(table):
                    if presence >> bit & 1:
                        n = struct.calcsize("<" + f[3]) * 8
                        data += rng.randint(0, (1 << n) - 1).to_bytes(n // 8, "little")
                if presence >> 8 & 1:
                    data += struct.pack("<I", random_stamp(rng))
                bodies.append(data)
            # each integer field at the ends of its type
            for bit, f in enumerate(table):
                n = struct.calcsize("<" + f[3])
                for b in (b"\x00" * n, b"\xff" * n, b"\x00" * (n - 1) + b"\x80",
                          b"\xff" * (n - 1) + b"\x7f", b"\x01" + b"\x00" * (n - 1)):
                    bodies.append(struct.pack("<H", 1 << bit) + b)
            # lengths: empty, one byte, truncated, overlong
            full = bytes(rng.randint(0, 255) for _ in range(28))
            ok_stamp = struct.pack("<I", stamp_of(5, 6, 7, 8, 9))
            bodies += [b"", b"\xff", b"\x00\x00", b"\x00\x00\x00",
                       struct.pack("<H", 0x1FF) + full[:24] + ok_stamp[:3],
                       struct.pack("<H", 0x1FF) + full[:24] + ok_stamp + b"\x00",
                       struct.pack("<H", 0x001) + b"\x01\x02\x03"]
            # reserved bits
            for pv in (0x200, 0x8000, 0xFE00, 0xFFFF):
                bodies.append(struct.pack("<H", pv))
            # bad time stamps, one per field
            for s in (stamp_of(0, 1, 1, 1, 1), stamp_of(1, 24, 1, 1, 1),
                      stamp_of(1, 1, 60, 1, 1), stamp_of(1, 1, 1, 61, 1),
                      stamp_of(1, 1, 1, 1, 1000), 0xFFFFFFFF, 0):
                bodies.append(struct.pack("<HI", 0x100, s))
            for data in bodies:
                st, presence, raw, stamp = unpack_model(message, form, data)
                rows.append((message, form, data, st, presence, raw, stamp))
    return rows


def c_bytes(data):
    return "{ %s }" % ", ".join("0x%02x" % b for b in data) if data else "{ 0 }"


def c_values(raw):
    return "{ %s }" % ", ".join("INT64_C(%d)" % v for v in raw)


def generate():
    rng = random.Random(4402)
    packs = pack_vectors(rng)
    unpacks = unpack_vectors(rng)
    prow = []
    for message, form, presence, raw, stamp, data, st, out in packs:
        prow.append("  { %d, %s, 0x%04x, %s, UINT32_C(0x%08x), %d, %s, %s, %s },"
                    % (message == "local", form, presence, c_values(raw), stamp,
                       len(data), c_bytes(data), st, c_values(out)))
    urow = []
    for message, form, data, st, presence, raw, stamp in unpacks:
        urow.append("  { %d, %s, %d, %s, %s, 0x%04x, %s, UINT32_C(0x%08x) },"
                    % (message == "local", form, len(data), c_bytes(data), st,
                       presence, c_values(raw), stamp))
    text = """/* SPDX-License-Identifier: BSD-2-Clause */
/* Generated by tests/ref/gen_jaus_pose.py: JAUS Report Global Pose and
 * Report Local Pose bodies (RA 3.x and AS6009) from the standards' field
 * tables, an exact Fraction model of the scaled integers and
 * struct.pack('<...'). Raw values: latitude/longitude nas, altitude
 * Q47.16 m, X/Y/Z and Position RMS Q15.16 m, roll/pitch/yaw signed binary
 * angles (-2^31..2^31), Attitude RMS binary angle. Do not edit; run
 * tools/generate.py. */
#ifndef VECTORS_JAUS_POSE_H
#define VECTORS_JAUS_POSE_H

#include <stdint.h>

#include <drdc/jaus_pose.h>

/* valid inputs -> bytes; the bytes unpacked -> status and raw values */
struct jaus_pose_pack_vector {
  uint8_t local;
  drdc_jaus_form_t form;
  uint16_t presence;
  int64_t in[8];
  uint32_t stamp;
  uint8_t length;
  uint8_t bytes[DRDC_JAUS_POSE_BODY_MAX];
  drdc_status_t unpacked;
  int64_t out[8];
};

/* any bytes -> status, presence, raw values and stamp */
struct jaus_pose_unpack_vector {
  uint8_t local;
  drdc_jaus_form_t form;
  uint8_t length;
  uint8_t bytes[DRDC_JAUS_POSE_BODY_MAX + 1];
  drdc_status_t status;
  uint16_t presence;
  int64_t out[8];
  uint32_t stamp;
};

static const struct jaus_pose_pack_vector jaus_pose_pack_vectors[] = {
%s
};

static const struct jaus_pose_unpack_vector jaus_pose_unpack_vectors[] = {
%s
};

#endif
""" % ("\n".join(prow), "\n".join(urow))
    return {"tests/jaus/vectors_jaus_pose.h": text}
