# SPDX-License-Identifier: BSD-2-Clause
"""The one table of targets: every board and toolchain libdrdc-fx is built
for, and the flags and budgets every build shares, as data.

wscript builds from it, qemu/harness.py boots its machines, the gates and
tests read their roles, set-up installs its packages; nothing else lists
targets. Adding a board is a folder bsp/<board>/ and one row of TARGETS
(README, "Adding a board").
"""
import os

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Warnings of every file we write, on every target; errors where the
# compiler is one the project tries (every target here, with the compilers
# of Debian 12 and 13) and where configure is asked to (--werror: the real
# RTEMS 6 build of ./waf check). A user's RTEMS tool suite may warn where
# these do not: its build warns but completes.
WARNINGS = ["-std=c99", "-Wall", "-Wextra", "-Wconversion",
            "-Wsign-conversion", "-Wshadow", "-Wcast-align",
            "-Wstrict-prototypes", "-Wundef"]
# Code generation of every file, ours and third-party.
CODEGEN = ["-O2", "-g", "-ffunction-sections", "-fdata-sections"]
# Every library file, on top of CODEGEN: no padding to align function
# entries, for flash. Instruction counts are the same; on a real Cortex-M3
# a 32-bit first instruction on a half-word boundary may cost one fetch per
# call.
LIBRARY_CODEGEN = ["-fno-align-functions"]
SANITIZE = ["-fsanitize=address,undefined", "-fno-sanitize-recover=all",
            "-fno-omit-frame-pointer"]

# The footprint policy: how each library file is compiled, on top of -O2
# (GCC keeps the last -O), and what the library may cost.
OPTIMISE_FLAGS = {"speed": [], "size": ["-Os"]}
# Every file of a module folder is compiled as its module says: "speed"
# where a speed goal of docs/performance.md runs through the module, "size"
# where the module turns text and messages at a few per second.
MODULE_OPTIMISE = {
    "fixed": "speed",
    "core/geo": "speed",
    "core/orient": "speed",
    "core/time": "speed",
    "core/jaus": "size",
    "core/nmea": "size",
    "core/units": "size",
}
# Files compiled otherwise than their module, each with its measured
# reason. Empty: no budget needs one.
FILE_OPTIMISE = {}


def optimise_kind(path):
    """"speed" or "size" for a library source (path from the top:
    core/geo/tm.c), as the footprint policy says."""
    if path in FILE_OPTIMISE:
        return FILE_OPTIMISE[path]
    module = os.path.dirname(path)
    while module and module not in MODULE_OPTIMISE:
        module = os.path.dirname(module)
    if not module:
        raise KeyError("no module of MODULE_OPTIMISE holds " + path)
    return MODULE_OPTIMISE[module]


# No public function's worst-case stack deeper than this on any bench
# target (bytes; the bench guard fails above it).
STACK_LIMIT = 512

# How an image runs: the command that boots it ({image}: its path), the
# Debian packages of that command, whether the exit status carries the
# number of failed tests, and what must be done once before the first
# image is timed.
MACHINES = {
    "host": {"command": ["{image}"], "packages": [], "exit_status": True},
    # QEMU's mpc8544ds (e500v2 core): -nic none, no network card, whose
    # option ROM (Debian's ipxe-qemu) no image uses. The reset request
    # always ends QEMU with status 0: the console is the verdict.
    "ppc-e500": {
        "command": ["qemu-system-ppc", "-M", "mpc8544ds", "-nographic",
                    "-nic", "none", "-no-reboot", "-kernel", "{image}"],
        "packages": ["qemu-system-ppc"], "exit_status": False},
    # The MPS2 boards' LAN9118 is part of the board and needs no ROM; -nic
    # none there would only leave it without a peer (a warning on every
    # run), so they keep QEMU's default. Semihosting: console and exit.
    "arm-cm3": {
        "command": ["qemu-system-arm", "-M", "mps2-an385", "-nographic",
                    "-semihosting-config", "enable=on,target=native",
                    "-kernel", "{image}"],
        "packages": ["qemu-system-arm"], "exit_status": True},
    # the same board with a Cortex-M4F (QEMU 6.0 and later)
    "arm-cm4f": {
        "command": ["qemu-system-arm", "-M", "mps2-an386", "-nographic",
                    "-semihosting-config", "enable=on,target=native",
                    "-kernel", "{image}"],
        "packages": ["qemu-system-arm"], "exit_status": True},
    # the MPS2 board with a Cortex-M7 (double-precision FPU): the AN385's
    # memory but its PSRAM at 0x60000000 (QEMU 6.0 and later)
    "arm-cm7": {
        "command": ["qemu-system-arm", "-M", "mps2-an500", "-nographic",
                    "-semihosting-config", "enable=on,target=native",
                    "-kernel", "{image}"],
        "packages": ["qemu-system-arm"], "exit_status": True},
    # the MPS2 board with a Cortex-M33 (Armv8-M mainline, TrustZone): the
    # image runs in the Secure state it boots in, code at the Secure
    # alias 0x10000000 of its SSRAM
    "arm-cm33": {
        "command": ["qemu-system-arm", "-M", "mps2-an505", "-nographic",
                    "-semihosting-config", "enable=on,target=native",
                    "-kernel", "{image}"],
        "packages": ["qemu-system-arm"], "exit_status": True},
    # QEMU virt, RV32, no firmware: the ELF image runs in machine mode
    "riscv32": {
        "command": ["qemu-system-riscv32", "-M", "virt", "-bios", "none",
                    "-nographic", "-net", "none", "-kernel", "{image}"],
        "packages": ["qemu-system-misc"], "exit_status": True},
    # An AVR under simavr: one image per part of the conformance digest
    # (fw/golden-part), judged by its printed digests, not by Unity
    "avr": {"command": ["simavr", "-m", "atmega2560", "{image}"],
            "packages": ["simavr"], "exit_status": True},
    # A Windows program under Wine, in a prefix of its own (qemu/wine.py),
    # made once before the first verdict is timed (8 s and more)
    "wine64": {"command": ["{python}", "{qemu}/wine.py", "{image}"],
               "prepare": ["{python}", "{qemu}/wine.py", "--init"],
               "packages": ["wine64"], "exit_status": True},
    # An RTEMS 6 qoriq_e500 application linked for QEMU (RTEMS_QEMU): its
    # work area reaches 512 MiB and QEMU puts the device tree after RAM,
    # so 1 GiB; the device tree beside the image is QEMU's own with the
    # CPU's bus-frequency set, without which the RTEMS clock never ticks
    # (tests/integration/rtems_qemu.py makes it).
    "rtems-qoriq_e500": {
        "command": ["qemu-system-ppc", "-M", "mpc8544ds", "-m", "1024",
                    "-nographic", "-nic", "none", "-no-reboot",
                    "-dtb", "{image}.dtb", "-kernel", "{image}"],
        "packages": ["qemu-system-ppc"], "exit_status": False},
}

# The default target: ./waf demo builds and runs it.
DEFAULT_TARGET = "ppc-e500"

# A row of TARGETS:
#   cross      tool prefix ("" for the native compiler)
#   compiler   the C compiler without prefix (default gcc)
#   packages   Debian packages that build it (its machine's run it)
#   bsp        folder under bsp/ with the board code (link.ld there, when
#              there is one, is the linker script)
#   ldscript   another linker script, where the board's memory differs
#              but its code is the same
#   machine    MACHINES entry that runs its images, or None
#   ext        file name ending of its programs
#   arch       flags for compiling, assembling and linking
#   library_arch  flags for the library's objects only
#   link       flags for linking images
#   libs       libraries linked after everything else
#   library_libs  what an application of the library links (default libs)
#   headers    bare metal: the only system include directories, in order,
#              after -nostdinc ("gcc:DIR" is the compiler's own DIR, as
#              -print-file-name gives it), so no host header can leak in
#   hosted_bait  headers of the host's C library that the target must not
#              see: configure proves that each is missing
#   isa        instruction set of the integer-only check (gates/intcheck),
#              or None to skip it
#   hard_float flags that make a floating-point unit available: the
#              integer-only check must catch the instructions they emit
#   object_format  what objdump calls its objects (the install test)
#   arm_arch   Arm only: the architecture every object's build attributes
#              must name (Tag_CPU_arch; Thumb-1 only for armv6-m)
#   abi        flags an application must compile with to link the library
#              (installed drdc-<target>.pc); None: a test build that
#              ./waf install leaves out
# and its roles, each false where absent:
#   images     firmware images and test runner (default True; False
#              builds the library and the bait objects only)
#   tool       the drdc command-line tool
#   fuzz       the libFuzzer targets (tests/fuzz)
#   golden_parts  one image per part of the conformance digest
#   check_only set up and built by ./waf check (or configure naming it),
#              not by a plain ./waf configure
#   soft_float_libm  the toolchain has soft-float double and a libm: the
#              benchmark image times double-precision baselines
#   bench      its counters repeat exactly under QEMU -icount: ./waf bench
#              times it; linked_budget is then the most of the library
#              the demo pose node may link (flash bytes)
#   footprint  the library's size, the demo's and a GGA-only node's are
#              reported for it in docs/performance.md (every bench target
#              too)
#   demo_check the demo's output is compared with the host's
#   selftest   the harness judges its self-test images here
#   examples   (folder of examples/, MACHINES entry): the installed
#              library's example firmware, built and run
#   cxx        the C++ layer's images: C++ compilers (the first with the
#              target's prefix, others native) and the flags the target
#              adds; cxx_bench: the wrapper's hot path timed here

PPC_BARE_METAL = {
    "cross": "powerpc-linux-gnu-", "bsp": "ppc-e500", "machine": "ppc-e500",
    "ext": ".elf", "packages": ["gcc-powerpc-linux-gnu"],
    "arch": ["-msoft-float", "-ffreestanding", "-fno-pic", "-fno-pie",
             "-msdata=none", "-G0", "-fno-stack-protector"],
    "link": ["-nostdlib", "-static", "-no-pie", "-Wl,--gc-sections",
             "-Wl,--build-id=none", "-Wl,--no-warn-rwx-segments"],
    # libgcc: 64-bit integer division (__udivdi3, __divdi3)
    "libs": ["gcc"],
    "isa": "ppc", "hard_float": ["-mhard-float"],
    "object_format": "elf32-powerpc",
    # freestanding: the compiler's <stdint.h>, <stddef.h>, <stdbool.h>;
    # the board's own <limits.h> (the compiler's wants a C library's below
    # it) and <string.h> (the four functions of its mem.c)
    "headers": ["bsp/ppc-e500/include", "gcc:include"],
    "hosted_bait": ["math.h", "stdio.h", "features.h"],
    "examples": ("powerpc", "ppc-e500"),
}
# Cortex-M on QEMU's MPS2 boards, newlib nano, semihosting console and exit
ARM_NEWLIB = {
    "cross": "arm-none-eabi-", "bsp": "arm-cm3", "machine": "arm-cm3",
    "ext": ".elf",
    "packages": ["gcc-arm-none-eabi", "libnewlib-arm-none-eabi"],
    "link": ["--specs=rdimon.specs", "-nostartfiles", "-Wl,--gc-sections"],
    "libs": [], "isa": "arm", "object_format": "elf32-littlearm",
    # the compiler's own, then newlib's (nano.specs puts newlib nano's
    # first with -isystem, which -nostdinc keeps)
    "headers": ["gcc:include", "gcc:include-fixed",
                "/usr/lib/arm-none-eabi/include"],
    "hosted_bait": ["features.h", "argp.h"],
    "examples": ("cortex-m", "arm-cm3"),
}
# Thumb-1 and Thumb-2 C++ images: no exceptions, RTTI or libstdc++ on bare
# metal, so they link with the C driver
BARE_METAL_CXX = {"compilers": ["g++"], "flags": ["-fno-exceptions",
                                                  "-fno-rtti"]}
# picolibc's libraries for rv32imac, ilp32 (Debian picolibc-riscv64-unknown-elf)
PICOLIBC_RV32 = "/usr/lib/picolibc/riscv64-unknown-elf/lib/rv32imac/ilp32"

TARGETS = {
    "host": {
        "cross": "", "bsp": "host", "machine": "host", "ext": "",
        "packages": ["gcc", "g++", "libc6-dev"],
        "arch": ["-D_POSIX_C_SOURCE=200809L"], "link": [], "libs": [],
        "isa": "x86-64", "hard_float": [], "object_format": "elf64-x86-64",
        "abi": [], "tool": True, "demo_check": True, "selftest": True,
        # clang++ comes with host-fuzz's clang
        "cxx": {"compilers": ["g++", "clang++"], "flags": []},
    },
    "host-asan": {
        "cross": "", "bsp": "host", "machine": "host", "ext": "",
        "packages": ["gcc", "g++", "libc6-dev"],
        "arch": ["-D_POSIX_C_SOURCE=200809L"] + SANITIZE,
        "link": SANITIZE, "libs": [], "isa": None,
        "cxx": {"compilers": ["g++"], "flags": []},
    },
    # libFuzzer with ASan and UBSan, by the release's clang (14 on Debian
    # 12, 19 on 13)
    "host-fuzz": {
        "cross": "", "compiler": "clang", "bsp": "host", "machine": None,
        "ext": "", "packages": ["gcc", "g++", "libc6-dev", "clang",
                                "libclang-rt-dev"],
        "arch": ["-D_POSIX_C_SOURCE=200809L",
                 "-fsanitize=fuzzer-no-link,address,undefined",
                 "-fno-sanitize-recover=all", "-fno-omit-frame-pointer"],
        "link": ["-fsanitize=fuzzer,address,undefined"], "libs": [],
        "isa": None, "images": False, "fuzz": True, "check_only": True,
    },
    "ppc-e500": dict(
        PPC_BARE_METAL,
        arch=["-mcpu=powerpc"] + PPC_BARE_METAL["arch"],
        abi=["-mcpu=powerpc", "-msoft-float", "-msdata=none", "-G0"],
        bench=True, linked_budget=64 * 1024, demo_check=True,
        selftest=True),
    # The same board with code for the e500 core itself (-mcpu=8540, as
    # RTEMS's qoriq_e500 BSP compiles), soft-float: e500 scheduling and
    # instructions (isel) that generic PowerPC lacks.
    "ppc-8540": dict(
        PPC_BARE_METAL,
        arch=["-mcpu=8540"] + PPC_BARE_METAL["arch"],
        abi=["-mcpu=8540", "-msoft-float", "-msdata=none", "-G0"]),
    # The node reads NMEA through drdc_nmea_parse(), which links every
    # sentence's decoder (ten of them, about 5.4 KiB on Cortex-M3).
    "arm-cm3": dict(
        ARM_NEWLIB,
        arch=["-mcpu=cortex-m3", "-mthumb", "-mfloat-abi=soft",
              "--specs=nano.specs"],
        hard_float=["-mcpu=cortex-m4", "-mfpu=fpv4-sp-d16",
                    "-mfloat-abi=hard"],
        soft_float_libm=True,
        abi=["-mcpu=cortex-m3", "-mthumb", "-mfloat-abi=soft"],
        arm_arch="v7", bench=True, linked_budget=38 * 1024,
        demo_check=True, selftest=True, cxx=dict(BARE_METAL_CXX, bench=True)),
    # Cortex-M4F (armv7e-m, hard-float ABI): the library stays integer-
    # only, but links into applications that pass floats in FPU registers.
    # QEMU's mps2-an386 is the AN385 board with a Cortex-M4, the same
    # memory map and board code.
    "arm-cm4f": dict(
        ARM_NEWLIB, machine="arm-cm4f",
        arch=["-mcpu=cortex-m4", "-mthumb", "-mfloat-abi=hard",
              "-mfpu=fpv4-sp-d16", "--specs=nano.specs"],
        # GCC would otherwise keep 64-bit integers in FPU registers across
        # calls (vstr d8): FP instructions in an integer-only library. The
        # ABI (floats in s0-s15) is unchanged. GCC 9 and later.
        library_arch=["-mgeneral-regs-only"],
        hard_float=[],
        abi=["-mcpu=cortex-m4", "-mthumb", "-mfloat-abi=hard",
             "-mfpu=fpv4-sp-d16"],
        arm_arch="v7E-M", examples=("cortex-m", "arm-cm4f"), footprint=True),
    # Cortex-M7 (armv7e-m, double-precision FPU fpv5-d16, hard-float ABI)
    # on QEMU's mps2-an500: the Cortex-M3's board code, its own memory map
    "arm-cm7": dict(
        ARM_NEWLIB, machine="arm-cm7", ldscript="bsp/arm-cm3/link-an500.ld",
        arch=["-mcpu=cortex-m7", "-mthumb", "-mfloat-abi=hard",
              "-mfpu=fpv5-d16", "--specs=nano.specs"],
        library_arch=["-mgeneral-regs-only"],
        hard_float=[],
        abi=["-mcpu=cortex-m7", "-mthumb", "-mfloat-abi=hard",
             "-mfpu=fpv5-d16"],
        arm_arch="v7E-M", examples=("cortex-m", "arm-cm7"), footprint=True),
    # Cortex-M33 (armv8-m mainline, single-precision FPU, hard-float ABI)
    # on QEMU's mps2-an505, in the Secure state: the Cortex-M3's board
    # code, the AN505's memory map (code at 0x10000000, so not the map of
    # examples/cortex-m/link.ld: no examples)
    "arm-cm33": dict(
        ARM_NEWLIB, machine="arm-cm33", ldscript="bsp/arm-cm3/link-an505.ld",
        arch=["-mcpu=cortex-m33", "-mthumb", "-mfloat-abi=hard",
              "-mfpu=fpv5-sp-d16", "--specs=nano.specs"],
        library_arch=["-mgeneral-regs-only"],
        hard_float=[],
        abi=["-mcpu=cortex-m33", "-mthumb", "-mfloat-abi=hard",
             "-mfpu=fpv5-sp-d16"],
        arm_arch="v8-M.mainline", examples=None, footprint=True),
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
        abi=["-mcpu=cortex-m0", "-mthumb", "-mfloat-abi=soft"],
        arm_arch="v6S-M", cxx=BARE_METAL_CXX, footprint=True),
    # RISC-V rv32imac (the FPU-less RV32 MCUs: integer multiply and divide,
    # atomics, compressed), machine mode on QEMU's virt board: 16550
    # console, SiFive test finisher for the exit status. picolibc (Debian's
    # rv32imac/ilp32 multilib) for the string functions of the tests and
    # the four GCC asks of every environment. RV32IMAC code, with its
    # 16-bit compressed forms, falls between Thumb-2 and PowerPC in size:
    # the 64-bit products take a mul/mulhu pair and the carries sltu.
    "riscv32": {
        "cross": "riscv64-unknown-elf-", "bsp": "riscv32",
        "machine": "riscv32", "ext": ".elf",
        "packages": ["gcc-riscv64-unknown-elf",
                     "picolibc-riscv64-unknown-elf"],
        "arch": ["-march=rv32imac", "-mabi=ilp32", "-mcmodel=medany",
                 "-ffreestanding", "-fno-pic", "-fno-pie",
                 "-fno-stack-protector"],
        "link": ["-nostdlib", "-nostartfiles", "-static", "-Wl,--gc-sections",
                 "-Wl,--build-id=none", "-Wl,--no-warn-rwx-segments",
                 "-L" + PICOLIBC_RV32],
        # the images: picolibc's string functions and libgcc's 64-bit
        # division; an application of the library: libgcc only
        "libs": ["c", "gcc"], "library_libs": ["gcc"],
        "isa": "riscv", "hard_float": ["-march=rv32imafdc", "-mabi=ilp32d"],
        "object_format": "elf32-littleriscv",
        "headers": ["gcc:include", "gcc:include-fixed",
                    "/usr/lib/picolibc/riscv64-unknown-elf/include"],
        "hosted_bait": ["features.h", "argp.h"],
        "abi": ["-march=rv32imac", "-mabi=ilp32"],
        "bench": True, "linked_budget": 48 * 1024, "demo_check": True,
        "selftest": True, "examples": ("riscv", "riscv32"),
        "cxx": BARE_METAL_CXX,
    },
    # AVR ATmega2560 (8-bit core, 16-bit int), avr-gcc (5.4 on Debian 12,
    # 14.2 on 13) and avr-libc: where integer code hides its width
    # assumptions (1 << 20, builtins that take an unsigned int). The
    # library only, warning-free with -Werror; each part of the conformance
    # digest runs alone under simavr (fw/golden-part).
    "avr": {
        "cross": "avr-", "bsp": "avr", "machine": "avr", "ext": ".elf",
        "packages": ["gcc-avr", "avr-libc"],
        # avr-gcc 5 predates `#pragma GCC unroll` (GCC 8): it leaves those
        # loops rolled, same results
        "arch": ["-mmcu=atmega2560", "-Wno-unknown-pragmas"],
        "link": ["-Wl,--gc-sections"], "libs": [], "isa": "avr",
        "headers": ["gcc:include", "gcc:include-fixed",
                    "/usr/lib/avr/include"],
        "hosted_bait": ["features.h", "argp.h"],
        "images": False, "golden_parts": True,
    },
    # Windows x86-64 (LLP64: 32-bit long), Debian's mingw-w64 GCC in its
    # win32 thread flavour (no thread library DLL to ship) and Windows's
    # own msvcrt. The library, the drdc tool (drdc.exe) and the Unity
    # runner, which Wine runs. C99 printf and scanf (%lld, %zu) from
    # mingw's own stdio, not msvcrt's.
    "win64": {
        "cross": "x86_64-w64-mingw32-", "compiler": "gcc-win32",
        "bsp": "win64", "machine": "wine64", "ext": ".exe",
        "packages": ["gcc-mingw-w64-x86-64-win32"],
        "arch": ["-D__USE_MINGW_ANSI_STDIO=1"],
        # one self-contained .exe: libgcc linked in, no libgcc_s DLL
        "link": ["-static"], "libs": [], "isa": "x86-64", "hard_float": [],
        "object_format": "pe-x86-64", "abi": [], "tool": True,
        "demo_check": True, "selftest": True,
    },
}

# RTEMS BSPs that QEMU runs. Their test-runner is linked a second time, as
# test-runner-qemu.exe, with the BSP's linker command file changed where
# QEMU's machine differs from the board; test-runner.exe stays the
# board's (rtems-test).
#   machine    MACHINES entry
#   linkcmds   the BSP's linker command file, in its libdir
#   replace    its line to change, and the line QEMU needs
RTEMS_QEMU = {
    "powerpc/qoriq_e500": {
        "machine": "rtems-qoriq_e500",
        "linkcmds": "linkcmds.qoriq_e500",
        # the BSP's CCSR base is a P1020's; QEMU's mpc8544ds has it at
        # 0xe0000000
        "replace": ("qoriq = 0xffe00000;", "qoriq = 0xe0000000;"),
    },
}


def ldscript(name):
    """The linker script of a target's images, from the top of the tree,
    or None where its board has none."""
    t = TARGETS[name]
    return t.get("ldscript") or (("bsp/%s/link.ld" % t["bsp"])
                                 if os.path.exists(os.path.join(
                                     TOP, "bsp", t["bsp"], "link.ld"))
                                 else None)


def role(name, key):
    """A target's role or field, false where its row leaves it out
    (images: true)."""
    return TARGETS[name].get(key, key == "images")


def with_role(key):
    """The names of the targets that have a role, in table order."""
    return [n for n in TARGETS if role(n, key)]
