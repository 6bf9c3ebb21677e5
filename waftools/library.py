# SPDX-License-Identifier: BSD-2-Clause
"""waf tool: the library of the variant being built, libdrdc.a from
fixed/ and core/, with the RTEMS glue where an RTEMS BSP has <rtems.h>,
its headers, the C++ layer's headers, its pkg-config file and the
documents the headers cite."""
from waflib import Context

from waftools import images
from waftools.targets import LIBRARY_CODEGEN, OPTIMISE_FLAGS, optimise_kind


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
    # the C++ layer, header-only, beside the C headers' folder
    bld.install_files("${INCLUDEDIR}", images.glob(bld, "cxx/include/*.hpp"))
    glue = bool(bld.env.RTEMS_BSP and bld.env.HAVE_RTEMS_H)
    if glue:
        # RTEMS clock glue, installed beside the library
        bld.stlib(source=images.glob(bld, "bsp/rtems/drdc_rtems.c"),
                  target="drdc_rtems", name="libdrdc_rtems", use="libdrdc",
                  cflags=cflags, includes=["bsp/rtems"],
                  install_path="${LIBDIR}")
        bld.install_as("${INCLUDEDIR}/drdc/rtems.h", "bsp/rtems/drdc_rtems.h")
    name = bld.env.PC_NAME or "drdc"
    bld(features="subst", source="waftools/drdc.pc.in", target=name + ".pc",
        install_path=bld.env.PKGCONFIGDIR or "${LIBDIR}/pkgconfig",
        VERSION=Context.g_module.VERSION, NAME=name, ABI_CFLAGS=bld.env.PC_CFLAGS or "",
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
