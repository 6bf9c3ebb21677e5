#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""./waf check's step for the Python package: pip installs ./python into a
throwaway folder under the build (never into the system), then pytest runs
python/tests against that install, the committed reference vectors and
the host build's tools.

  python/check.py [--build build]

pip runs without an index (--no-index): the package's build backend needs
no package and its one dependency, numpy, comes from PYTHONPATH
(.deps/python, pinned in waftools/deps.py) as pytest does, so the step
downloads nothing.
"""
import argparse
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(HERE)


def main():
    ap = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(TOP, "build"),
                    help="waf's build folder (default: build)")
    args = ap.parse_args()
    build = os.path.abspath(args.build)
    site = os.path.join(build, "python", "site")
    shutil.rmtree(site, ignore_errors=True)
    r = subprocess.call([sys.executable, "-m", "pip", "install", "--quiet",
                         "--disable-pip-version-check",
                         "--root-user-action=ignore", "--no-index",
                         "--no-deps", "--no-cache-dir", "--target", site,
                         HERE])
    if r != 0:
        print("python: pip install ./python failed")
        return 1
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        [site] + [os.path.abspath(p) for p in
                  env.get("PYTHONPATH", "").split(os.pathsep) if p])
    env["DRDC_HOST_BUILD"] = os.path.join(build, "host")
    env["DRDC_REQUIRE_HOST_TOOLS"] = "1"
    # from the install's folder, so that no drdc/ source folder shadows it
    return subprocess.call([sys.executable, "-m", "pytest", "-q",
                            "-p", "no:cacheprovider",
                            os.path.join(HERE, "tests")], cwd=site, env=env)


if __name__ == "__main__":
    sys.exit(main())
