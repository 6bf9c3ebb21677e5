# SPDX-License-Identifier: BSD-2-Clause
"""The aiohttp application: routes, limits and JSON errors.

Order of the middlewares, outermost first: every answer that is an error
becomes {"error": {"status", "reason"}} JSON (also aiohttp's own 404,
405, 413); the rate limit answers 429 before any body is read; the
timeout bounds the whole handler, body reading included. The library
calls run in a worker thread so that the timeout can answer while a
batch is still computing (the batch cap bounds how long that goes on)."""
import asyncio
import json
import logging
import os
from dataclasses import dataclass

from aiohttp import web

from . import evaluate as ev
from .functions import FUNCTIONS, describe
from .limits import TokenBuckets
from .openapi import document

LOG = logging.getLogger("drdc.serve")
HERE = os.path.dirname(os.path.abspath(__file__))
# the page needs nothing from elsewhere: no script, style, font or image
# from another origin, no frame, no form posted anywhere
CSP = ("default-src 'none'; script-src 'unsafe-inline'; "
       "style-src 'unsafe-inline'; connect-src 'self'; "
       "form-action 'none'; frame-ancestors 'none'; base-uri 'none'")


@dataclass
class Limits:
    body_bytes: int = 1 << 20      # request body cap
    batch: int = 10000             # elements of one /v1/eval request
    rate: float = 10.0             # tokens a second per client address
    burst: float = 40.0            # bucket size per client address
    timeout: float = 10.0          # seconds for one request, body included
    max_clients: int = 10000       # addresses the rate limiter remembers


def _error(status, reason, headers=None):
    return web.json_response({"error": {"status": status, "reason": reason}},
                             status=status, headers=headers)


@web.middleware
async def json_errors(request, handler):
    try:
        return await handler(request)
    except ev.RequestError as e:
        return _error(e.status, e.reason)
    except web.HTTPException as e:
        if e.status < 400:
            raise
        return _error(e.status, e.reason, headers={
            k: v for k, v in e.headers.items() if k in ("Allow",
                                                         "Retry-After")})
    except asyncio.CancelledError:
        raise
    except Exception:  # a defect of the service, never the client's input
        LOG.exception("internal error on %s %s", request.method,
                      request.path)
        return _error(500, "internal error")


def rate_limit(buckets):
    @web.middleware
    async def middleware(request, handler):
        ok, wait = buckets.take(request.remote or "?")
        if not ok:
            retry = max(1, int(wait + 0.999))
            return _error(429, "rate limit: %g requests a second per "
                          "client, bursts of %g" % (buckets.rate,
                                                    buckets.burst),
                          headers={"Retry-After": str(retry)})
        return await handler(request)
    return middleware


def timeout(seconds):
    @web.middleware
    async def middleware(request, handler):
        try:
            return await asyncio.wait_for(handler(request), seconds)
        except asyncio.TimeoutError:
            return _error(503, "request took more than %g s" % seconds)
    return middleware


@web.middleware
async def headers(request, handler):
    response = await handler(request)
    response.headers.setdefault("X-Content-Type-Options", "nosniff")
    response.headers.setdefault("Cache-Control", "no-store")
    return response


async def _body(request, limits):
    """The body as bytes, refused before reading when it says it is too
    big (aiohttp's client_max_size refuses the rest while reading)."""
    if request.content_length is not None and \
            request.content_length > limits.body_bytes:
        raise ev.RequestError(413, "body of %d bytes, at most %d"
                              % (request.content_length, limits.body_bytes))
    return await request.read()


def _json(raw):
    try:
        return json.loads(raw.decode("utf-8"))
    except UnicodeDecodeError:
        raise ev.RequestError(400, "the body is not UTF-8 text") from None
    except RecursionError:
        raise ev.RequestError(400, "JSON nested too deeply") from None
    except ValueError as e:
        # JSONDecodeError, and integers of more than 4 300 digits
        raise ev.RequestError(400, "malformed JSON: %s" % e) from None


def _media_type(request):
    return request.content_type.lower()


def make_app(limits=None):
    limits = limits or Limits()
    buckets = TokenBuckets(limits.rate, limits.burst, limits.max_clients)
    app = web.Application(
        client_max_size=limits.body_bytes,
        middlewares=[json_errors, headers, rate_limit(buckets),
                     timeout(limits.timeout)])
    openapi = document(limits)
    functions = {"functions": [describe(f) for f in FUNCTIONS]}
    with open(os.path.join(HERE, "page.html"), "rb") as f:
        page = f.read()

    async def index(request):
        return web.Response(body=page, content_type="text/html",
                            charset="utf-8",
                            headers={"Content-Security-Policy": CSP})

    async def get_openapi(request):
        return web.json_response(openapi)

    async def get_functions(request):
        return web.json_response(functions)

    async def post_eval(request):
        if _media_type(request) != "application/json":
            raise ev.RequestError(415, "Content-Type: application/json")
        body = _json(await _body(request, limits))
        loop = asyncio.get_running_loop()
        result = await loop.run_in_executor(None, ev.evaluate, body,
                                            limits.batch)
        return web.json_response(result)

    async def post_conformance(request):
        media = _media_type(request)
        raw = await _body(request, limits)
        if media == "application/json":
            body = _json(raw)
            if not isinstance(body, dict) or set(body) != {"log"} or \
                    not isinstance(body["log"], str):
                raise ev.RequestError(400, "the body is {\"log\": \"<the "
                                      "test-runner's console text>\"}")
            text = body["log"]
        elif media == "text/plain":
            try:
                text = raw.decode("utf-8")
            except UnicodeDecodeError:
                raise ev.RequestError(400, "the log is not UTF-8 "
                                      "text") from None
        else:
            raise ev.RequestError(415, "Content-Type: text/plain (the log) "
                                  "or application/json ({\"log\": ...})")
        try:
            from .. import conformance
        except ImportError:
            raise ev.RequestError(503, "the conformance judge "
                                  "(drdc.conformance) is not "
                                  "installed") from None
        loop = asyncio.get_running_loop()
        try:
            verdict = await loop.run_in_executor(None, conformance.judge,
                                                 text)
        except ValueError as e:
            raise ev.RequestError(422, "not a test-runner log: %s"
                                  % e) from None
        return web.json_response(verdict)

    app.router.add_get("/", index)
    app.router.add_get("/openapi.json", get_openapi)
    app.router.add_get("/v1/functions", get_functions)
    app.router.add_post("/v1/eval", post_eval)
    app.router.add_post("/v1/conformance", post_conformance)
    return app
