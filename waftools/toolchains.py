# SPDX-License-Identifier: BSD-2-Clause
"""What a result was computed with: the release of each compiler, emulator
and interpreter the build found, for configure's log and the one line of
./waf check's summary that traces a result to its toolchain.

  python3 waftools/toolchains.py     print the emulators' and Python's lines
"""
import os
import platform
import re
import shutil
import subprocess
import sys

# The programs that run the images, by what the summary calls them: the
# first found of each list answers.
RUNNERS = [
    ("QEMU", [["qemu-system-ppc", "--version"],
              ["qemu-system-arm", "--version"],
              ["qemu-system-riscv32", "--version"]]),
    ("Wine", [["/usr/lib/wine/wine64", "--version"], ["wine", "--version"]]),
]
# Debian packages whose program prints no version of its own
PACKAGED = [("simavr", "simavr")]
VERSION = re.compile(r"\d+(\.\d+)+")


def _output(cmd):
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=60)
    except (OSError, subprocess.TimeoutExpired):
        return None
    return r.stdout.strip() if r.returncode == 0 else None


def _package_of(program):
    """(package, version) of the Debian package that installed program."""
    path = shutil.which(program) or program
    owner = _output(["dpkg-query", "-S", os.path.realpath(path)])
    if not owner:
        return None
    package = owner.split(":", 1)[0]
    return package, _output(["dpkg-query", "-W", "-f", "${Version}",
                             package])


def compiler(cc):
    """The release of a C compiler (a command as a list): GCC's full
    version, else clang's; where the compiler names none (mingw-w64's
    "12-win32"), the version of its Debian package."""
    for flag in ("-dumpfullversion", "-dumpversion"):
        text = _output(list(cc) + [flag])
        if text and VERSION.fullmatch(text.split()[0]):
            return text.split()[0]
    owner = _package_of(cc[0])
    if owner and owner[1]:
        return "(%s %s)" % owner
    return "unknown"


def runners():
    """[(name, release)] of the emulators found and of Python."""
    found = []
    for name, commands in RUNNERS:
        for cmd in commands:
            if not (os.path.isabs(cmd[0]) and os.access(cmd[0], os.X_OK)
                    or shutil.which(cmd[0])):
                continue
            m = VERSION.search(_output(cmd) or "")
            if m:
                found.append((name, m.group(0)))
                break
    for name, package in PACKAGED:
        if shutil.which(name):
            text = _output(["dpkg-query", "-W", "-f", "${Version}", package])
            m = VERSION.search(text or "")
            if m:
                found.append((name, m.group(0)))
    found.append(("Python", platform.python_version()))
    return found


def summary(envs):
    """One line: every configured target's compiler (waf environments with
    CC and CC_RELEASE), once each, then the emulators and Python."""
    compilers = []
    for env in envs:
        if not env.CC:
            continue
        text = "%s %s" % (os.path.basename(env.CC[0]), env.CC_RELEASE)
        if text not in compilers:
            compilers.append(text)
    return "toolchains: %s; %s" % (
        ", ".join(compilers),
        ", ".join("%s %s" % kv for kv in runners()))


if __name__ == "__main__":
    for what, release in runners():
        print("%s %s" % (what, release))
    sys.exit(0)
