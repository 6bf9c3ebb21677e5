# SPDX-License-Identifier: BSD-2-Clause
"""The real RTEMS 6 job of ./waf check.

With a real RTEMS 6 prefix (the one given to ./waf configure --rtems, or
else the project's shared RTEMS 6 archive, ../shared/rtems/ beside the
checkout, unpacked into build/rtems-real/), it does what an RTEMS user
does, in a build of its own (build/rtems-real/build, lock file
.lock-waf-rtems-real):

    ./waf configure --rtems=PREFIX --rtems-bsps=powerpc/qoriq_e500 [--werror]
    ./waf
    ./waf install --destdir=build/rtems-real/destdir

checks that the BSP's prefix (under that DESTDIR, so a user's RTEMS
installation is never written) then holds the library, the glue, the
headers and drdc.pc, and makes the device tree that QEMU needs for
test-runner-qemu.exe: QEMU's own for mpc8544ds with 1 GiB (dumped with
-machine dumpdtb), with the CPU's bus-frequency set (fdtput), since QEMU
writes 0 there and RTEMS's clock then never ticks.

Warnings are errors (--werror) with the project's archive, whose compiler
(gcc 13.3) is a tried one; a user's tool suite only warns, as in their own
build.

It writes the image's path for the harness into build/rtems-real/image.txt,
or, with no RTEMS 6 prefix at all (or one without that BSP), says in one
line that the job did not run and writes no such file.
"""
import argparse
import hashlib
import os
import shutil
import subprocess
import sys
import tarfile


TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, TOP)
from qemu import harness  # noqa: E402
import rtems_standin  # noqa: E402  (beside this file)
WORK = os.path.join(TOP, "build", "rtems-real")
ARCHIVE = os.path.join(os.path.dirname(TOP), "shared", "rtems",
                       "rtems6-powerpc-qoriq_e500.tar.xz")
ARCH, BSP, VERSION = "powerpc", "qoriq_e500", "6"
VARIANT = "%s-rtems%s-%s" % (ARCH, VERSION, BSP)
PROFILE = "rtems-qoriq_e500"  # of qemu/harness.py
# QEMU's mpc8544ds CPU node, and a bus frequency (200 MHz) that gives the
# BSP's decrementer clock its tick.
CPU_NODE = "/cpus/PowerPC,8544@0"
BUS_FREQUENCY = "200000000"


def run(cmd, **kw):
    print("rtems: " + " ".join(cmd), flush=True)
    status = subprocess.run(cmd, **kw).returncode
    if status != 0:
        sys.exit("rtems: %s failed (exit status %d)"
                 % (os.path.basename(cmd[1] if cmd[0] == sys.executable
                                     else cmd[0]), status))


def unpack(archive):
    """The archive's 6/ under build/rtems-real/, unpacked once per
    archive content."""
    h = hashlib.sha256()
    with open(archive, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    prefix = os.path.join(WORK, "6")
    stamp = os.path.join(WORK, "6.%s.ok" % h.hexdigest()[:16])
    if os.path.exists(stamp):
        return prefix
    shutil.rmtree(WORK, ignore_errors=True)
    os.makedirs(WORK)
    print("rtems: unpacking %s" % archive, flush=True)
    with tarfile.open(archive) as tar:
        # Python 3.12 and later (Debian 13) check each member against the
        # folder ("data" filter) and warn without one; 3.11.2 (Debian 12)
        # has no filter, and the archive is the project's own
        if hasattr(tarfile, "data_filter"):
            tar.extractall(WORK, filter="data")
        else:
            tar.extractall(WORK)
    open(stamp, "w").close()
    return prefix


def waf(args):
    env = dict(os.environ, WAFLOCK=".lock-waf-rtems-real")
    run([sys.executable, os.path.join(TOP, "waf")] + args, cwd=TOP, env=env,
        stdout=subprocess.DEVNULL)


def check_installed(destdir, prefix):
    """The BSP's lib/ holds, of the project's files, exactly those of the
    stand-in's install (the BSP's own files are not ours to list)."""
    libdir = destdir + os.path.join(prefix, "%s-rtems%s" % (ARCH, VERSION),
                                    BSP, "lib")
    want = rtems_standin.expected_install()
    got = [p for p in rtems_standin.installed_tree(libdir) if "drdc" in p]
    if got != want:
        sys.exit("rtems: installed tree differs:\n  got  %s\n  want %s"
                 % (got, want))
    print("rtems: installed %d files into %s" % (len(got), libdir))


def device_tree(image):
    """QEMU's own tree of the harness's machine, its bus frequency set."""
    dtb = image + ".dtb"
    machine = harness.command(PROFILE, image)
    i = machine.index("-dtb")
    del machine[i:i + 2]
    run(machine + ["-machine", "dumpdtb=" + dtb], stdout=subprocess.DEVNULL)
    run(["fdtput", "-t", "i", dtb, CPU_NODE, "bus-frequency", BUS_FREQUENCY])
    return dtb


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--prefix", help="an installed RTEMS 6 prefix")
    ap.add_argument("--tools", help="its tool suite (default: --prefix)")
    args = ap.parse_args()
    listing = os.path.join(WORK, "image.txt")
    if os.path.exists(listing):
        os.remove(listing)
    if args.prefix and not os.path.exists(os.path.join(
            args.prefix, "lib", "pkgconfig", VARIANT + ".pc")):
        print("rtems: the real RTEMS 6 job did not run: the configured "
              "prefix %s has no %s/%s BSP" % (args.prefix, ARCH, BSP))
        return 0
    if args.prefix:
        prefix = os.path.abspath(args.prefix)
        tools = os.path.abspath(args.tools or args.prefix)
        werror = []
    elif os.path.exists(ARCHIVE):
        prefix = tools = unpack(ARCHIVE)
        werror = ["--werror"]
    else:
        print("rtems: the real RTEMS 6 job did not run: no prefix was "
              "configured (--rtems) and there is no %s" % ARCHIVE)
        return 0
    build = os.path.join(WORK, "build")
    image = os.path.join(build, VARIANT, "fw", "test-runner",
                         "test-runner-qemu.exe")
    if os.path.exists(image):
        os.remove(image)
    waf(["configure", "--rtems=" + prefix, "--rtems-tools=" + tools,
         "--rtems-bsps=%s/%s" % (ARCH, BSP), "--with-targets=host",
         "--out=" + build] + werror)
    waf([])
    destdir = os.path.join(WORK, "destdir")
    shutil.rmtree(destdir, ignore_errors=True)
    waf(["install", "--destdir=" + destdir])
    check_installed(destdir, prefix)
    if not os.path.exists(image):
        sys.exit("rtems: no %s: the BSP has no <rtems/confdefs.h>?" % image)
    device_tree(image)
    with open(listing, "w") as f:
        f.write(image + "\n")
    print("rtems: %s and its device tree are ready" % image)
    return 0


if __name__ == "__main__":
    sys.exit(main())
