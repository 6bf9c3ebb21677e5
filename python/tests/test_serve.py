# SPDX-License-Identifier: BSD-2-Clause
"""The gold-standard service over real HTTP on loopback: every endpoint,
results bit-equal to the package's functions and to the committed
reference vectors, every malformed request a 4xx JSON error, the limits
(body, batch, rate), the OpenAPI document equal to python/openapi.json,
and python -m drdc.serve's refusal to run as root."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

import drdc
from cvectors import TOP, load
from drdc.serve.app import Limits
from drdc.serve.functions import EXAMPLES, FUNCTIONS
from drdc.serve.limits import TokenBuckets
from serve_helpers import RUNNER, Chunks, Server, fast_limits, runner_log

OPENAPI = os.path.join(TOP, "python", "openapi.json")


@pytest.fixture(scope="module")
def srv():
    s = Server(fast_limits())
    yield s
    s.stop()


def ok(srv, function, inputs):
    status, _, body = srv.request("POST", "/v1/eval",
                                  {"function": function, "inputs": inputs})
    assert status == 200, body
    return body


def test_functions_lists_formats_accuracy_and_header(srv):
    status, _, body = srv.request("GET", "/v1/functions")
    assert status == 200
    names = [f["name"] for f in body["functions"]]
    assert names == [f.name for f in FUNCTIONS]
    assert len(names) == 14
    for f in body["functions"]:
        assert os.path.isfile(os.path.join(TOP, f["header"])), f["header"]
        with open(os.path.join(TOP, f["header"])) as h:
            assert f["c_function"] + "(" in h.read(), f["name"]
        assert f["accuracy"] and f["inputs"] and f["outputs"]
        assert all(a["format"] for a in f["inputs"] + f["outputs"])
        assert f["outputs"][-1]["name"] == "status"


@pytest.mark.parametrize("f", FUNCTIONS, ids=lambda f: f.name)
def test_every_example_equals_the_package(srv, f):
    body = ok(srv, f.name, EXAMPLES[f.name])
    arrays = {}
    for a in f.inputs:
        v = EXAMPLES[f.name].get(a.name, a.default)
        arrays[a.name] = (np.array(v) if a.kind in ("int", "text") else v)
    want = f.call(arrays)
    assert body["status"] == want.status.tolist()
    assert body["status_name"] == ["DRDC_OK"] * body["count"]
    for o in f.outputs:
        assert body["outputs"][o.name] == getattr(want, o.name).tolist()


def test_quantities_typed_are_converted_exactly(srv):
    body = ok(srv, "geo_to_utm", {"lat_nas": [{"degrees": "50.27"}, 0],
                                  "lon_nas": {"degrees": "-111.17"}})
    u = drdc.geo_to_utm_array([drdc.degrees_to_nas("50.27"), 0],
                              drdc.degrees_to_nas("-111.17"))
    assert body["outputs"]["easting_q47_16"] == u.easting_q47_16.tolist()
    assert body["exact"]["scale_q5_58"] == [str(v) for v in u.scale_q5_58]
    assert body["display"]["easting_q47_16"] == [
        t + " m" for t in drdc.format_q47_16_array(u.easting_q47_16)]
    assert body["display"]["convergence_nas"][0] == \
        drdc.format_nas_degrees_array(u.convergence_nas[0]).item() + " deg"
    # a UTC time typed carries its nanoseconds into nsec
    body = ok(srv, "time_utc_to_gps",
              {"sec": [{"utc": "2016-12-31T23:59:60.5Z"},
                       {"utc": "2017-01-01T00:00:00Z"}]})
    t = drdc.time_iso8601_parse_array(np.array(["2016-12-31T23:59:60.5Z",
                                                "2017-01-01T00:00:00Z"]))
    g = drdc.time_utc_to_gps_array(t.sec, t.nsec)
    assert body["outputs"]["tow"] == g.tow.tolist()
    assert body["outputs"]["nsec"] == g.nsec.tolist() == [500000000, 0]
    body = ok(srv, "geo_from_utm", {"zone": 12, "north": 1,
                                    "easting_q47_16": {"metres": "487884.5"},
                                    "northing_q47_16": {"metres": "5568665"}})
    assert body["status_name"] == ["DRDC_OK"]
    body = ok(srv, "units_convert", {"raw": [65536], "from_frac": 16,
                                     "from_unit": "ft", "to_frac": 16,
                                     "to_unit": "m"})
    v = drdc.units_convert(65536, 16, "ft", 16, "m")
    assert body["display"]["value"] == [
        drdc.format_q47_16_array(v).item() + " m"]
    # refused: not decimal text, a quantity the argument does not take,
    # a time the library refuses, nsec beside a utc
    for function, inputs in (
            ("geo_to_utm", {"lat_nas": {"degrees": "1e3"}, "lon_nas": 0}),
            ("geo_to_utm", {"lat_nas": {"degrees": 50.27}, "lon_nas": 0}),
            ("geo_to_utm", {"lat_nas": {"metres": "5"}, "lon_nas": 0}),
            ("geo_to_utm", {"lat_nas": 0, "lon_nas": 0,
                            "zone": {"degrees": "5"}}),
            ("time_utc_to_gps", {"sec": {"utc": "2017-02-30T00:00:00Z"}}),
            ("time_utc_to_gps", {"sec": {"utc": "2017-01-01T00:00:00Z"},
                                 "nsec": 5})):
        status, _, answer = srv.request("POST", "/v1/eval", {
            "function": function, "inputs": inputs})
        assert status == 400, (inputs, answer)
        assert answer["error"]["reason"]


def test_geo_to_utm_equals_the_geographiclib_vectors(srv):
    rows = load("tests/geo/vectors_geo.h")["geo_random_vectors"][:200]
    body = ok(srv, "geo_to_utm", {"lat_nas": [r["lat"] for r in rows],
                                  "lon_nas": [r["lon"] for r in rows]})
    assert body["count"] == len(rows)
    assert set(body["status"]) == {0}
    out = body["outputs"]
    assert out["zone"] == [r["zone"] for r in rows]
    for name, field in (("easting_q47_16", "easting"),
                        ("northing_q47_16", "northing")):
        # the C suite's bound: 1 LSB of Q47.16 against GeoConvert
        d = np.abs(np.array(out[name]) - [r[field] for r in rows])
        assert d.max() <= 1, name
    # and bit for bit the package's array function
    u = drdc.geo_to_utm_array([r["lat"] for r in rows],
                              [r["lon"] for r in rows])
    assert out["easting_q47_16"] == u.easting_q47_16.tolist()
    assert out["scale_q5_58"] == u.scale_q5_58.tolist()


def test_mgrs_decode_gives_the_vectors_statuses(srv):
    rows = load("tests/geo/vectors_mgrs.h")["mgrs_dec_vectors"][:300]
    body = ok(srv, "geo_mgrs_decode", {"text": [r["text"] for r in rows]})
    assert body["status"] == [r["status"] for r in rows]
    for i, r in enumerate(rows):
        if r["status"] == 0:
            assert body["outputs"]["easting_q47_16"][i] == r["easting"]
            assert body["outputs"]["northing_q47_16"][i] == r["northing"]
        else:
            assert body["outputs"]["zone"][i] == 0


def test_quaternion_header_example_and_statuses(srv):
    # orient.h: yaw 90 degrees is { 759250125, 0, 0, 759250125 }
    q = ok(srv, "quat_from_euler", {"yaw_bam32": 1 << 30, "pitch_bam32": 0,
                                    "roll_bam32": 0})["outputs"]
    assert [q[k][0] for k in "sxyz"] == [759250125, 0, 0, 759250125]
    e = ok(srv, "euler_from_quat", {"s_q1_30": [759250125, 0],
                                    "x_q1_30": 0, "y_q1_30": 0,
                                    "z_q1_30": [759250125, 0]})
    assert e["outputs"]["yaw"] == [1 << 30, 0]
    assert e["status_name"] == ["DRDC_OK", "DRDC_E_DOMAIN"]


def test_time_round_trip_with_a_leap_second(srv):
    # 2016-12-31T23:59:60.5: the sec of 23:59:59 with 1.5e9 ns
    leap = drdc.time_from_civil(2016, 12, 31, 23, 59, 60, 500000000)
    g = ok(srv, "time_utc_to_gps", {"sec": [leap.sec], "nsec": [leap.nsec]})
    want = drdc.time_utc_to_gps(leap.sec, leap.nsec)
    assert [g["outputs"][k][0] for k in ("week", "tow", "nsec")] == \
        list(want)
    u = ok(srv, "time_gps_to_utc", {"week": g["outputs"]["week"],
                                    "tow": g["outputs"]["tow"],
                                    "nsec": g["outputs"]["nsec"]})
    assert (u["outputs"]["sec"][0], u["outputs"]["nsec"][0]) == tuple(leap)


def test_units_against_the_gnu_units_vectors(srv):
    rows = load("tests/units/vectors_units.h")["units_vectors"]
    groups = {}
    for r in rows:
        groups.setdefault((r["from"], r["to"], r["from_frac"],
                           r["to_frac"]), []).append(r)
    # a few unit pairs, each one batch: within GNU units' 1 LSB
    for (a, b, ff, tf), rs in sorted(groups.items())[::max(
            1, len(groups) // 12)]:
        body = ok(srv, "units_convert", {
            "raw": [r["raw"] for r in rs], "from_frac": ff, "from_unit": a,
            "to_frac": tf, "to_unit": b})
        got = body["outputs"]["value"]
        assert max(abs(g - r["expect"]) for g, r in zip(got, rs)) <= 1
        assert got == drdc.units_convert_array(
            [r["raw"] for r in rs], ff, a, tf, b).value.tolist()
    # a unit of another dimension is each element's status, not a refusal
    body = ok(srv, "units_convert", {"raw": [1, 2], "from_frac": 0,
                                     "from_unit": "ft", "to_frac": 0,
                                     "to_unit": "s"})
    assert body["status_name"] == ["DRDC_E_DIMENSION"] * 2
    assert body["outputs"]["value"] == [0, 0]


MALFORMED = [
    ("POST", "/v1/eval", b"{", "application/json"),
    ("POST", "/v1/eval", b"[" * 100000, "application/json"),
    ("POST", "/v1/eval", b"\xff\xfe", "application/json"),
    ("POST", "/v1/eval", b"1" * 5000, "application/json"),
    ("POST", "/v1/eval", b"{}", "text/plain"),
    ("POST", "/v1/eval", b"", "application/json"),
    ("POST", "/v1/eval", b"null", "application/json"),
    ("POST", "/v1/eval", b"[]", "application/json"),
    ("POST", "/v1/eval", b'{"function": "nope", "inputs": {}}',
     "application/json"),
    ("POST", "/v1/eval", b'{"function": 7, "inputs": {}}',
     "application/json"),
    ("POST", "/v1/eval", b'{"function": "geo_to_utm"}', "application/json"),
    ("POST", "/v1/eval", b'{"function": "geo_to_utm", "inputs": []}',
     "application/json"),
    ("POST", "/v1/eval", b'{"function": "geo_to_utm", "inputs": {}, '
     b'"x": 1}', "application/json"),
    ("POST", "/v1/eval", b'{"function": "geo_to_utm", "inputs": '
     b'{"lat_nas": 1.5, "lon_nas": 0}}', "application/json"),
    ("POST", "/v1/eval", b'{"function": "geo_to_utm", "inputs": '
     b'{"lat_nas": true, "lon_nas": 0}}', "application/json"),
    ("POST", "/v1/eval", b'{"function": "geo_to_utm", "inputs": '
     b'{"lat_nas": [1, 2], "lon_nas": [1, 2, 3]}}', "application/json"),
    ("POST", "/v1/eval", b'{"function": "geo_to_utm", "inputs": '
     b'{"lat_nas": [[1]], "lon_nas": 0}}', "application/json"),
    ("POST", "/v1/eval", b'{"function": "geo_to_utm", "inputs": '
     b'{"lat_nas": 9223372036854775808, "lon_nas": 0}}',
     "application/json"),
    ("POST", "/v1/eval", b'{"function": "geo_to_utm", "inputs": '
     b'{"lat_nas": "1", "lon_nas": 0}}', "application/json"),
    ("POST", "/v1/eval", b'{"function": "geo_to_utm", "inputs": '
     b'{"lat_nas": 0, "lon_nas": 0, "zone": 2147483648}}',
     "application/json"),
    ("POST", "/v1/eval", b'{"function": "geo_to_utm", "inputs": '
     b'{"lat_nas": 0, "lon_nas": 0, "height": 1}}', "application/json"),
    ("POST", "/v1/eval", b'{"function": "geo_mgrs_decode", "inputs": '
     b'{"text": [1]}}', "application/json"),
    ("POST", "/v1/eval", b'{"function": "geo_mgrs_decode", "inputs": '
     b'{"text": "' + b"A" * 65 + b'"}}', "application/json"),
    ("POST", "/v1/eval", b'{"function": "quat_from_euler", "inputs": '
     b'{"yaw_bam32": -2147483649, "pitch_bam32": 0, "roll_bam32": 0}}',
     "application/json"),
    ("POST", "/v1/eval", b'{"function": "units_convert", "inputs": '
     b'{"raw": 1, "from_frac": -1, "from_unit": "ft", "to_frac": 0, '
     b'"to_unit": "m"}}', "application/json"),
    ("POST", "/v1/eval", b'{"function": "units_convert", "inputs": '
     b'{"raw": 1, "from_frac": 0, "from_unit": "no such unit", '
     b'"to_frac": 0, "to_unit": "m"}}', "application/json"),
    ("POST", "/v1/eval", b'{"function": "units_convert", "inputs": '
     b'{"raw": 1, "from_frac": 0, "from_unit": ["ft"], "to_frac": 0, '
     b'"to_unit": "m"}}', "application/json"),
    ("POST", "/v1/conformance", b"no digest in here", "text/plain"),
    ("POST", "/v1/conformance", b"\xff\xfe\xfd", "text/plain"),
    ("POST", "/v1/conformance", b'{"log": 1}', "application/json"),
    ("POST", "/v1/conformance", b'{"text": ""}', "application/json"),
    ("POST", "/v1/conformance", b"x", "image/png"),
    ("POST", "/v1/conformance", b"x", None),
    ("GET", "/v1/eval", None, None),
    ("PUT", "/v1/functions", b"x", "text/plain"),
    ("GET", "/../../etc/passwd", None, None),
    ("GET", "/static/../python/openapi.json", None, None),
    ("GET", "/nope", None, None),
]


@pytest.mark.parametrize("method,path,body,ctype", MALFORMED)
def test_malformed_requests_are_4xx_json(srv, method, path, body, ctype):
    status, headers, answer = srv.request(method, path, body, ctype)
    assert 400 <= status < 500, (status, answer)
    assert headers["Content-Type"].startswith("application/json")
    assert answer["error"]["status"] == status
    assert answer["error"]["reason"]


def test_body_and_batch_caps(srv):
    big = b'{"function": "geo_to_utm", "inputs": {"lat_nas": [' + \
        b"0, " * (1 << 19) + b'0], "lon_nas": 0}}'
    status, _, answer = srv.request("POST", "/v1/eval", big,
                                    "application/json")
    assert status == 413 and answer["error"]["status"] == 413
    # no Content-Length to refuse up front: the cap while reading
    status, _, answer = srv.request("POST", "/v1/conformance",
                                    Chunks([b"a" * (1 << 19)] * 3),
                                    "text/plain")
    assert status == 413 and answer["error"]["status"] == 413
    n = Limits().batch + 1
    status, _, answer = srv.request(
        "POST", "/v1/eval", {"function": "time_utc_to_gps",
                             "inputs": {"sec": [0] * n}})
    assert status == 422, answer
    assert "at most %d" % Limits().batch in answer["error"]["reason"]
    # the cap itself is accepted
    body = ok(srv, "time_utc_to_gps", {"sec": [0] * (n - 1)})
    assert body["count"] == n - 1


def test_committed_openapi_is_served():
    # the default limits: the document served equals the committed one
    s = Server(Limits())
    try:
        status, _, served = s.request("GET", "/openapi.json")
    finally:
        s.stop()
    assert status == 200
    with open(OPENAPI) as f:
        assert served == json.load(f), \
            "python -m drdc.serve --openapi > python/openapi.json"


def test_rate_limit_429_per_client():
    # a token every 100 s: the burst of 5, then 429 however slow the
    # machine runs the test
    s = Server(Limits(rate=0.01, burst=5))
    try:
        statuses = [s.request("GET", "/v1/functions")[0] for _ in range(8)]
        status, headers, answer = s.request("POST", "/v1/eval", b"{",
                                            "application/json")
    finally:
        s.stop()
    assert statuses == [200] * 5 + [429] * 3
    # refused before the body is read, with the wait for the next token
    assert status == 429 and answer["error"]["status"] == 429
    assert 1 <= int(headers["Retry-After"]) <= 100


def test_conformance_verdicts(srv):
    log = runner_log()
    if log is None:
        pytest.skip("no host build (DRDC_HOST_BUILD)")
    for status, _, v in (srv.request("POST", "/v1/conformance", log,
                                     "text/plain"),
                         srv.request("POST", "/v1/conformance",
                                     {"log": log})):
        assert status == 200, v
        assert v["verdict"] == "conforms"
        assert v["digest"] == {"expected": "0x7a79f8ad",
                               "got": "0x7a79f8ad"}
        assert {m["verdict"] for m in v["modules"]} == {"equal"}
    changed = log.replace("GOLDEN DIGEST: 0x7a79f8ad",
                          "GOLDEN DIGEST: 0x6d842394")
    assert changed != log
    status, _, v = srv.request("POST", "/v1/conformance", changed,
                               "text/plain")
    assert status == 200 and v["verdict"] == "differs"


def test_conformance_names_a_planted_lsb(srv):
    """The port of test-runner-broken (GOLDEN_BREAK_TO_UTM: the easting
    of drdc_geo_to_utm one LSB up) through the service: the geo module
    differs, and the first difference is that function at its first
    accepted input, the record test_conformance.py works out on its own
    from the golden generator."""
    path = RUNNER + "-broken"
    if not os.path.exists(path):
        pytest.skip("no host build (DRDC_HOST_BUILD)")
    log = subprocess.run([path], capture_output=True, text=True,
                         timeout=300).stdout
    status, _, v = srv.request("POST", "/v1/conformance", log, "text/plain")
    assert status == 200, v
    assert v["verdict"] == "differs"
    differs = [m for m in v["modules"] if m["verdict"] == "differs"]
    assert [m["name"] for m in differs] == ["geo"]
    first = differs[0]["first_difference"]
    assert first["function"] == "drdc_geo_to_utm"
    assert first["record"] == 3
    assert first["input"].startswith(
        "lat_nas=57877737200000, lon_nas=-898800195000000")
    assert int(first["got"], 16) == int(first["expected"], 16) + 1


def test_page_is_self_contained(srv):
    status, headers, page = srv.request("GET", "/")
    assert status == 200 and headers["Content-Type"].startswith("text/html")
    assert "default-src 'none'" in headers["Content-Security-Policy"]
    # nothing from another origin: no http(s) URL at all in the page
    assert "http://" not in page and "https://" not in page
    assert 'id="verdict"' in page


def test_module_refuses_root_without_the_flag():
    env = dict(os.environ)
    r = subprocess.run([sys.executable, "-m", "drdc.serve", "--port", "0"]
                       + ([] if os.geteuid() == 0 else ["--help"]),
                       capture_output=True, text=True, env=env, timeout=60)
    if os.geteuid() == 0:
        assert r.returncode == 2
        assert "refusing to run as root" in r.stderr
    else:
        assert r.returncode == 0


def test_module_without_aiohttp_says_what_to_install(tmp_path):
    """The package alone, as `pip install ./python` leaves it: numpy but
    no aiohttp on the path. python -m drdc.serve names the extra to
    install, in one message and no traceback."""
    import numpy
    import drdc
    for module in (numpy, drdc):
        folder = os.path.dirname(module.__file__)
        os.symlink(folder, tmp_path / os.path.basename(folder))
    libs = os.path.join(os.path.dirname(os.path.dirname(numpy.__file__)),
                        "numpy.libs")
    if os.path.isdir(libs):
        os.symlink(libs, tmp_path / "numpy.libs")
    env = dict(os.environ, PYTHONPATH=str(tmp_path))
    probe = subprocess.run([sys.executable, "-c", "import aiohttp"],
                           env=env, capture_output=True, cwd=tmp_path)
    assert probe.returncode != 0  # the path has no aiohttp indeed
    r = subprocess.run([sys.executable, "-m", "drdc.serve", "--port", "0"],
                       capture_output=True, text=True, env=env, timeout=60,
                       cwd=tmp_path)
    assert r.returncode == 1
    assert "pip install 'drdc[serve]'" in r.stderr
    assert "Traceback" not in r.stderr and r.stdout == ""


def test_timeout_answers_503_json():
    # 10 000 geo_to_utm take about 13 ms in the library alone
    s = Server(Limits(rate=1e9, burst=1e9, timeout=0.001))
    try:
        status, _, answer = s.request("POST", "/v1/eval", {
            "function": "geo_to_utm",
            "inputs": {"lat_nas": list(range(10000)), "lon_nas": 0}})
    finally:
        s.stop()
    assert status == 503, answer
    assert answer["error"]["reason"] == "request took more than 0.001 s"


def test_token_bucket_refills_and_forgets():
    now = [0.0]
    b = TokenBuckets(rate=2.0, burst=3.0, max_clients=4,
                     clock=lambda: now[0])
    assert [b.take("a")[0] for _ in range(4)] == [True, True, True, False]
    assert b.take("a") == (False, 0.5)
    now[0] += 0.5  # one token back
    assert b.take("a") == (True, 0.0)
    assert b.take("a")[0] is False
    for c in "bcd":
        b.take(c)
    now[0] += 10.0  # every bucket full again: all of them may go
    b.take("e")
    assert set(b.buckets) == {"e"}
