# SPDX-License-Identifier: BSD-2-Clause
"""python -m drdc: the `drdc` command (drdc/_cli.py)."""
import sys

from ._cli import main

sys.exit(main())
