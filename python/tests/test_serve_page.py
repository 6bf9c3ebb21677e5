# SPDX-License-Identifier: BSD-2-Clause
"""The service's page in headless Chromium (Debian's chromium, from
waftools/deps.py's "check" group), driven over the Chrome DevTools protocol
with aiohttp's websocket client: load the page, upload the host
test-runner's console log through the file input, click Judge and read
the verdict the page shows; paste a changed log and see it differ; type
degrees, metres and ISO times into conversions and compare what the
page shows, quantities with their units and the exact integers, with
the package's."""
import asyncio
import base64
import json
import os
import shutil
import subprocess
import tempfile
import time
import urllib.request

import aiohttp
import pytest

import drdc
from serve_helpers import Server, fast_limits, runner_log

CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu",
                  "--disable-quic", "--no-first-run",
                  "--disable-background-networking",
                  "--disable-component-update", "--disable-sync",
                  "--remote-debugging-port=0"]


def _chromium():
    path = shutil.which("chromium")
    if path is None:
        if os.environ.get("DRDC_REQUIRE_HOST_TOOLS"):
            pytest.fail("chromium is missing (waftools/deps.py, group check)")
        pytest.skip("no chromium")
    return path


class Page:
    """One page target over its DevTools websocket."""

    def __init__(self, ws):
        self.ws = ws
        self.next_id = 0

    async def call(self, method, **params):
        self.next_id += 1
        mine = self.next_id
        await self.ws.send_str(json.dumps({"id": mine, "method": method,
                                           "params": params}))
        while True:
            msg = json.loads((await self.ws.receive(timeout=60)).data)
            if msg.get("id") == mine:
                if "error" in msg:
                    raise RuntimeError("%s: %s" % (method, msg["error"]))
                return msg["result"]

    async def js(self, expression):
        r = await self.call("Runtime.evaluate", expression=expression,
                            returnByValue=True, awaitPromise=True)
        if "exceptionDetails" in r:
            raise RuntimeError(r["exceptionDetails"])
        return r["result"].get("value")

    async def until(self, expression, seconds=30):
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            value = await self.js(expression)
            if value:
                return value
            await asyncio.sleep(0.1)
        raise AssertionError("page never showed: " + expression)


def _devtools_port(profile, proc):
    """The port Chromium chose, from the file it writes into its profile."""
    path = os.path.join(profile, "DevToolsActivePort")
    end = time.monotonic() + 60
    while time.monotonic() < end:
        if proc.poll() is not None:
            raise RuntimeError("chromium exited with %d" % proc.returncode)
        if os.path.exists(path):
            lines = open(path).read().split()
            if lines:
                return int(lines[0])
        time.sleep(0.1)
    raise RuntimeError("chromium wrote no DevToolsActivePort")


def _page_socket(port, url):
    end = time.monotonic() + 30
    while time.monotonic() < end:
        with urllib.request.urlopen("http://127.0.0.1:%d/json/list" % port,
                                    timeout=10) as r:
            for t in json.load(r):
                if t.get("type") == "page" and t["url"].startswith(url):
                    return t["webSocketDebuggerUrl"]
        time.sleep(0.1)
    raise RuntimeError("no page target for " + url)


async def _drive(ws_url, log_path, log_text):
    async with aiohttp.ClientSession() as session:
        async with session.ws_connect(ws_url, max_msg_size=0) as ws:
            page = Page(ws)
            await page.until("document.body && document.body.dataset.ready")
            # upload: the file input, as a person choosing the log's file
            doc = await page.call("DOM.getDocument")
            node = await page.call("DOM.querySelector",
                                   nodeId=doc["root"]["nodeId"],
                                   selector="#log-file")
            await page.call("DOM.setFileInputFiles", files=[log_path],
                            nodeId=node["nodeId"])
            await page.until("document.getElementById('log').value"
                             ".includes('GOLDEN DIGEST')")
            await page.js("document.getElementById('judge').click()")
            uploaded = await page.until(
                "(t => t !== '-' && t !== 'judging...' && t)"
                "(document.getElementById('verdict').textContent)")
            rows = await page.js("document.querySelectorAll('#modules tr')"
                                 ".length")
            # paste: a log whose digest differs
            changed = log_text.replace("GOLDEN DIGEST: 0x7a79f8ad",
                                       "GOLDEN DIGEST: 0x00000000")
            await page.js("document.getElementById('log').value = %s; "
                          "document.getElementById('judge').click()"
                          % json.dumps(changed))
            pasted = await page.until(
                "(t => t.startsWith('differs') && t)"
                "(document.getElementById('verdict').textContent)")
            # conversions typed as a person types them: degrees, metres,
            # an ISO time, or the integers themselves
            conversions = {}
            for name, fields in CONVERSIONS:
                await page.js("document.getElementById('function').value = "
                              "%s; document.getElementById('function')"
                              ".dispatchEvent(new Event('change'))"
                              % json.dumps(name))
                for arg, (text, unit) in fields.items():
                    await page.js(
                        "document.getElementById('in-%s').value = %s; "
                        "document.getElementById('unit-%s').value = %s"
                        % (arg, json.dumps(text), arg, json.dumps(unit)))
                await page.js("document.getElementById('outputs')"
                              ".textContent = ''; document.getElementById("
                              "'result').textContent = ''; document."
                              "getElementById('evaluate').click()")
                await page.until(
                    "(t => (t.startsWith('{') || t.startsWith('error')) "
                    "&& t)(document.getElementById('result').textContent)")
                conversions[name] = await page.js(
                    "[...document.querySelectorAll('#outputs tr')].slice(1)"
                    ".map(r => [r.dataset.output, r.cells[2].textContent, "
                    "r.cells[3].textContent, r.cells[4].textContent])")
                conversions[name + " error"] = await page.js(
                    "document.getElementById('result').className")
            shot = os.environ.get("DRDC_SERVE_SCREENSHOT")
            if shot:
                png = await page.call("Page.captureScreenshot")
                with open(shot, "wb") as f:
                    f.write(base64.b64decode(png["data"]))
            return uploaded, rows, pasted, conversions


def test_page_in_headless_chromium():
    chromium = _chromium()
    log = runner_log()
    if log is None:
        pytest.skip("no host build (DRDC_HOST_BUILD)")
    srv = Server(fast_limits())
    work = tempfile.mkdtemp(prefix="drdc-serve-page-")
    profile = os.path.join(work, "profile")
    os.mkdir(profile)
    log_path = os.path.join(work, "test-runner.log")
    with open(log_path, "w") as f:
        f.write(log)
    proc = subprocess.Popen(
        [chromium] + CHROMIUM_FLAGS + ["--user-data-dir=" + profile,
                                       srv.url + "/"],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        port = _devtools_port(profile, proc)
        ws_url = _page_socket(port, srv.url)
        uploaded, rows, pasted, result = asyncio.run(
            asyncio.wait_for(_drive(ws_url, log_path, log), 120))
    finally:
        proc.terminate()
        try:
            proc.wait(30)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
        srv.stop()
        shutil.rmtree(work, ignore_errors=True)
    assert uploaded == ("conforms (digest 0x7a79f8ad, expected "
                        "0x7a79f8ad)")
    assert rows == 1 + len(drdc.conformance.reference_digests())
    assert pasted.startswith("differs (digest 0x00000000")
    # degrees typed: converted exactly as degrees_to_nas does, and each
    # output shown with its unit beside the exact integer
    u = drdc.geo_to_utm(drdc.degrees_to_nas("50.27"),
                        drdc.degrees_to_nas("-111.17"))
    rows = {r[0]: r[1:] for r in result["geo_to_utm"]}
    assert result["geo_to_utm error"] == ""
    assert rows["zone"] == ["12", "12", "DRDC_OK"]
    assert rows["easting_q47_16"] == [
        drdc.format_q47_16_array(u.easting_q47_16).item() + " m",
        str(u.easting_q47_16), "DRDC_OK"]
    assert rows["convergence_nas"][1] == str(u.convergence_nas)
    assert rows["convergence_nas"][0] == drdc.format_nas_degrees_array(
        u.convergence_nas).item() + " deg"
    # integers beyond 2^53 stay exact on the page (a JavaScript number
    # would round them)
    assert rows["scale_q5_58"][1] == str(u.scale_q5_58)
    assert u.scale_q5_58 > 1 << 53
    # metres typed
    g = drdc.geo_from_utm(12, True, drdc.metres_to_q47_16("487884.969"),
                          drdc.metres_to_q47_16("5568665.062"),
                          with_scale=True)
    rows = {r[0]: r[1:] for r in result["geo_from_utm"]}
    assert rows["lat_nas"][:2] == [
        drdc.format_nas_degrees_array(g.lat_nas).item() + " deg",
        str(g.lat_nas)]
    assert rows["scale_q5_58"][1] == str(g.scale_q5_58)
    # an ISO 8601 time typed, the leap second's half
    t = drdc.time_iso8601_parse("2016-12-31T23:59:60.5Z")
    gps = drdc.time_utc_to_gps(*t)
    rows = {r[0]: r[1:] for r in result["time_utc_to_gps"]}
    assert [rows["week"][1], rows["tow"][1], rows["nsec"][1]] == [
        str(gps.week), str(gps.tow), str(gps.nsec)]
    rows = {r[0]: r[1:] for r in result["time_gps_to_utc"]}
    assert rows["sec"][0] == "2016-12-31T23:59:60.500000000Z"
    assert rows["sec"][1] == str(t.sec)
    # a typing error is an error line, not a wrong number
    assert result["time_unix_to_utc error"] == "error"


CONVERSIONS = [
    ("geo_to_utm", {"lat_nas": ("50.27", "degrees"),
                    "lon_nas": ("-111.17", "degrees")}),
    ("geo_from_utm", {"zone": ("12", "integer"), "north": ("1", "integer"),
                      "easting_q47_16": ("487884.969", "metres"),
                      "northing_q47_16": ("5568665.062", "metres")}),
    ("time_utc_to_gps", {"sec": ("2016-12-31T23:59:60.5Z", "utc"),
                         "nsec": ("", "integer")}),
    ("time_gps_to_utc", {"week": ("1930", "integer"),
                         "tow": ("17", "integer"),
                         "nsec": ("500000000", "integer")}),
    ("time_unix_to_utc", {"sec": ("12.5", "integer")}),
]
