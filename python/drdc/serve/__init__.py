# SPDX-License-Identifier: BSD-2-Clause
"""The gold-standard web service: the library's exact integers and the
conformance verdict of a test-runner log over HTTP (docs/service.md).

    python -m drdc.serve [--host 127.0.0.1] [--port 8080]

Endpoints: GET / (the page), GET /openapi.json, GET /v1/functions,
POST /v1/eval, POST /v1/conformance. Needs aiohttp (pinned in
waftools/deps.py) besides numpy."""
