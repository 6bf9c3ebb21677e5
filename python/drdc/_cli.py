# SPDX-License-Identifier: BSD-2-Clause
"""The `drdc` command of the wheel: the host tool tools/drdc/, compiled
with the package's library into drdc/bin/drdc (python/build_backend.py),
so that `pip install ./python` puts the same command on PATH as `./waf
install` does. The console script only hands over to it: the tool's
output is its own, byte for byte, and its exit status too (`drdc nmea
--keep-going`: 0 once every line was read)."""
import os
import subprocess
import sys

TOOL = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bin", "drdc")


def main(argv=None):
    args = sys.argv[1:] if argv is None else list(argv)
    if not os.access(TOOL, os.X_OK):
        sys.stderr.write("drdc: %s is missing or not executable: reinstall "
                         "the package (pip install ./python)\n" % TOOL)
        return 2
    sys.stdout.flush()
    sys.stderr.flush()
    if argv is None and hasattr(os, "execv"):
        # the process becomes the tool: signals, pipes and the exit
        # status are its own
        os.execv(TOOL, [TOOL] + args)
    return subprocess.call([TOOL] + args)


if __name__ == "__main__":
    sys.exit(main())
