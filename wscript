# SPDX-License-Identifier: BSD-2-Clause
"""Build of libdrdc-fx: one waf variant per target of the one table of
targets (waftools/targets.py).

  ./waf configure [--with-targets=T,...]   set up and configure targets
  ./waf build_<target>, clean_<target>, install_<target>   one target
  ./waf install  every configured RTEMS BSP into its prefix, or, without
                 RTEMS, every configured target into --prefix
                 (lib/<target>/, lib/pkgconfig/drdc-<target>.pc)
  ./waf demo, check, bench, docs, fuzz, serve   (waftools/commands.py)

Here: options, configure, and the images' builds. The waf tools of
waftools/, loaded by name, add the library itself (library), the RTEMS
BSP variants (rtems), the C++ layer's images (cxx_layer), the
conformance digest's programs (golden), the commands (commands) and the
check's steps (checks).
"""
import os

from waflib import Build, ConfigSet, Configure, Logs, Options

from waftools import deps, headers, images, toolchains, variants
from waftools.targets import CODEGEN, DEFAULT_TARGET, TARGETS, ldscript, role

top = "."
out = "build"

APPNAME = "drdc"
VERSION = "0.1.0"  # also in core/include/drdc/version.h

# Re-run configure by itself when it has not run or a wscript changed,
# with the options it was last given ("clobber"; True would drop them,
# --rtems among them).
Configure.autoconfig = "clobber"

# Images that test the QEMU harness itself: qemu/selftest.c built once per
# kind (the number is SELFTEST_KIND) on each target of role selftest.
SELFTEST_KINDS = {"pass": 1, "fail": 2, "hang": 3, "crash": 4,
                  "flood": 5, "fake-summary": 6, "silent": 7}


def options(opt):
    opt.load("compiler_c")
    opt.load("waftools.rtems waftools.commands waftools.checks "
             "waftools.variants")
    opt.add_option("--with-targets", dest="with_targets", default=None,
                   help="configure: the targets to set up and build, comma "
                   "separated (default: %s; ./waf check adds every other, "
                   "./waf demo %s)" % (", ".join(_default_targets()),
                                       DEFAULT_TARGET))
    opt.add_option("--werror", action="store_true", default=False,
                   dest="werror", help="configure: warnings are errors in "
                   "RTEMS BSP builds too (always in the targets' builds)")


def _register_variant_commands(names):
    """build_<v>, clean_<v>, install_<v> for each variant name."""
    for name in names:
        for base in (Build.BuildContext, Build.CleanContext,
                     Build.InstallContext):
            cmd = base.__name__.replace("Context", "").lower() + "_" + name
            type(base.__name__ + "_" + name, (base,),
                 {"cmd": cmd, "variant": name})


def init(ctx):
    # RTEMS BSP variants and custom targets exist only once configured:
    # register their commands from the configuration cache (as rtems_waf
    # does), and the custom targets' rows in the table.
    try:
        lock = ConfigSet.ConfigSet(Options.lockfile)
        cache = ConfigSet.ConfigSet(os.path.join(lock.out_dir, "c4che",
                                                 "_cache.py"))
    except (EnvironmentError, AttributeError):
        return
    _register_variant_commands((cache.RTEMS_VARIANTS or [])
                               + variants.load(cache))


def _default_targets():
    """What a plain ./waf configure sets up: all but the check-only."""
    return [n for n in TARGETS if not role(n, "check_only")]


def _selected_targets(conf):
    if conf.options.with_targets is None:
        return _default_targets()
    names = [n for n in conf.options.with_targets.split(",") if n]
    unknown = [n for n in names if n not in TARGETS]
    if unknown or not names:
        conf.fatal("--with-targets: unknown %s; choose from %s"
                   % (", ".join(unknown) or "(none)", ", ".join(TARGETS)))
    return [n for n in TARGETS if n in names]


def _configure_target(conf, name, t, prefix):
    conf.setenv(name)
    conf.msg("Target", name)
    compiler = t.get("compiler", "gcc")
    if "cc_command" in t:
        conf.env.CC = t["cc_command"]
    for var, tool in (("CC", compiler), ("AR", "ar"), ("OBJDUMP", "objdump"),
                      ("NM", "nm"), ("SIZE", "size")):
        if not conf.env[var]:
            conf.find_program(t["cross"] + tool, var=var)
    conf.env.AS = conf.env.CC
    conf.load(("clang" if compiler.startswith("clang") else "gcc") + " gas")
    # what this target's results were computed with, in the build log and
    # in ./waf check's summary
    conf.env.CC_RELEASE = toolchains.compiler(conf.env.CC)
    conf.msg("Compiler of %s" % name, "%s %s" % (
        os.path.basename(conf.env.CC[0]), conf.env.CC_RELEASE))
    # the table's "ext" names the programs (waf would add .exe for Windows
    # by itself)
    conf.env.cprogram_PATTERN = "%s"
    if t["cross"]:
        # static images only: no -Bstatic/-Bdynamic switching
        conf.env.STLIB_MARKER = []
        conf.env.SHLIB_MARKER = []
    arch = list(t["arch"])
    if "headers" in t:
        arch += headers.system_includes(conf, name, t)
    conf.env.ARCH = arch
    conf.env.LIBRARY_ARCH = t.get("library_arch", [])
    conf.env.ASFLAGS = arch + CODEGEN
    conf.env.LINKFLAGS = arch + t["link"]
    if ldscript(name):
        # its folder searched too: a script may INCLUDE its board's common
        # part
        script = conf.path.find_node(ldscript(name)).abspath()
        conf.env.LINKFLAGS += ["-Wl,-L," + os.path.dirname(script),
                               "-Wl,-T," + script]
    conf.env.LIB = t["libs"]
    conf.env.WERROR = True
    # Install layout: one library directory and one pkg-config name a
    # target, so that targets installed into one prefix never clobber each
    # other; the headers are the same for all. drdc-<target>.pc names its
    # directories relative to its prefix, so that pkg-config
    # --define-variable=prefix=... can move them.
    conf.env.PREFIX = prefix
    conf.env.LIBDIR = os.path.join(prefix, "lib", name)
    conf.env.PKGCONFIGDIR = os.path.join(prefix, "lib", "pkgconfig")
    conf.env.PC_PREFIX = prefix
    conf.env.PC_LIBDIR = "${prefix}/lib/" + name
    conf.env.PC_INCLUDEDIR = "${prefix}/include"
    conf.env.PC_NAME = "drdc-" + name
    conf.env.PC_CFLAGS = " ".join(t.get("abi") or [])
    conf.env.PC_LIBS = "".join(" -l" + lib
                               for lib in t.get("library_libs", t["libs"]))
    conf.env.INCLUDEDIR = os.path.join(prefix, "include")
    conf.env.BINDIR = os.path.join(prefix, "bin")
    conf.env.DOCDIR = os.path.join(prefix, "share", "doc", "drdc")
    conf.env.INSTALLABLE = t.get("abi") is not None
    conf.check_cc(fragment="int main(void) { return 0; }\n",
                  features="c", cflags=arch,
                  msg="Checking that %s compiles" % name)
    if "hosted_bait" in t:
        headers.check_hermetic(conf, name, t)
    conf.load("waftools.cxx_layer")


def configure(conf):
    prefix = os.path.abspath(conf.options.prefix)
    # The table's rows name their compilers and flags: waf's tools must not
    # take the environment's CC or CFLAGS for them (custom variants do,
    # waftools/variants.py).
    conf.environ = {k: v for k, v in os.environ.items()
                    if k not in ("CC", "CFLAGS", "CPPFLAGS", "LDFLAGS",
                                 "LINKFLAGS", "AR")}
    custom = variants.configure(conf)
    targets = _selected_targets(conf) + list(custom)
    pkgs = deps.packages([p for n in targets for p in TARGETS[n]["packages"]],
                         # pkg-config reads an RTEMS BSP's flags
                         ["rtems"] if conf.options.rtems else [])
    # the compilers only, and only where missing: the upstream sources of
    # the test images come with the builds that need them
    try:
        deps.ensure(pkgs)
    except deps.SetupError as e:
        conf.fatal(str(e))
    for name in targets:
        _configure_target(conf, name, TARGETS[name], prefix)
    # The RTEMS BSP variants derive from the default environment (the
    # targets' own are set above).
    conf.setenv("")
    conf.env.TARGETS = targets
    conf.env.CUSTOM_TARGETS = custom
    conf.env.WERROR = conf.options.werror
    for what, version in toolchains.runners():
        conf.msg(what, version)
    conf.load("waftools.rtems")


def _build_baits(bld, t):
    """Objects the gates must reject, proof that each bites: a name
    without drdc_ (symcheck) and floating point (intcheck)."""
    arch = bld.env.ARCH
    bld.stlib(source=["tests/symcheck/symbol_bait.c"], target="bait-symbols",
              cflags=arch + CODEGEN + ["-w"], idx=3, install_path=None)
    if t.get("isa"):
        bld.stlib(source=["tests/intcheck/float_bait.c"], target="bait-soft",
                  cflags=arch + CODEGEN + ["-w"], idx=1, install_path=None)
        if t.get("hard_float"):
            bld.stlib(source=["tests/intcheck/float_bait.c"],
                      target="bait-hard", idx=2, install_path=None,
                      cflags=[f for f in arch if "float" not in f]
                      + t["hard_float"] + CODEGEN + ["-w"])


def _build_fuzzers(bld):
    """libFuzzer targets (tools/gates/fuzz.py), one program per file."""
    for src in images.glob(bld, "tests/fuzz/fuzz_*.c"):
        # fuzz_tool drives the host tool's own command code
        tool = ([n for n in images.glob(bld, "tools/drdc/*.c")
                 if n.name != "main.c"] if src.name == "fuzz_tool.c" else [])
        bld.program(source=[src] + tool, target="tests/fuzz/" + src.name[:-2],
                    use="libdrdc", cflags=images.ours(bld.env),
                    includes=["tools/drdc"], install_path=None, idx=100)


def _build_third_party(bld):
    """Unity and libfixmath, from the set-up's sources in .deps/."""
    unity = images.source_dir(bld, "unity")
    bld.objects(source=[unity.find_node("unity.c")], target="unity",
                cflags=images.theirs(bld.env),
                includes=[unity, "tests", "bsp"],
                defines=["UNITY_INCLUDE_CONFIG_H"],
                export_includes=[unity, "tests"],
                export_defines=["UNITY_INCLUDE_CONFIG_H"])
    fixmath = images.source_dir(bld, "libfixmath")
    # fix16_str.c (text conversion) needs the hosted <ctype.h>
    bld.stlib(source=fixmath.ant_glob("fix16*.c fract32.c uint32.c",
                                      excl=["fix16_fft.c", "fix16_str.c"]),
              target="fixmath", cflags=images.theirs(bld.env),
              includes=[fixmath], install_path=None,
              # no 32-80 KiB result caches: no global state, like ours
              defines=["FIXMATH_NO_CACHE"],
              export_defines=["FIXMATH_NO_CACHE"])


def _build_images(bld, t):
    """The test runner, the demo, the benchmark, the harness's self-tests
    and the host's tools."""
    ours = images.ours(bld.env)
    # Everything of the runner but the golden part that a broken port
    # changes (test-runner-broken, host only) is compiled once for both.
    golden_geo = bld.path.find_node("tests/golden/golden_geo.c")
    bld.objects(source=["fw/test-runner/main.c"]
                + [n for n in images.suite_sources(bld) if n != golden_geo],
                target="runner-suites", cflags=ours, includes=["tests"],
                use="libdrdc unity bsp")
    runner = images.image(bld, "fw/test-runner/test-runner", [golden_geo],
                          "runner-suites libdrdc unity bsp",
                          includes=["tests"])
    # The runner's object files, one path a line, so the same image can be
    # linked against an installed libdrdc.a (tests/integration/
    # rtems_standin.py).
    runner.post()
    bld(rule=lambda task: task.outputs[0].write(
            "".join(n.abspath() + "\n" for n in task.inputs)),
        source=list(runner.link_task.inputs),
        target="fw/test-runner/objects.txt")
    # the demo's link map: what of the library an application really links
    # (tools/gates/footprint.py, docs/performance.md)
    demo_map = bld.path.find_or_declare("fw/demo/demo.map").abspath()
    images.image(bld, "fw/demo/demo", images.glob(bld, "fw/demo/*.c"),
                 "libdrdc bsp", linkflags=[] if t["machine"] == "host"
                 else ["-Wl,-Map=" + demo_map])
    if t.get("bench") or t.get("footprint"):
        # what a GGA-only node links of the NMEA parser, against every
        # sentence's decoder (tools/gates/bench.py reads both maps)
        for every in (1, 0):
            name = "fw/nmea-size/nmea-" + ("every" if every else "gga")
            images.image(bld, name, ["fw/nmea-size/main.c"], "libdrdc bsp",
                         defines=["NMEA_SIZE_EVERY=%d" % every],
                         idx=500 + every, linkflags=[
                             "-Wl,-Map=" + bld.path.find_or_declare(
                                 name + ".map").abspath()])
    if t.get("bench"):
        # soft-float double baselines where the toolchain has soft-float
        libm = bool(t.get("soft_float_libm"))
        fixmath = images.source_dir(bld, "libfixmath")
        images.image(bld, "fw/bench/bench", images.glob(bld, "fw/bench/*.c"),
                     "libdrdc bsp fixmath",
                     defines=["BENCH_DOUBLE=%d" % libm],
                     lib=t["libs"] + (["m"] if libm else []),
                     # third-party header: its warnings are not ours to fix
                     extra_cflags=["-isystem", fixmath.abspath()])
    if t.get("selftest"):
        for kind, number in SELFTEST_KINDS.items():
            images.image(bld, "qemu/selftest-" + kind, ["qemu/selftest.c"],
                         "unity bsp", defines=["SELFTEST_KIND=%d" % number],
                         idx=number)
    if bld.variant == "host":
        # the library's own results for the plots of docs/accuracy.md
        bld.program(source=["tools/accuracy/sample.c"],
                    target="accuracy-sample", use="libdrdc", cflags=ours,
                    install_path=None)


def build(bld):
    if not bld.variant:
        # ./waf build (and ./waf): every configured target and RTEMS BSP,
        # one after the other
        from waftools.commands import run_now
        run_now(["build_" + n for n in (bld.env.TARGETS or [])
                 + (bld.env.RTEMS_VARIANTS or [])])
        return
    if bld.variant not in (bld.all_envs[""].TARGETS or []) \
            and not bld.env.RTEMS_BSP:
        bld.fatal("target %s is not configured (configured: %s): "
                  "./waf configure sets up every target, or name it in "
                  "--with-targets"
                  % (bld.variant, ", ".join(bld.all_envs[""].TARGETS or [])))
    bld.load("waftools.library")
    # An install is the library, its headers and the host tool: no test
    # build, so no test tool's set-up or download either.
    installing = isinstance(bld, Build.InstallContext)
    if bld.env.RTEMS_BSP:
        if not installing:
            bld.load("waftools.rtems")
        return
    t = TARGETS[bld.variant]
    if t.get("tool"):
        bld.program(source=images.glob(bld, "tools/drdc/*.c"),
                    target="drdc" + t["ext"], use="libdrdc",
                    cflags=images.ours(bld.env))
    if installing:
        return
    _build_baits(bld, t)
    if t.get("fuzz"):
        _build_fuzzers(bld)
    if t.get("images", True) or t.get("golden_parts"):
        # the board
        bld.objects(source=["bsp/console.c"]
                    + images.glob(bld, "bsp/%s/*.c" % t["bsp"])
                    + images.glob(bld, "bsp/%s/*.S" % t["bsp"]),
                    target="bsp", cflags=images.ours(bld.env),
                    includes=["bsp"], export_includes=["bsp"])
    if t.get("images", True):
        _build_third_party(bld)
        _build_images(bld, t)
        bld.load("waftools.cxx_layer")
    bld.load("waftools.golden")


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
        from waftools.commands import run_now
        run_now(["install_" + v for v in variants])

    # configure first where it has not run or a wscript changed, as the
    # build commands do
    from waflib import Scripting
    execute = Scripting.autoconfigure(execute)
