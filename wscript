# SPDX-License-Identifier: BSD-2-Clause
"""Build of libdrdc-fx: one waf variant per target, all in the TARGETS table.

  ./waf demo    set up, build the default target, run the demo under QEMU
  ./waf check   build every target and run every check and test suite
  ./waf build_<target>, clean_<target>, install_<target>   one target only
  ./waf install  every configured RTEMS BSP into its prefix (tools/waf_rtems.py),
                 or, without RTEMS, every configured target into --prefix
                 (lib/<target>/, lib/pkgconfig/drdc-<target>.pc)
"""
import glob
import logging
import os
import re
import subprocess
import sys
import time

from waflib import Build, Configure, Context, Errors, Logs, Options

top = "."
out = "build"

APPNAME = "drdc"
VERSION = "0.1.0"  # also in core/include/drdc/version.h
DEFAULT_TARGET = "ppc-e500"

# Re-run configure by itself when it has not run or a wscript changed,
# with the options it was last given ("clobber"; True would drop them,
# --rtems among them).
Configure.autoconfig = "clobber"

# Warnings of every file we write, on every target.
WARNINGS = ["-std=c99", "-Wall", "-Wextra", "-Wconversion",
            "-Wsign-conversion", "-Wshadow", "-Wcast-align",
            "-Wstrict-prototypes", "-Wundef"]
# Warnings are errors where the compiler is one the project tries (every
# target of TARGETS, with the compilers of Debian 12 and 13: gcc 12 and 14,
# clang 14 and 19, avr-gcc 5 and 14) and where configure is asked to
# (--werror: ./waf check's real RTEMS 6 build, gcc 13.3). Another compiler
# (a user's RTEMS tool suite) may warn where these do not: its build warns
# but completes.
# Code generation of every file, ours and third-party.
CODEGEN = ["-O2", "-g", "-ffunction-sections", "-fdata-sections"]
# Every library file, on top of CODEGEN: no padding to align function
# entries, for flash. Instruction counts are the same; on a real
# Cortex-M3 a 32-bit first instruction on a half-word boundary may cost
# one fetch per call.
LIBRARY_CODEGEN = ["-fno-align-functions"]
# Which library files are compiled for speed or size: the footprint
# policy of tools/footprint.py (MODULE_OPTIMISE, FILE_OPTIMISE).
SANITIZE = ["-fsanitize=address,undefined", "-fno-sanitize-recover=all",
            "-fno-omit-frame-pointer"]

# The one table of targets. Adding a board: a folder bsp/<name>/ with its
# start-up code, console and exit, plus one entry here.
#   cross      tool prefix ("" for the native compiler)
#   compiler   the C compiler without prefix (default gcc)
#   images     firmware images and test runner (default True); False
#              builds the library only (and the libFuzzer targets where
#              fuzz is True)
#   bsp        folder under bsp/ with the board code
#   qemu       machine profile of qemu/harness.py that runs the images
#   arch       flags for compiling and assembling
#   link       flags for linking images; bsp/<bsp>/link.ld, when there is
#              one, is added as the linker script
#   libs       libraries linked after everything else
#   library_libs  what an application of the library links (drdc-<target>.pc
#              Libs; default libs)
#   hard_float flags that make a floating-point unit available: the
#              integer-only check must catch the instructions they emit
#   intcheck   instruction set of tools/intcheck.py, or None to skip
#   soft_float_libm  the toolchain has soft-float double and a libm: the
#              benchmark image times double-precision baselines
#   apt        groups of Debian packages the target builds with
#              (tools/deps.py APT_GROUPS)
#   apt_run    groups of Debian packages that run its images (QEMU, Wine,
#              simavr), set up by ./waf demo, check and bench
#   check_only set up and built by ./waf check (and configure
#              --with-targets naming it), not by a plain ./waf configure
#   library_arch  flags for the library's objects only (default none)
#   abi        flags an application must compile with to link the library
#              (in the installed drdc-<target>.pc); None: a test build
#              that ./waf install leaves out
#   headers    bare metal: the only system include directories, in order,
#              after -nostdinc ("gcc:DIR" is the compiler's own DIR, as
#              -print-file-name gives it), so no host header can leak in
#   hosted_bait  headers of the host's C library (glibc) that the target
#              must not see: configure proves that each is missing
#   tool       also build the drdc tool (tools/drdc/) for this target
#   bench      build the benchmark image (default: every target QEMU
#              runs, whose counters repeat exactly)
# What the bare-metal targets of one family share; each row of TARGETS
# adds its core's flags.
PPC_BARE_METAL = {
    "cross": "powerpc-linux-gnu-", "bsp": "ppc-e500", "qemu": "ppc-e500",
    "ext": ".elf",
    "arch": ["-msoft-float", "-ffreestanding", "-fno-pic", "-fno-pie",
             "-msdata=none", "-G0", "-fno-stack-protector"],
    "link": ["-nostdlib", "-static", "-no-pie", "-Wl,--gc-sections",
             "-Wl,--build-id=none", "-Wl,--no-warn-rwx-segments"],
    # libgcc: 64-bit integer division (__udivdi3, __divdi3)
    "libs": ["gcc"],
    "hard_float": ["-mhard-float"], "intcheck": "ppc",
    # Debian's PowerPC libgcc is hard-float: no soft-float routines
    "soft_float_libm": False, "apt": ["ppc"], "apt_run": ["qemu-ppc"],
    # freestanding: the compiler's <stdint.h>, <stddef.h>, <stdbool.h>;
    # the board's own <limits.h> (the compiler's wants a C library's
    # below it) and <string.h> (the four functions of its mem.c)
    "headers": ["bsp/ppc-e500/include", "gcc:include"],
    "hosted_bait": ["math.h", "stdio.h", "features.h"],
}
# Cortex-M on QEMU's MPS2 boards, newlib nano, semihosting console and exit
ARM_NEWLIB = {
    "cross": "arm-none-eabi-", "bsp": "arm-cm3", "qemu": "arm-cm3",
    "ext": ".elf",
    "link": ["--specs=rdimon.specs", "-nostartfiles", "-Wl,--gc-sections"],
    "libs": [], "intcheck": "arm", "apt": ["arm"], "apt_run": ["qemu-arm"],
    # the compiler's own, then newlib's (nano.specs puts newlib nano's
    # first with -isystem, which -nostdinc keeps)
    "headers": ["gcc:include", "gcc:include-fixed",
                "/usr/lib/arm-none-eabi/include"],
    "hosted_bait": ["features.h", "argp.h"],
}

# picolibc's libraries for rv32imac, ilp32 (Debian picolibc-riscv64-unknown-elf)
PICOLIBC_RV32 = "/usr/lib/picolibc/riscv64-unknown-elf/lib/rv32imac/ilp32"

TARGETS = {
    "host": {
        "cross": "", "bsp": "host", "qemu": "host", "ext": "",
        "arch": ["-D_POSIX_C_SOURCE=200809L"],
        "link": [], "libs": [], "hard_float": [], "intcheck": "x86-64",
        "soft_float_libm": False, "apt": ["host"], "apt_run": [], "abi": [],
        "tool": True,
    },
    "host-asan": {
        "cross": "", "bsp": "host", "qemu": "host", "ext": "",
        "arch": ["-D_POSIX_C_SOURCE=200809L"] + SANITIZE,
        "link": SANITIZE, "libs": [], "hard_float": None, "intcheck": None,
        "soft_float_libm": False, "apt": ["host"], "apt_run": [],
        "abi": None,
    },
    # libFuzzer with ASan and UBSan, by the release's clang (14 on Debian
    # 12, 19 on 13)
    "host-fuzz": {
        "cross": "", "compiler": "clang", "bsp": "host", "qemu": None,
        "ext": "", "images": False, "fuzz": True, "check_only": True,
        "arch": ["-D_POSIX_C_SOURCE=200809L",
                 "-fsanitize=fuzzer-no-link,address,undefined",
                 "-fno-sanitize-recover=all", "-fno-omit-frame-pointer"],
        "link": ["-fsanitize=fuzzer,address,undefined"], "libs": [],
        "hard_float": None, "intcheck": None, "soft_float_libm": False,
        "apt": ["host", "clang"], "apt_run": [], "abi": None,
    },
    "ppc-e500": dict(
        PPC_BARE_METAL,
        arch=["-mcpu=powerpc"] + PPC_BARE_METAL["arch"],
        abi=["-mcpu=powerpc", "-msoft-float", "-msdata=none", "-G0"]),
    # The same board with code for the e500 core itself (-mcpu=8540, as
    # RTEMS's qoriq_e500 BSP compiles), soft-float: e500 scheduling and
    # instructions (isel) that generic PowerPC lacks.
    "ppc-8540": dict(
        PPC_BARE_METAL,
        arch=["-mcpu=8540"] + PPC_BARE_METAL["arch"],
        abi=["-mcpu=8540", "-msoft-float", "-msdata=none", "-G0"]),
    "arm-cm3": dict(
        ARM_NEWLIB,
        arch=["-mcpu=cortex-m3", "-mthumb", "-mfloat-abi=soft",
              "--specs=nano.specs"],
        hard_float=["-mcpu=cortex-m4", "-mfpu=fpv4-sp-d16",
                    "-mfloat-abi=hard"],
        soft_float_libm=True,
        abi=["-mcpu=cortex-m3", "-mthumb", "-mfloat-abi=soft"]),
    # Cortex-M4F (armv7e-m, hard-float ABI): the library stays integer-
    # only (tools/intcheck.py), but links into applications that pass
    # floats in FPU registers. QEMU's mps2-an386 is the AN385 board with a
    # Cortex-M4, the same memory map and board code.
    "arm-cm4f": dict(
        ARM_NEWLIB, qemu="arm-cm4f",
        arch=["-mcpu=cortex-m4", "-mthumb", "-mfloat-abi=hard",
              "-mfpu=fpv4-sp-d16", "--specs=nano.specs"],
        # GCC would otherwise keep 64-bit integers in FPU registers across
        # calls (vstr d8): FP instructions in an integer-only library. The
        # ABI (floats in s0-s15) is unchanged.
        library_arch=["-mgeneral-regs-only"],
        hard_float=[], soft_float_libm=False,
        abi=["-mcpu=cortex-m4", "-mthumb", "-mfloat-abi=hard",
             "-mfpu=fpv4-sp-d16"]),
    # Cortex-M0/M0+ (armv6-m, Thumb-1 only, no divide instruction): the
    # most common FPU-less MCUs. Its code runs unchanged on the Cortex-M3
    # of QEMU's mps2-an385, whose memory holds the suites' vectors (the
    # Cortex-M0 machines of QEMU 7.2 have 16 KiB of RAM), with the same
    # board code.
    "arm-cm0": dict(
        ARM_NEWLIB,
        # inline assembly in unified syntax, as on Thumb-2 (GCC's default
        # for Thumb-1 is the old divided syntax)
        arch=["-mcpu=cortex-m0", "-mthumb", "-mfloat-abi=soft",
              "-masm-syntax-unified", "--specs=nano.specs"],
        hard_float=["-mcpu=cortex-m4", "-mfpu=fpv4-sp-d16",
                    "-mfloat-abi=hard"],
        soft_float_libm=True,
        abi=["-mcpu=cortex-m0", "-mthumb", "-mfloat-abi=soft"]),
    # RISC-V rv32imac (the FPU-less RV32 MCUs: integer multiply and
    # divide, atomics, compressed), machine mode on QEMU's virt board:
    # 16550 console, SiFive test finisher for the exit status. picolibc
    # (Debian's, the rv32imac/ilp32 multilib) for the string functions of
    # the tests and the four GCC asks of every environment.
    "riscv32": {
        "cross": "riscv64-unknown-elf-", "bsp": "riscv32", "qemu": "riscv32",
        "ext": ".elf",
        "arch": ["-march=rv32imac", "-mabi=ilp32", "-mcmodel=medany",
                 "-ffreestanding", "-fno-pic", "-fno-pie",
                 "-fno-stack-protector"],
        "link": ["-nostdlib", "-nostartfiles", "-static", "-Wl,--gc-sections",
                 "-Wl,--build-id=none", "-Wl,--no-warn-rwx-segments",
                 "-L" + PICOLIBC_RV32],
        # the images: picolibc's string functions and libgcc's 64-bit
        # division; an application of the library: libgcc only
        "libs": ["c", "gcc"], "library_libs": ["gcc"],
        "hard_float": ["-march=rv32imafdc", "-mabi=ilp32d"],
        "intcheck": "riscv", "soft_float_libm": False, "apt": ["riscv"],
        "apt_run": ["qemu-riscv"],
        "headers": ["gcc:include", "gcc:include-fixed",
                    "/usr/lib/picolibc/riscv64-unknown-elf/include"],
        "hosted_bait": ["features.h", "argp.h"],
        "abi": ["-march=rv32imac", "-mabi=ilp32"],
    },
    # AVR ATmega2560 (8-bit core, 16-bit int), avr-gcc (5.4 on Debian 12,
    # 14.2 on 13) and avr-libc: where integer code hides its width
    # assumptions (1 << 20, builtins that take an unsigned int). The
    # library only, warning-free with -Werror; each part of the
    # conformance digest runs alone under simavr (fw/golden-part,
    # tools/test_avr.py).
    "avr": {
        "cross": "avr-", "bsp": "avr", "qemu": None, "ext": ".elf",
        "images": False, "golden_parts": True,
        # avr-gcc 5 predates `#pragma GCC unroll` (GCC 8): it leaves
        # those loops rolled, same results
        "arch": ["-mmcu=atmega2560", "-Wno-unknown-pragmas"],
        "link": ["-Wl,--gc-sections"], "libs": [], "hard_float": None, "intcheck": "avr",
        "soft_float_libm": False, "apt": ["avr"], "apt_run": ["simavr"],
        "headers": ["gcc:include", "gcc:include-fixed", "/usr/lib/avr/include"],
        "hosted_bait": ["features.h", "argp.h"],
        "abi": None,
    },
}

# --- Windows (win64) ---------------------------------------------------
# Windows x86-64 (LLP64: 32-bit long), Debian's mingw-w64 GCC in its
# win32 thread flavour (no thread library DLL to ship) and Windows's own
# msvcrt. The library, the drdc tool (drdc.exe) and the Unity runner,
# which Wine runs (qemu/wine.py, harness profile "wine64"). C99 printf
# and scanf (%lld, %zu) from mingw's own stdio, not msvcrt's.
TARGETS["win64"] = {
    "cross": "x86_64-w64-mingw32-", "compiler": "gcc-win32", "bsp": "win64",
    "qemu": "wine64", "ext": ".exe", "tool": True, "bench": False,
    "arch": ["-D__USE_MINGW_ANSI_STDIO=1"],
    # one self-contained .exe: libgcc linked in, no libgcc_s DLL
    "link": ["-static"], "libs": [], "hard_float": [], "intcheck": "x86-64",
    "soft_float_libm": False, "apt": ["mingw"], "apt_run": ["wine"],
    "abi": [],
}
# --- end of Windows (win64) --------------------------------------------

# RTEMS BSPs that QEMU runs. Their test-runner is linked a second time,
# as test-runner-qemu.exe, with the BSP's linker command file changed
# where QEMU's machine differs from the board; test-runner.exe stays the
# board's (rtems-test).
#   profile    QEMU profile of qemu/harness.py
#   linkcmds   the BSP's linker command file, in its libdir
#   replace    its line to change, and the line QEMU needs
RTEMS_QEMU = {
    "powerpc/qoriq_e500": {
        "profile": "rtems-qoriq_e500",
        "linkcmds": "linkcmds.qoriq_e500",
        # the BSP's CCSR base is a P1020's; QEMU's mpc8544ds has it at
        # 0xe0000000
        "replace": ("qoriq = 0xffe00000;", "qoriq = 0xe0000000;"),
    },
}

# Images that test the QEMU harness itself: qemu/selftest.c built once per
# kind (the number is SELFTEST_KIND) on each target.
SELFTEST_KINDS = {"pass": 1, "fail": 2, "hang": 3, "crash": 4,
                  "flood": 5, "fake-summary": 6, "silent": 7}


def _tools_module(name):
    tools = os.path.join(os.path.dirname(Context.g_module.root_path), "tools")
    if tools not in sys.path:
        sys.path.insert(0, tools)
    return __import__(name)


def options(opt):
    opt.load("compiler_c")
    _tools_module("waf_rtems").options(opt)
    opt.add_option("--with-targets", dest="with_targets", default=None,
                   help="configure: the targets to set up and build, comma "
                   "separated (default: %s; ./waf check adds every other, "
                   "./waf demo %s)" % (", ".join(_default_targets()),
                                       DEFAULT_TARGET))
    opt.add_option("--werror", action="store_true", default=False,
                   dest="werror", help="configure: warnings are errors in "
                   "RTEMS BSP builds too (always in the targets' builds)")
    opt.add_option("--seconds", type=int, default=60, dest="fuzz_seconds",
                   help="./waf fuzz: seconds per fuzzer (default 60)")


def _register_variant_commands(names):
    """build_<v>, clean_<v>, install_<v> for each variant name."""
    for name in names:
        for base in (Build.BuildContext, Build.CleanContext,
                     Build.InstallContext):
            cmd = base.__name__.replace("Context", "").lower() + "_" + name
            type(base.__name__ + "_" + name, (base,),
                 {"cmd": cmd, "variant": name})


def init(ctx):
    # RTEMS BSP variants exist only once configured: register their
    # commands from the configuration cache (as rtems_waf does).
    from waflib import ConfigSet
    try:
        lock = ConfigSet.ConfigSet(Options.lockfile)
        cache = ConfigSet.ConfigSet(os.path.join(lock.out_dir, "c4che",
                                                 "_cache.py"))
    except (EnvironmentError, AttributeError):
        return
    _register_variant_commands(cache.RTEMS_VARIANTS or [])


def _default_targets():
    """What a plain ./waf configure sets up: all but the check-only."""
    return [n for n, t in TARGETS.items() if not t.get("check_only")]


def _selected_targets(conf):
    if conf.options.with_targets is None:
        return _default_targets()
    names = [n for n in conf.options.with_targets.split(",") if n]
    unknown = [n for n in names if n not in TARGETS]
    if unknown or not names:
        conf.fatal("--with-targets: unknown %s; choose from %s"
                   % (", ".join(unknown) or "(none)", ", ".join(TARGETS)))
    return [n for n in TARGETS if n in names]


def _system_includes(conf, name, t):
    """-nostdinc and the include directories of t["headers"], each checked
    to exist."""
    flags = ["-nostdinc"]
    for d in t["headers"]:
        if d.startswith("gcc:"):
            d = conf.cmd_and_log(conf.env.CC + t["arch"]
                                 + ["-print-file-name=" + d[4:]],
                                 quiet=Context.BOTH).strip()
        elif not os.path.isabs(d):
            d = conf.path.make_node(d).abspath()
        if not os.path.isabs(d) or not os.path.isdir(d):
            conf.fatal("%s: no include directory %s (TARGETS headers)"
                       % (name, d))
        flags += ["-isystem", d]
    return flags


def _check_hermetic(conf, name, t):
    """Each hosted-only header must be missing for a bare-metal target: the
    compiler must stop on the bait's own #include line, proof that no host
    header can leak into its build. (Without -nostdinc, Debian's PowerPC
    GCC finds the host's <math.h> and only fails inside it.)"""
    bait = conf.bldnode.make_node("hosted_bait.c")
    for header in t["hosted_bait"]:
        conf.start_msg("Checking that %s has no <%s>" % (name, header))
        bait.write("#include <%s>\nint bait;\n" % header)
        r = subprocess.run(conf.env.CC + conf.env.ARCH
                           + ["-c", bait.abspath(), "-o", os.devnull],
                           capture_output=True, text=True)
        # line 1, the #include (GCC 12 names its column 10, GCC 5 the end)
        missing = re.compile(r"hosted_bait\.c:1:\d+: fatal error: %s: No such file"
                             % re.escape(header))
        if r.returncode == 0 or not missing.search(r.stderr):
            conf.end_msg("it has", "RED")
            conf.fatal("%s: <%s> is not simply missing, so host headers "
                       "can leak into the bare-metal build (TARGETS headers "
                       "in wscript); the compiler said:\n%s"
                       % (name, header, r.stderr))
        conf.end_msg("none, as it must be")


# The upstream sources the images build with: Unity and libfixmath.
SOURCES = ("unity", "libfixmath")


def _setup(ctx, groups, python=False):
    """Install what a command needs (tools/deps.py): the Debian packages of
    groups, the upstream sources and, if python, the Python packages. Not
    root: stop with the one command that installs all of it."""
    deps = _tools_module("deps")
    try:
        return deps.ensure(sorted(set(groups)), SOURCES, python)
    except deps.SetupError as e:
        ctx.fatal(str(e))


def _apt_groups(targets, run=False):
    """The Debian package groups that build (and, if run, run) targets."""
    return [g for n in targets
            for g in TARGETS[n]["apt"] + (TARGETS[n]["apt_run"] if run else [])]


def configure(conf):
    prefix = os.path.abspath(conf.options.prefix)
    targets = _selected_targets(conf)
    # pkg-config reads an RTEMS BSP's flags
    found = _setup(conf, _apt_groups(targets)
                   + (["rtems"] if conf.options.rtems else []))
    versions = _tools_module("toolchains")
    for name in targets:
        t = TARGETS[name]
        conf.setenv(name)
        conf.msg("Target", name)
        compiler = t.get("compiler", "gcc")
        for var, tool in (("CC", compiler), ("AR", "ar"), ("OBJDUMP", "objdump"),
                          ("NM", "nm"), ("SIZE", "size")):
            conf.find_program(t["cross"] + tool, var=var)
        conf.env.AS = conf.env.CC
        conf.load(("clang" if compiler.startswith("clang") else "gcc") + " gas")
        # what this target's results were computed with, in the build log
        # and in ./waf check's summary
        conf.env.CC_RELEASE = versions.compiler(conf.env.CC)
        conf.msg("Compiler of %s" % name, "%s %s" % (
            os.path.basename(conf.env.CC[0]), conf.env.CC_RELEASE))
        # the table's "ext" names the programs (waf would add .exe for
        # Windows by itself)
        conf.env.cprogram_PATTERN = "%s"
        if t["cross"]:
            # static images only: no -Bstatic/-Bdynamic switching
            conf.env.STLIB_MARKER = []
            conf.env.SHLIB_MARKER = []
        arch = list(t["arch"])
        if "headers" in t:
            arch += _system_includes(conf, name, t)
        conf.env.ARCH = arch
        conf.env.LIBRARY_ARCH = t.get("library_arch", [])
        conf.env.ASFLAGS = arch + CODEGEN
        conf.env.LINKFLAGS = arch + t["link"]
        ldscript = conf.path.find_node("bsp/%s/link.ld" % t["bsp"])
        if ldscript:
            conf.env.LINKFLAGS += ["-Wl,-T," + ldscript.abspath()]
        conf.env.LIB = t["libs"]
        conf.env.WERROR = True
        conf.env.UNITY = found["unity"]
        conf.env.LIBFIXMATH = found["libfixmath"]
        # Install layout: one library directory and one pkg-config name a
        # target, so that targets installed into one prefix never clobber
        # each other; the headers are the same for all.
        conf.env.PREFIX = prefix
        conf.env.LIBDIR = os.path.join(prefix, "lib", name)
        conf.env.PKGCONFIGDIR = os.path.join(prefix, "lib", "pkgconfig")
        # drdc-<target>.pc names its directories relative to its prefix,
        # so that pkg-config --define-variable=prefix=... can move them
        conf.env.PC_PREFIX = prefix
        conf.env.PC_LIBDIR = "${prefix}/lib/" + name
        conf.env.PC_INCLUDEDIR = "${prefix}/include"
        conf.env.PC_NAME = "drdc-" + name
        conf.env.PC_CFLAGS = " ".join(t["abi"] or [])
        conf.env.PC_LIBS = "".join(" -l" + lib
                                   for lib in t.get("library_libs", t["libs"]))
        conf.env.INCLUDEDIR = os.path.join(prefix, "include")
        conf.env.BINDIR = os.path.join(prefix, "bin")
        conf.env.DOCDIR = os.path.join(prefix, "share", "doc", "drdc")
        conf.env.INSTALLABLE = t["abi"] is not None
        conf.check_cc(fragment="int main(void) { return 0; }\n",
                      features="c", cflags=arch,
                      msg="Checking that %s compiles" % name)
        if "hosted_bait" in t:
            _check_hermetic(conf, name, t)
        configure_cxx(conf, name, t)
    # The RTEMS BSP variants derive from the default environment (the
    # targets' own are set above).
    conf.setenv("")
    conf.env.TARGETS = targets
    conf.env.WERROR = conf.options.werror
    conf.env.UNITY = found["unity"]
    conf.env.LIBFIXMATH = found["libfixmath"]
    for what, version in versions.runners():
        conf.msg(what, version)
    conf.env.RTEMS_VARIANTS = _tools_module("waf_rtems").configure(
        conf, CODEGEN)


def _glob(bld, pattern):
    return bld.path.ant_glob(pattern)


# The parts of the conformance digest (tests/golden): function, its file,
# the name the test runner prints for it.
GOLDEN_PARTS = [
    ("golden_time", "golden_time.c", "time"),
    ("golden_time_scales", "golden_time.c", "time scales"),
    ("golden_fixed", "golden_fixed.c", "fixed"),
    ("golden_orient", "golden_orient.c", "orient"),
    ("golden_interop", "golden_interop.c", "interop"),
    ("golden_geo", "golden_geo.c", "geo"),
    ("golden_poses", "golden_poses.c", "poses and JAUS bodies"),
]


def build_golden_parts(bld, t, ours):
    """fw/golden-part/<part>.elf: one image per part of the conformance
    digest, for a board whose memory holds one module's tables at a time
    (AVR: avr-gcc copies the const tables not marked DRDC_FLASH_TABLE
    into RAM)."""
    bld.objects(source=["bsp/console.c"] + _glob(bld, "bsp/%s/*.c" % t["bsp"]),
                target="bsp", cflags=ours, includes=["bsp"],
                export_includes=["bsp"])
    for k, (part, source, name) in enumerate(GOLDEN_PARTS):
        bld.program(source=["fw/golden-part/main.c", "tests/golden/golden.c",
                            "tests/golden/" + source],
                    target="fw/golden-part/%s%s" % (part, t["ext"]),
                    use="libdrdc bsp", cflags=ours, idx=200 + k,
                    includes=["tests/golden"], install_path=None,
                    # no trace labels: their strings would take RAM
                    defines=["GOLDEN_PART=" + part,
                             'GOLDEN_NAME="%s"' % name, "GOLDEN_TRACE=0"])


def build_golden_trace(bld, ours, image, golden_geo):
    """Host only: fw/golden-trace/golden-trace, the reference records of
    the conformance digest (it writes tests/golden/golden_expected.c),
    and fw/test-runner/test-runner-broken, a port with drdc_geo_to_utm
    one LSB off (GOLDEN_BREAK_TO_UTM) whose log
    python/tests/test_conformance.py judges."""
    parts = [n for n in _glob(bld, "tests/golden/golden*.c")
             if n.name != "golden_expected.c"]
    bld.program(source=["fw/golden-trace/main.c"] + parts,
                target="fw/golden-trace/golden-trace", use="libdrdc",
                cflags=ours, includes=["tests/golden"], install_path=None,
                idx=400)
    image("fw/test-runner/test-runner-broken", [golden_geo],
          "runner-suites libdrdc unity bsp", includes=["tests"], idx=401,
          defines=["GOLDEN_BREAK_TO_UTM=1"])


def build_library(bld, cflags):
    """libdrdc.a, its headers and drdc.pc, installed under the variant's
    LIBDIR and INCLUDEDIR. Each object gets a call graph with stack usage
    (.ci) for the footprint report (tools/footprint.py), each file
    compiled for speed or size as the footprint policy says."""
    gcc = bld.env.CC_NAME == "gcc"
    # call graphs: GCC 10 and later (not avr-gcc 5, not clang)
    graphs = gcc and int((bld.env.CC_VERSION or ("0",))[0]) >= 10
    lib_cflags = cflags + LIBRARY_CODEGEN + (["-fcallgraph-info=su"]
                                             if graphs else [])
    sources = _glob(bld, "fixed/**/*.c") + _glob(bld, "core/**/*.c")
    policy = _tools_module("footprint")
    includes = ["fixed/internal", "fixed/include", "core/include"]
    by_kind = {}
    for node in sources:
        kind = policy.optimise_kind(node.path_from(bld.path))
        by_kind.setdefault(kind, []).append(node)
    # the library's own task compiles for speed; the other kinds are
    # object groups it archives with its own
    others = sorted(k for k in by_kind if k != "speed")
    for kind in others:
        # idx=1: objects named x.c.1.o, as those of the library's own task;
        # GCC's flags: clang (the fuzz build) keeps its own
        bld.objects(source=by_kind[kind], target="drdc_" + kind, idx=1,
                    cflags=lib_cflags + (policy.OPTIMISE_FLAGS[kind]
                                         if gcc else []),
                    includes=includes)
    bld.stlib(source=by_kind.get("speed", []), target="drdc",
              name="libdrdc", idx=1, cflags=lib_cflags, includes=includes,
              use=["drdc_" + kind for kind in others],
              export_includes=["fixed/include", "core/include"],
              install_path="${LIBDIR}")
    bld.install_files("${INCLUDEDIR}/drdc",
                      _glob(bld, "fixed/include/drdc/*.h")
                      + _glob(bld, "core/include/drdc/*.h"))
    # the C++ layer, header-only, beside the C headers' folder
    bld.install_files("${INCLUDEDIR}", _glob(bld, "cxx/include/*.hpp"))
    glue = bool(bld.env.RTEMS_BSP and bld.env.HAVE_RTEMS_H)
    if glue:
        # RTEMS clock glue, installed beside the library
        bld.stlib(source=_glob(bld, "bsp/rtems/drdc_rtems.c"),
                  target="drdc_rtems", name="libdrdc_rtems", use="libdrdc",
                  cflags=cflags, includes=["bsp/rtems"],
                  install_path="${LIBDIR}")
        bld.install_as("${INCLUDEDIR}/drdc/rtems.h", "bsp/rtems/drdc_rtems.h")
    name = bld.env.PC_NAME or "drdc"
    bld(features="subst", source="tools/drdc.pc.in", target=name + ".pc",
        install_path=bld.env.PKGCONFIGDIR or "${LIBDIR}/pkgconfig",
        VERSION=VERSION, NAME=name, ABI_CFLAGS=bld.env.PC_CFLAGS or "",
        PC_PREFIX=bld.env.PC_PREFIX or bld.env.PREFIX,
        PC_LIBDIR=bld.env.PC_LIBDIR or bld.env.LIBDIR,
        PC_INCLUDEDIR=bld.env.PC_INCLUDEDIR or bld.env.INCLUDEDIR,
        EXTRA_LIBS=" -ldrdc_rtems" if glue else "",
        LIBS_AFTER=bld.env.PC_LIBS or "")
    if bld.env.DOCDIR:
        # the documents the headers cite as docs/<name>.md
        bld.install_files("${DOCDIR}/docs",
                          ["docs/conventions.md", "docs/accuracy.md",
                           "docs/performance.md", "docs/bad-input.md"])


def _suite_sources(bld):
    """The Unity suites of suites.def and the golden digest; tests/rtems/
    (suites_rtems.def) needs an RTEMS kernel."""
    return (bld.path.ant_glob("tests/**/test_*.c", excl=["tests/rtems/**"])
            + _glob(bld, "tests/golden/golden*.c"))


def _qemu_linkcmds(task):
    """The BSP's linker command file with the one line QEMU needs
    changed; a BSP whose file lacks the line fails loudly."""
    line, replacement = task.generator.replace
    text = task.inputs[0].read()
    if text.count(line + "\n") != 1:
        Logs.error("%s: no line %r to change for QEMU (RTEMS_QEMU in wscript)"
                   % (task.inputs[0].abspath(), line))
        return 1
    task.outputs[0].write(text.replace(line + "\n", replacement + "\n"))
    return 0


# ---------------------------------------------------------------------
# The C++ layer: cxx/include/drdc.hpp (header-only, C++17, over the C
# API), its Unity runner, the C++ demo and the wrapper's benchmark. One
# entry per target that builds them:
#   compilers  C++ compilers, the first with the target's tool prefix
#              (its g++), the others native (host only)
#   flags      what the target adds: bare metal has no exceptions, RTTI
#              or libstdc++, so the images link with the C driver
#   bench      the wrapper's quaternion product beside the C call, timed
#              under QEMU -icount (tools/test_cxx.py)
CXX_TARGETS = {
    "host": {"compilers": ["g++", "clang++"], "flags": [],
             "bench": False},
    # the same under ASan and UBSan (the target's flags)
    "host-asan": {"compilers": ["g++"], "flags": [], "bench": False},
    "arm-cm3": {"compilers": ["g++"], "flags": ["-fno-exceptions",
                                               "-fno-rtti"],
                "bench": True},
    # Thumb-1 without a divide instruction, and RISC-V: the same header
    # on the other instruction sets whose g++ comes with the pinned C
    # cross compiler
    "arm-cm0": {"compilers": ["g++"], "flags": ["-fno-exceptions",
                                               "-fno-rtti"],
                "bench": False},
    "riscv32": {"compilers": ["g++"], "flags": ["-fno-exceptions",
                                               "-fno-rtti"],
                "bench": False},
}
# The warnings of every C++ file we write, errors on every compiler.
CXX_WARNINGS = ["-std=c++17", "-Wall", "-Wextra", "-pedantic", "-Werror",
                "-Wconversion", "-Wsign-conversion", "-Wshadow"]


def configure_cxx(conf, name, t):
    """CXX (and CXX_<n> for the further compilers) of a target of
    CXX_TARGETS; LINK_CXX is the C driver where there is no libstdc++."""
    spec = CXX_TARGETS.get(name)
    if spec is None:
        return
    first, others = spec["compilers"][0], spec["compilers"][1:]
    conf.find_program(t["cross"] + first, var="CXX")
    conf.load("gxx")
    # for tools/test_cxx.py: how to run this target's images
    conf.env.CXX_QEMU = t["qemu"]
    conf.env.CXX_EXT = t["ext"]
    if t["cross"]:
        conf.env.LINK_CXX = conf.env.CC
    # the further compilers come with other targets' packages (clang:
    # host-fuzz), so a tree configured for the host alone may lack them;
    # ./waf check configures every target and tools/test_cxx.py demands
    # them all
    conf.env.CXX_OTHERS = []
    for compiler in others:
        var = "CXX_" + re.sub(r"\W", "_", compiler).upper()
        if conf.find_program(compiler, var=var, mandatory=False):
            conf.env.CXX_OTHERS += [(compiler, var)]


def build_cxx(bld, t):
    """Per C++ compiler of the target: fw/cxx-runner/cxx-runner (the Unity
    tests of drdc.hpp) and fw/demo-cxx/demo-cxx (the C++ demo); the
    further compilers' images get the compiler's name as a suffix
    (cxx-runner-clang++). On a bench target also fw/bench-cxx."""
    spec = CXX_TARGETS.get(bld.variant)
    if spec is None:
        return
    unity = bld.root.find_dir(bld.env.UNITY)
    cxxflags = (bld.env.ARCH + CODEGEN + CXX_WARNINGS + spec["flags"]
                + ["-isystem", unity.abspath()])
    includes = ["cxx/include", "tests", "bsp"]
    ldscript = bld.path.find_node("bsp/%s/link.ld" % t["bsp"])
    compilers = [("", None)] + [("-" + c, var)
                                for c, var in bld.env.CXX_OTHERS]
    for k, (suffix, var) in enumerate(compilers):
        images = [
            ("fw/cxx-runner/cxx-runner",
             ["fw/cxx-runner/main.cpp", "tests/cxx/test_cxx.cpp"],
             "libdrdc unity bsp"),
            ("fw/demo-cxx/demo-cxx", ["fw/demo-cxx/main.cpp"],
             "libdrdc bsp"),
        ]
        if spec["bench"] and not var:
            images.append(("fw/bench-cxx/bench-cxx",
                           ["fw/bench-cxx/main.cpp"], "libdrdc bsp"))
        for name, source, use in images:
            target = name + suffix + t["ext"]
            # an environment of its own per image: waf appends the task
            # generator's flags to it
            env = bld.env.derive()
            if var:
                env.CXX = env.LINK_CXX = bld.env[var]
            bld.program(features="cxx cxxprogram", source=source,
                        target=target, use=use, env=env, idx=300 + k,
                        cxxflags=cxxflags, includes=includes,
                        install_path=None)
            if ldscript:
                bld.add_manual_dependency(
                    bld.path.find_or_declare(target), ldscript)


def cxx_runner_images(all_envs):
    """harness.py specs of the C++ Unity runners: <target>-cxx[-<compiler>],
    one per compiler configure found."""
    specs = []
    for name in CXX_TARGETS:
        if name not in (all_envs[""].TARGETS or []):
            continue
        t = TARGETS[name]
        compilers = [""] + [c for c, _ in all_envs[name].CXX_OTHERS or []]
        for compiler in compilers:
            suffix = "-" + compiler if compiler else ""
            specs.append("%s-cxx%s=%s:%s" % (
                name, suffix, t["qemu"], os.path.join(
                    out, name, "fw/cxx-runner/cxx-runner" + suffix + t["ext"])))
    return specs
# ---------------------------------------------------------------------


def build_rtems_runner(bld, cflags):
    """An RTEMS BSP gets the library; its applications link it. With a full
    RTEMS installation also the Unity suites, with the glue's, as an RTEMS
    application: test-runner.exe for rtems-test on a board, and for a BSP
    of RTEMS_QEMU test-runner-qemu.exe."""
    if not bld.env.HAVE_RTEMS_CONFDEFS:
        Logs.info("%s: no rtems/confdefs.h, so no test-runner.exe"
                  % bld.variant)
        return
    unity = bld.root.find_dir(bld.env.UNITY)
    bld.objects(source=["fw/test-runner/main.c", "fw/test-runner/rtems_init.c",
                        "bsp/rtems/board.c", "bsp/console.c",
                        unity.find_node("unity.c")]
                + _suite_sources(bld) + _glob(bld, "tests/rtems/test_*.c"),
                target="rtems-runner", cflags=cflags, use="libdrdc",
                includes=["tests", "bsp", "bsp/rtems", "fw/test-runner", unity],
                defines=["UNITY_INCLUDE_CONFIG_H"])
    use = "rtems-runner libdrdc_rtems libdrdc"
    # The tool suite's own ecrtn.o has no .note.GNU-stack: ld would warn
    # that the stack is executable, which means nothing on this MMU-less
    # setup.
    quiet = ["-Wl,--no-warn-execstack"]
    bld(features="c cprogram", target="fw/test-runner/test-runner.exe",
        use=use, install_path=None, linkflags=quiet)
    qemu = RTEMS_QEMU.get(bld.env.RTEMS_BSP)
    if qemu:
        original = bld.root.find_node(os.path.join(bld.env.LIBDIR,
                                                   qemu["linkcmds"]))
        if original is None:
            bld.fatal("%s: no %s in %s" % (bld.variant, qemu["linkcmds"],
                                           bld.env.LIBDIR))
        adjusted = bld.path.find_or_declare("fw/test-runner/linkcmds.qemu")
        bld(rule=_qemu_linkcmds, source=[original], target=[adjusted],
            replace=qemu["replace"])
        image = bld(features="c cprogram", use=use, install_path=None,
                    target="fw/test-runner/test-runner-qemu.exe",
                    linkflags=quiet + ["-qnolinkcmds",
                                       "-Wl,-T," + adjusted.abspath()])
        # link after the file is written, and again when it changes
        image.post()
        image.link_task.dep_nodes.append(adjusted)


def build(bld):
    if not bld.variant:
        # ./waf build (and ./waf): every configured target and RTEMS BSP,
        # one after the other
        _run_now(["build_" + n for n in (bld.env.TARGETS or [])
                  + (bld.env.RTEMS_VARIANTS or [])])
        return
    if bld.variant not in (bld.all_envs[""].TARGETS or []) \
            and not bld.env.RTEMS_BSP:
        bld.fatal("target %s is not configured (configured: %s): "
                  "./waf configure sets up every target, or name it in "
                  "--with-targets"
                  % (bld.variant, ", ".join(bld.all_envs[""].TARGETS or [])))
    arch = bld.env.ARCH
    ours = arch + CODEGEN + WARNINGS + (["-Werror"] if bld.env.WERROR else [])
    theirs = arch + CODEGEN + ["-w"]
    build_library(bld, ours + (bld.env.LIBRARY_ARCH or []))
    if bld.env.RTEMS_BSP:
        build_rtems_runner(bld, ours)
        return
    t = TARGETS[bld.variant]
    # An object that exports a name without drdc_: tools/symcheck.py must
    # reject it (proof that the check of libdrdc.a's names bites).
    bld.stlib(source=["tests/symcheck/symbol_bait.c"], target="bait-symbols",
              cflags=arch + CODEGEN + ["-w"], idx=3, install_path=None)
    if t.get("fuzz"):
        # libFuzzer targets (tools/fuzz.py), one program per file
        for src in _glob(bld, "tests/fuzz/fuzz_*.c"):
            # fuzz_tool drives the host tool's own command code
            tool = ([n for n in _glob(bld, "tools/drdc/*.c")
                     if n.name != "main.c"]
                    if src.name == "fuzz_tool.c" else [])
            bld.program(source=[src] + tool,
                        target="tests/fuzz/" + src.name[:-2],
                        use="libdrdc", cflags=ours, includes=["tools/drdc"],
                        install_path=None, idx=100)
    # Objects that must fail the integer-only check (proof that it bites).
    if t["intcheck"]:
        bld.stlib(source=["tests/intcheck/float_bait.c"], target="bait-soft",
                  cflags=arch + CODEGEN + ["-w"], idx=1, install_path=None)
        if t["hard_float"]:
            bld.stlib(source=["tests/intcheck/float_bait.c"],
                      target="bait-hard", idx=2, install_path=None,
                      cflags=[f for f in arch if "float" not in f]
                      + t["hard_float"] + CODEGEN + ["-w"])

    if t.get("golden_parts"):
        build_golden_parts(bld, t, ours)
    if not t.get("images", True):
        return

    # Third-party parts, from the pinned sources in .deps/.
    unity = bld.root.find_dir(bld.env.UNITY)
    bld.objects(source=[unity.find_node("unity.c")], target="unity",
                cflags=theirs, includes=[unity, "tests", "bsp"],
                defines=["UNITY_INCLUDE_CONFIG_H"],
                export_includes=[unity, "tests"],
                export_defines=["UNITY_INCLUDE_CONFIG_H"])
    fixmath = bld.root.find_dir(bld.env.LIBFIXMATH)
    # fix16_str.c (text conversion) needs the hosted <ctype.h>
    bld.stlib(source=fixmath.ant_glob("fix16*.c fract32.c uint32.c",
                                      excl=["fix16_fft.c", "fix16_str.c"]),
              target="fixmath", cflags=theirs, includes=[fixmath],
              install_path=None,
              # no 32-80 KiB result caches: no global state, like ours
              defines=["FIXMATH_NO_CACHE"],
              export_defines=["FIXMATH_NO_CACHE"])

    # The board.
    bld.objects(source=["bsp/console.c"] + _glob(bld, "bsp/%s/*.c" % t["bsp"])
                + _glob(bld, "bsp/%s/*.S" % t["bsp"]),
                target="bsp", cflags=ours, includes=["bsp"],
                export_includes=["bsp"])

    def image(name, source, use, **kw):
        node = bld.path.find_or_declare(name + t["ext"])
        tg = bld.program(source=source, target=name + t["ext"], use=use,
                         cflags=ours + kw.pop("extra_cflags", []),
                         install_path=None, **kw)
        ldscript = bld.path.find_node("bsp/%s/link.ld" % t["bsp"])
        if ldscript:
            bld.add_manual_dependency(node, ldscript)
        return tg

    # Everything of the runner but the golden part that a broken port
    # changes (test-runner-broken, host only) is compiled once for both.
    golden_geo = bld.path.find_node("tests/golden/golden_geo.c")
    bld.objects(source=["fw/test-runner/main.c"]
                + [n for n in _suite_sources(bld) if n != golden_geo],
                target="runner-suites", cflags=ours, includes=["tests"],
                use="libdrdc unity bsp")
    runner = image("fw/test-runner/test-runner", [golden_geo],
                   "runner-suites libdrdc unity bsp", includes=["tests"])
    # The runner's object files, one path a line, so the same image can be
    # linked against an installed libdrdc.a (tools/rtems_standin.py).
    runner.post()
    bld(rule=lambda task: task.outputs[0].write(
            "".join(n.abspath() + "\n" for n in task.inputs)),
        source=list(runner.link_task.inputs),
        target="fw/test-runner/objects.txt")
    build_cxx(bld, t)
    # the demo's link map: what of the library an application really links
    # (tools/footprint.py, docs/performance.md)
    demo_map = bld.path.find_or_declare("fw/demo/demo.map").abspath()
    image("fw/demo/demo", _glob(bld, "fw/demo/*.c"), "libdrdc bsp",
          linkflags=[] if t["qemu"] == "host" else ["-Wl,-Map=" + demo_map])
    if t.get("bench", t["qemu"] != "host"):
        # soft-float double baselines where the toolchain has soft-float
        image("fw/bench/bench", _glob(bld, "fw/bench/*.c"),
              "libdrdc bsp fixmath",
              defines=["BENCH_DOUBLE=%d" % bool(t["soft_float_libm"])],
              lib=t["libs"] + (["m"] if t["soft_float_libm"] else []),
              # third-party header: its warnings are not ours to fix
              extra_cflags=["-isystem", fixmath.abspath()])
    for kind, number in SELFTEST_KINDS.items():
        image("qemu/selftest-" + kind, ["qemu/selftest.c"], "unity bsp",
              defines=["SELFTEST_KIND=%d" % number],
              idx=number)

    if t.get("tool"):
        bld.program(source=_glob(bld, "tools/drdc/*.c"),
                    target="drdc" + t["ext"], use="libdrdc", cflags=ours)
    if bld.variant == "host":
        build_golden_trace(bld, ours, image, golden_geo)
    if t["qemu"] == "host" and not bld.variant.endswith("asan"):
        # the library's own results for the plots of docs/accuracy.md
        bld.program(source=["tools/accuracy/sample.c"],
                    target="accuracy-sample", use="libdrdc", cflags=ours,
                    install_path=None)


# build_<target>, clean_<target>, install_<target> for every target.
_register_variant_commands(TARGETS)


class InstallAll(Build.InstallContext):
    """install every configured RTEMS BSP, or else every configured
    target (lib/<target>/, lib/pkgconfig/drdc-<target>.pc)"""
    cmd = "install"

    def execute(self):
        self.restore()
        if not self.all_envs:
            self.load_envs()
        variants = self.all_envs[""].RTEMS_VARIANTS or [
            n for n in (self.all_envs[""].TARGETS or [])
            if self.all_envs[n].INSTALLABLE]
        Logs.info("install: %s" % ", ".join(variants))
        _run_now(["install_" + v for v in variants])

    # configure first where it has not run or a wscript changed, as the
    # build commands do
    from waflib import Scripting
    execute = Scripting.autoconfigure(execute)


def _run_now(commands):
    """Run waf commands within the current one, so that waf's closing
    "'<command>' finished successfully" follows the work."""
    from waflib import Scripting
    for cmd in commands:
        Scripting.run_command(cmd)


def _configured():
    """(options, targets) of the last configure; (None, []) before the
    first."""
    from waflib import ConfigSet
    try:
        lock = ConfigSet.ConfigSet(os.path.join(Context.top_dir,
                                                Options.lockfile))
        cache = ConfigSet.ConfigSet(os.path.join(lock.out_dir, "c4che",
                                                 "_cache.py"))
    except (EnvironmentError, AttributeError):
        return None, []
    return lock.options, list(cache.TARGETS or [])


def _configure_with(targets):
    """Configure where the last configure left out any of targets (or none
    ran), adding them to its targets and keeping its other options."""
    options, have = _configured()
    if options is not None and set(targets) <= set(have):
        return
    saved = Options.options.__dict__
    Options.options.__dict__ = dict(options or saved)
    Options.options.with_targets = ",".join(
        n for n in TARGETS if n in set(targets) | set(have))
    try:
        _run_now(["configure"])
    finally:
        Options.options.__dict__ = saved


def _command(ctx, targets, then, groups=(), python=False):
    """Set up what a command needs (the packages that build and run
    targets, groups, and if python the Python packages), configure
    targets where needed, build them, then run the command `then`."""
    _setup(ctx, _apt_groups(targets, run=True) + list(groups), python)
    _configure_with(targets)
    _run_now(["build_" + n for n in targets] + [then])


def check(ctx):
    """build every target, then run every check and test suite"""
    _command(ctx, list(TARGETS), "run_checks", ["check"], python=True)


def demo(ctx):
    """build the default target and run the demo firmware under QEMU"""
    _command(ctx, [DEFAULT_TARGET], "run_demo")


# Targets with a deterministic counter under QEMU -icount (tools/bench.py).
BENCH_TARGETS = ["ppc-e500", "arm-cm3", "riscv32"]


def bench(ctx):
    """benchmark and footprint: build/bench/report.json, docs/performance.*"""
    _command(ctx, BENCH_TARGETS, "run_bench", python=True)


def _python_path(ctx):
    """The folder of the pinned Python packages, installed if missing."""
    return _setup(ctx, [], python=True)["python"]


def _python(ctx, args, extra_env=None, **kw):
    env = dict(os.environ)
    env["PYTHONPATH"] = getattr(ctx, "python_path", "")
    env.update(extra_env or {})
    return subprocess.call([sys.executable] + args, cwd=ctx.path.abspath(),
                           env=env, **kw)


class RunDemo(Build.BuildContext):
    """(internal) run the demo image of the default target"""
    cmd = "run_demo"
    variant = DEFAULT_TARGET

    def execute(self):
        self.restore()
        if not self.all_envs:
            self.load_envs()
        t = TARGETS[DEFAULT_TARGET]
        img = os.path.join(out, DEFAULT_TARGET, "fw/demo/demo" + t["ext"])
        if _python(self, ["qemu/harness.py", "show", t["qemu"], img]) != 0:
            self.fatal("demo failed")


def docs(ctx):
    """API reference (Doxygen) and the error plots of docs/accuracy.md"""
    _command(ctx, ["host"], "run_docs", ["docs"], python=True)


class RunDocs(Build.BuildContext):
    """(internal) Doxygen into build/docs/html, plots into docs/img"""
    cmd = "run_docs"
    variant = ""

    def execute(self):
        self.restore()
        if not self.all_envs:
            self.load_envs()
        # matplotlib for the plots
        self.python_path = _python_path(self)
        if subprocess.call(["doxygen", "docs/Doxyfile"],
                           cwd=self.path.abspath()) != 0:
            self.fatal("Doxygen found undocumented or badly documented "
                       "symbols")
        Logs.info("API reference: build/docs/html/index.html")
        sampler = os.path.join(out, "host", "accuracy-sample")
        if _python(self, ["tools/accuracy/plots.py", sampler,
                          "docs/img"]) != 0:
            self.fatal("accuracy plots failed")


def fuzz(ctx):
    """run every libFuzzer target for --seconds each (tests/fuzz/)"""
    _command(ctx, ["host-fuzz"], "run_fuzz")


class RunFuzz(Build.BuildContext):
    """(internal) run the fuzzers"""
    cmd = "run_fuzz"
    variant = ""

    def execute(self):
        self.restore()
        if not self.all_envs:
            self.load_envs()
        if _python(self, ["tools/fuzz.py", "--build", out, "--seconds",
                          str(Options.options.fuzz_seconds)]) != 0:
            self.fatal("fuzzing found something")


class RunBench(Build.BuildContext):
    """(internal) run the benchmark images and write the reports"""
    cmd = "run_bench"
    variant = ""

    def execute(self):
        self.restore()
        if not self.all_envs:
            self.load_envs()
        self.python_path = _python_path(self)  # matplotlib, for the chart
        if _python(self, ["tools/bench.py", "--build", out, "--out",
                          os.path.join(out, "bench", "report.json"),
                          "--docs", "docs"]) != 0:
            self.fatal("benchmark failed")


def serve(ctx):
    """run the gold-standard web service on 127.0.0.1:8080 (docs/service.md)"""
    _command(ctx, ["host"], "run_serve", python=True)


class RunServe(Build.BuildContext):
    """(internal) pip install ./python into the build, run drdc.serve"""
    cmd = "run_serve"
    variant = ""

    def execute(self):
        self.restore()
        if not self.all_envs:
            self.load_envs()
        self.python_path = _python_path(self)  # aiohttp and numpy
        site = os.path.join(out, "python", "serve-site")
        if _python(self, ["-m", "pip", "install", "--quiet", "--no-index",
                          "--no-deps", "--disable-pip-version-check",
                          "--root-user-action=ignore", "--upgrade",
                          "--target", site,
                          os.path.join(self.path.abspath(), "python")]) != 0:
            self.fatal("pip install ./python failed")
        env = {"PYTHONPATH": os.pathsep.join([site, self.python_path])}
        args = os.environ.get("DRDC_SERVE_ARGS", "").split()
        try:
            _python(self, ["-m", "drdc.serve"] + args, env)
        except KeyboardInterrupt:
            pass


class RunChecks(Build.BuildContext):
    """(internal) run the checks and the Unity suites of every target"""
    cmd = "run_checks"
    variant = ""

    def execute(self):
        self.restore()
        if not self.all_envs:
            self.load_envs()
        top_env = self.all_envs[""]
        self.python_path = _python_path(self)
        steps = [
            ("set-up: no Debian version pin, README's package tables true",
             ["-m", "unittest", "-q", "tools.test_setup"]),
            ("reference vectors regenerate identically",
             ["tests/ref/generate.py", "--check"]),
            ("integer-only check of core/ and fixed/",
             ["tools/intcheck.py", "--build", out, "--all"]
             + ["%s:%s:%s" % (n, t["intcheck"], t["cross"])
                for n, t in TARGETS.items() if t["intcheck"]]),
            ("C sources laid out as .clang-format says",
             ["tools/formatcheck.py"]),
            ("every external name of libdrdc.a starts with drdc_",
             ["tools/symcheck.py", "--build", out]
             + ["%s:%s" % (n, t["cross"]) for n, t in TARGETS.items()]),
            ("API reference: Doxygen without a warning",
             ["-c", "import subprocess, sys; sys.exit(subprocess.call("
              "['doxygen', 'docs/Doxyfile']))"]),
            ("bad-input catalogue docs/bad-input.md up to date",
             ["tools/badinput.py", "--check"]),
            ("fuzz corpora replay without a finding",
             ["tools/fuzz.py", "--build", out, "--replay"]),
            ("MISRA C:2012 of core/ and fixed/ (cppcheck)",
             ["tools/misra.py"]),
            ("cycles and flash within 5 % of docs/performance.json",
             ["tools/bench.py", "--build", out, "--check",
              "docs/performance.json"]),
            ("QEMU harness judges its own test images",
             ["-m", "unittest", "-q", "qemu.test_harness"]),
            ("host tool drdc, the demo against it, the benchmark guard",
             ["-m", "unittest", "-q", "tools.test_drdc",
              "tools.test_drdc_nmea", "tools.test_demo", "tools.test_bench"]),
            ("Python package: pip install ./python and pytest against "
             "the vectors",
             ["python/check.py", "--build", out]),
            # --- Windows (win64) ---
            ("drdc.exe (win64) under Wine: the tool's tests",
             ["-m", "unittest", "-q", "tools.test_drdc",
              "tools.test_drdc_nmea"], {"DRDC_TARGET": "win64"}),
            # --- end of Windows (win64) ---
            ("C++ layer: demo equals C demo, hot path within 5 %, example",
             ["-m", "unittest", "-q", "tools.test_cxx"]),
            ("16-bit int: every digest part on an AVR under simavr",
             ["-m", "unittest", "-q", "tools.test_avr"]),
            ("installed tree: every target side by side, a client of it",
             ["-m", "unittest", "-q", "tools.test_install"]),
            ("RTEMS build path through a stand-in prefix",
             ["-m", "unittest", "-q", "tools.test_rtems"]),
            ("RTEMS 6 (real): configure, build, install, QEMU image",
             ["tools/rtems_qemu.py"]
             + (["--prefix", top_env.RTEMS_PREFIX, "--tools",
                 top_env.RTEMS_TOOLS] if top_env.RTEMS_PREFIX else [])),
        ]
        # each step: title, arguments of Python, and maybe its environment
        for title, args, *env in steps:
            Logs.pprint("CYAN", "== " + title)
            start = time.monotonic()
            if _python(self, args, *env) != 0:
                self.fatal("check failed: " + title)
            Logs.pprint("CYAN", "   (%.0f s)" % (time.monotonic() - start))
        Logs.pprint("CYAN", "== Unity suites on every target")
        images = ["%s=%s:%s" % (n, t["qemu"], os.path.join(
            out, n, "fw/test-runner/test-runner" + t["ext"]))
            for n, t in TARGETS.items() if t.get("images", True)]
        # the C++ layer's Unity suite, per C++ compiler (CXX_TARGETS)
        images += cxx_runner_images(self.all_envs)
        # the ppc-e500 runner linked against the library installed into
        # the stand-in RTEMS BSP prefix (tools/rtems_standin.py)
        images.append("rtems-standin=ppc-e500:" + os.path.join(
            out, "rtems-standin", "test-runner.elf"))
        # the RTEMS 6 application under the real kernel, when it was built
        real = os.path.join(out, "rtems-real", "image.txt")
        if os.path.exists(real):
            with open(real) as f:
                images.append("rtems=rtems-qoriq_e500:" + f.read().strip())
        # what the results were computed with, in the summary
        note = _tools_module("toolchains").summary(
            [self.all_envs[n] for n in top_env.TARGETS])
        failed = _python(self, ["qemu/harness.py", "run", "--junit-dir",
                                os.path.join(out, "reports"),
                                "--note", note] + images)
        if failed:
            self.fatal("test suites failed")
        # The harness's "N passed, M failed" stays the last line: CI reads
        # it; waf's own "finished successfully" would follow it.
        Logs.log.setLevel(logging.WARNING)
