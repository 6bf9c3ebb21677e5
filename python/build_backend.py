# SPDX-License-Identifier: BSD-2-Clause
"""PEP 517 build backend of the drdc Python package (pip calls it).

It compiles the library's C sources, core/ and fixed/ of this checkout,
and the array loops of python/src/ with the host C compiler into
drdc/libdrdc.so, and packs that beside the Python modules into a wheel.
The library's sources, include directories and flags are those of
wscript's host variant (the same glob, the footprint policy's -O2/-Os
per module from waftools/targets.py, -fPIC added for a shared library),
so the package computes what build/host/drdc computes.

Why a backend of our own instead of setuptools: it needs no package, so
pip downloads nothing to build and there is no build backend to pin; and
the compiler sees the project's flags, not those of the Python that runs
pip (setuptools would add sysconfig's CFLAGS).

It needs a C compiler (gcc, or $CC) and the C library's headers: on
Debian 12, `./waf configure --with-targets=host` installs them (the
packages gcc and libc6-dev). The wheel holds no code for a particular
Python version: it is tagged py3-none-<platform>.
"""
import base64
import concurrent.futures
import glob
import hashlib
import importlib.util
import os
import re
import shlex
import shutil
import stat
import subprocess
import sysconfig
import tempfile
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(HERE)
NAME = "drdc"

# wscript: WARNINGS, CODEGEN, LIBRARY_CODEGEN and the host target's arch,
# without -Werror (another compiler may warn where the pinned one does not)
# and -fcallgraph-info (the footprint report's, not code)
CFLAGS = ["-std=c99", "-Wall", "-Wextra", "-Wconversion", "-Wsign-conversion",
          "-Wshadow", "-Wcast-align", "-Wstrict-prototypes", "-Wundef",
          "-O2", "-g", "-ffunction-sections", "-fdata-sections",
          "-fno-align-functions", "-D_POSIX_C_SOURCE=200809L", "-fPIC"]
INCLUDES = ["fixed/internal", "fixed/include", "core/include",
            "tests/golden", "tools/drdc"]


class BuildError(Exception):
    """The library could not be compiled; the message says why."""


def _version():
    with open(os.path.join(TOP, "core/include/drdc/version.h")) as f:
        m = re.search(r'#define DRDC_VERSION_STRING "([^"]+)"', f.read())
    return m.group(1)


def _footprint():
    """The footprint policy: the table of targets' optimise_kind() and
    OPTIMISE_FLAGS."""
    spec = importlib.util.spec_from_file_location(
        "targets", os.path.join(TOP, "waftools", "targets.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _sources():
    """The library's sources (wscript's glob), then the array loops and
    the golden reference of python/src/ with tests/golden's parts."""
    paths = []
    for folder in ("fixed", "core", "python/src"):
        paths += sorted(glob.glob(os.path.join(TOP, folder, "**", "*.c"),
                                  recursive=True))
    # the reasons `drdc nmea` and `drdc time` print, for DrdcError
    paths.append(os.path.join(TOP, "tools", "drdc", "reasons.c"))
    # the conformance digest's parts, for drdc.conformance's reference
    # records (python/src/golden.c); not the runner's test and tables
    paths += [p for p in sorted(glob.glob(os.path.join(
        TOP, "tests", "golden", "golden*.c")))
        if os.path.basename(p) != "golden_expected.c"]
    return [os.path.relpath(p, TOP) for p in paths]


def _compiler():
    cc = shlex.split(os.environ.get("CC", "gcc"))
    if shutil.which(cc[0]) is None:
        raise BuildError(
            "no C compiler '%s': the drdc package compiles libdrdc.so from "
            "core/ and fixed/; on Debian 12 run ./waf configure "
            "--with-targets=host (or apt-get install gcc libc6-dev)" % cc[0])
    return cc


def _run(cmd):
    r = subprocess.run(cmd, cwd=TOP, capture_output=True, text=True)
    if r.returncode != 0:
        raise BuildError("%s\n%s%s" % (" ".join(cmd), r.stdout, r.stderr))
    return r.stderr


def build_library(out_path, tool_path, work_dir):
    """Compile core/ and fixed/ into the shared library out_path, and the
    host tool tools/drdc/ with the same objects into tool_path."""
    if not os.path.isdir(os.path.join(TOP, "core")):
        raise BuildError("no core/ beside python/ (%s): build the package "
                         "from a checkout of libdrdc-fx" % TOP)
    cc = _compiler()
    policy = _footprint()
    includes = ["-I" + os.path.join(TOP, d) for d in INCLUDES]
    jobs = []
    for k, src in enumerate(_sources()):
        stem = os.path.basename(src)[:-2]
        obj = os.path.join(work_dir, "%03d_%s.o" % (k, stem))
        # the footprint policy's flags for the library; the loops (and the
        # tool's reasons) for speed
        kind = ("speed" if src.startswith(("python" + os.sep,
                                           "tests" + os.sep,
                                           "tools" + os.sep))
                else policy.optimise_kind(src))
        flags = CFLAGS + policy.OPTIMISE_FLAGS[kind]
        if src.startswith("tests" + os.sep):
            # the golden parts serve python/src/golden.c inside the
            # library: their golden_* names stay out of its exports, so
            # only drdc_ names leave libdrdc.so as they leave libdrdc.a
            flags = flags + ["-fvisibility=hidden"]
        jobs.append((cc + flags + includes + ["-c", src, "-o", obj], obj))
    # the host tool drdc: its own files, linked with the library's
    tool = []
    for k, src in enumerate(sorted(glob.glob(os.path.join(
            TOP, "tools", "drdc", "*.c")))):
        src = os.path.relpath(src, TOP)
        obj = os.path.join(work_dir, "tool_%03d_%s.o"
                           % (k, os.path.basename(src)[:-2]))
        jobs.append((cc + CFLAGS + policy.OPTIMISE_FLAGS["speed"] + includes
                     + ["-c", src, "-o", obj], obj))
        tool.append(obj)
    with concurrent.futures.ThreadPoolExecutor(os.cpu_count() or 1) as pool:
        list(pool.map(_run, [cmd for cmd, _ in jobs]))
    library = [obj for _, obj in jobs if obj not in tool]
    _run(cc + ["-shared", "-o", out_path] + library)
    # the tool links the library's own objects, as build/host/drdc links
    # libdrdc.a: the same code, so the same bits (python/src's loops and
    # the golden parts are not part of it)
    core = [obj for (cmd, obj) in jobs if obj not in tool
            and _source_of(cmd).startswith(("core" + os.sep,
                                            "fixed" + os.sep))]
    _run(cc + ["-o", tool_path] + tool + core)


def _source_of(cmd):
    return cmd[cmd.index("-c") + 1]


def _status_texts():
    """{value: meaning} of every status, from the comments of
    fixed/include/drdc/status.h (DrdcError's reason where `drdc` has no
    words of its own for a function)."""
    with open(os.path.join(TOP, "fixed/include/drdc/status.h")) as f:
        text = f.read()
    body = text[text.index("typedef enum drdc_status {"):
                text.index("} drdc_status_t;")]
    texts, pending, last = {}, None, None
    for m in re.finditer(r"/\*\*(<?)(.*?)\*/|\b(DRDC_\w+)\s*=\s*(\d+)",
                         body, re.S):
        if m.group(3):
            last = int(m.group(4)) if m.group(3) != "DRDC_STATUS_COUNT" \
                else None
            if pending is not None and last is not None:
                texts[last] = pending
            pending = None
            continue
        words = " ".join(w for w in m.group(2).split() if w != "*")
        if m.group(1) and last is not None:
            texts[last] = words
        elif not m.group(1):
            pending = words
    return texts


def _record_line(arcname, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest())
    return "%s,sha256=%s,%d\n" % (arcname, digest.rstrip(b"=").decode(),
                                  len(data))


def _metadata(version):
    return ("Metadata-Version: 2.1\n"
            "Name: %s\n"
            "Version: %s\n"
            "Summary: libdrdc-fx from Python: the firmware's exact integers\n"
            "License: BSD-2-Clause\n"
            "Requires-Python: >=3.9\n"
            "Requires-Dist: numpy>=1.24\n"
            "Provides-Extra: serve\n"
            "Requires-Dist: aiohttp>=3.9; extra == \"serve\"\n"
            "Provides-Extra: pandas\n"
            "Requires-Dist: pandas>=2.0; extra == \"pandas\"\n"
            "Provides-Extra: dask\n"
            "Requires-Dist: pandas>=2.0; extra == \"dask\"\n"
            "Requires-Dist: dask>=2024.1; extra == \"dask\"\n"
            "Requires-Dist: distributed>=2024.1; extra == \"dask\"\n"
            % (NAME, version))


def _tag():
    return "py3-none-" + re.sub(r"[-.]", "_", sysconfig.get_platform())


# ---- PEP 517 hooks -------------------------------------------------------

def get_requires_for_build_wheel(config_settings=None):
    return []


def build_wheel(wheel_directory, config_settings=None,
                metadata_directory=None):
    version = _version()
    tag = _tag()
    dist_info = "%s-%s.dist-info" % (NAME, version)
    files = {}
    # the package, and the service's subpackage with its page
    for pattern in ("*.py", "serve/*.py", "serve/*.html"):
        for path in sorted(glob.glob(os.path.join(HERE, NAME, pattern))):
            with open(path, "rb") as f:
                files["%s/%s" % (NAME, os.path.relpath(
                    path, os.path.join(HERE, NAME)))] = f.read()
    # the version of core/include/drdc/version.h, for drdc.__version__
    files[NAME + "/_version.py"] = (
        "# Written by python/build_backend.py from core/include/drdc/"
        "version.h.\nVERSION = %r\n" % version).encode()
    files[NAME + "/_status_text.py"] = (
        "# Written by python/build_backend.py from fixed/include/drdc/"
        "status.h.\nSTATUS_TEXT = {\n%s}\n" % "".join(
            "    %d: %r,\n" % kv for kv in sorted(_status_texts().items()))
    ).encode()
    with tempfile.TemporaryDirectory() as work:
        lib = os.path.join(work, "libdrdc.so")
        tool = os.path.join(work, "drdc")
        build_library(lib, tool, work)
        with open(lib, "rb") as f:
            files[NAME + "/libdrdc.so"] = f.read()
        with open(tool, "rb") as f:
            files[NAME + "/bin/drdc"] = f.read()
    files[dist_info + "/METADATA"] = _metadata(version).encode()
    # `drdc` on PATH: a console script that runs drdc/bin/drdc
    files[dist_info + "/entry_points.txt"] = (
        "[console_scripts]\ndrdc = drdc._cli:main\n").encode()
    files[dist_info + "/WHEEL"] = (
        "Wheel-Version: 1.0\nGenerator: drdc build_backend\n"
        "Root-Is-Purelib: false\nTag: %s\n" % tag).encode()
    files[dist_info + "/top_level.txt"] = (NAME + "\n").encode()
    record = "".join(_record_line(n, d) for n, d in files.items())
    record += dist_info + "/RECORD,,\n"
    files[dist_info + "/RECORD"] = record.encode()
    name = "%s-%s-%s.whl" % (NAME, version, tag)
    with zipfile.ZipFile(os.path.join(wheel_directory, name), "w",
                         zipfile.ZIP_DEFLATED) as whl:
        for arcname, data in files.items():
            info = zipfile.ZipInfo(arcname, date_time=(1980, 1, 1, 0, 0, 0))
            # the shared library and the tool must stay executable: pip
            # keeps the executable bits of a regular file's mode only
            info.external_attr = (stat.S_IFREG | (
                0o755 if arcname.endswith(".so") or
                arcname.endswith("/bin/drdc") else 0o644)) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            whl.writestr(info, data)
    return name
