#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""libFuzzer targets of tests/fuzz/ (built by the fuzz target's variant with
clang, AddressSanitizer and UndefinedBehaviorSanitizer).

  fuzz.py --replay            run every seed corpus input once (./waf check)
  fuzz.py --seconds N         fuzz each target for N seconds (./waf fuzz)

Seeds live in tests/fuzz/corpus/<name>/; new inputs found while fuzzing go
to build/fuzz/<name>/ (not the repository); crashes to build/fuzz/crashes/.
A finding is any crash, sanitizer report, leak or timeout.
"""
import argparse
import glob
import os
import re
import subprocess
import sys

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, TOP)
from waftools.targets import with_role  # noqa: E402

# the target that builds the fuzzers (its row's role "fuzz")
FUZZ_TARGET = with_role("fuzz")[0]


def targets(build):
    names = sorted(os.path.basename(p)[len("fuzz_"):-2]
                   for p in glob.glob(os.path.join(TOP, "tests", "fuzz", "fuzz_*.c")))
    return [(n, os.path.join(build, FUZZ_TARGET, "tests", "fuzz", "fuzz_" + n),
             os.path.join(TOP, "tests", "fuzz", "corpus", n)) for n in names]


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--replay", action="store_true")
    ap.add_argument("--seconds", type=int, default=60)
    args = ap.parse_args()
    build = os.path.abspath(args.build)
    crashes = os.path.join(build, "fuzz", "crashes") + os.sep
    os.makedirs(crashes, exist_ok=True)
    failed = 0
    for name, binary, corpus in targets(build):
        if not os.path.exists(binary):
            sys.exit("fuzz: %s not built (./waf build_%s)"
                     % (binary, FUZZ_TARGET))
        seeds = len(os.listdir(corpus)) if os.path.isdir(corpus) else 0
        if args.replay:
            cmd = [binary, "-runs=0", "-artifact_prefix=" + crashes, corpus]
        else:
            work = os.path.join(build, "fuzz", name)
            os.makedirs(work, exist_ok=True)
            cmd = [binary, "-max_total_time=%d" % args.seconds, "-print_final_stats=1",
                   "-timeout=5", "-artifact_prefix=" + crashes, work, corpus]
        r = subprocess.run(cmd, capture_output=True, text=True)
        log = r.stdout + r.stderr
        runs = re.findall(r"stat::number_of_executed_units:\s+(\d+)", log)
        done = re.findall(r"Done (\d+) runs", log)
        executions = int(runs[-1]) if runs else (int(done[-1]) if done else seeds)
        ok = r.returncode == 0
        failed += not ok
        print("%s fuzz_%-12s %d seed(s), %d execution(s)%s" % (
            "PASS" if ok else "FAIL", name, seeds, executions,
            "" if ok else "\n" + log[-3000:]))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
