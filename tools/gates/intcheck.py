#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Integer-only check of compiled objects (the core and fixed/ libraries).

What is checked, per object file or static library:
  1. No floating-point instruction, by disassembly (objdump -d):
       ppc     classic FPU (f*, lf*, stf*, mffs, mtfs*) and e500 SPE
               floating point (efs*, efd*, evfs*)
       arm     VFP/NEON (every v* mnemonic)
       x86-64  x87 (f*) and SSE/AVX scalar or packed floating-point
               arithmetic, comparison and conversion
       riscv   the F, D and Q extensions (every f* mnemonic but fence:
               loads, stores, arithmetic, moves, conversions, c.f*)
       avr     none exist: only the calls of step 2
  2. No call to anything outside the library except the integer helpers of
     libgcc listed in INTEGER_HELPERS and the four memory functions GCC
     requires of every environment: so no soft-float routine (__adddf3,
     __aeabi_dmul, ...), no libm (sin, sqrt, ...), no other libc, no heap.

  intcheck.py ARCH FILE...            check files; exit 1 on any finding
  intcheck.py --build DIR --all T:ARCH[:TOOL_PREFIX]...
        for each target T: libdrdc.a must pass, and the bait libraries
        (tests/intcheck/float_bait.c) must be caught, proving the check bites.
        TOOL_PREFIX names the target's objdump and nm where they are not
        the instruction set's usual ones (PREFIX): Windows x86-64 objects
        (win64) are COFF, read by x86_64-w64-mingw32-objdump.
"""
import argparse
import os
import re
import subprocess
import sys

FP_INSTRUCTION = {
    "ppc": re.compile(r"^(f[a-z]+\.?|lf[sd]\w*|stf[sd]\w*|mffs\w*|mtfs\w*|"
                      r"efs\w+|efd\w+|evfs\w+)$"),
    "arm": re.compile(r"^v[a-z]"),
    # fence and fence.i order memory: integer instructions
    "riscv": re.compile(r"^(c\.)?f(?!ence)[a-z]"),
    # AVR has no floating-point instruction: floats become libgcc calls,
    # which outside_calls() reports
    "avr": re.compile(r"(?!)"),
    "x86-64": re.compile(r"^(f[a-z0-9]+|"
                         r"v?(add|sub|mul|div|sqrt|min|max|round|rcp|rsqrt|"
                         r"hadd|hsub|dp|andn?|x?or)(ss|sd|ps|pd)|"
                         r"v?u?comis[sd]|v?cmp\w*(ss|sd|ps|pd)|v?cvt\w+|"
                         r"vf(n?m(add|sub)\w+))$"),
}
# x86 zeroing idiom "xorps %xmmN,%xmmN" moves no floating-point value.
X86_ZERO_IDIOM = re.compile(r"^v?xorp[sd]\s+%xmm(\d+),%xmm\1$")

# libgcc routines for integer arithmetic the targets lack in hardware:
# 64-bit division, shifts and multiplication, count of leading zeros.
INTEGER_HELPERS = {
    "__divdi3", "__udivdi3", "__moddi3", "__umoddi3", "__udivmoddi4",
    "__divmoddi4", "__ashldi3", "__ashrdi3", "__lshrdi3", "__muldi3",
    "__clzsi2", "__clzdi2", "__ctzsi2", "__ctzdi2", "__cmpdi2", "__ucmpdi2",
    "__aeabi_ldivmod", "__aeabi_uldivmod", "__aeabi_idiv", "__aeabi_uidiv",
    "__aeabi_idivmod", "__aeabi_uidivmod", "__aeabi_llsl", "__aeabi_llsr",
    "__aeabi_lasr", "__aeabi_lmul", "__aeabi_lcmp", "__aeabi_ulcmp",
} | {
    # PowerPC -Os: prologues and epilogues that store and load the
    # callee-saved registers r14..r31 through one shared sequence of
    # stw/lwz (libgcc's crtsavres), in the caller's own frame
    "_%sgpr_%d%s" % (op, reg, tail) for op in ("save", "rest")
    for reg in range(14, 32) for tail in ("", "_x")
}
# AVR (8-bit registers): libgcc's 32- and 64-bit multiply (avr-gcc 14
# also calls __usmulhisi3, unsigned by signed 16 x 16 -> 32), divide, add,
# subtract, negate and compare, its switch-table jump, and the start-up's
# copy of .data into RAM, which every object with initialised or constant
# data references (constants live in RAM on AVR unless placed in flash).
INTEGER_HELPERS |= {
    "__mulsi3", "__divmodsi4", "__udivmodsi4", "__mulsidi3", "__umulsidi3",
    "__mulohisi3", "__muluhisi3", "__umulhisi3", "__mulhisi3", "__usmulhisi3",
    "__adddi3", "__adddi3_s8", "__subdi3", "__subdi3_s8", "__negdi2",
    "__cmpdi2_s8",
    "__tablejump2__", "__do_copy_data", "__do_clear_bss",
}
# Thumb-1 (Cortex-M0) switch tables: libgcc's case-table dispatchers.
INTEGER_HELPERS |= {"__gnu_thumb1_case_%s" % k
                    for k in ("uqi", "sqi", "uhi", "shi", "si")}
# GCC may call these four for structure copies and initialisers even in
# freestanding code, and requires every environment to provide them (GCC
# manual, "C Language": the freestanding environment); on Cortex-M0 it
# calls memcpy and memset where Thumb-2 cores copy inline.
FREESTANDING_REQUIRED = {"memcpy", "memmove", "memset", "memcmp"}
SOFT_FLOAT = re.compile(r"^__(aeabi_[dfi]\w*|\w*[sdtx]f\d?|float\w*|fix\w*|"
                        r"extend\w*|trunc\w*|unord\w*|pow\w+|mul[sdt]c3|div[sdt]c3)$")


def run(cmd):
    return subprocess.run(cmd, check=True, capture_output=True, text=True).stdout


def fp_instructions(objdump, arch, path):
    """Lines of the disassembly that hold a floating-point instruction."""
    found = []
    where = "?"
    for line in run([objdump, "-d", "--no-show-raw-insn", path]).splitlines():
        head = re.match(r"^[0-9a-f]+ <(.+)>:$", line)
        if head:
            where = head.group(1)
            continue
        m = re.match(r"^\s*[0-9a-f]+:\s+(\S+)(.*)$", line)
        if not m:
            continue
        mnemonic, rest = m.group(1), m.group(2).strip()
        if arch == "x86-64" and X86_ZERO_IDIOM.match(mnemonic + " " + rest):
            continue
        if FP_INSTRUCTION[arch].match(mnemonic):
            found.append("%s: FP instruction in %s: %s %s" % (path, where, mnemonic, rest))
    return found


def outside_calls(nm, path):
    """Undefined symbols not defined in the same file and not allowed."""
    defined, undefined = set(), set()
    # POSIX format: "FILE[MEMBER]: NAME TYPE [VALUE SIZE]"
    for line in run([nm, "-A", "-P", path]).splitlines():
        parts = line.split()
        if len(parts) < 3:
            continue
        (undefined if parts[2] in ("U", "w", "v") else defined).add(parts[1])
    found = []
    for sym in sorted(undefined - defined - INTEGER_HELPERS
                      - FREESTANDING_REQUIRED):
        kind = "soft-float routine" if SOFT_FLOAT.match(sym) else "outside call"
        found.append("%s: %s %s" % (path, kind, sym))
    return found


def check(arch, paths, prefix=""):
    findings = []
    for p in paths:
        findings += fp_instructions(prefix + "objdump", arch, p)
        findings += outside_calls(prefix + "nm", p)
    return findings


PREFIX = {"x86-64": "", "ppc": "powerpc-linux-gnu-", "arm": "arm-none-eabi-",
          "riscv": "riscv64-unknown-elf-", "avr": "avr-"}


def check_build(build, specs):
    ok = True
    for spec in specs:
        target, _, arch = spec.partition(":")
        arch, _, tools = arch.partition(":")
        tools = tools or PREFIX[arch]
        lib = os.path.join(build, target, "libdrdc.a")
        findings = check(arch, [lib], tools)
        print("%-10s libdrdc.a: %s" % (target, "integer-only" if not findings
                                         else "%d finding(s)" % len(findings)))
        for f in findings:
            print("  " + f)
        ok &= not findings
        # The bait must be caught, each for the reasons it was built for:
        # with the target's own flags its doubles become soft-float calls
        # (or FP instructions where the target has an FPU, the host) and
        # sin() a libm call; with hard-float flags, FP instructions.
        for bait, wants in (("libbait-soft.a", (("soft-float routine", "FP instruction"),
                                                ("outside call",))),
                            ("libbait-hard.a", (("FP instruction",),))):
            path = os.path.join(build, target, bait)
            if not os.path.exists(path):
                continue
            caught = check(arch, [path], tools)
            missing = [" or ".join(w) for w in wants
                       if not any(k in c for k in w for c in caught)]
            print("%-10s %s: %s" % (target, bait, "caught (%d findings)" % len(caught)
                                    if not missing else "NOT caught: " + ", ".join(missing)))
            ok &= not missing
    return ok


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", help="build directory (with --all)")
    ap.add_argument("--all", nargs="+", metavar="TARGET:ARCH")
    ap.add_argument("arch", nargs="?", choices=sorted(FP_INSTRUCTION))
    ap.add_argument("files", nargs="*")
    args = ap.parse_args()
    if args.all:
        return 0 if check_build(args.build or "build", args.all) else 1
    findings = check(args.arch, args.files, PREFIX[args.arch])
    for f in findings:
        print(f)
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
