# SPDX-License-Identifier: BSD-2-Clause
"""The `drdc` command the wheel installs (a console script over
drdc/bin/drdc, the host tool compiled with the package's library) prints
what build/host/drdc prints, byte for byte, with its exit statuses:
`drdc nmea --keep-going` exits 0 on a real receiver log."""
import os
import shutil
import subprocess
import sys

import pytest

import drdc
from drdc import _cli
from cvectors import TOP
from test_host_tool import tool

LOG = os.path.join(TOP, "tests", "nmea", "logs", "nmea-0.8.0",
                   "nmea1-first-3000.log")


def console_script():
    """The installed `drdc`: beside the package for a --target install
    (python/check.py's), else on PATH (a virtual environment's)."""
    here = os.path.join(os.path.dirname(os.path.dirname(drdc.__file__)),
                        "bin", "drdc")
    if os.path.exists(here):
        return here
    found = shutil.which("drdc")
    if found is None:
        pytest.fail("no drdc console script beside %s nor on PATH" % here)
    return found


def run(cmd, data=b""):
    env = dict(os.environ)
    # the script's own Python must find the package: as pip installs it
    env["PYTHONPATH"] = os.pathsep.join(
        [os.path.dirname(os.path.dirname(drdc.__file__))]
        + [p for p in env.get("PYTHONPATH", "").split(os.pathsep) if p])
    return subprocess.run(cmd, input=data, capture_output=True, env=env,
                          timeout=120)


def test_the_wheel_holds_the_tool():
    assert os.access(_cli.TOOL, os.X_OK)
    with open(_cli.TOOL, "rb") as f:
        assert f.read(4) == b"\x7fELF"


@pytest.mark.parametrize("args", [
    ["nmea", "--keep-going"], ["nmea", "--keep-going", "--raw"],
    ["nmea"], ["nmea", "--strict", "--keep-going"]])
def test_the_console_script_is_the_host_tool(args):
    with open(LOG, "rb") as f:
        data = f.read()
    host = subprocess.run([tool("drdc")] + args, input=data,
                          capture_output=True)
    for cmd in ([console_script()], [sys.executable, "-m", "drdc"]):
        mine = run(cmd + args, data)
        assert mine.stdout == host.stdout
        assert mine.returncode == host.returncode
    expected = 0 if "--keep-going" in args else 1
    assert host.returncode == expected
    assert b"ERROR: " in host.stdout and b"type=GGA" in host.stdout


def test_exit_statuses_and_other_commands():
    script = console_script()
    # a usage error is 2, distinct from "some lines failed" (1)
    assert run([script, "nmea", "--no-such-option"]).returncode == 2
    assert run([script, "--version"]).stdout == subprocess.run(
        [tool("drdc"), "--version"], capture_output=True).stdout
    r = run([script, "geo", "-u", "-p", "4"], b"50.27 -111.17\n")
    assert r.returncode == 0
    assert r.stdout == subprocess.run(
        [tool("drdc"), "geo", "-u", "-p", "4"], input=b"50.27 -111.17\n",
        capture_output=True).stdout
    # a line that fails in `drdc time`: 1, its words as DrdcError's
    r = run([script, "time", "--from", "utc", "--to", "gps"],
            b"2017-02-30T00:00:00Z\n")
    assert r.returncode == 1
    with pytest.raises(drdc.DrdcError) as e:
        drdc.time_from_civil(2017, 2, 30)
    assert r.stdout.decode().strip() == "ERROR: %s (%s)" % (e.value.reason,
                                                           e.value.name)
