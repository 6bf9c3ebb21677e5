# SPDX-License-Identifier: BSD-2-Clause
"""drdc.conformance: the host runner's log conforms; the log of a port
with drdc_geo_to_utm one LSB off (build/host/fw/test-runner/
test-runner-broken, GOLDEN_BREAK_TO_UTM) names that function and the
golden input; malformed logs give ValueError or "incomplete".

The runners need `./waf build_host`; without it those tests are
skipped, unless DRDC_REQUIRE_HOST_TOOLS is set (./waf check sets it)."""
import os
import random
import re
import subprocess

import pytest

import drdc
from drdc import conformance
from cvectors import TOP

BUILD = os.environ.get("DRDC_HOST_BUILD", os.path.join(TOP, "build", "host"))


def runner_log(name):
    path = os.path.join(BUILD, "fw", "test-runner", name)
    if not os.access(path, os.X_OK):
        message = "%s not built (./waf build_host)" % path
        if os.environ.get("DRDC_REQUIRE_HOST_TOOLS"):
            pytest.fail(message)
        pytest.skip(message)
    r = subprocess.run([path], capture_output=True, text=True, timeout=300)
    return r.stdout


@pytest.fixture(scope="module")
def host_log():
    return runner_log("test-runner")


@pytest.fixture(scope="module")
def broken_log():
    return runner_log("test-runner-broken")


def crc32_of_digests(digests):
    """tests/golden/test_golden.c's fold of the parts' digests, written
    again here: CRC-32 (reflected 0xEDB88320), bytes LSB first."""
    crc = 0xFFFFFFFF
    for text in digests:
        value = int(text, 16)
        for shift in (0, 8, 16, 24):
            crc ^= (value >> shift) & 0xFF
            for _ in range(8):
                crc = (crc >> 1) ^ (0xEDB88320 & -(crc & 1))
    return "0x%08x" % (~crc & 0xFFFFFFFF)


def test_reference_digests_are_digest_h():
    with open(os.path.join(TOP, "tests", "golden", "digest.h")) as f:
        header = f.read()
    committed = dict(re.findall(r"#define (DRDC_GOLDEN_DIGEST\w*)\s+"
                                r"(0x[0-9a-f]{8})u", header))
    ref = conformance.reference_digests()
    assert list(ref) == ["time", "time scales", "fixed", "orient",
                         "interop", "geo", "poses and JAUS bodies"]
    assert committed["DRDC_GOLDEN_DIGEST"] == conformance.reference_digest()
    assert crc32_of_digests(ref.values()) == committed["DRDC_GOLDEN_DIGEST"]
    for name, digest in ref.items():
        macro = "DRDC_GOLDEN_DIGEST_" + name.split()[0].upper()
        if name == "time scales":
            macro = "DRDC_GOLDEN_DIGEST_TIME_SCALES"
        assert committed[macro] == digest, name


def test_host_runner_conforms(host_log):
    verdict = conformance.judge(host_log)
    assert verdict["verdict"] == "conforms"
    assert verdict["digest"] == {"expected": "0x7a79f8ad",
                                 "got": "0x7a79f8ad"}
    assert [m["verdict"] for m in verdict["modules"]] == ["equal"] * 7
    # a conforming runner prints no trace: the log stays short
    assert "golden trace" not in host_log


def golden_geo_inputs():
    """tests/golden/golden_geo.c's inputs, from the xorshift32 stream
    computed here: four draws an iteration (lat, lon, prec, height)."""
    x = 2463534242

    def draw():
        nonlocal x
        x ^= (x << 13) & 0xFFFFFFFF
        x ^= x >> 17
        x ^= (x << 5) & 0xFFFFFFFF
        return x

    def signed(u):
        return u - (1 << 32) if u >= 1 << 31 else u

    for _ in range(512):
        lat = signed(draw()) * 80000
        lon = signed(draw()) * 500000
        draw()
        draw()
        yield lat, lon


def test_broken_port_names_function_and_input(broken_log):
    verdict = conformance.judge(broken_log)
    assert verdict["verdict"] == "differs"
    by_name = {m["name"]: m for m in verdict["modules"]}
    assert by_name.pop("geo")["verdict"] == "differs"
    assert {m["verdict"] for m in by_name.values()} == {"equal"}
    diff = [m for m in verdict["modules"] if m["name"] == "geo"][0]
    first = diff["first_difference"]
    # the first golden input drdc_geo_to_utm accepts (the Python API as
    # the oracle): the broken port adds its LSB only there
    records_per_input = 22016 // 512
    for i, (lat, lon) in enumerate(golden_geo_inputs()):
        try:
            drdc.geo_to_utm(lat, lon)
        except drdc.DrdcError:
            continue
        break
    assert first["function"] == "drdc_geo_to_utm"
    assert first["input"] == "lat_nas=%d, lon_nas=%d" % (lat, lon)
    # status, zone, north, then the easting
    assert first["record"] == i * records_per_input + 3
    assert int(first["got"], 16) - int(first["expected"], 16) == 1
    assert int(first["expected"], 16) == drdc.geo_to_utm(lat, lon)[2]


def test_broken_trace_is_bounded(broken_log):
    lines = [l for l in broken_log.splitlines()
             if l.startswith("golden trace of geo: ")]
    assert len(lines) == 1024 + 2
    assert len(broken_log) < 200_000


@pytest.mark.parametrize("text", ["", "\n\n", "hello world\n" * 100,
                                  "\x00\xff" * 1000,
                                  "golden digest of geo: 0xZZ\n"])
def test_not_a_runner_log(text):
    with pytest.raises(ValueError):
        conformance.judge(text)


def test_not_text():
    with pytest.raises(ValueError):
        conformance.judge(b"golden digest of geo: 0x09898737\n")


def test_huge_log(host_log):
    huge = host_log + "x" * (conformance.MAX_LOG_CHARS + 1)
    with pytest.raises(ValueError, match="more than"):
        conformance.judge(huge)


def test_truncated_log_is_incomplete(host_log):
    cut = host_log[:host_log.index("golden digest of interop")]
    verdict = conformance.judge(cut)
    assert verdict["verdict"] == "incomplete"
    assert verdict["digest"]["got"] is None
    assert [m["verdict"] for m in verdict["modules"]] == \
        ["equal"] * 4 + ["missing"] * 3


def test_truncated_trace_still_judged(broken_log):
    # cut within the geo trace: the digest says geo differs; the records
    # printed up to the cut still hold the first difference
    cut = broken_log[:broken_log.index("golden trace of geo: 500 ")]
    verdict = conformance.judge(cut)
    assert verdict["verdict"] == "differs"
    geo = [m for m in verdict["modules"] if m["name"] == "geo"][0]
    assert geo["first_difference"]["function"] == "drdc_geo_to_utm"
    # cut before any record: differs, but no record to name
    cut = broken_log[:broken_log.index("golden trace of geo: 0 ")]
    geo = [m for m in conformance.judge(cut)["modules"]
           if m["name"] == "geo"][0]
    assert geo["verdict"] == "differs" and geo["first_difference"] is None


def test_forged_records_are_bounded(host_log):
    # more records than any runner prints, far beyond the part's end
    forged = host_log.replace(
        "golden digest of geo: 0x09898737",
        "golden digest of geo: 0x00000000\n" + "".join(
            "golden trace of geo: %d drdc_geo_to_utm 0x00000000\n" % k
            for k in range(4000000000, 4000020000)))
    verdict = conformance.judge(forged)
    geo = [m for m in verdict["modules"] if m["name"] == "geo"][0]
    assert geo["verdict"] == "differs"
    assert geo["first_difference"]["record"] == 4000000000
    assert geo["first_difference"]["expected"] is None


def test_mutated_logs_never_crash(broken_log):
    rng = random.Random(20261126)
    lines = broken_log.splitlines(keepends=True)
    for _ in range(200):
        mutated = list(lines)
        for _ in range(rng.randint(1, 20)):
            k = rng.randrange(len(mutated))
            line = mutated[k]
            if line and rng.random() < 0.5:
                at = rng.randrange(len(line))
                line = line[:at] + chr(rng.randrange(256)) + line[at + 1:]
            else:
                line = ""
            mutated[k] = line
        try:
            verdict = conformance.judge("".join(mutated))
        except ValueError:
            continue
        assert verdict["verdict"] in ("conforms", "differs", "incomplete")


def test_reference_records_match_the_runner_tables():
    # every record of every part carries its function, and the package
    # counts the records golden-trace wrote into golden_expected.c
    with open(os.path.join(TOP, "tests", "golden",
                           "golden_expected.c")) as f:
        counts = [int(n) for n in re.findall(r"\{(\d+)u, sizeof", f.read())]
    assert len(counts) == 7
    for part, count in enumerate(counts):
        records, total = conformance._reference(part, 0, (1 << 32) - 1)
        assert total == count == len(records)
        assert not [i for i, r in records.items() if r[0] == "?"]


def test_difference_within_a_later_block(host_log):
    # a port whose orient part first differs at record 3500 (block 3):
    # its trace is the host's records 3072..4095 with that one changed
    first, end, wrong = 3072, 4096, 3500
    part = list(conformance.reference_digests()).index("orient")
    records, total = conformance._reference(part, first, end)
    lines = ["golden digest of orient: 0x00000000",
             "golden trace of orient: block 3 differs, records %d to %d "
             "of %d" % (first, end, total)]
    for index in range(first, end):
        function, value, _ = records[index]
        if index == wrong:
            value = "0x%0*x" % (len(value) - 2, int(value, 16) ^ 1)
        lines.append("golden trace of orient: %d %s %s"
                     % (index, function, value))
    lines.append("golden trace of orient: end")
    log = host_log.replace("golden digest of orient: 0x13b49878",
                           "\n".join(lines))
    verdict = conformance.judge(log)
    assert verdict["verdict"] == "differs"
    orient = [m for m in verdict["modules"] if m["name"] == "orient"][0]
    diff = orient["first_difference"]
    assert diff["record"] == wrong
    assert diff["function"] == records[wrong][0]
    assert diff["input"] == records[wrong][2] != ""
    assert int(diff["got"], 16) ^ int(diff["expected"], 16) == 1
