#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Bounded load test of the gold-standard service (docs/service.md):
`--clients` concurrent clients, each sending one request after another for
`--seconds`, then it stops by itself. Loopback only: it refuses any URL
whose host is not a loopback address.

  python3 tools/serve_load.py [--url http://127.0.0.1:8080] [--clients 16]
                              [--seconds 60]

The requests cycle through the kinds of a real client: a batch of 100
geo_to_utm, a batch of 100 GPS times, one MGRS decode, the function
table. Prints requests a second, p50/p99 latency and the count of
errors (any answer other than 200, or no answer); exit status 1 when
there was an error. Start the server with a rate limit above the load
(every client is 127.0.0.1): --rate 1e9 --burst 1e9.
"""
import argparse
import asyncio
import ipaddress
import json
import sys
import time
import urllib.parse

import aiohttp

NAS = 3600000000000
REQUESTS = [
    ("POST", "/v1/eval", {"function": "geo_to_utm", "inputs": {
        "lat_nas": [(i * 7919 % 160 - 80) * NAS for i in range(100)],
        "lon_nas": [(i * 104729 % 360 - 180) * NAS for i in range(100)]}}),
    ("POST", "/v1/eval", {"function": "time_utc_to_gps", "inputs": {
        "sec": [1795453201 + 3600 * i for i in range(100)]}}),
    ("POST", "/v1/eval", {"function": "geo_mgrs_decode", "inputs": {
        "text": ["12UVA8788568665"]}}),
    ("GET", "/v1/functions", None),
]


def _loopback(url):
    host = urllib.parse.urlsplit(url).hostname or ""
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


async def _client(session, url, end, latencies, errors, k):
    while time.monotonic() < end:
        method, path, body = REQUESTS[k % len(REQUESTS)]
        k += 1
        data = None if body is None else json.dumps(body)
        t0 = time.perf_counter()
        try:
            async with session.request(
                    method, url + path, data=data,
                    headers={"Content-Type": "application/json"}
                    if data else None) as r:
                await r.read()
                ok = r.status == 200
        except (aiohttp.ClientError, asyncio.TimeoutError):
            ok = False
        latencies.append(time.perf_counter() - t0)
        if not ok:
            errors.append(path)


async def run(url, clients, seconds):
    latencies, errors = [], []
    timeout = aiohttp.ClientTimeout(total=30)
    conn = aiohttp.TCPConnector(limit=clients)
    async with aiohttp.ClientSession(timeout=timeout,
                                     connector=conn) as session:
        start = time.monotonic()
        end = start + seconds
        await asyncio.gather(*(_client(session, url, end, latencies, errors,
                                       i) for i in range(clients)))
        elapsed = time.monotonic() - start
    return latencies, errors, elapsed


def percentile(sorted_values, p):
    if not sorted_values:
        return float("nan")
    i = min(len(sorted_values) - 1, int(p / 100.0 * len(sorted_values)))
    return sorted_values[i]


def main():
    ap = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--url", default="http://127.0.0.1:8080")
    ap.add_argument("--clients", type=int, default=16)
    ap.add_argument("--seconds", type=float, default=60.0)
    args = ap.parse_args()
    if not _loopback(args.url):
        sys.exit("serve_load: loopback addresses only, not %s" % args.url)
    if not (1 <= args.clients <= 256 and 0 < args.seconds <= 600):
        sys.exit("serve_load: 1..256 clients, at most 600 s")
    latencies, errors, elapsed = asyncio.run(
        run(args.url.rstrip("/"), args.clients, args.seconds))
    lat = sorted(latencies)
    print("%d clients, %.1f s: %d requests, %.0f requests/s, "
          "p50 %.1f ms, p99 %.1f ms, max %.1f ms, %d errors"
          % (args.clients, elapsed, len(lat), len(lat) / elapsed,
             1000 * percentile(lat, 50), 1000 * percentile(lat, 99),
             1000 * (lat[-1] if lat else float("nan")), len(errors)))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
