# SPDX-License-Identifier: BSD-2-Clause
"""Set-up of everything the build needs, pinned by version and checksum.

Debian packages are pinned by exact version (apt verifies their checksums
through the signed archive index); source tarballs and Python wheels are
pinned by SHA-256 here. Sources are unpacked into .deps/ (ignored by git).
Every step first checks whether its result is already present, so a second
run costs a few dpkg queries and file tests.

Run by `./waf configure` (and so by the first `./waf check` or `./waf demo`);
`python3 tools/deps.py` runs it alone.
"""
import hashlib
import glob
import os
import shutil
import subprocess
import sys
import tarfile

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEPS = os.path.join(TOP, ".deps")

# Debian 12 binary packages by the part of the build that uses them, each
# pinned by exact version. Set-up installs with --no-install-recommends:
# whatever a tool needs at run time is named here, never left to a
# package's Recommends.
APT_GROUPS = {
    # the waf launcher: pip installs the pinned waflib and Python wheels
    # (Debian's python3 has no pip of its own)
    "pip": {"python3-pip": "23.0.1+dfsg-1"},
    # host and host-asan: the native compiler (ASan and UBSan come with it)
    # and the C library's headers (a Recommends of gcc); g++ for the C++
    # layer's images (cxx/, CXX_TARGETS in wscript; clang++-14 is in
    # clang-14, below)
    "host": {"gcc": "4:12.2.0-3", "g++": "4:12.2.0-3", "libc6-dev": None},
    # host-fuzz: libFuzzer (tools/fuzz.py)
    "host-fuzz": {"clang-14": "1:14.0.6-12",
                  "libclang-rt-14-dev": "1:14.0.6-12"},
    # ppc-e500: freestanding, so the cross compiler's own headers only
    # (tools/deps.py never installs libc6-dev-powerpc-cross); QEMU runs
    # with -nic none, so without the option ROMs of ipxe-qemu
    "ppc-e500": {"gcc-powerpc-linux-gnu": "4:12.2.0-5",
                 "qemu-system-ppc": "1:7.2+dfsg-7+deb12u18+b3"},
    # arm-cm3: newlib nano and semihosting
    "arm-cm3": {"gcc-arm-none-eabi": "15:12.2.rel1-1",
                "libnewlib-arm-none-eabi": "3.3.0-1.3+deb12u1",
                "qemu-system-arm": "1:7.2+dfsg-7+deb12u18+b3"},
    # riscv32: bare-metal RV32 compiler, picolibc (rv32imac/ilp32
    # multilib), qemu-system-riscv32 (QEMU's "misc" systems)
    "riscv32": {"gcc-riscv64-unknown-elf": "12.2.0-14+deb12u1+11+b2",
                "picolibc-riscv64-unknown-elf": "1.8-1",
                "qemu-system-misc": "1:7.2+dfsg-7+deb12u18+b3"},
    # avr: the 16-bit-int build of the library (ATmega2560) and simavr,
    # which runs each part of the conformance digest
    "avr": {"gcc-avr": "1:5.4.0+Atmel3.6.2-3",
            "avr-libc": "1:2.0.0+Atmel3.6.2-3", "simavr": "1.6+dfsg-3"},
    # win64: mingw-w64's GCC for Windows x86-64 in its win32 thread
    # flavour (Win32 threads, no libwinpthread DLL: the programs need
    # nothing but Windows's own msvcrt.dll and kernel32.dll), and Wine,
    # which runs the .exe files (qemu/wine.py; no X display, so none of
    # wine's Recommends)
    "win64": {"gcc-mingw-w64-x86-64-win32": "12.2.0-14+deb12u1+25.2+b1",
              "wine64": "8.0~repack-4"},
    # ./waf check beyond the targets' own tools
    "check": {
        # pkg-config: reads RTEMS BSP flags, checks the installed drdc.pc
        "pkgconf": "1.8.1-1",
        # make: the Makefiles of examples/ (tools/test_install.py)
        "make": "4.3-4.1",
        # MISRA C:2012 addon (tools/misra.py)
        "cppcheck": "2.10-2",
        # API reference without a warning
        "doxygen": "1.9.4-4",
        # the layout of every C source (tools/formatcheck.py)
        "clang-format-14": "1:14.0.6-12",
        # GNU units: oracle of the unit-conversion vectors
        # (tests/ref/gen_units.py) and of tools/test_drdc.py
        "units": "2.22-2",
        # GeoConvert, TransverseMercatorProj: oracle of the geodesy
        # vectors (tests/ref/gen_geo*.py) and of tools/test_drdc.py
        "geographiclib-tools": "2.1.2-1",
        # the real RTEMS 6 job (tools/rtems_qemu.py): the run-time
        # libraries of the RTEMS tool suite's compiler, and fdtput for
        # the device tree of QEMU's mpc8544ds
        "libgmp10": "2:6.2.1+dfsg1-1.1", "libmpfr6": "4.2.0-1",
        "libmpc3": "1.3.1-1",
        "device-tree-compiler": "1.6.1-4+b1",
    },
}
# the gold-standard service's check (python/tests/test_serve_page.py):
# headless Chromium loads the page, as a person's browser would
APT_GROUPS["serve"] = {"chromium": "156.0.8078.108-1~deb12u1"}
# ./waf docs: the API reference and the error plots of docs/accuracy.md
APT_GROUPS["docs"] = {p: APT_GROUPS["check"][p]
                      for p in ("doxygen", "geographiclib-tools")}
# A version None: any version will do, apt installs the archive's.
# libc6-dev must be the very version of the machine's libc6, so it cannot
# be pinned apart from it; apt upgrades libc6 along with it where needed.

# Debian source packages whose upstream tarball we unpack. The checksum is
# the one in the package's .dsc (Checksums-Sha256 of the .orig.tar.xz).
SOURCES = {
    "unity": {
        "package": "ntpsec", "version": "1.2.2+dfsg1-1+deb12u1",
        "tarball": "ntpsec_1.2.2+dfsg1.orig.tar.xz",
        "sha256": "53e527e3d04d551d41af2d359c2715c2de5f5bfa2a695d4ec1a811b3e9137f63",
        # Unity 2.5.1 ships inside ntpsec's tree
        "member": "ntpsec-1.2.2+dfsg1/tests/unity/",
    },
    "libfixmath": {
        "package": "libfixmath", "version": "0~20220222-3",
        "tarball": "libfixmath_0~20220222.orig.tar.xz",
        "sha256": "38a93f38bcf2b6fbc00bfc4e10905f8f012cc72943ec5eed69a459c3bc0349e0",
        "member": "./libfixmath/",
    },
}

# Python packages of the host reference-vector generator (tests/ref/).
# Wheels for CPython 3.11 on manylinux x86_64 (pyerfa is abi3).
#   numpy, pyerfa: ERFA (the C library behind astropy's time scales) is the
#     oracle of TAI-UTC and of UTC <-> TAI across leap seconds;
#   astropy-iers-data: the IERS Leap_Second.dat (Bulletin C) that dates the
#     expiry of the built-in leap-second table.
PYTHON_PACKAGES = {
    "mpmath==1.3.0":
        "a0b2b9fe80bbcd81a6647ff13108738cfb482d481d826cc0e02f5b35e5c88d2c",
    "numpy==2.4.6":
        "89cd468399cfd2504718f0ba50e410dca55a170b61a02ad92bb18c8a65186e93",
    # the benchmark chart (tools/bench.py) and its dependencies
    "matplotlib==3.11.2":
        "07d9b9fa60cd4c393692f50d0bb03123242ddf61c99bb0e95e75feb354e7c1a8",
    "contourpy==1.3.3":
        "51e79c1f7470158e838808d4a996fa9bac72c498e93d8ebe5119bc1e6becb0db",
    "cycler==0.12.1":
        "85cef7cff222d8644161529808465972e51340599459b8ac3ccbac5a854e0d30",
    "fonttools==4.68.0":
        "4b9c89b5876f1a74b1341632dfaf4c4c2be565d76c060445df401ebe7a4ceefa",
    "kiwisolver==1.5.1":
        "95a02752aa032eef4aed01cda6d9b687c669bd0396bf4519eef8bba22a286720",
    "packaging==26.3":
        "d7193f7c8e4e93f444fde0262bf90af30e16fa0ad0ad44cb553c87339b23cd1c",
    "pillow==13.0.0":
        "a625df9a2a5597fa5e5266e01aefc82604bb85d291e3547981e863560d75da6c",
    "pyparsing==3.3.3":
        "ece8c00a69cf01b45d0b1dedabb469c90d8caf996d4fda40f147627a122849a4",
    "python-dateutil==4.0.0":
        "a5e246f79eb80475e691bf93862cead98decd8a498cf53ba0516fcdc0f50dc1c",
    "tzdata==2026.6":
        "0a10eec6e13ef16b627fabed9a5f2ba61a62b1c67f327305f4e7e412a70b4aec",
    # time vectors: ERFA (TAI-UTC) and the IERS leap-second file
    "pyerfa==2.0.1.5":
        "0e43c7194e3242083f2350b46c09fd4bf8ba1bcc0ebd1460b98fc47fe2389906",
    "astropy-iers-data==0.2026.11.2.0.34.55":
        "785cd5bc193d9206316bd7c786fe0647e212ebf017cd861beabedd91cbe585bf",
    # NMEA vectors: an independent decoder (NMEA 0183 v4.11 layouts of
    # every sentence the library reads) locates and names each field
    "pynmeagps==1.1.8":
        "8c529f28ffcc39257277c89b1b0dce6b20d54dd89181da9c81911886d580b779",
    # orientation vectors: SciPy's Rotation (numpy pinned above)
    # cp311 manylinux x86-64 wheels; scipy 1.17.1 supports numpy < 2.7
    "scipy==1.17.1":
        "43af8d1f3bea642559019edfe64e9b11192a8978efbd1539d7bc2aaa23d92de4",
    # unit-expression vectors: pint's registry, the second oracle beside
    # GNU units (tests/ref/gen_units_expr.py); pure-Python wheels, pint
    # 0.25.3 being the last for CPython 3.11
    "pint==0.25.3":
        "27eb25143bd5de9fcc4d5a4b484f16faf6b4615aa93ece6b3373a8c1a3c1b97d",
    "flexcache==0.3":
        "d43c9fea82336af6e0115e308d9d33a185390b8346a017564611f1466dcd2e32",
    "flexparser==0.4":
        "3738b456192dcb3e15620f324c447721023c0293f6af9955b481e91d00179846",
    "platformdirs==4.3.8":
        "ff7059bb7eb1179e2685604f4aaf157cfd9535242bd23742eadc3c13542139b4",
    "typing_extensions==4.14.1":
        "d1e1e3b58374dc93031d6eda2420a48ea44a36c2b4766a4fdeb3710755731d76",
    # the Python package's tests (python/check.py): pytest and what it
    # needs on CPython 3.11 (packaging is pinned above); pure-Python wheels
    "pytest==9.2.0":
        "07acdcf88ec174f907dc01af70bf52d49b014bbab03faeeade31c96b18c2e588",
    "pluggy==1.7.0":
        "7dd7b0d8832ba3cb632c306926ded123429211b83641b35dc5c41ad2d34f9bec",
    "iniconfig==2.3.1":
        "9121e2c1fdb355232495be3194c8dfe87ccc2d5dee45947b78e68f499790d7a7",
    "pygments==2.21.0":
        "2363c69b61c4a97c838da3b130dcd6468f4848992b21a82f2a63ec34377137d9",
    # the gold-standard service (python/drdc/serve/): aiohttp's server
    # (body cap, timeouts), its client drives Chromium's DevTools
    # websocket in the page's test and the load test; cp311 manylinux
    # wheels and pure-Python ones (typing_extensions is pinned above)
    "aiohttp==3.14.5":
        "50a195903119008fe9cc68710535eb37f556ffffd6a7759afe70a2c145587045",
    "aiohappyeyeballs==2.7.1":
        "9243213661e29250eb41368e5daa826fc017156c3b8a11440826b2e3ed376472",
    "aiosignal==1.4.0":
        "053243f8b92b990551949e63930a839ff0cf0b0ebbe0597b0f3fb19e1a0fe82e",
    "attrs==26.1.0":
        "c647aa4a12dfbad9333ca4e71fe62ddc36f4e63b2d260a37a8b83d2f043ac309",
    "frozenlist==1.8.0":
        "2552f44204b744fba866e573be4c1f9048d6a324dfe14475103fd51613eb1d1f",
    "idna==3.20":
        "ab7ae7122974553370f0bdb919e1a960b2cd1bc1ef0276416d896db81c14582c",
    "multidict==7.2.1":
        "3b7542fad2706595c1b1853b46f2c3c4ae5cc5a6252b7225f294d607a29e1bdf",
    "propcache==0.5.4":
        "6e9368e87a3efc285e559131092c5db643eb8e56de4ee42064d5baec22ef2bb5",
    "yarl==1.25.1":
        "d5add7b4ca7afeea91d52e4d4e4db3b1fe9885b71f07054560d8c4296b7441a2",
}

DEB_SRC_LIST = "/etc/apt/sources.list.d/drdc-deb-src.sources"
DEB_SRC_ENTRY = """Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm bookworm-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
"""


class SetupError(Exception):
    """A dependency is missing and cannot be installed by this process."""


def _is_root():
    return os.geteuid() == 0


def _say(text):
    print("deps: " + text, flush=True)


def _run(cmd, **kw):
    _say(" ".join(cmd))
    status = subprocess.call(cmd, **kw)
    if status != 0:
        raise SetupError("%s failed (exit status %d)" % (cmd[0], status))


def _apt_env():
    env = dict(os.environ)
    env["DEBIAN_FRONTEND"] = "noninteractive"
    return env


def _installed_version(pkg):
    r = subprocess.run(["dpkg-query", "-W", "-f", "${Status}|${Version}", pkg],
                       capture_output=True, text=True)
    if r.returncode != 0 or not r.stdout.startswith("install ok installed"):
        return None
    return r.stdout.split("|", 1)[1]


def _have_deb_src():
    return bool(glob.glob("/var/lib/apt/lists/*_source_Sources*"))


class _Apt:
    """apt-get update at most once a process, with the deb-src entry that
    the source tarballs need written before it."""
    updated = False

    @classmethod
    def update(cls):
        if cls.updated:
            return
        if not os.path.exists(DEB_SRC_LIST):
            with open(DEB_SRC_LIST, "w") as f:
                f.write(DEB_SRC_ENTRY)
        _run(["apt-get", "update", "-q"], env=_apt_env())
        cls.updated = True


def apt_packages(groups):
    """{package: pinned version} of the named APT_GROUPS."""
    wanted = {}
    for g in groups:
        wanted.update(APT_GROUPS[g])
    return wanted


def ensure_apt(groups):
    """Install the Debian packages of the named APT_GROUPS that are absent
    or at another version; as another user, say the command to run."""
    missing = []
    for pkg, version in sorted(apt_packages(groups).items()):
        have = _installed_version(pkg)
        if have is None or (version is not None and have != version):
            missing.append("%s=%s" % (pkg, version) if version else pkg)
    if not missing:
        return
    cmd = ["apt-get", "install", "-y", "-q", "--no-install-recommends"]
    if not _is_root():
        raise SetupError("missing Debian packages; run as root:\n"
                         "  apt-get update && " + " ".join(cmd + missing))
    _say("installing %d Debian packages (%s) with their dependencies"
         % (len(missing), ", ".join(m.split("=")[0] for m in missing)))
    _Apt.update()
    _run(cmd + missing, env=_apt_env())


def _sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def _fetch_source(spec, dl):
    path = os.path.join(dl, spec["tarball"])
    if os.path.exists(path) and _sha256(path) == spec["sha256"]:
        return path
    os.makedirs(dl, exist_ok=True)
    if _is_root():
        _Apt.update()
    elif not _have_deb_src():
        raise SetupError(
            "apt has no source-package index; run as root:\n"
            "  printf '%s' > %s && apt-get update"
            % (DEB_SRC_ENTRY.replace("\n", "\\n"), DEB_SRC_LIST))
    what = "%s %s" % (spec["package"], spec["version"])
    _say("fetching %s from the %s %s source package"
         % (spec["tarball"], spec["package"], spec["version"]))
    # Only the upstream tarball is used. The archive may answer 404 for
    # the Debian part of a source package, so apt's exit status and its
    # messages are kept for a failure; the checksum below is the test.
    r = subprocess.run(["apt-get", "source", "--download-only", "-q",
                        "%s=%s" % (spec["package"], spec["version"])],
                       cwd=dl, env=_apt_env(), capture_output=True,
                       text=True)
    if not os.path.exists(path):
        raise SetupError("could not download %s (%s) from the Debian "
                         "archive; apt-get said:\n%s%s"
                         % (spec["tarball"], what, r.stdout, r.stderr))
    got = _sha256(path)
    if got != spec["sha256"]:
        raise SetupError("%s: SHA-256 %s, expected %s"
                         % (spec["tarball"], got, spec["sha256"]))
    _say("%s: SHA-256 as pinned" % spec["tarball"])
    return path


def ensure_source(name):
    """Unpack the pinned source `name` into .deps/<name>/ and return it."""
    spec = SOURCES[name]
    dest = os.path.join(DEPS, name)
    stamp = os.path.join(dest, ".%s.ok" % spec["sha256"][:16])
    if os.path.exists(stamp):
        return dest
    tarball = _fetch_source(spec, os.path.join(DEPS, "dl"))
    shutil.rmtree(dest, ignore_errors=True)
    os.makedirs(dest)
    prefix = spec["member"]
    with tarfile.open(tarball) as tar:
        for m in tar.getmembers():
            if not m.isfile() or not m.name.startswith(prefix):
                continue
            rel = m.name[len(prefix):]
            if ".." in rel.split("/"):
                continue
            out = os.path.join(dest, rel)
            os.makedirs(os.path.dirname(out), exist_ok=True)
            with tar.extractfile(m) as src, open(out, "wb") as dst:
                shutil.copyfileobj(src, dst)
    open(stamp, "w").close()
    return dest


def _have_pip():
    return subprocess.run([sys.executable, "-m", "pip", "--version"],
                          capture_output=True).returncode == 0


def pip_install(dest, requirements, what):
    """pip-install the hash-pinned requirements (text of a requirements
    file) into dest, without their dependencies: every package is named."""
    if not _have_pip():
        ensure_apt(["pip"])
    os.makedirs(dest, exist_ok=True)
    tmp = os.path.join(dest, "requirements.in")
    with open(tmp, "w") as f:
        f.write(requirements)
    _say("installing %s into %s" % (what, dest))
    # a live bar on a terminal; in a log, one line a download
    bar = "on" if sys.stdout.isatty() else "off"
    _run([sys.executable, "-m", "pip", "install", "--progress-bar", bar,
          "--upgrade", "--disable-pip-version-check",
          "--root-user-action=ignore",
          "--no-deps", "--require-hashes", "--target", dest, "-r", tmp])


def ensure_waflib(dest, version, sha256):
    """The pinned waflib wheel in dest (the waf launcher's)."""
    stamp = os.path.join(dest, "waflib-%s.ok" % version)
    if os.path.exists(stamp):
        return
    pip_install(dest, "waflib==%s --hash=sha256:%s\n" % (version, sha256),
                "waflib %s" % version)
    open(stamp, "w").close()


def ensure_python():
    """Install the generator's Python packages into .deps/python/."""
    dest = os.path.join(DEPS, "python")
    req = "".join("%s --hash=sha256:%s\n" % kv
                  for kv in sorted(PYTHON_PACKAGES.items()))
    stamp = os.path.join(dest, ".requirements.txt")
    if os.path.exists(stamp) and open(stamp).read() == req:
        return dest
    shutil.rmtree(dest, ignore_errors=True)
    pip_install(dest, req, "%d Python packages of the reference-vector "
                "generator and the plots (about 90 MB to download)"
                % len(PYTHON_PACKAGES))
    with open(stamp, "w") as f:
        f.write(req)
    return dest


def ensure_all(groups, python=True):
    """Make the Debian packages of the named APT_GROUPS, the Unity and
    libfixmath sources and (if python) the Python packages present; return
    the paths of the unpacked ones (None for what was not asked)."""
    ensure_apt(groups)
    return {
        "unity": ensure_source("unity"),
        "libfixmath": ensure_source("libfixmath"),
        "python": ensure_python() if python else None,
    }


if __name__ == "__main__":
    try:
        for k, v in ensure_all(sorted(APT_GROUPS)).items():
            print("%s: %s" % (k, v))
    except SetupError as e:
        sys.exit("deps: " + str(e))
