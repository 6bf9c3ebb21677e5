#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Offline measurement of the accuracy bounds of the orientation and
kinematics headers on random inputs over their whole documented domain.

    PYTHONPATH=.deps/python python3 tools/accuracy/orient_bounds.py \\
        build/host/accuracy-sample [cases [seed]]

The library's results come from the host sampler (tools/accuracy/
sample.c: the same library code and bits as the firmware); the oracle is
independent: numpy float64 for DH chains (its 1e-16 relative error is
1e-7 LSB of Q1.30 and 3e-12 m at 32 km), mpmath at 40 digits for the
quaternion functions, exact Python integers for every sign decision.
Errors are against the exact value: "raw" is |library - exact| in LSB,
"LSB" is |library - exact rounded to the format| (docs/accuracy.md's
unit). `cases` per quaternion function (default 12 000) and as many
single links; four times as many DH chains. docs/accuracy.md's figures
are the maxima of three runs: the defaults, `50000 77` and `50000 99`.
The random cases (seed 2811 unless given) and the domains are those of
tests/ref/gen_orient_bounds.py, whose smaller committed tables the unit
tests check with the documented bounds as tolerances.
"""
import os
import random
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tests", "ref"))

import gen_orient_bounds as gb  # noqa: E402


def run(sampler, requests):
    out = subprocess.run([sampler], input="".join(r + "\n" for r in requests),
                         capture_output=True, text=True, check=True).stdout
    lines = out.splitlines()
    assert len(lines) == len(requests)
    return lines


def ints(line):
    return None if line.startswith("ERR") else [int(x) for x in line.split()]


def measure_dh(sampler, count, rng):
    chains = [gb.random_chain(rng) for _ in range(count)]
    req = [gb.chain_request(c) for c in chains]
    fw = run(sampler, ["dh " + r for r in req])
    cc = run(sampler, ["dhc " + r for r in req])
    iv = run(sampler, ["dhinv " + r for r in req])
    st = {"n": 0, "ovf": 0, "ovf_disagree": 0, "rot_raw": 0.0, "rot": 0,
          "rot_by_n": {}, "pos_um": 0.0, "pos_k": 0.0, "pos_short_um": 0.0,
          "cmp_rot": 0, "cmp_pos": 0, "cmp_rot_raw": 0.0, "cmp_pos_k": 0.0,
          "inv_rot": 0, "inv_pos": 0, "inv_pos_k": 0.0, "worst": None,
          "beyond2": 0, "link_rot_raw": 0.0}
    for ch, a, b, c in zip(chains, fw, cc, iv):
        exact, partial_max = gb.dh_oracle(ch)
        la, lb = ints(a), ints(b)
        if partial_max >= 32768 + gb.EDGE_MARGIN_M:
            st["ovf"] += 1
            if la is not None or lb is not None:
                st["ovf_disagree"] += 1
            continue
        if partial_max >= 32768 - gb.EDGE_MARGIN_M:
            continue  # within the roundings of the edge: either status
        if la is None or lb is None:
            st["ovf_disagree"] += 1
            continue
        st["n"] += 1
        n = len(ch[1])
        rot = exact[:3, :3].ravel() * gb.ONE
        raw = max(abs(x - y) for x, y in zip(la[:9], rot))
        lsb = max(abs(x - gb.rnd(y)) for x, y in zip(la[:9], rot))
        st["rot_raw"] = max(st["rot_raw"], raw)
        if lsb > st["rot"]:
            st["rot"] = lsb
            st["worst"] = gb.chain_request(ch)
        st["beyond2"] += lsb > 2
        st["rot_by_n"][n] = max(st["rot_by_n"].get(n, 0), lsb)
        pos = exact[:3, 3]
        perr = max(abs(x / 65536.0 - y) for x, y in zip(la[9:], pos))
        span = gb.chain_span(ch)
        st["pos_um"] = max(st["pos_um"], perr * 1e6)
        if span <= 2.0 * n:
            st["pos_short_um"] = max(st["pos_short_um"], perr * 1e6)
        if span > 0:
            st["pos_k"] = max(st["pos_k"],
                              (perr - 0.5 / 65536) / (span * 2.0 ** -30))
        # link-by-link composition against drdc_dh_forward and the oracle
        st["cmp_rot"] = max(st["cmp_rot"],
                            max(abs(x - y) for x, y in zip(la[:9], lb[:9])))
        st["cmp_pos"] = max(st["cmp_pos"],
                            max(abs(x - y) for x, y in zip(la[9:], lb[9:])))
        st["cmp_rot_raw"] = max(st["cmp_rot_raw"], max(
            abs(x - y) for x, y in zip(lb[:9], rot)))
        cerr = max(abs(x / 65536.0 - y) for x, y in zip(lb[9:], pos))
        st["cmp_pos_k"] = max(st["cmp_pos_k"], cerr * 1e6)
        lc = ints(c)
        if lc is not None:
            ident = [gb.ONE, 0, 0, 0, gb.ONE, 0, 0, 0, gb.ONE]
            st["inv_rot"] = max(st["inv_rot"], max(
                abs(x - y) for x, y in zip(lc[:9], ident)))
            ip = max(abs(x) for x in lc[9:])
            st["inv_pos"] = max(st["inv_pos"], ip)
            tn = max(abs(x) for x in la[9:]) / 65536.0
            st["inv_pos_k"] = max(st["inv_pos_k"], (ip - 1) / max(
                tn * 2.0 ** -30 * 65536, 1e-30))
    return st


def measure_link(sampler, count, rng):
    links = [gb.random_chain(rng, n=1) for _ in range(count)]
    # composed onto the identity: drdc_dh_link_transform()'s own bits
    out = run(sampler, ["dhc " + gb.chain_request(c) for c in links])
    worst = 0.0
    for ch, line in zip(links, out):
        v = ints(line)
        if v is None:
            continue
        exact, _ = gb.dh_oracle(ch)
        rot = exact[:3, :3].ravel() * gb.ONE
        worst = max(worst, max(abs(x - y) for x, y in zip(v[:9], rot)))
    return worst


def measure_quat(sampler, name, cases, oracle, width):
    out = run(sampler, [name + " " + " ".join(str(x) for x in c)
                        for c in cases])
    worst = [0.0] * width
    worst_lsb = [0] * width
    arg = None
    errs = 0
    for c, line in zip(cases, out):
        v = ints(line)
        e = oracle(c)
        if v is None or e is None:
            errs += (v is None) != (e is None)
            continue
        for k, (x, y) in enumerate(zip(v, e)):
            d = abs(x - float(y))
            if k < width and d > worst[k]:
                worst[k] = d
                if k == 0:
                    arg = c
            if k < width:
                worst_lsb[k] = max(worst_lsb[k], abs(x - gb.rnd(y)))
    return worst, worst_lsb, errs, arg


def main(argv):
    sampler = argv[1]
    count = int(argv[2]) if len(argv) > 2 else 12000
    rng = random.Random(int(argv[3]) if len(argv) > 3 else 2811)
    st = measure_dh(sampler, 4 * count, rng)
    print("(%d cases per quaternion function, %d links, %d chains)" % (
        count, count, 4 * count))
    print("drdc_dh_forward: %d chains in range, %d beyond 32 km on the way "
          "(%d status disagreements)" % (st["n"], st["ovf"],
                                          st["ovf_disagree"]))
    print("  rotation: max %d LSB (raw %.2f), %d chains beyond 2 LSB; by n: %s"
          % (st["rot"], st["rot_raw"], st["beyond2"],
             sorted(st["rot_by_n"].items())))
    print("  worst: %s" % st["worst"])
    print("  position: max %.2f um (chains of <= 2 m per link: %.2f um); "
          "(err - 0.5 LSB) / (span 2^-30) max %.3f" % (
              st["pos_um"], st["pos_short_um"], st["pos_k"]))
    print("link by link: %d LSB rotation, %d LSB position from dh_forward; "
          "rotation raw %.2f LSB from exact; position %.2f um from exact" % (st["cmp_rot"], st["cmp_pos"],
                                     st["cmp_rot_raw"], st["cmp_pos_k"]))
    print("T T^-1 - I: rotation %d LSB, translation %d LSB, (err - 1) / "
          "(|t| 2^-30) max %.3f" % (st["inv_rot"], st["inv_pos"],
                                    st["inv_pos_k"]))
    print("drdc_dh_link_transform rotation: raw %.3f LSB (%d links)" % (
        measure_link(sampler, count, rng), count))
    for name, gen, orc, width in (
            ("slerp", gb.slerp_cases, gb.slerp_oracle, 4),
            ("nlerp", gb.nlerp_cases, gb.nlerp_oracle, 4),
            ("axang", gb.axang_cases, gb.axang_oracle, 4)):
        cases = gen(rng, count)
        worst, lsb, errs, arg = measure_quat(sampler, name, cases, orc, width)
        print("%s: %d cases, raw max %s, LSB max %s, status disagreements %d,"
              " worst at %s" % (name, len(cases),
                                ["%.3f" % w for w in worst], lsb, errs, arg))


if __name__ == "__main__":
    main(sys.argv)
