#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Prove the RTEMS build path without RTEMS (run by ./waf check).

RTEMS is in no package archive reachable here, so this makes a stand-in
RTEMS 6 prefix: bin/powerpc-rtems6-* wrappers over Debian's PowerPC cross
tools, share/rtems6/, and lib/pkgconfig/powerpc-rtems6-qoriq_e500.pc with
that BSP's compiler flags. Then, exactly as an RTEMS user would:

  ./waf configure --rtems=PREFIX --rtems-bsps=powerpc/qoriq_e500
  ./waf install

(in a build directory of its own), checks that the installed tree holds
exactly libdrdc.a, the public headers and drdc.pc, that
`pkg-config --cflags --libs drdc` works, and links the installed library
into the bare-metal PowerPC test-runner image (objects of build/ppc-e500)
(the objects listed in build/ppc-e500/fw/test-runner/objects.txt) as
build/rtems-standin/test-runner.elf, which ./waf check then runs.

What a real RTEMS run adds: the RTEMS compiler's own specs and start files
(-qrtems), the BSP's libraries, and the test image under RTEMS itself.
"""
import glob
import os
import shutil
import subprocess
import sys

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
VERSION = "6"
ARCH, BSP = "powerpc", "qoriq_e500"
CROSS = "powerpc-linux-gnu-"
# Compiler flags of RTEMS 6's powerpc/qoriq_e500 BSP configuration (e500
# core, EABI, SVR4 small data, software floating point).
BSP_CFLAGS = ("-mcpu=8540 -meabi -msdata=sysv -fno-common -msoft-float "
              "-D__ppc_generic")

GCC_WRAPPER = """#!/bin/sh
# Stand-in for RTEMS {ver}'s {arch}-rtems{ver}-gcc, made by ./waf check:
# Debian's cross compiler with the defaults of an RTEMS tool suite (no PIE,
# no stack protector, __rtems__ defined). -qrtems selects RTEMS start
# files, which a stand-in does not have. Debian's cross compiler has no C
# library headers (an RTEMS tool suite has newlib's): the stand-in compiles
# freestanding with the compiler's own headers and the BSP's (the stand-in
# <rtems.h> and <time.h>), so no host header can leak in.
for a do
  shift
  [ "$a" = -qrtems ] || set -- "$@" "$a"
done
exec {cross}gcc -D__rtems__ -fno-pic -fno-pie -fno-stack-protector \\
  -ffreestanding -nostdinc -isystem {gcc_include} "$@"
"""
TOOL_WRAPPER = """#!/bin/sh
# Stand-in for RTEMS {ver}'s {arch}-rtems{ver}-{tool}, made by ./waf check.
exec {cross}{tool} "$@"
"""
# The few declarations of the RTEMS Classic API that the glue of bsp/rtems
# uses, as the RTEMS 6 manual documents them, so that the glue compiles in
# the stand-in. A real BSP installs the real <rtems.h>; the stand-in has no
# <rtems/confdefs.h>, so no RTEMS test application is built here.
RTEMS_H = """/* Stand-in for <rtems.h> made by libdrdc-fx's ./waf check: only the
 * Classic API declarations that bsp/rtems/drdc_rtems.c uses. */
#ifndef STANDIN_RTEMS_H
#define STANDIN_RTEMS_H
#include <stdint.h>
typedef enum {{ RTEMS_SUCCESSFUL = 0, RTEMS_INVALID_CLOCK = 20,
               RTEMS_NOT_DEFINED = 11, RTEMS_INVALID_ADDRESS = 9 }} rtems_status_code;
typedef uint32_t rtems_interval;
typedef struct {{
  uint32_t year;
  uint32_t month;
  uint32_t day;
  uint32_t hour;
  uint32_t minute;
  uint32_t second;
  uint32_t ticks;
}} rtems_time_of_day;
rtems_status_code rtems_clock_get_tod(rtems_time_of_day *time_of_day);
rtems_status_code rtems_clock_set(const rtems_time_of_day *time_of_day);
rtems_interval rtems_clock_get_ticks_per_second(void);
#endif
"""

# newlib's struct timespec, as RTEMS 6 has it (a 64-bit time_t), the one
# POSIX type of <time.h> that the glue uses.
TIME_H = """/* Stand-in for newlib's <time.h> made by libdrdc-fx's ./waf check: only
 * what bsp/rtems/drdc_rtems.c uses. */
#ifndef STANDIN_TIME_H
#define STANDIN_TIME_H
#include <stdint.h>
typedef int64_t time_t;
struct timespec {{
  time_t tv_sec;
  long tv_nsec;
}};
#endif
"""

BSP_PC = """prefix={prefix}
exec_prefix=${{prefix}}/{arch}-rtems{ver}
includedir=${{exec_prefix}}/{bsp}/lib/include
libdir=${{exec_prefix}}/{bsp}/lib

Name: {arch}-rtems{ver}-{bsp}
Version: {ver}
Description: RTEMS BSP {arch}-rtems{ver}-{bsp} (stand-in made by libdrdc-fx's ./waf check)
Libs: -L${{libdir}} -qrtems -B${{libdir}} -Wl,--gc-sections
Cflags: {cflags} -isystem${{includedir}} -ffunction-sections -fdata-sections
"""


def make_prefix(prefix):
    shutil.rmtree(prefix, ignore_errors=True)
    os.makedirs(os.path.join(prefix, "bin"))
    os.makedirs(os.path.join(prefix, "share", "rtems" + VERSION))
    os.makedirs(os.path.join(prefix, "lib", "pkgconfig"))
    include = os.path.join(prefix, "%s-rtems%s" % (ARCH, VERSION), BSP, "lib", "include")
    os.makedirs(include)
    for name, text in (("rtems.h", RTEMS_H), ("time.h", TIME_H)):
        with open(os.path.join(include, name), "w") as f:
            f.write(text.format())
    gcc_include = subprocess.run([CROSS + "gcc", "-print-file-name=include"],
                                 check=True, capture_output=True,
                                 text=True).stdout.strip()
    kw = dict(ver=VERSION, arch=ARCH, cross=CROSS, bsp=BSP, prefix=prefix,
              cflags=BSP_CFLAGS, gcc_include=gcc_include)
    tools = {"gcc": GCC_WRAPPER.format(**kw)}
    for tool in ("ar", "as", "ld", "nm", "objdump", "objcopy", "size", "ranlib"):
        tools[tool] = TOOL_WRAPPER.format(tool=tool, **kw)
    for tool, text in tools.items():
        path = os.path.join(prefix, "bin", "%s-rtems%s-%s" % (ARCH, VERSION, tool))
        with open(path, "w") as f:
            f.write(text)
        os.chmod(path, 0o755)
    with open(os.path.join(prefix, "lib", "pkgconfig", "%s-rtems%s-%s.pc"
                           % (ARCH, VERSION, BSP)), "w") as f:
        f.write(BSP_PC.format(**kw))


def waf(args, lock, out=None):
    env = dict(os.environ, WAFLOCK=lock)
    cmd = [sys.executable, os.path.join(TOP, "waf")] + args
    if out:
        cmd.append("--out=" + out)
    print("rtems-standin: " + " ".join(args), flush=True)
    subprocess.run(cmd, cwd=TOP, env=env, check=True, stdout=subprocess.DEVNULL)


def expected_install():
    """What ./waf install puts under an RTEMS BSP's lib/ (with the glue),
    sorted: the libraries, the public headers (C and C++) and drdc.pc."""
    headers = sorted(os.path.basename(h) for h in
                     glob.glob(os.path.join(TOP, "fixed/include/drdc/*.h"))
                     + glob.glob(os.path.join(TOP, "core/include/drdc/*.h")))
    return sorted(["libdrdc.a", "libdrdc_rtems.a", "pkgconfig/drdc.pc",
                   "include/drdc/rtems.h"]
                  + ["include/drdc/" + h for h in headers]
                  + ["include/drdc/" + os.path.basename(h) for h in
                     glob.glob(os.path.join(TOP, "cxx/include/drdc/*.hpp"))])


def installed_tree(bspdir):
    return sorted(os.path.relpath(p, bspdir) for p in
                  glob.glob(os.path.join(bspdir, "**"), recursive=True)
                  if os.path.isfile(p))


def main():
    build = os.path.join(TOP, "build")
    work = os.path.join(build, "rtems-standin")
    prefix = os.path.join(work, "prefix")
    make_prefix(prefix)
    lock = ".lock-waf-rtems-standin"
    waf(["configure", "--rtems=" + prefix, "--rtems-version=" + VERSION,
         "--rtems-bsps=%s/%s" % (ARCH, BSP)], lock, out=os.path.join(work, "build"))
    waf(["install"], lock)

    bspdir = os.path.join(prefix, "%s-rtems%s" % (ARCH, VERSION), BSP, "lib")
    want = expected_install()
    # everything under the BSP's lib/ except the stand-in's own headers
    got = [p for p in installed_tree(bspdir)
           if p not in ("include/rtems.h", "include/time.h")]
    if got != want:
        sys.exit("rtems-standin: installed tree differs:\n  got  %s\n  want %s"
                 % (got, want))
    print("rtems-standin: installed %d files into %s" % (len(got), bspdir))

    env = dict(os.environ, PKG_CONFIG_PATH=os.path.join(bspdir, "pkgconfig"))
    flags = subprocess.run(["pkg-config", "--cflags", "--libs", "drdc"], env=env,
                           check=True, capture_output=True, text=True).stdout.split()
    # the RTEMS glue needs an RTEMS kernel to link; the bare-metal image
    # takes the library alone
    flags = [f for f in flags if f != "-ldrdc_rtems"]
    print("rtems-standin: pkg-config --cflags --libs drdc: " + " ".join(flags))

    # Link the installed library into the bare-metal test image.
    ppc = os.path.join(build, "ppc-e500")
    listing = os.path.join(ppc, "fw", "test-runner", "objects.txt")
    if not os.path.exists(listing):
        sys.exit("rtems-standin: %s missing: build ppc-e500 first" % listing)
    with open(listing) as f:
        objects = f.read().split()
    image = os.path.join(work, "test-runner.elf")
    link = ([CROSS + "gcc", "-mcpu=powerpc", "-msoft-float", "-nostdlib", "-static",
             "-no-pie", "-Wl,--gc-sections", "-Wl,--build-id=none",
             "-Wl,--no-warn-rwx-segments",
             "-Wl,-T," + os.path.join(TOP, "bsp", "ppc-e500", "link.ld")]
            + objects + [f for f in flags if not f.startswith("-I")]
            + ["-lgcc", "-o", image])
    subprocess.run(link, check=True)
    print("rtems-standin: linked %s against the installed libdrdc.a" % image)


if __name__ == "__main__":
    main()
