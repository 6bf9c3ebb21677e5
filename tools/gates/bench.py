#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Deterministic benchmarks and footprint of the library (./waf bench).

Boots fw/bench on each QEMU target with -icount shift=0, where QEMU's
virtual clock advances by exactly one nanosecond per executed instruction,
so the board's tick counter (time base on ppc-e500, SysTick on arm-cm3)
follows the instruction count and repeats run to run. The image prints raw
ticks; this tool calibrates ticks to instructions with bsp_spin() (a loop
of known instruction count), subtracts the measured loop overhead and
reports instructions per call, which is QEMU's cycle model: one cycle per
instruction. Real silicon adds wait states and pipeline effects; ratios
between implementations on the same target are the meaningful figures.

  bench.py --build build --out build/bench/report.json [--docs docs]
  bench.py --build build --check docs/performance.json   (the guard)

The guard fails when a function's instruction count on a target grows
more than 5 % over the committed report, or the library's flash (text +
rodata + data) grows more than 5 %; regenerating the report (./waf bench)
and committing it with the change that causes the growth is what makes it
pass. It also fails, whatever the committed report says, when a budget of
tools/gates/footprint.py fails: a public function's worst-case stack over
STACK_LIMIT on a target (or unbounded: recursion), or the demo pose node
linking more of the library than LINKED_BUDGET allows.

Instruction counts, sizes and stack depths are the compiler's as much as
the library's, so the report records the compilers that built it and the
guard holds them on that toolchain only: images built by another compiler
(another Debian release's) get the same comparisons and budgets printed,
marked as reported, and pass.
"""
import argparse
import ast
import json
import os
import re
import subprocess
import sys

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, TOP)
from qemu import harness  # noqa: E402
from tools.gates import footprint  # noqa: E402
from waftools import deps  # noqa: E402
from waftools.targets import TARGETS as ALL_TARGETS  # noqa: E402
from waftools.targets import role, with_role  # noqa: E402

TARGETS = with_role("bench")
# the sizes of every Cortex-M target, and of the bench targets
SIZE_TARGETS = [t for t in ALL_TARGETS
                if role(t, "bench") or role(t, "footprint")]
# where the soft-float double baselines run: bench targets whose
# toolchain has soft-float double and a libm
DOUBLE_TARGETS = tuple(t for t in TARGETS if role(t, "soft_float_libm"))
GROWTH_LIMIT = 1.05

CASE_RE = re.compile(r"^BENCH (\S+) (\S+) symbol=(\S+) calls=(\d+) ticks=(\d+)$")
CAL_RE = re.compile(r"^BENCH-CALIBRATE iterations=(\d+) per_iteration=(\d+) ticks=(\d+)$")
CHECK_RE = re.compile(r"^BENCH-CHECK (\S+) worst=(\d+) limit=(\d+) unit=(\S+) (ok|FAIL)$")

# How each double baseline (fw/bench/cases_double.c) is written and why it
# is a fair comparison, as docs/performance.md states it.
BASELINE_NOTES = {
    "quat_mul": "the 16 products and 12 sums of the Hamilton product on "
                "operands already in double.",
    "quat_rotate": "v + s t + u x t with t = (2 / |q|^2) u x v: one "
                   "division, no square root, no matrix; the library rotates "
                   "by q / |q| too.",
    "euler_to_quat": "sin and cos of the three half angles (six libm calls; "
                     "newlib's sincos is the two calls) and the z-y-x "
                     "composition with its four pair products shared (12 "
                     "products).",
    "quat_to_euler": "two atan2 and one asin of the unnormalised "
                     "quaternion's products, one division by |q|^2 for the "
                     "pitch's sine, no square root; no gimbal-lock branch "
                     "(the library has one).",
    "utm_forward": "the library's computation in 7 libm calls: sin and cos "
                   "of phi and lambda, atan2 for xi', log for eta', atan2 "
                   "for the convergence, one square root for the scale; chi "
                   "by its 6-term series (Clenshaw) and a small rotation, "
                   "the double angles of xi' and eta' from tanh eta' by "
                   "products, Krueger's 6 terms and their derivative by one "
                   "complex Clenshaw recurrence (as GeographicLib sums it); "
                   "the zone rules included.",
    "utm_reverse": "the library's computation in 10 libm calls: sin and cos "
                   "of 2 xi, exp of 2 eta and of eta', sin and cos of xi', "
                   "one root and atan2 for chi, atan2 for lambda, atan2 for "
                   "the convergence, one root for the scale; Krueger's beta "
                   "series and its derivative by one complex Clenshaw "
                   "recurrence, phi by the 7-term series and a small "
                   "rotation. The library takes the same series with one "
                   "sin/cos (of xi), sin and cos chi by quotients, and the "
                   "atan series near the axis (core/geo/tm.c).",
    "ecef_forward": "sin and cos of latitude and longitude and one square "
                    "root for the prime vertical radius.",
    "ecef_reverse": "Bowring's iteration with the library's two steps: one "
                    "reciprocal square root per normalisation, two atan2, "
                    "constants multiplied, not divided.",
    "utc_to_gps": "Unix seconds with fraction in one double (0.24 us "
                  "resolution in 2026, no 23:59:60: less than the library "
                  "delivers); the leap seconds counted by a binary search "
                  "of the 18-entry table; floor for the week.",
    "gps_to_utc": "the week and seconds in one double, a binary search of "
                  "the leap instants in GPS seconds (made once).",
}


def run_target(build, target, image=None):
    """Instructions per call of each case of a benchmark image (fw/bench,
    or another that prints its lines, such as fw/bench-cxx)."""
    image = image or os.path.join(build, target, "fw", "bench", "bench.elf")
    data, status, killed = harness.boot(target, image, inactivity=20, timeout=300,
                                        max_bytes=1 << 20, extra=["-icount", "shift=0"])
    text = data.decode("ascii", errors="replace").replace("\r", "")
    if killed or "BENCH-DONE" not in text:
        sys.exit("bench: %s did not finish (%s)\n%s" % (target, killed, text[-2000:]))
    per_tick = None
    raw = []
    checks = []
    for line in text.splitlines():
        m = CHECK_RE.match(line)
        if m:
            checks.append({"name": m.group(1), "worst": int(m.group(2)),
                           "limit": int(m.group(3)), "unit": m.group(4),
                           "ok": m.group(5) == "ok"})
        m = CAL_RE.match(line)
        if m:
            iterations, per_iter, ticks = (int(x) for x in m.groups())
            per_tick = iterations * per_iter / ticks
        m = CASE_RE.match(line)
        if m:
            raw.append((m.group(1), m.group(2), m.group(3), int(m.group(4)), int(m.group(5))))
    overhead = next(r for r in raw if r[0] == "overhead")
    cases = {}
    for impl, name, symbol, calls, ticks in raw:
        if impl == "overhead":
            continue
        instructions = (ticks - overhead[4] * calls / overhead[3]) * per_tick / calls
        cases[(impl, name)] = {"instructions": round(instructions, 1), "symbol": symbol}
    return cases, per_tick, checks


def symbol_sizes(build, target):
    image = os.path.join(build, target, "fw", "bench", "bench.elf")
    out = subprocess.run([footprint.PREFIX[target] + "nm", "-S", image], check=True,
                         capture_output=True, text=True).stdout
    sizes = {}
    clones = []
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 4:
            if "." in parts[3]:
                clones.append((parts[3], int(parts[1], 16)))
            sizes[parts[3]] = int(parts[1], 16)
    # GCC's pieces of a function (f.part.0 after partial inlining, f.cold,
    # f.isra.0, f.constprop.0) are its code too: counted with f.
    for name, size in clones:
        base = name.split(".")[0]
        if base in sizes:
            sizes[base] += size
    return sizes


def records(build):
    out = []
    calibration = {}
    checks = {}
    for target in TARGETS:
        cases, per_tick, checks[target] = run_target(build, target)
        calibration[target] = round(per_tick, 4)
        sizes = symbol_sizes(build, target)
        for (impl, name), c in sorted(cases.items()):
            if impl != "drdc":
                continue
            rec = {"name": name, "target": target, "function": c["symbol"],
                   "instructions": c["instructions"], "code_bytes": sizes.get(c["symbol"]),
                   "baselines": []}
            for base in ("double", "libfixmath", "hand"):
                b = cases.get((base, name))
                if b:
                    rec["baselines"].append({
                        "name": base, "function": b["symbol"], "instructions": b["instructions"],
                        "ratio": round(b["instructions"] / c["instructions"], 2)})
            first = rec["baselines"][0] if rec["baselines"] else None
            rec["baseline"] = first["name"] if first else None
            rec["baseline_instructions"] = first["instructions"] if first else None
            rec["ratio"] = first["ratio"] if first else None
            out.append(rec)
        # baselines without a drdc counterpart yet: listed for reference
        for (impl, name), c in sorted(cases.items()):
            if impl != "drdc" and ("drdc", name) not in cases:
                out.append({"name": name, "target": target, "function": None,
                            "instructions": None, "code_bytes": None,
                            "baselines": [{"name": impl, "function": c["symbol"],
                                           "instructions": c["instructions"], "ratio": None}],
                            "baseline": impl, "baseline_instructions": c["instructions"],
                            "ratio": None})
    return out, calibration, checks


def flash(fp):
    lib = fp["library"]
    return lib["text"] + lib["rodata"] + lib["data"]


def linked_flash(fp):
    """Flash bytes of the library that the demo pose node links."""
    return flash({"library": fp["linked"]["sections"]})


def over_linked_budget(target, fp):
    budget = footprint.LINKED_BUDGET.get(target)
    return budget is not None and "linked" in fp and linked_flash(fp) > budget


def too_deep(fp):
    """Public functions deeper than the stack limit or unbounded."""
    return sorted(f for f, s in fp.get("stack", {}).items()
                  if s.get("bytes") is None or s["bytes"] > footprint.STACK_LIMIT)


# The speed goals: (goal, case name, baseline, targets, least ratio
# baseline instructions / ours).
SPEED_GOALS = [
    ("quaternion multiply >= 10x soft-float double", "quat_mul", "double",
     DOUBLE_TARGETS, 10.0),
    ("rotation >= 10x", "quat_rotate", "double", DOUBLE_TARGETS, 10.0),
    ("Euler -> quaternion >= 10x", "euler_to_quat", "double", DOUBLE_TARGETS, 10.0),
    ("quaternion -> Euler >= 10x", "quat_to_euler", "double", DOUBLE_TARGETS, 10.0),
    ("geographic -> UTM >= 10x", "utm_forward", "double", DOUBLE_TARGETS, 10.0),
    ("time UTC -> GPS >= 5x", "utc_to_gps", "double", DOUBLE_TARGETS, 5.0),
    ("time GPS -> UTC >= 5x", "gps_to_utc", "double", DOUBLE_TARGETS, 5.0),
    ("sin no slower than libfixmath", "sin", "libfixmath", TARGETS, 1.0),
    ("cos no slower than libfixmath", "cos", "libfixmath", TARGETS, 1.0),
    ("atan2 no slower than libfixmath", "atan2", "libfixmath", TARGETS, 1.0),
    ("quaternion multiply within 1.5x of the hand floor", "quat_mul", "hand",
     TARGETS, 1.0 / 1.5),
]


def goal_lines(report):
    """The goals table of docs/performance.md: each goal, its measured value
    and whether it is met."""
    lines = ["| goal | target | measured | met |", "|---|---|---:|---|"]
    for goal, name, base, targets, least in SPEED_GOALS:
        for target in targets:
            rec = next(r for r in report["functions"]
                       if r["name"] == name and r["target"] == target and r["instructions"])
            b = next(b for b in rec["baselines"] if b["name"] == base)
            ratio = b["instructions"] / rec["instructions"]
            shown = ("%.2fx the floor" % (1.0 / ratio)) if base == "hand" else "%.1fx" % ratio
            lines.append("| %s | %s | %s | %s |" % (
                goal, target, shown, "yes" if ratio >= least else "**no**"))
    for target, fp in sorted(report["footprint"].items()):
        ram = fp["library"]["data"] + fp["library"]["bss"]
        lines += [
            "| demo pose node links at most %d bytes of the library | %s | %d | %s |"
            % (footprint.LINKED_BUDGET[target], target, linked_flash(fp),
               "yes" if not over_linked_budget(target, fp) else "**no**"),
            "| no .data/.bss | %s | %d | %s |" % (
                target, ram, "yes" if ram == 0 else "**no**"),
            "| no public function deeper than %d bytes | %s | %d deeper | %s |" % (
                footprint.STACK_LIMIT, target, len(too_deep(fp)),
                "yes" if not too_deep(fp) else "**no**")]
    return lines


def baseline_lines(report):
    lines = []
    checks = [c for cs in report.get("baseline_checks", {}).values() for c in cs]
    for name, note in sorted(BASELINE_NOTES.items()):
        mine = [c for c in checks if c["name"].split(".")[0] == name] or \
            [c for c in checks if c["name"] == "time" and name in (
                "utc_to_gps", "gps_to_utc")]
        for i, c in enumerate(mine or [None]):
            lines.append("| %s | %s | %s | %s | %s | %s |" % (
                name if i == 0 else "", note if i == 0 else "",
                c["name"] if c else "-", c["worst"] if c else "-",
                c["limit"] if c else "-", c["unit"] if c else "-"))
    return lines


def write_docs(report, docs):
    lines = ["# Performance and footprint", "",
             "Generated by `./waf bench` (tools/gates/bench.py); do not edit.", "",
             "**Unit.** Every figure is the number of instructions executed per",
             "call under QEMU `-icount shift=0`, after subtracting the empty loop,",
             "over %d-call runs on fixed operands made before timing. It is not a"
             % 4096,
             "clock-cycle count. On a Cortex-M3 with zero wait states most",
             "instructions take one cycle, loads two, a taken branch 2-4 (pipeline",
             "refill), a 32x32->64 multiply (UMULL/SMULL) 3-5 and a divide 2-12",
             "(ARM Cortex-M3 Technical Reference Manual, DDI 0337, table 3.1);",
             "flash wait states (typically 1-2 above 24-48 MHz, partly hidden by a",
             "prefetch buffer) add more. The e500 issues up to two instructions per",
             "clock, with a 4-cycle multiply latency and divides of up to 35 cycles",
             "(Freescale e500 Core Reference Manual). Ratios between two",
             "implementations on the same target are the meaningful figures; the",
             "64-bit products that dominate the library (one UMULL-based sequence",
             "each) cost more cycles per instruction than the soft-float",
             "baselines' shifts and adds, so on silicon the ratios against double",
             "are likely somewhat lower than shown.", "",
             "**Toolchain.** Measured on Debian %s with"
             % (report.get("release") or "(unknown)"),
             toolchain_text(report) + ".",
             "Instruction counts, sizes and stack depths move with the compiler:",
             "`./waf check` holds them to this report (5 %, and the budgets below)",
             "where these compilers build the images, and where another release's",
             "do (Debian 13's gcc 14) it prints the same comparisons and budgets in",
             "its log without failing.", "",
             "**Baselines.** `double`: the same computation written in double by a",
             "competent engineer, compiled with soft-float and newlib's libm",
             "(Cortex-M3 only: Debian's PowerPC libgcc has no soft-float routines);",
             "how each is written and why it is fair is under Baselines below, and",
             "before timing the bench compares every one with the library on all",
             "its operands (a baseline beyond the library's documented accuracy",
             "fails `./waf bench` and `./waf check`). `libfixmath`: Debian's",
             "libfixmath 0~20220222 (Q16.16, FIXMATH_NO_CACHE). `hand`: the floor",
             "of a quaternion product, a function with the signature of",
             "`drdc_quat_mul` (operands and result through pointers, called, not",
             "inlined) doing its 16 multiply-accumulates by hand with truncating",
             "shifts, without rounding, null or overflow checks",
             "(fw/bench/cases_orient.c); its goal is a ratio of at least 0.67x",
             "(within 1.5 times the floor). Ratio = baseline instructions /",
             "ours (higher is better for us).", "",
             "## Goals", ""] + goal_lines(report) + [
             "", "## Baselines", "",
             "Each double baseline (fw/bench/cases_double.c) takes its operands",
             "already in double (converted before timing), is called through",
             "pointers like the library, makes the fewest libm calls its formula",
             "needs, and folds its results by their bits. Checked before timing",
             "against the library on all 256 operands; worst difference and the",
             "limit (the library's documented accuracy plus the baseline's own",
             "rounding):", "",
             "| baseline | how it is written | checked output | worst | limit | unit |",
             "|---|---|---|---:|---:|---|"] + baseline_lines(report) + [
             "", "## Instructions per call", "",
             "![instructions per call](performance.png)", "",
             "| function | target | instructions | code bytes | baseline | baseline instructions | ratio |",
             "|---|---|---:|---:|---|---:|---:|"]
    for r in report["functions"]:
        bases = r["baselines"] or [{"name": "-", "instructions": None, "ratio": None}]
        for b in bases:
            lines.append("| %s | %s | %s | %s | %s | %s | %s |" % (
                r["function"] or "(%s)" % r["name"], r["target"],
                "-" if r["instructions"] is None else "%.1f" % r["instructions"],
                "-" if r["code_bytes"] is None else r["code_bytes"], b["name"],
                "-" if b["instructions"] is None else "%.1f" % b["instructions"],
                "-" if b["ratio"] is None else "%.1fx" % b["ratio"]))
    lines += ["", "## Footprint of libdrdc.a", "",
              "Flash = .text + .rodata + .data of the whole archive, reported, not",
              "budgeted: what a device pays is what it links (next table).", "",
              "| target | module | .text | .rodata | .data | .bss | flash |",
              "|---|---|---:|---:|---:|---:|---:|"]
    for target, fp in sorted(report["footprint"].items()):
        for module, s in sorted(fp["modules"].items()) + [("**library**", fp["library"])]:
            lines.append("| %s | %s | %d | %d | %d | %d | %d |" % (
                target, module, s["text"], s["rodata"], s["data"], s["bss"],
                flash({"library": s})))
    lines += ["", "What an application links of it: the demo firmware (fw/demo: NMEA",
              "GGA/RMC, time scales, poses {W}/{We}/{We-UTM}/{l}, MGRS, JAUS Report",
              "Global Pose) takes, after `--gc-sections`, from its link map:", "",
              "| target | image | .text | .rodata | .data | .bss | flash |",
              "|---|---|---:|---:|---:|---:|---:|"]
    for target, fp in sorted(report["footprint"].items()):
        s = fp["linked"]["sections"]
        lines.append("| %s | %s | %d | %d | %d | %d | %d |" % (
            target, fp["linked"]["image"], s["text"], s["rodata"], s["data"],
            s["bss"], flash({"library": s})))
    lines += ["", "## Sizes by target", "",
              "Flash bytes, on every Cortex-M and bench target, of the library",
              "taken whole, of what the demo pose node links, and of what a",
              "node that parses NMEA links: with",
              "`drdc_nmea_parse()` (every sentence's decoder) and with",
              "`drdc_nmea_parse_some()` naming the GGA decoder alone",
              "(fw/nmea-size), and what the second saves.", "",
              "| target | library | demo | NMEA, every sentence | NMEA, GGA "
              "only | saved |", "|---|---:|---:|---:|---:|---:|"]
    for target, s in sorted(report.get("sizes", {}).items()):
        lines.append("| %s | %d | %d | %d | %d | %d |" % (
            target, s["library"], s["demo"], s["nmea_every"], s["nmea_gga"],
            s["nmea_every"] - s["nmea_gga"]))
    lines += ["", "## Largest symbols of libdrdc.a", "",
              "The 20 largest functions and constant tables of each target (`nm -S`;",
              "`T`/`t` code, `R`/`r` constant data, lower case: file-local). Code",
              "sizes include every helper inlined into the function.", ""]
    for target, fp in sorted(report["footprint"].items()):
        lines += ["| %s: symbol | object | type | bytes |" % target,
                  "|---|---|---|---:|"]
        for r in fp.get("symbols", []):
            lines.append("| %s | %s | %s | %d |" % (
                r["symbol"], r["object"], r["type"], r["bytes"]))
        lines.append("")
    deep = {t: too_deep(fp) for t, fp in report["footprint"].items()}
    lines += ["## Worst-case stack of each public function (bytes)", "",
              "From GCC's call graphs (`-fcallgraph-info=su`): own frame plus the",
              "deepest chain of library callees, except after a sibling (tail) call,",
              "made once the caller's frame is gone (`objdump -dr`: an unconditional",
              "jump, not a call, to the callee); libgcc helpers listed, not counted.",
              "Deeper than the limit of %d bytes: %s." % (footprint.STACK_LIMIT, "; ".join(
                  "%d on %s" % (len(v), t) for t, v in sorted(deep.items()))), "",
              "| function | " + " | ".join(sorted(report["footprint"])) + " | calls outside |",
              "|---|" + "---:|" * len(report["footprint"]) + "---|"]
    fns = sorted(set(f for fp in report["footprint"].values() for f in fp["stack"]))
    for fn in fns:
        cells, outside = [], set()
        for target in sorted(report["footprint"]):
            s = report["footprint"][target]["stack"].get(fn, {})
            cells.append("-" if s.get("bytes") is None else str(s["bytes"]))
            outside |= set(s.get("calls_outside", []))
        lines.append("| %s | %s | %s |" % (fn, " | ".join(cells), ", ".join(sorted(outside))))
    with open(os.path.join(docs, "performance.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(os.path.join(docs, "performance.json"), "w") as f:
        json.dump(report, f, indent=1, sort_keys=True)
        f.write("\n")
    chart(report, os.path.join(docs, "performance.png"))


def chart(report, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = [r for r in report["functions"] if r["instructions"] is not None]
    fig, axes = plt.subplots(1, len(TARGETS), figsize=(12, 0.5 * max(4, len(rows)) + 1.5))
    for ax, target in zip(axes, TARGETS):
        mine = [r for r in rows if r["target"] == target]
        labels = [r["name"] for r in mine]
        y = range(len(mine))
        ax.barh([i - 0.25 for i in y], [r["instructions"] for r in mine], height=0.25,
                label="libdrdc-fx", color="#1f77b4")
        for k, (base, colour) in enumerate((("libfixmath", "#ff7f0e"), ("double", "#7f7f7f"))):
            vals = [next((b["instructions"] for b in r["baselines"] if b["name"] == base), 0)
                    for r in mine]
            if any(vals):
                ax.barh([i + 0.25 * k for i in y], vals, height=0.25, label=base, color=colour)
        ax.set_yticks(list(y))
        ax.set_yticklabels(labels)
        ax.set_xscale("log")
        ax.set_xlim(left=1)
        ax.set_xlabel("instructions per call (QEMU -icount, log scale)")
        ax.set_title(target)
        ax.invert_yaxis()
        ax.legend(loc="lower right", fontsize="small")
    fig.tight_layout()
    fig.savefig(path, dpi=80, metadata={"Software": None})
    plt.close(fig)


def toolchain(build):
    """{target: its C compiler and release}, as configure recorded them
    (build/c4che/<target>_cache.py)."""
    found = {}
    for target in TARGETS:
        values = {}
        with open(os.path.join(build, "c4che", target + "_cache.py")) as f:
            for line in f:
                name, _, value = line.partition(" = ")
                if name in ("CC", "CC_RELEASE"):
                    values[name] = ast.literal_eval(value.strip())
        found[target] = "%s %s" % (os.path.basename(values["CC"][0]),
                                   values["CC_RELEASE"])
    return found


def measure(build):
    functions, calibration, checks = records(build)
    return {"functions": functions, "instructions_per_tick": calibration,
            "baseline_checks": checks, "toolchain": toolchain(build),
            "release": deps.release(),
            "footprint": {t: footprint.footprint(build, t) for t in TARGETS},
            "sizes": {t: sizes(build, t) for t in SIZE_TARGETS}}


def sizes(build, target):
    """Flash bytes (.text + .rodata + .data) of the whole library, of what
    the demo pose node links, and of what the NMEA parser costs a node
    that parses every sentence (drdc_nmea_parse) and one that parses GGA
    alone (drdc_nmea_parse_some with the GGA decoder)."""
    lib = footprint.footprint_library(build, target)
    return {"library": lib,
            "demo": linked_flash({"linked": footprint.linked(build, target)}),
            "nmea_every": linked_flash({"linked": footprint.linked(
                build, target, "fw/nmea-size/nmea-every")}),
            "nmea_gga": linked_flash({"linked": footprint.linked(
                build, target, "fw/nmea-size/nmea-gga")})}


def toolchain_text(report):
    return ", ".join("%s (%s)" % (cc, t)
                     for t, cc in sorted(report.get("toolchain", {}).items()))


def failed_checks(report):
    """The baseline checks beyond their limit: a baseline that does not
    compute what the library computes gives no ratio worth printing."""
    return ["%s on %s: worst %d %s, limit %d" % (c["name"], t, c["worst"], c["unit"],
                                                 c["limit"])
            for t, cs in sorted(report.get("baseline_checks", {}).items())
            for c in cs if not c["ok"]]


def check(report, committed_path):
    with open(committed_path) as f:
        old = json.load(f)
    # a report written before the key was named for what it counts
    before = {(r["function"], r["target"]): r.get("instructions", r.get("cycles"))
              for r in old["functions"]
              if r.get("instructions", r.get("cycles")) is not None}
    bad = []
    for r in report["functions"]:
        prev = before.get((r["function"], r["target"]))
        if prev and r["instructions"] > prev * GROWTH_LIMIT:
            bad.append("%s on %s: %.1f instructions, committed %.1f (+%.0f %%)" % (
                r["function"], r["target"], r["instructions"], prev, 100 * (r["instructions"] / prev - 1)))
    for target, fp in report["footprint"].items():
        prev = old["footprint"].get(target)
        if prev and flash(fp) > flash(prev) * GROWTH_LIMIT:
            bad.append("library flash on %s: %d bytes, committed %d" % (
                target, flash(fp), flash(prev)))
    deep = []
    for target, fp in sorted(report["footprint"].items()):
        for fn in too_deep(fp):
            bytes_ = fp["stack"][fn].get("bytes")
            deep.append("%s on %s: %s" % (fn, target, (
                "stack unbounded (%s)" % fp["stack"][fn].get("recursion"))
                if bytes_ is None else "worst-case stack %d bytes, over %d"
                % (bytes_, footprint.STACK_LIMIT)))
        if over_linked_budget(target, fp):
            deep.append("demo pose node on %s links %d bytes of the library, "
                        "over %d" % (target, linked_flash(fp),
                                     footprint.LINKED_BUDGET[target]))
    if report.get("toolchain") != old.get("toolchain"):
        # another compiler: its code, not the library, moves these
        ratios = sorted(r["instructions"] / before[(r["function"], r["target"])]
                        for r in report["functions"]
                        if before.get((r["function"], r["target"])))
        print("bench guard: built by %s; %s was measured with %s. Reported, "
              "not guarded: the guard holds on that toolchain."
              % (toolchain_text(report), committed_path,
                 toolchain_text(old) or "no recorded toolchain"))
        if ratios:
            print("bench guard: instructions per call against the committed "
                  "report: median %.3f, %.3f to %.3f over %d"
                  % (ratios[len(ratios) // 2], ratios[0], ratios[-1],
                     len(ratios)))
        for target, fp in sorted(report["footprint"].items()):
            stack = max((v.get("bytes") or 0, fn)
                        for fn, v in fp["stack"].items())
            print("bench guard: %s: library flash %d bytes, the demo links "
                  "%d (budget %d), deepest stack %d bytes (%s; limit %d)"
                  % (target, flash(fp), linked_flash(fp),
                     footprint.LINKED_BUDGET[target], stack[0], stack[1],
                     footprint.STACK_LIMIT))
        for line in bad + deep:
            print("bench guard: reported: " + line)
        return True
    for line in bad + deep:
        print("bench guard: " + line)
    if bad:
        print("bench guard: regenerate with ./waf bench and commit the "
              "report with the change that costs it")
    if deep:
        print("bench guard: a regenerated report does not lift a budget of "
              "tools/gates/footprint.py")
    if not (bad or deep):
        print("bench guard: %d function(s) and %d target(s) within 5 %% of %s, "
              "every stack within %d bytes, the demo within its budget"
              % (len(report["functions"]), len(report["footprint"]),
                 committed_path, footprint.STACK_LIMIT))
    return not (bad or deep)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", help="write the report JSON here")
    ap.add_argument("--docs", help="write performance.md/.json/.png here")
    ap.add_argument("--check", help="compare with this committed report")
    args = ap.parse_args()
    report = measure(args.build)
    failed = failed_checks(report)
    for line in failed:
        print("bench: baseline disagrees with the library: " + line)
    if failed:
        return 1
    if args.out:
        os.makedirs(os.path.dirname(args.out), exist_ok=True)
        with open(args.out, "w") as f:
            json.dump(report, f, indent=1, sort_keys=True)
            f.write("\n")
        print("bench: wrote " + args.out)
    if args.docs:
        write_docs(report, args.docs)
        print("bench: wrote %s/performance.md, .json, .png" % args.docs)
    if args.check:
        return 0 if check(report, args.check) else 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
