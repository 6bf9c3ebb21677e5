#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""The API reference (docs/Doxyfile over the public headers) without a
warning: Doxygen writes it all and then fails on any warning
(WARN_AS_ERROR = FAIL_ON_WARNINGS), so an undocumented symbol or
parameter fails ./waf check and ./waf docs.

  tools/gates/doxygen.py
"""
import os
import subprocess
import sys

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

if __name__ == "__main__":
    sys.exit(subprocess.call(["doxygen", "docs/Doxyfile"], cwd=TOP))
