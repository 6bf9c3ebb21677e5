# SPDX-License-Identifier: BSD-2-Clause
"""The service on a free loopback port, in a thread of the test process
(its own event loop), and a small HTTP client over urllib: every test
talks real HTTP to it."""
import asyncio
import json
import os
import subprocess
import threading
import urllib.error
import urllib.request

from aiohttp import web

from drdc.serve.app import Limits, make_app

HOST_BUILD = os.environ.get("DRDC_HOST_BUILD", "")
RUNNER = os.path.join(HOST_BUILD, "fw", "test-runner", "test-runner")


class Chunks(list):
    """A body sent in chunks, without a Content-Length (urllib sends an
    iterable that way)."""


class Server:
    def __init__(self, limits):
        self.limits = limits
        self.loop = asyncio.new_event_loop()
        self.ready = threading.Event()
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()
        if not self.ready.wait(30):
            raise RuntimeError("the service did not start")
        self.url = "http://127.0.0.1:%d" % self.port

    def _run(self):
        asyncio.set_event_loop(self.loop)
        self.runner = web.AppRunner(make_app(self.limits), access_log=None)
        self.loop.run_until_complete(self.runner.setup())
        site = web.TCPSite(self.runner, "127.0.0.1", 0)
        self.loop.run_until_complete(site.start())
        self.port = site._server.sockets[0].getsockname()[1]
        self.ready.set()
        self.loop.run_forever()
        self.loop.run_until_complete(self.runner.cleanup())
        self.loop.close()

    def stop(self):
        self.loop.call_soon_threadsafe(self.loop.stop)
        self.thread.join(30)

    def request(self, method, path, body=None, content_type=None,
                headers=None):
        """(status, headers, decoded JSON or text) of one request."""
        data = body
        if isinstance(body, str):
            data = body.encode("utf-8")
        elif body is not None and not isinstance(body, (bytes, Chunks)):
            data = json.dumps(body).encode()
            content_type = content_type or "application/json"
        h = dict(headers or {})
        if content_type:
            h["Content-Type"] = content_type
        req = urllib.request.Request(self.url + path, data=data,
                                     method=method, headers=h)
        try:
            with urllib.request.urlopen(req, timeout=60) as r:
                status, hdrs, raw = r.status, dict(r.headers), r.read()
        except urllib.error.HTTPError as e:
            status, hdrs, raw = e.code, dict(e.headers), e.read()
        if hdrs.get("Content-Type", "").startswith("application/json"):
            return status, hdrs, json.loads(raw)
        return status, hdrs, raw.decode("utf-8", "replace")


def runner_log():
    """The host test-runner's console log, or None without a host build."""
    if not os.path.exists(RUNNER):
        return None
    return subprocess.run([RUNNER], capture_output=True, text=True,
                          timeout=300).stdout


def fast_limits():
    """Default limits, with a rate limit that a test's burst stays within."""
    return Limits(rate=10000.0, burst=10000.0)


def main():
    """A service for the fuzz run of docs/service.md (a rate limit above
    the fuzzer's pace: every request comes from 127.0.0.1)."""
    import argparse
    from drdc.serve.app import Limits
    ap = argparse.ArgumentParser(description=main.__doc__)
    ap.add_argument("--port", type=int, default=8080)
    args = ap.parse_args()
    web.run_app(make_app(Limits(rate=1e9, burst=1e9)), host="127.0.0.1",
                port=args.port, access_log=None)


if __name__ == "__main__":
    main()
