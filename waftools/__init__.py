# SPDX-License-Identifier: BSD-2-Clause
"""The build's own modules: the table of targets (targets.py), set-up
(deps.py), and the waf tools that wscript loads."""
