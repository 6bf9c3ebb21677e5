#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Boot firmware images under QEMU (or natively on the host, or Windows
programs under Wine), watch the console and turn it into a verdict, like
RTEMS's tester does.

  harness.py run [--junit-dir D] [LABEL=]PROFILE:IMAGE ...
                                                     judge Unity test images
  harness.py show PROFILE IMAGE                      stream a console (demo)

An image passes only when all of this holds: it printed the RTEMS
"BEGIN OF TEST" marker, Unity's per-test lines and a summary that agree
with each other, no failure, the "END OF TEST" marker, no exception or
sanitizer report, only printable text, and it ended by itself with the
expected exit status. Hang (no output for --inactivity seconds), overrun of
--timeout, console flood and garbage are failures with their reason.

The run ends with the line "N passed, M failed": N and M count Unity tests
across all images; an image that fails for another reason (crash, hang...)
adds one failure of its own. Standard library only, and the table of
machines (waftools/targets.py).
"""
import argparse
import os
import re
import select
import shlex
import signal
import subprocess
import sys
import time
from xml.sax.saxutils import escape, quoteattr

# The machines that boot images (a profile is a machine's name): their
# commands, packages and exit-status rule are rows of the one table of
# targets, waftools/targets.py MACHINES.
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from waftools.targets import MACHINES  # noqa: E402

PROFILES = sorted(MACHINES)


def _expand(args, image=""):
    return [a.format(image=image, python=sys.executable, qemu=HERE)
            for a in args]


_prepared = set()


def prepare(profile):
    """Do once what the machine's "prepare" says it needs before its
    first image runs (nothing for the others)."""
    if "prepare" in MACHINES[profile] and profile not in _prepared:
        subprocess.run(_expand(MACHINES[profile]["prepare"]),
                       stdin=subprocess.DEVNULL,
                       stdout=subprocess.DEVNULL, check=True)
        _prepared.add(profile)


BEGIN_RE = re.compile(r"^\*\*\* BEGIN OF TEST (.+) \*\*\*$")
END_RE = re.compile(r"^\*\*\* END OF TEST (.+) \*\*\*$")
# Unity 2.5.1: FILE:LINE:TEST:PASS, or FILE:LINE:TEST:FAIL:MESSAGE
# (earlier releases used another separator before the message).
RESULT_RE = re.compile(r"^(?P<file>[^:]+):(?P<line>\d+):(?P<name>[A-Za-z_]\w*):"
                       r"(?P<result>PASS|FAIL|IGNORE)(?::(?P<message>.*))?$")
# Conformance digest (tests/golden): every image of a run must agree.
DIGEST_RE = re.compile(r"^\*\*\* GOLDEN DIGEST: (0x[0-9a-f]{8})$")
SUMMARY_RE = re.compile(r"^(\d+) Tests (\d+) Failures (\d+) Ignored\s*$")
# Lines that mean the program died: our boards' exception report and the
# host sanitizers' reports.
CRASH_RES = [re.compile(p) for p in (
    r"^\*\*\* EXCEPTION: ", r"ERROR: AddressSanitizer", r"ERROR: LeakSanitizer",
    r"runtime error: ")]
# Bytes allowed on the console: printable ASCII, tab, CR, LF.
ALLOWED = set(range(0x20, 0x7F)) | {0x09, 0x0A, 0x0D}


class Verdict:
    """What one image did and what the harness concluded."""

    def __init__(self, profile, image, label=None):
        self.label = label or profile
        self.profile = profile
        self.image = image
        self.results = []      # (file, line, name, result, message)
        self.reasons = []      # why the image failed, if it did
        self.console = ""
        self.exit_status = None
        self.seconds = 0.0
        self.digest = None     # the conformance digest the image printed

    @property
    def passed(self):
        return not self.reasons

    @property
    def name(self):
        return "%s.%s" % (self.label, os.path.splitext(os.path.basename(self.image))[0])

    def count(self, result):
        return sum(1 for r in self.results if r[3] == result)

    @property
    def test_failures(self):
        """failed tests, plus one when the image failed beyond its tests"""
        extra = any(not r.startswith("test failures:") for r in self.reasons)
        return self.count("FAIL") + (1 if extra else 0)


def command(profile, image, extra=()):
    """The command line that boots image on profile."""
    cmd = _expand(MACHINES[profile]["command"], os.path.abspath(image))
    cmd[1:1] = list(extra)
    return cmd


def boot(profile, image, inactivity, timeout, max_bytes, echo=None, extra=()):
    """Run an image; return (console bytes, exit status or None, why killed).
    `extra` arguments go to QEMU (e.g. -icount shift=0 for benchmarks)."""
    if profile not in PROFILES:
        raise SystemExit("harness: unknown profile %r (have %s)"
                         % (profile, ", ".join(PROFILES)))
    if not os.path.exists(image):
        return b"", None, "image not found: %s" % image
    prepare(profile)
    cmd = command(profile, image, extra)
    proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, start_new_session=True)
    fd = proc.stdout.fileno()
    data = bytearray()
    start = last = time.monotonic()
    killed = None
    while True:
        now = time.monotonic()
        wait = min(inactivity - (now - last), timeout - (now - start))
        if wait <= 0:
            killed = ("hang: no console output for %g s" % inactivity
                      if inactivity - (now - last) <= 0 else
                      "timeout: still running after %g s" % timeout)
            break
        ready, _, _ = select.select([fd], [], [], wait)
        if not ready:
            continue
        chunk = os.read(fd, 65536)
        if not chunk:
            break
        last = time.monotonic()
        data += chunk
        if echo:
            echo(chunk)
        if len(data) > max_bytes:
            killed = "console flood: more than %d bytes" % max_bytes
            break
    if killed:
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    status = proc.wait()
    proc.stdout.close()
    return bytes(data), (None if killed else status), killed


def judge(profile, image, data, status, killed, label=None):
    """Turn a console and an exit status into a Verdict."""
    v = Verdict(profile, image, label)
    v.exit_status = status
    if killed:
        v.reasons.append(killed)
    bad = next((i for i, b in enumerate(data) if b not in ALLOWED), None)
    if bad is not None:
        v.reasons.append("garbage on console: byte 0x%02x at offset %d"
                         % (data[bad], bad))
    text = data.decode("ascii", errors="replace")
    v.console = text
    lines = [l.rstrip("\r") for l in text.split("\n")]
    begin = end = summary = None
    summary_result = None
    for i, line in enumerate(lines):
        if any(r.search(line) for r in CRASH_RES):
            v.reasons.append("crash: " + line.strip())
        if BEGIN_RE.match(line) and begin is None:
            begin = i
        elif END_RE.match(line):
            end = i
        m = DIGEST_RE.match(line)
        if m:
            v.digest = m.group(1)
        m = RESULT_RE.match(line)
        if m and summary is None:
            v.results.append((m["file"], int(m["line"]), m["name"], m["result"],
                              m["message"] or ""))
            continue
        m = SUMMARY_RE.match(line)
        if m and summary is None:
            summary = tuple(int(x) for x in m.groups())
            summary_result = lines[i + 1].strip() if i + 1 < len(lines) else ""
    if begin is None:
        v.reasons.append("no BEGIN OF TEST marker: the image never started")
    if summary is None:
        v.reasons.append("no Unity summary")
    else:
        tests, failures, ignored = summary
        if tests != len(v.results) or failures != v.count("FAIL") \
                or ignored != v.count("IGNORE"):
            v.reasons.append("summary (%d tests, %d failures, %d ignored) does "
                             "not match the %d result lines" % (
                                 tests, failures, ignored, len(v.results)))
        if summary_result not in ("OK", "FAIL"):
            v.reasons.append("summary not followed by OK or FAIL")
        if failures:
            v.reasons.append("test failures: %d" % failures)
        elif summary_result == "OK" and end is None:
            v.reasons.append("no END OF TEST marker after a passing summary")
    if not killed and MACHINES[profile]["exit_status"]:
        expected = v.count("FAIL")
        if status != expected:
            v.reasons.append("exit status %s, expected %d" % (status, expected))
    return v


def junit(v):
    """JUnit XML of one image: a test case per Unity test, plus 'boot'."""
    cases = []
    for f, line, name, result, message in v.results:
        body = ""
        if result == "FAIL":
            body = "<failure message=%s>%s:%d</failure>" % (
                quoteattr(message), escape(f), line)
        elif result == "IGNORE":
            body = "<skipped/>"
        cases.append('  <testcase classname=%s name=%s>%s</testcase>' % (
            quoteattr(v.name + "." + os.path.splitext(os.path.basename(f))[0]),
            quoteattr(name), body))
    other = [r for r in v.reasons if not r.startswith("test failures:")]
    body = "<failure message=%s/>" % quoteattr("; ".join(other)) if other else ""
    cases.append('  <testcase classname=%s name="boot">%s</testcase>'
                 % (quoteattr(v.name), body))
    return ('<?xml version="1.0" encoding="UTF-8"?>\n'
            '<testsuite name=%s tests="%d" failures="%d" skipped="%d" time="%.3f">\n'
            '%s\n  <system-out>%s</system-out>\n</testsuite>\n' % (
                quoteattr(v.name), len(v.results) + 1, v.count("FAIL") + (1 if other else 0),
                v.count("IGNORE"), v.seconds, "\n".join(cases), escape(v.console)))


def run_image(profile, image, inactivity=10.0, timeout=300.0, max_bytes=8 << 20,
              label=None):
    t0 = time.monotonic()
    data, status, killed = boot(profile, image, inactivity, timeout, max_bytes)
    v = judge(profile, image, data, status, killed, label)
    v.seconds = time.monotonic() - t0
    return v


def cmd_run(args):
    passed = failed = 0
    digests = {}  # digest -> names of the images that printed it
    if args.junit_dir:
        os.makedirs(args.junit_dir, exist_ok=True)
    for spec in args.images:
        label, _, spec = spec.rpartition("=")
        profile, _, image = spec.partition(":")
        v = run_image(profile, image, args.inactivity, args.timeout, args.max_bytes,
                      label or None)
        for f, line, name, result, message in v.results:
            if result == "FAIL":
                print("  FAIL %s %s:%d %s: %s" % (v.name, f, line, name, message))
        if args.junit_dir:
            base = os.path.join(args.junit_dir, v.name)
            with open(base + ".xml", "w") as fh:
                fh.write(junit(v))
            with open(base + ".log", "w") as fh:
                fh.write(v.console)
        print("%s %-28s %4d tests %6.2f s%s" % (
            "PASS" if v.passed else "FAIL", v.name, len(v.results), v.seconds,
            "" if v.passed else "  (" + "; ".join(v.reasons) + ")"))
        passed += v.count("PASS")
        failed += v.test_failures
        if v.digest:
            digests.setdefault(v.digest, []).append(v.name)
    if len(digests) > 1:
        failed += 1
        print("FAIL conformance digests differ between targets: %s" % "; ".join(
            "%s on %s" % (d, ", ".join(names)) for d, names in sorted(digests.items())))
    elif digests:
        d, names = next(iter(digests.items()))
        print("PASS conformance digest %s on all %d images" % (d, len(names)))
    if args.note:
        print(args.note)
    print("%d passed, %d failed" % (passed, failed))
    return 0 if failed == 0 else 1


def cmd_show(args):
    def echo(chunk):
        sys.stdout.write(chunk.decode("ascii", errors="replace").replace("\r", ""))
        sys.stdout.flush()
    if args.profile in PROFILES:
        print("harness: running " + " ".join(
            shlex.quote(a) for a in command(args.profile, args.image)))
        sys.stdout.flush()
    data, status, killed = boot(args.profile, args.image, args.inactivity,
                                args.timeout, args.max_bytes, echo)
    text = data.decode("ascii", errors="replace")
    crash = [l for l in text.split("\n") if any(r.search(l) for r in CRASH_RES)]
    if killed or crash or (status not in (0, None)):
        print("harness: %s" % (killed or (crash[0] if crash else "exit status %s" % status)))
        return 1
    return 0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--inactivity", type=float, default=10.0,
                    help="seconds without console output that count as a hang")
    ap.add_argument("--timeout", type=float, default=300.0,
                    help="seconds an image may run in all")
    ap.add_argument("--max-bytes", type=int, default=8 << 20,
                    help="console bytes beyond which an image is flooding")
    sub = ap.add_subparsers(dest="command", required=True)
    r = sub.add_parser("run", help="judge Unity test images")
    r.add_argument("--junit-dir", help="write NAME.xml and NAME.log here")
    r.add_argument("--note", help="a line to print before the last (what "
                   "the images were built and run with)")
    r.add_argument("images", nargs="+", metavar="[LABEL=]PROFILE:IMAGE",
                   help="LABEL names the image in reports (default PROFILE)")
    s = sub.add_parser("show", help="stream the console of one image")
    s.add_argument("profile", choices=PROFILES)
    s.add_argument("image")
    args = ap.parse_args(argv)
    return cmd_run(args) if args.command == "run" else cmd_show(args)


if __name__ == "__main__":
    sys.exit(main())
