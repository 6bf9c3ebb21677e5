# SPDX-License-Identifier: BSD-2-Clause
"""waf tool: the library of the variant being built, libdrdc.a from
fixed/ and core/, with the RTEMS glue where an RTEMS BSP has <rtems.h>,
its headers, the C++ layer's headers, its pkg-config file and the
documents the headers cite."""
import os
import re
import subprocess

from waflib import Context, Logs

from waftools import images
from waftools.targets import (LIBRARY_CODEGEN, OPTIMISE_FLAGS, TARGETS,
                              optimise_kind)


def build(bld):
    """libdrdc.a, its headers and drdc.pc, installed under the variant's
    LIBDIR and INCLUDEDIR. Each object gets a call graph with stack usage
    (.ci) for the footprint report (tools/gates/footprint.py), each file
    compiled for speed or size as the footprint policy says."""
    cflags = images.ours(bld.env) + (bld.env.LIBRARY_ARCH or [])
    gcc = bld.env.CC_NAME == "gcc"
    # call graphs: GCC 10 and later (not avr-gcc 5, not clang)
    graphs = gcc and int((bld.env.CC_VERSION or ("0",))[0]) >= 10
    lib_cflags = cflags + LIBRARY_CODEGEN + (["-fcallgraph-info=su"]
                                             if graphs else [])
    sources = images.glob(bld, "fixed/**/*.c") + images.glob(bld, "core/**/*.c")
    includes = ["fixed/internal", "fixed/include", "core/include"]
    by_kind = {}
    for node in sources:
        by_kind.setdefault(optimise_kind(node.path_from(bld.path)),
                           []).append(node)
    # the library's own task compiles for speed; the other kinds are object
    # groups it archives with its own
    others = sorted(k for k in by_kind if k != "speed")
    for kind in others:
        # idx=1: objects named x.c.1.o, as those of the library's own task;
        # GCC's flags: clang (the fuzz build) keeps its own
        bld.objects(source=by_kind[kind], target="drdc_" + kind, idx=1,
                    cflags=lib_cflags + (OPTIMISE_FLAGS[kind] if gcc else []),
                    includes=includes)
    bld.stlib(source=by_kind.get("speed", []), target="drdc",
              name="libdrdc", idx=1, cflags=lib_cflags, includes=includes,
              use=["drdc_" + kind for kind in others],
              export_includes=["fixed/include", "core/include"],
              install_path="${LIBDIR}")
    bld.install_files("${INCLUDEDIR}/drdc",
                      images.glob(bld, "fixed/include/drdc/*.h")
                      + images.glob(bld, "core/include/drdc/*.h"))
    # the C++ layer, header-only, with the C headers
    bld.install_files("${INCLUDEDIR}/drdc",
                      images.glob(bld, "cxx/include/drdc/*.hpp"))
    glue = bool(bld.env.RTEMS_BSP and bld.env.HAVE_RTEMS_H)
    if glue:
        # RTEMS clock glue, installed beside the library
        bld.stlib(source=images.glob(bld, "bsp/rtems/drdc_rtems.c"),
                  target="drdc_rtems", name="libdrdc_rtems", use="libdrdc",
                  cflags=cflags, includes=["bsp/rtems"],
                  install_path="${LIBDIR}")
        bld.install_as("${INCLUDEDIR}/drdc/rtems.h", "bsp/rtems/drdc_rtems.h")
    # drdc-<target>.pc (drdc.pc for an RTEMS BSP) names every folder from
    # its own place (${pcfiledir}), so a moved install keeps working; the
    # ABI flags are a variable the user reads, never imposed in Cflags
    name = bld.env.PC_NAME or "drdc"
    pcdir = bld.env.PKGCONFIGDIR or os.path.join(bld.env.LIBDIR, "pkgconfig")
    prefix = bld.env.PREFIX
    bld(features="subst", source="waftools/drdc.pc.in", target=name + ".pc",
        install_path=pcdir, VERSION=Context.g_module.VERSION, NAME=name,
        ABI_CFLAGS=bld.env.PC_CFLAGS or "",
        REL_PREFIX=os.path.relpath(prefix, pcdir),
        REL_LIBDIR=os.path.relpath(bld.env.LIBDIR, prefix),
        REL_INCLUDEDIR=os.path.relpath(bld.env.INCLUDEDIR, prefix),
        EXTRA_LIBS=" -ldrdc_rtems" if glue else "",
        LIBS_AFTER=bld.env.PC_LIBS or "")
    if bld.env.PC_NAME and bld.env.INSTALLABLE:
        cmake_package(bld)
    if bld.env.DOCDIR:
        # the documents the headers cite as docs/<name>.md
        bld.install_files("${DOCDIR}/docs",
                          ["docs/conventions.md", "docs/accuracy.md",
                           "docs/performance.md", "docs/bad-input.md"])
        # the example application of README's "Use it in your firmware"
        examples = bld.path.find_dir("examples")
        bld.install_files("${PREFIX}/share/drdc/examples",
                          examples.ant_glob("**/*"), cwd=examples,
                          relative_trick=True)


def abi_macros(bld):
    """The predefined macros that decide an ABI (cmake/drdc_abi.cmake's
    DRDC_ABI_MACROS: one list for both builds)."""
    text = bld.path.find_node("cmake/drdc_abi.cmake").read()
    names = re.search(r"set\(DRDC_ABI_MACROS\s+([^)]*)\)", text).group(1)
    return names.split()


def _variant_file(task):
    """lib/cmake/drdc/drdc-<target>.cmake: the variant's library and the
    ABI its compiler gives with its ABI flags."""
    env = task.env
    empty = task.outputs[0].parent.make_node("abi_empty.c")
    empty.write("")
    r = subprocess.run(env.CC + task.generator.abi + ["-dM", "-E",
                                                      empty.abspath()],
                       capture_output=True, text=True)
    if r.returncode != 0:
        Logs.error("%s -dM -E: %s" % (env.CC[0], r.stderr))
        return 1
    defines = dict(re.findall(r"^#define (\S+) ?(.*)$", r.stdout, re.M))
    abi = ";".join("%s=%s" % (n, defines[n].strip())
                   for n in task.generator.macros if n in defines)
    name = task.generator.variant_name
    libs = " ".join(env.PC_LIBS.split()).replace("-l", "")
    task.outputs[0].write(
        "# written by ./waf install of libdrdc-fx: the variant %s\n"
        "list(APPEND DRDC_INSTALLED_VARIANTS %s)\n"
        "set(DRDC_VARIANT_%s_LIBRARY \"lib/%s/libdrdc.a\")\n"
        "set(DRDC_VARIANT_%s_ABI \"%s\")\n"
        "set(DRDC_VARIANT_%s_LIBS \"%s\")\n"
        % (name, name, name, name, name, abi, name, libs))
    return 0


def cmake_package(bld):
    """find_package(drdc) of the install: the package's files, shared by
    every target, and this target's variant file."""
    name = bld.variant
    cmakedir = "${PREFIX}/lib/cmake/drdc"
    variant = bld.path.find_or_declare("drdc-%s.cmake" % name)
    bld(rule=_variant_file, target=variant, abi=TARGETS[name]["abi"],
        macros=abi_macros(bld), variant_name=name,
        vars=["CC", "PC_LIBS"])
    version = Context.g_module.VERSION
    bld(features="subst", source="cmake/drdcConfigVersion.cmake.in",
        target="drdcConfigVersion.cmake", VERSION=version,
        VERSION_MAJOR=version.split(".")[0],
        VERSION_MINOR=version.split(".")[1])
    bld.install_files(cmakedir, [variant, "drdcConfigVersion.cmake",
                                 "cmake/drdcConfig.cmake",
                                 "cmake/drdc_abi.cmake"])

