# SPDX-License-Identifier: BSD-2-Clause
"""waf tool: custom variants, a firmware team's own CPU and ABI flags on
a row of the table of targets.

  ./waf configure --variant "NAME=BASE:FLAGS" [--variant ...]

makes a target NAME: the row BASE of waftools/targets.py with its ABI
flags replaced by FLAGS (its other flags, its board code and roles kept)
and FLAGS recorded as the ABI of its install (drdc-NAME.pc,
lib/cmake/drdc/drdc-NAME.cmake). The environment's CC, when set, is the
compiler of the custom variants (its binutils found beside it) and
CFLAGS are added to their flags; the table's targets never take either.
A custom variant gets the checks of any target: the integer-only and
symbol gates of ./waf check run on every configured target.

  ./waf configure --prefix=/opt/drdc --with-targets=host \\
      --variant "m7=arm-cm4f:-mcpu=cortex-m7 -mthumb -mfloat-abi=hard -mfpu=fpv5-d16"
  ./waf install
"""
import os
import re
import shlex

from waftools.targets import TARGETS

NAME = re.compile(r"^[a-z0-9][a-z0-9_-]*$")


def options(opt):
    opt.add_option("--variant", action="append", default=[], dest="variants",
                   metavar="NAME=BASE:FLAGS",
                   help="configure: a custom target NAME, the row BASE of "
                   "waftools/targets.py with FLAGS as its ABI flags "
                   "(repeatable; CC and CFLAGS of the environment apply to "
                   "these)")


def derive(conf, spec):
    """(name, row) of one --variant NAME=BASE:FLAGS."""
    name, _, rest = spec.partition("=")
    base, _, flags = rest.partition(":")
    if not NAME.match(name) or base not in TARGETS or not flags.strip():
        conf.fatal("--variant %r: expected NAME=BASE:FLAGS, NAME of "
                   "[a-z0-9_-], BASE one of %s, FLAGS the CPU and ABI flags"
                   % (spec, ", ".join(TARGETS)))
    if name in TARGETS:
        conf.fatal("--variant %s: the table has a target of that name" % name)
    row = dict(TARGETS[base])
    if row.get("abi") is None:
        conf.fatal("--variant %s: %s is a test build; take a row that "
                   "installs" % (name, base))
    abi = shlex.split(flags)
    # the base's flags that are not its ABI (specs, freestanding, ...)
    row["arch"] = [f for f in row["arch"] if f not in row["abi"]] + abi \
        + shlex.split(os.environ.get("CFLAGS", ""))
    row["abi"] = abi
    cc = os.environ.get("CC")
    if cc:
        command = shlex.split(cc)
        row["cc_command"] = command
        tool = os.path.basename(command[0])
        row["cross"] = os.path.join(os.path.dirname(command[0]),
                                    tool[:-3]) if tool.endswith("gcc") else ""
    row["base"] = base
    # measured, demo-checked and self-tested are the table's targets
    for role in ("bench", "footprint", "demo_check", "selftest",
                 "check_only", "examples", "golden_parts", "cxx", "arm_arch"):
        row.pop(role, None)
    return name, row


def configure(conf):
    """The --variant targets, added to the table and recorded in the
    default environment (CUSTOM_TARGETS) for later commands."""
    custom = dict(derive(conf, spec) for spec in conf.options.variants)
    TARGETS.update(custom)
    return custom


def load(cache):
    """The custom targets a configure recorded, added to the table again
    for the commands after it; their names."""
    custom = dict(cache.CUSTOM_TARGETS or {})
    TARGETS.update(custom)
    return list(custom)
