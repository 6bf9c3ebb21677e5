# SPDX-License-Identifier: BSD-2-Clause
"""waf tool: RTEMS BSP variants, after the conventions of RTEMS's own waf
support (rtems_waf, as used by rtems-libbsd), written for this project.

  ./waf configure --rtems=PREFIX [--rtems-tools=PREFIX] [--rtems-version=6]
                  [--rtems-archs=powerpc] [--rtems-bsps=powerpc/qoriq_e500,...]

Each BSP becomes a variant named <arch>-rtems<version>-<bsp>, built into
build/<variant>/ with the tools <tools>/bin/<arch>-rtems<version>-gcc ... and
the flags of the BSP's pkg-config file
<rtems>/lib/pkgconfig/<arch>-rtems<version>-<bsp>.pc (never hard-coded).
It installs into the BSP's own prefix: libdrdc.a into the BSP's libdir,
headers into <includedir>/drdc/, drdc.pc into <libdir>/pkgconfig/.
"""
import os
import re
import subprocess

from waflib import Logs

from waftools import images
from waftools.targets import CODEGEN, RTEMS_QEMU


def options(opt):
    g = opt.add_option_group("RTEMS options (as rtems_waf)")
    g.add_option("--rtems", dest="rtems", default=None,
                 help="prefix of the installed RTEMS kernel and BSPs")
    g.add_option("--rtems-tools", dest="rtems_tools", default=None,
                 help="prefix of the RTEMS tool suite (default: --rtems)")
    g.add_option("--rtems-version", dest="rtems_version", default="6",
                 help="RTEMS version (default: 6)")
    g.add_option("--rtems-archs", dest="rtems_archs", default="all",
                 help="comma-separated architectures to build (default: all)")
    g.add_option("--rtems-bsps", dest="rtems_bsps", default="all",
                 help="comma-separated arch/bsp names, e.g. "
                      "powerpc/qoriq_e500,powerpc/mpc55xxevb (default: all)")


def _pkg_config(pcdir, *args):
    """pkg-config confined to the RTEMS prefix's own .pc files."""
    env = dict(os.environ, PKG_CONFIG_PATH=pcdir, PKG_CONFIG_LIBDIR=pcdir)
    r = subprocess.run(["pkg-config"] + list(args), env=env,
                       capture_output=True, text=True)
    if r.returncode != 0:
        raise ValueError(r.stderr.strip() or "pkg-config %s failed" % " ".join(args))
    return r.stdout.split()


def _installed_bsps(pcdir, version):
    """(arch, bsp) of every BSP pkg-config file in the prefix."""
    pat = re.compile(r"^([a-z0-9_]+)-rtems%s-(.+)\.pc$" % re.escape(version))
    found = []
    for f in sorted(os.listdir(pcdir)):
        m = pat.match(f)
        if m:
            found.append((m.group(1), m.group(2)))
    return found


def _select(conf, installed, archs, bsps):
    if bsps != "all":
        wanted = []
        for ab in bsps.split(","):
            arch, _, bsp = ab.strip().partition("/")
            if not bsp:
                conf.fatal("--rtems-bsps: %r is not of the form arch/bsp" % ab)
            if (arch, bsp) not in installed:
                conf.fatal("RTEMS BSP %s/%s is not installed in the prefix (found: %s)"
                           % (arch, bsp, ", ".join("%s/%s" % x for x in installed)
                              or "none"))
            wanted.append((arch, bsp))
    else:
        wanted = list(installed)
    if archs != "all":
        keep = set(a.strip() for a in archs.split(","))
        wanted = [(a, b) for a, b in wanted if a in keep]
    if not wanted:
        conf.fatal("no RTEMS BSP selected (architectures %s, BSPs %s)" % (archs, bsps))
    return wanted


def configure(conf):
    """Set up one variant per selected BSP; their names in the default
    environment's RTEMS_VARIANTS."""
    o = conf.options
    conf.env.RTEMS_VARIANTS = []
    if not o.rtems:
        return
    rtems = os.path.abspath(o.rtems)
    tools = os.path.abspath(o.rtems_tools or o.rtems)
    version = o.rtems_version
    pcdir = os.path.join(rtems, "lib", "pkgconfig")
    share = os.path.join(rtems, "share", "rtems" + version)
    tbin = os.path.join(tools, "bin")
    # What rtems_waf checks before anything else, each with its own message.
    if not os.path.isdir(rtems):
        conf.fatal("--rtems: %s does not exist" % rtems)
    if not os.path.isdir(pcdir):
        conf.fatal("--rtems: %s has no lib/pkgconfig: not an installed RTEMS "
                   "(BSPs install their .pc files there)" % rtems)
    if not os.path.isdir(share):
        conf.fatal("--rtems: %s has no share/rtems%s: not an installed RTEMS %s"
                   % (rtems, version, version))
    if not os.path.isdir(tbin):
        conf.fatal("--rtems-tools: %s has no bin/ directory with the "
                   "<arch>-rtems%s-* tools" % (tools, version))
    variants = []
    base = conf.env.derive()
    for arch, bsp in _select(conf, _installed_bsps(pcdir, version),
                             o.rtems_archs, o.rtems_bsps):
        name = "%s-rtems%s-%s" % (arch, version, bsp)
        conf.setenv(name, base)
        conf.msg("RTEMS board support package", "%s/%s" % (arch, bsp), "YELLOW")
        prefix = "%s-rtems%s-" % (arch, version)
        for var, tool in (("CC", "gcc"), ("AR", "ar"), ("NM", "nm"),
                          ("OBJDUMP", "objdump"), ("SIZE", "size")):
            conf.find_program(prefix + tool, var=var, path_list=[tbin])
        conf.env.AS = conf.env.CC
        conf.load("gcc gas")
        conf.env.STLIB_MARKER = []
        conf.env.SHLIB_MARKER = []
        try:
            cflags = _pkg_config(pcdir, "--cflags", name)
            libs = _pkg_config(pcdir, "--libs", name)
            libdir = _pkg_config(pcdir, "--variable=libdir", name)
            includedir = _pkg_config(pcdir, "--variable=includedir", name)
        except ValueError as e:
            conf.fatal("pkg-config of BSP %s: %s" % (name, e))
        if not libdir or not includedir:
            conf.fatal("%s.pc defines no libdir or includedir" % name)
        # As rtems_waf: optimisation and debug flags are the project's.
        cflags = [f for f in cflags if not f.startswith(("-O", "-g"))]
        conf.env.ARCH = cflags
        conf.env.ASFLAGS = cflags + CODEGEN
        conf.env.LINKFLAGS = cflags + libs
        conf.env.RTEMS_BSP = "%s/%s" % (arch, bsp)
        conf.env.RTEMS_VERSION = version
        conf.env.LIBDIR = libdir[0]
        conf.env.INCLUDEDIR = includedir[0]
        conf.env.PREFIX = os.path.dirname(libdir[0])
        conf.check_cc(fragment="int main(void) { return 0; }\n", features="c",
                      cflags=cflags + CODEGEN,
                      msg="Compiling a program for %s/%s" % (arch, bsp))
        # The RTEMS glue (bsp/rtems) needs the Classic API header; the
        # Unity test application (test-runner.exe) needs the configuration.
        conf.env.HAVE_RTEMS_H = bool(conf.check_cc(
            fragment="#include <rtems.h>\nint main(void) { return 0; }\n",
            features="c", cflags=cflags + CODEGEN, mandatory=False,
            msg="Checking for rtems.h"))
        conf.env.HAVE_RTEMS_CONFDEFS = bool(conf.check_cc(
            fragment="#include <rtems.h>\n#include <rtems/confdefs.h>\n",
            features="c", cflags=cflags + CODEGEN, mandatory=False,
            msg="Checking for rtems/confdefs.h"))
        variants.append(name)
    conf.setenv("")
    conf.env.RTEMS_PREFIX = rtems
    conf.env.RTEMS_TOOLS = tools
    conf.env.RTEMS_VARIANTS = variants


def _qemu_linkcmds(task):
    """The BSP's linker command file with the one line QEMU needs
    changed; a BSP whose file lacks the line fails loudly."""
    line, replacement = task.generator.replace
    text = task.inputs[0].read()
    if text.count(line + "\n") != 1:
        Logs.error("%s: no line %r to change for QEMU (RTEMS_QEMU in "
                   "waftools/targets.py)" % (task.inputs[0].abspath(), line))
        return 1
    task.outputs[0].write(text.replace(line + "\n", replacement + "\n"))
    return 0


def build(bld):
    """An RTEMS BSP gets the library (wscript); its applications link it.
    With a full RTEMS installation also the Unity suites, with the glue's,
    as an RTEMS application: test-runner.exe for rtems-test on a board,
    and for a BSP of RTEMS_QEMU test-runner-qemu.exe."""
    if not bld.env.HAVE_RTEMS_CONFDEFS:
        Logs.info("%s: no rtems/confdefs.h, so no test-runner.exe"
                  % bld.variant)
        return
    unity = images.source_dir(bld, "unity")
    bld.objects(source=["fw/test-runner/main.c", "fw/test-runner/rtems_init.c",
                        "bsp/rtems/board.c", "bsp/console.c",
                        unity.find_node("unity.c")]
                + images.suite_sources(bld)
                + images.glob(bld, "tests/rtems/test_*.c"),
                target="rtems-runner", cflags=images.ours(bld.env),
                use="libdrdc",
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
