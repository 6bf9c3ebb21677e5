# SPDX-License-Identifier: BSD-2-Clause
"""waf tool: the C++ layer's images, for the variant being configured or
built (a target whose row has "cxx"): cxx/include/drdc/drdc.hpp
(header-only, C++17, over the C API), its Unity runner (fw/cxx-runner, tests/cxx), the
C++ demo (fw/demo-cxx) and, where "bench" says so, the wrapper's
benchmark (fw/bench-cxx).

Each C++ compiler of the row builds its own images; the further
compilers' images get the compiler's name as a suffix
(cxx-runner-clang++).
"""
import os
import re

from waftools import images
from waftools.targets import CODEGEN, TARGETS, ldscript

# The warnings of every C++ file we write, errors on every compiler.
CXX_WARNINGS = ["-std=c++17", "-Wall", "-Wextra", "-pedantic", "-Werror",
                "-Wconversion", "-Wsign-conversion", "-Wshadow"]


def configure(conf):
    """CXX (and CXX_<n> for the further compilers); LINK_CXX is the C
    driver where there is no libstdc++."""
    t = TARGETS[conf.variant]
    spec = t.get("cxx")
    if spec is None:
        return
    first, others = spec["compilers"][0], spec["compilers"][1:]
    conf.find_program(t["cross"] + first, var="CXX")
    conf.load("gxx")
    # for tests/integration/test_cxx.py: how to run this target's images
    conf.env.CXX_QEMU = t["machine"]
    conf.env.CXX_EXT = t["ext"]
    if t["cross"]:
        conf.env.LINK_CXX = conf.env.CC
    # the further compilers come with other targets' packages (clang++:
    # host-fuzz), so a tree configured for the host alone may lack them;
    # ./waf check configures every target and test_cxx demands them all
    conf.env.CXX_OTHERS = []
    for compiler in others:
        var = "CXX_" + re.sub(r"\W", "_", compiler).upper()
        if conf.find_program(compiler, var=var, mandatory=False):
            conf.env.CXX_OTHERS += [(compiler, var)]


def build(bld):
    t = TARGETS[bld.variant]
    spec = t.get("cxx")
    if spec is None:
        return
    unity = images.source_dir(bld, "unity")
    cxxflags = (bld.env.ARCH + CODEGEN + CXX_WARNINGS + spec["flags"]
                + ["-isystem", unity.abspath()])
    includes = ["cxx/include", "tests", "bsp"]
    script = ldscript(bld.variant)
    script = script and bld.path.find_node(script)
    compilers = [("", None)] + [("-" + c, var)
                                for c, var in bld.env.CXX_OTHERS]
    for k, (suffix, var) in enumerate(compilers):
        programs = [
            ("fw/cxx-runner/cxx-runner",
             ["fw/cxx-runner/main.cpp", "tests/cxx/test_cxx.cpp"],
             "libdrdc unity bsp"),
            ("fw/demo-cxx/demo-cxx", ["fw/demo-cxx/main.cpp"],
             "libdrdc bsp"),
        ]
        if spec.get("bench") and not var:
            programs.append(("fw/bench-cxx/bench-cxx",
                             ["fw/bench-cxx/main.cpp"], "libdrdc bsp"))
        for name, source, use in programs:
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
            if script:
                bld.add_manual_dependency(
                    bld.path.find_or_declare(target), script)


def runner_images(all_envs, out):
    """harness.py specs of the C++ Unity runners: <target>-cxx[-<compiler>],
    one per compiler configure found."""
    specs = []
    for name, t in TARGETS.items():
        if "cxx" not in t or name not in (all_envs[""].TARGETS or []):
            continue
        compilers = [""] + [c for c, _ in all_envs[name].CXX_OTHERS or []]
        for compiler in compilers:
            suffix = "-" + compiler if compiler else ""
            specs.append("%s-cxx%s=%s:%s" % (
                name, suffix, t["machine"], os.path.join(
                    out, name, "fw/cxx-runner/cxx-runner" + suffix + t["ext"])))
    return specs
