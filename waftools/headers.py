# SPDX-License-Identifier: BSD-2-Clause
"""A bare-metal target's system headers: exactly the directories its row
of waftools/targets.py names ("headers"), and proof at configure that a
hosted-only header ("hosted_bait") is simply missing, so that no host
header can leak into its build.
"""
import os
import re
import subprocess

from waflib import Context


def system_includes(conf, name, t):
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
            conf.fatal("%s: no include directory %s (its headers in "
                       "waftools/targets.py)" % (name, d))
        flags += ["-isystem", d]
    return flags


def check_hermetic(conf, name, t):
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
                       "can leak into the bare-metal build (its headers in "
                       "waftools/targets.py); the compiler said:\n%s"
                       % (name, header, r.stderr))
        conf.end_msg("none, as it must be")
