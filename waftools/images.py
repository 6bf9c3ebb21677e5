# SPDX-License-Identifier: BSD-2-Clause
"""What the build's parts share: the flags of our files and of third-party
ones, and how a firmware image of a target is declared."""
from waftools import deps
from waftools.targets import CODEGEN, TARGETS, WARNINGS, ldscript


def ours(env):
    """Flags of every file we write, for the variant of env."""
    return (env.ARCH + CODEGEN + WARNINGS
            + (["-Werror"] if env.WERROR else []))


def theirs(env):
    """Flags of third-party files (Unity, libfixmath): our code generation,
    their warnings are not ours to fix."""
    return env.ARCH + CODEGEN + ["-w"]


def source_dir(bld, name):
    """The folder node of an upstream source of waftools/deps.py SOURCES
    (Unity, libfixmath), fetched and unpacked on first use: only the
    test images need them."""
    try:
        return bld.root.find_dir(deps.ensure_source(name))
    except deps.SetupError as e:
        bld.fatal(str(e))


def glob(bld, pattern, **kw):
    return bld.path.ant_glob(pattern, **kw)


def suite_sources(bld):
    """The Unity suites of suites.def and the golden digest; tests/rtems/
    (suites_rtems.def) needs an RTEMS kernel."""
    return (glob(bld, "tests/**/test_*.c", excl=["tests/rtems/**"])
            + glob(bld, "tests/golden/golden*.c"))


def image(bld, name, source, use, **kw):
    """A program of the variant's target: `name` plus the target's file
    ending, linked by its board's linker script where there is one, never
    installed."""
    t = TARGETS[bld.variant]
    target = name + t["ext"]
    tg = bld.program(source=source, target=target, use=use,
                     cflags=ours(bld.env) + kw.pop("extra_cflags", []),
                     install_path=None, **kw)
    script = ldscript(bld.variant)
    if script:
        bld.add_manual_dependency(bld.path.find_or_declare(target),
                                  bld.path.find_node(script))
    return tg
