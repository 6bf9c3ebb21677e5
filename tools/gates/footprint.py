#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Footprint of libdrdc.a per target: section sizes of the library and of
each module (folder of core/ or fixed/), and the worst-case stack of every
public function from GCC's call graphs (-fcallgraph-info=su, one .ci file
per object, written by the library build).

  footprint.py [--build build] TARGET...   print JSON {target: footprint}

Worst-case stack of a function = its own frame + the deepest chain of
callees inside the library; a callee reached only by sibling (tail) calls,
which the compiler makes after the caller's epilogue, adds its chain to
the caller's entry stack instead of to its frame; a call through a pointer
counts as a call of every function whose address the library's data
holds. Calls out of the library (libgcc's integer helpers) are listed with
the function; their frames are not counted, and a recursive chain is
reported as such instead of a number.
"""
import argparse
import collections
import glob
import json
import os
import re
import subprocess
import sys

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, TOP)
# The footprint policy (how each file compiles, the stack limit, each
# bench target's budget for the demo pose node) is part of the table of
# targets; this module measures, tools/gates/bench.py guards.
from waftools.targets import STACK_LIMIT, TARGETS, with_role  # noqa: E402,F401

# What the demo pose node (fw/demo: NMEA, time scales, the paper's poses,
# MGRS, JAUS Report Global Pose) may link of libdrdc.a, flash bytes
# (.text + .rodata + .data) per bench target. The whole library's size is
# reported in docs/performance.md, not budgeted.
LINKED_BUDGET = {n: TARGETS[n]["linked_budget"] for n in with_role("bench")}
PREFIX = {n: t["cross"] for n, t in TARGETS.items()}
NODE = re.compile(r'node: \{ title: "([^"]+)" label: "([^"]*)"')
EDGE = re.compile(r'edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"')
STACK = re.compile(r"\\n(\d+) bytes \((static|dynamic|dynamic,bounded)\)")
SECTIONS = ("text", "rodata", "data", "bss")


def members(build, target):
    """Library objects by path under the build, with their module folder.
    Members are matched by name and count: two modules may have a file of
    the same name (fixed/convert.c, core/units/convert.c), and both are in
    the archive."""
    lib = os.path.join(build, target, "libdrdc.a")
    names = collections.Counter(subprocess.run(
        [PREFIX[target] + "ar", "t", lib], check=True, capture_output=True,
        text=True).stdout.split())
    found = {}
    for top in ("core", "fixed"):
        for path in glob.glob(os.path.join(build, target, top, "**", "*.o"),
                              recursive=True):
            if os.path.basename(path) in names:
                rel = os.path.relpath(path, os.path.join(build, target))
                found[rel] = (path, os.path.dirname(rel))
    seen = collections.Counter(os.path.basename(p) for p in found)
    if seen != names:
        sys.exit("footprint: objects of %s not matched: archive %s, found %s"
                 % (lib, sorted((names - seen).elements()),
                    sorted((seen - names).elements())))
    return found


def section_sizes(target, path):
    """Sizes of .text/.rodata/.data/.bss (with their subsections) of one object."""
    sizes = dict.fromkeys(SECTIONS, 0)
    out = subprocess.run([PREFIX[target] + "size", "-A", path], check=True,
                         capture_output=True, text=True).stdout
    for line in out.splitlines():
        parts = line.split()
        if len(parts) < 2 or not parts[1].isdigit():
            continue
        sec = section_kind(parts[0])
        if sec:
            sizes[sec] += int(parts[1])
    return sizes


def section_kind(name):
    """Which of SECTIONS an input section of that name belongs to, or None."""
    for sec in SECTIONS:
        if name == "." + sec or name.startswith("." + sec + ".") or \
                (sec == "rodata" and name.startswith(".sdata2")) or \
                (sec == "data" and name.startswith(".sdata")) or \
                (sec == "bss" and name.startswith(".sbss")):
            return sec
    return None


# an input section in a GNU ld map: name (alone on the line before when
# long), address, size, and the object it comes from
MAP_SECTION = re.compile(r"^ (\.\S+)?\s+0x[0-9a-f]+\s+0x([0-9a-f]+) (\S+)$")


def linked(build, target, image="fw/demo/demo"):
    """Sections of libdrdc.a that the image really links (after
    --gc-sections), from its link map: what the library costs an
    application, against the whole archive of footprint()."""
    sizes = dict.fromkeys(SECTIONS, 0)
    with open(os.path.join(build, target, image + ".map")) as f:
        text = f.read()
    # the list before this line is of discarded sections
    text = text[text.index("Linker script and memory map"):]
    name = None
    for line in text.splitlines():
        m = MAP_SECTION.match(line)
        if not m:
            name = line.strip() if line.startswith(" .") else None
            continue
        sec = section_kind(m.group(1) or name or "")
        if sec and "libdrdc.a(" in m.group(3):
            sizes[sec] += int(m.group(2), 16)
        name = None
    return {"image": image, "sections": sizes}


def call_graph(paths):
    frames, edges = {}, {}
    for ci in paths:
        with open(ci) as f:
            text = f.read()
        for name, label in NODE.findall(text):
            m = STACK.search(label)
            if m:
                frames[name] = int(m.group(1))
        for src, dst in EDGE.findall(text):
            edges.setdefault(src, set()).add(dst)
    return frames, edges


# objdump -dr: a function's label, an instruction, a relocation under it
LABEL = re.compile(r"^[0-9a-f]+ <([^>]+)>:$")
INSN = re.compile(r"^\s+[0-9a-f]+:\t[0-9a-f ]+\t(\S+)")
RELOC = re.compile(r"^\s+[0-9a-f]+: R_\w+\t([^+\s]+)(\+0x[0-9a-f]+)?$")
# the unconditional jumps a sibling (tail) call is made with
TAIL_JUMPS = {"b", "b.w", "b.n", "jmp"}


def tail_calls(target, path, ci_path):
    """(caller, callee) pairs of one object whose every call is a sibling
    call: an unconditional jump made after the caller's epilogue, so the
    callee runs on the caller's entry stack pointer, not below its frame.
    Names as in the object's call graph ("file.c:name" for static ones)."""
    with open(ci_path) as f:
        titles = set(t for t, _ in NODE.findall(f.read()))
    out = subprocess.run([PREFIX[target] + "objdump", "-dr", path], check=True,
                         capture_output=True, text=True).stdout

    def title(name):
        local = [t for t in titles if t.endswith(":" + name)]
        return local[0] if len(local) == 1 else name

    kinds = {}
    fn = insn = None
    for line in out.splitlines():
        m = LABEL.match(line)
        if m:
            fn, insn = m.group(1), None
            continue
        m = INSN.match(line)
        if m:
            insn = m.group(1)
            continue
        m = RELOC.match(line)
        if m and fn and insn:
            callee = m.group(1)
            if callee.startswith(".text."):      # PowerPC: a static's section
                if m.group(2):
                    continue                    # not at the section's start
                callee = callee[len(".text."):]
            pair = (title(fn), title(callee))
            kinds.setdefault(pair, set()).add(insn in TAIL_JUMPS)
    return {pair for pair, k in kinds.items() if k == {True}}


# GCC's call graph names every call through a pointer so
INDIRECT = "__indirect_call"
# objdump -r: a section's relocations, and one record of them
RELOC_SECTION = re.compile(r"^RELOCATION RECORDS FOR \[([^\]]+)\]:$")
RELOC_RECORD = re.compile(r"^[0-9a-f]+ \S+\s+([^+\s]+)")
# sections of code and of its metadata: their relocations are calls and
# unwinding or debugging records, not addresses kept as data
NOT_DATA = (".text", ".debug", ".eh_frame", ".ARM.ex")


def address_taken(target, paths, functions):
    """The functions whose address the library's data holds (relocations
    outside code sections, such as the decoders of drdc_nmea_parse_some()):
    what a call through a pointer may reach."""
    found = set()
    for path in paths:
        out = subprocess.run([PREFIX[target] + "objdump", "-r", path],
                             check=True, capture_output=True, text=True).stdout
        section = None
        for line in out.splitlines():
            m = RELOC_SECTION.match(line)
            if m:
                section = m.group(1)
                continue
            m = RELOC_RECORD.match(line)
            if m and section and not section.startswith(NOT_DATA) \
                    and m.group(1) in functions:
                found.add(m.group(1))
    return found


def resolve_indirect(edges, taken):
    """A call through a pointer counted as a call of every function whose
    address the library's data holds (the deepest of them decides); left
    as an outside call where the data holds none."""
    if not taken:
        return edges
    return {src: ((dsts - {INDIRECT}) | taken) if INDIRECT in dsts else dsts
            for src, dsts in edges.items()}


def worst_stack(fn, frames, edges, tails=frozenset(), chain=()):
    """(bytes, outside callees) of the deepest chain from fn. A sibling
    call (in tails) runs after fn's frame is gone: its depth is not added
    to fn's own frame."""
    if fn in chain:
        raise RecursionError(" -> ".join(chain + (fn,)))
    own = frames[fn]
    deepest, outside = own, set()
    for callee in sorted(edges.get(fn, ())):
        if callee in frames:
            depth, out = worst_stack(callee, frames, edges, tails, chain + (fn,))
            deepest = max(deepest, depth + (0 if (fn, callee) in tails else own))
            outside |= out
        else:
            outside.add(callee)
    return deepest, outside


def symbols(target, objs, top=20):
    """The `top` largest symbols (code and constant data) of the library
    objects `objs` (from members()): name, object path, nm type letter and
    size in bytes."""
    rows = []
    for rel, (path, _) in sorted(objs.items()):
        out = subprocess.run([PREFIX[target] + "nm", "-S", "-t", "d", path],
                             check=True, capture_output=True, text=True).stdout
        for line in out.splitlines():
            parts = line.split()
            if len(parts) == 4 and parts[2] in "TtRrDdBb":
                rows.append({"symbol": parts[3], "object": rel,
                             "type": parts[2], "bytes": int(parts[1])})
    rows.sort(key=lambda r: (-r["bytes"], r["symbol"], r["object"]))
    return rows[:top]


def footprint_library(build, target):
    """Flash bytes (.text + .rodata + .data) of the whole libdrdc.a."""
    total = 0
    for path, _ in members(build, target).values():
        s = section_sizes(target, path)
        total += s["text"] + s["rodata"] + s["data"]
    return total


def footprint(build, target):
    objs = members(build, target)
    library = dict.fromkeys(SECTIONS, 0)
    modules = {}
    for name, (path, module) in sorted(objs.items()):
        sizes = section_sizes(target, path)
        mod = modules.setdefault(module, dict.fromkeys(SECTIONS, 0))
        for sec in SECTIONS:
            mod[sec] += sizes[sec]
            library[sec] += sizes[sec]
    cis = {p: os.path.splitext(p)[0] + ".ci" for p, _ in objs.values()}
    cis = {p: c for p, c in cis.items() if os.path.exists(c)}
    frames, edges = call_graph(cis.values())
    edges = resolve_indirect(edges, address_taken(
        target, [p for p, _ in objs.values()], set(frames)))
    tails = set()
    for path, ci in sorted(cis.items()):
        tails |= tail_calls(target, path, ci)
    # drdc__ marks the library's internal external symbols
    public = sorted(f for f in frames
                    if f.startswith("drdc_") and not f.startswith("drdc__"))
    stack = {}
    for fn in public:
        try:
            depth, outside = worst_stack(fn, frames, edges, tails)
            stack[fn] = {"bytes": depth, "calls_outside": sorted(outside)}
        except RecursionError as e:
            stack[fn] = {"bytes": None, "recursion": str(e)}
    return {"library": library, "modules": modules, "stack": stack,
            "symbols": symbols(target, objs), "linked": linked(build, target)}


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("targets", nargs="+")
    args = ap.parse_args()
    json.dump({t: footprint(args.build, t) for t in args.targets}, sys.stdout,
              indent=1, sort_keys=True)
    print()


if __name__ == "__main__":
    main()
