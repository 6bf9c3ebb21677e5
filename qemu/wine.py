#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Run a Windows program (the win64 target's .exe files) under Wine,
quietly and hermetically, as QEMU runs the firmware images.

  wine.py PROGRAM.exe [ARG...]   run it; its exit status is ours
  wine.py --init                 make the Wine prefix now, say how long it took

Hermetic: the program sees a Wine prefix (its C: drive and registry) of
its own, build/wine/ (WINEPREFIX), made on first use by `wineboot --init`
and never one of the user's; no X display (DISPLAY is dropped; the
programs are console programs); no Wine messages (WINEDEBUG=-all); no
offer to install Wine's Mono or Gecko (mscoree and mshtml disabled) and
no menu entries (winemenubuilder disabled). Standard input, output and
error are the program's own, untouched: the harness and the tool tests see
exactly the bytes the program writes.

Debian's wine64 package (12 and 13) has no `wine` command (that is in the `wine`
package, with the 32-bit loader and desktop integration); its loader is
/usr/lib/wine/wine64 and its server /usr/lib/wine/wineserver64.

The program's output comes through pipes of ours, relayed as it arrives,
and ends when the program ends: Wine's services (services.exe,
winedevice.exe, plugplay.exe), which the first program of a server
starts, inherit its streams and outlive it, so a caller that read the
program's own pipe would wait for them (seen: the harness judged a
finished Unity runner as hung). The server is started here, detached from
our streams, and stays PERSIST seconds after its last program, so a test
that runs the tool a few hundred times starts it once.
"""
import fcntl
import os
import select
import shutil
import subprocess
import sys
import time

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PREFIX = os.path.join(TOP, "build", "wine")
# the stamp that says `wineboot --init` ran to its end in PREFIX
READY = ".drdc-wineboot-done"
LOCK = PREFIX + ".lock"
PERSIST = 10  # seconds the server outlives its last program
WINE_DIRS = ("/usr/lib/wine",)


def _find(name):
    """Wine's program `name`, in Debian's private directory or on PATH."""
    for d in WINE_DIRS:
        path = os.path.join(d, name)
        if os.access(path, os.X_OK):
            return path
    path = shutil.which(name)
    if path is None:
        sys.exit("wine.py: no %s; Debian's wine64 package has it "
                 "(the wine64 machine of waftools/targets.py)" % name)
    return path


def environment():
    env = {k: v for k, v in os.environ.items()
           if k not in ("DISPLAY", "WAYLAND_DISPLAY", "WINELOADER")}
    env.update({
        "WINEPREFIX": PREFIX,
        "WINEARCH": "win64",
        "WINEDEBUG": "-all",
        "WINEDLLOVERRIDES": "mscoree,mshtml=;winemenubuilder.exe=d",
        "WINESERVER": _find("wineserver64"),
    })
    return env


def _quiet(cmd, env, log):
    return subprocess.call(cmd, env=env, stdin=subprocess.DEVNULL,
                           stdout=log, stderr=subprocess.STDOUT,
                           start_new_session=True)


def ensure_prefix(env):
    """Make PREFIX with wineboot unless it is complete; return the seconds
    that took (0.0 when it was there). Serialised by a lock, so parallel
    callers make it once; a prefix left half made is made anew."""
    ready = os.path.join(PREFIX, READY)
    if os.path.exists(ready):
        return 0.0
    os.makedirs(os.path.dirname(PREFIX), exist_ok=True)
    with open(LOCK, "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if os.path.exists(ready):
            return 0.0
        shutil.rmtree(PREFIX, ignore_errors=True)
        os.makedirs(PREFIX)
        start = time.monotonic()
        with open(os.path.join(PREFIX, "wineboot.log"), "w") as log:
            boot = _quiet([_find("wine64"), "wineboot", "--init"], env, log)
            # wineboot returns before the prefix's services are done with
            # it: wait until the server has nothing left to run
            wait = _quiet([env["WINESERVER"], "--wait"], env, log)
        if boot != 0 or wait != 0:
            sys.exit("wine.py: wineboot --init failed in %s (status %d, %d); "
                     "see %s" % (PREFIX, boot, wait,
                                 os.path.join(PREFIX, "wineboot.log")))
        open(ready, "w").close()
        return time.monotonic() - start


def start_server(env):
    """A persistent server for PREFIX, detached from our streams (it
    returns at once when one is running)."""
    subprocess.call([env["WINESERVER"], "--persistent=%d" % PERSIST],
                    env=env, stdin=subprocess.DEVNULL,
                    stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def run_relayed(cmd, env):
    """Run cmd with its standard output and error relayed to ours until it
    ends, whoever else holds the pipes; return its exit status."""
    proc = subprocess.Popen(cmd, env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE)
    relay = {proc.stdout.fileno(): sys.stdout.fileno(),
             proc.stderr.fileno(): sys.stderr.fileno()}
    open_fds = set(relay)
    # after the program's end, only what it already wrote: no waiting
    while open_fds:
        ended = proc.poll() is not None
        ready, _, _ = select.select(list(open_fds), [], [],
                                    0 if ended else 0.02)
        if ended and not ready:
            break
        for fd in ready:
            chunk = os.read(fd, 65536)
            if not chunk:
                open_fds.discard(fd)
                continue
            view = memoryview(chunk)
            while view:
                view = view[os.write(relay[fd], view):]
    proc.stdout.close()
    proc.stderr.close()
    return proc.wait()


def main(argv):
    if not argv or argv[0] in ("-h", "--help"):
        sys.exit(__doc__)
    env = environment()
    if argv == ["--init"]:
        seconds = ensure_prefix(env)
        print("wine.py: prefix %s %s" % (
            PREFIX, "made in %.1f s" % seconds if seconds else "ready"))
        return 0
    ensure_prefix(env)
    start_server(env)
    program = os.path.abspath(argv[0])
    return run_relayed([_find("wine64"), program] + argv[1:], env)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
