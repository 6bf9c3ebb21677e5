# SPDX-License-Identifier: BSD-2-Clause
"""The conformance engine: a port's test-runner console log judged
against the host library.

The test runner prints one line per part of the conformance digest
(tests/golden), "golden digest of <part>: 0x........", and
"*** GOLDEN DIGEST: 0x........". For a part whose digest differs from
the host's it also prints the records of its first differing block of
1024 (see python/README.md, "Conformance engine"):

    golden trace of <part>: block <k> differs, records <a> to <b> of <n>
    golden trace of <part>: <index> <function> 0x<value>
    golden trace of <part>: end

judge() compares those records with the reference records this package's
libdrdc.so computes for the same indices (python/src/golden.c), and names
the first record that differs: its function, index and golden input.

The log is text only: nothing of it is executed or used as a path; its
size and the number of trace records read are bounded.
"""
import ctypes
import functools
import re

from ._lib import lib

# The host runner's log is 22 KB, a differing part's trace 58 to 82 KB
# more: 4 MiB leaves room for chatty boards and refuses floods.
MAX_LOG_CHARS = 4 << 20
# Seven parts of 1024 records each is the most a runner prints.
MAX_TRACE_RECORDS = 8192
# A runner's line is under 100 characters; longer ones are not its.
MAX_LINE_CHARS = 4096

DIGEST_LINE = re.compile(r"golden digest of ([A-Za-z ]{1,64}): "
                         r"(0x[0-9a-f]{8})$")
OVERALL_LINE = re.compile(r"\*\*\* GOLDEN DIGEST: (0x[0-9a-f]{8})$")
TRACE_LINE = re.compile(r"golden trace of ([A-Za-z ]{1,64}): "
                        r"([0-9]{1,10}) ([A-Za-z0-9_?]{1,64}) "
                        r"(0x[0-9a-f]{8}|0x[0-9a-f]{16})$")


class _Input(ctypes.Structure):
    """golden_input_t (tests/golden/golden.h)"""
    _fields_ = [("name", ctypes.c_char_p), ("value", ctypes.c_int64),
                ("text", ctypes.c_char_p)]


_RECORD_CB = ctypes.CFUNCTYPE(None, ctypes.c_uint32, ctypes.c_char_p,
                              ctypes.c_uint64, ctypes.c_uint,
                              ctypes.POINTER(_Input), ctypes.c_uint)

lib.drdc_golden_part_count.argtypes = []
lib.drdc_golden_part_count.restype = ctypes.c_uint
lib.drdc_golden_part_name.argtypes = [ctypes.c_uint]
lib.drdc_golden_part_name.restype = ctypes.c_char_p
lib.drdc_golden_trace.argtypes = [ctypes.c_uint, ctypes.c_uint32,
                                  ctypes.c_uint32, _RECORD_CB,
                                  ctypes.POINTER(ctypes.c_uint32)]
lib.drdc_golden_trace.restype = ctypes.c_uint32

lib.drdc_golden_digest.argtypes = []
lib.drdc_golden_digest.restype = ctypes.c_uint32


def _hex(value, nbytes):
    return "0x%0*x" % (2 * nbytes, value)


def _text(raw):
    """A C text input as the host program prints it: bytes outside
    printable ASCII, quotes and backslashes as \\x escapes."""
    out = []
    for b in raw:
        if b < 0x20 or b >= 0x7F or b in (0x22, 0x5C):
            out.append("\\x%02x" % b)
        else:
            out.append(chr(b))
    return '"%s"' % "".join(out)


def _inputs(inputs, count):
    parts = []
    for k in range(count):
        item = inputs[k]
        value = (_text(item.text) if item.text is not None
                 else str(item.value))
        parts.append("%s=%s" % (item.name.decode("ascii"), value))
    return ", ".join(parts)


def _part_names():
    return [lib.drdc_golden_part_name(k).decode("ascii")
            for k in range(lib.drdc_golden_part_count())]


def _reference(part, first, end):
    """The host's records first..end-1 of part number `part`: {index:
    (function, value text, input text)}, and the part's record count."""
    records = {}

    def keep(index, function, value, nbytes, inputs, count):
        records[index] = ((function or b"?").decode("ascii"),
                          _hex(value, nbytes), _inputs(inputs, count))

    callback = _RECORD_CB(keep)
    total = ctypes.c_uint32(0)
    lib.drdc_golden_trace(part, first, end, callback, ctypes.byref(total))
    return records, total.value


@functools.lru_cache(maxsize=1)
def _reference_digests():
    digests = {}
    total = ctypes.c_uint32(0)
    for k, name in enumerate(_part_names()):
        digest = lib.drdc_golden_trace(k, 0, 0, _RECORD_CB(0),
                                       ctypes.byref(total))
        digests[name] = "0x%08x" % digest
    return digests


@functools.lru_cache(maxsize=1)
def reference_digest():
    """The conformance digest ("*** GOLDEN DIGEST") as the host library
    computes it: "0x7a79f8ad" unless results were meant to change."""
    return "0x%08x" % lib.drdc_golden_digest()


def reference_digests():
    """{part name: "0x........"}: each part's digest as the host library
    computes it, in the order the test runner prints them."""
    return dict(_reference_digests())


def _parse(log_text):
    """Digest lines, the overall digest and the trace records of a log."""
    digests = {}
    overall = None
    traces = {}
    kept = 0
    for raw in log_text.splitlines():
        if len(raw) > MAX_LINE_CHARS:
            continue
        line = raw.strip()
        m = DIGEST_LINE.search(line)
        if m:
            # the first line of a part counts: a second one would be
            # another run's
            digests.setdefault(m.group(1), m.group(2))
            continue
        m = OVERALL_LINE.search(line)
        if m:
            if overall is None:
                overall = m.group(1)
            continue
        m = TRACE_LINE.search(line)
        if m and kept < MAX_TRACE_RECORDS:
            records = traces.setdefault(m.group(1), {})
            index = int(m.group(2))
            # a record index is a uint32 on the runner
            if index < (1 << 32) and index not in records:
                records[index] = (m.group(3), m.group(4))
                kept += 1
    return digests, overall, traces


def _first_difference(part, records):
    """The port's first record that is not the host's, from the lowest
    index the port printed on, without a gap; None when the printed
    records all agree or none were printed."""
    if not records:
        return None
    first = min(records)
    end = first
    while end in records:
        end += 1
    reference, total = _reference(part, first, end)
    for index in range(first, end):
        function, value = records[index]
        if index >= total:
            return {"function": function, "record": index,
                    "input": "(beyond the %d records of the part)" % total,
                    "expected": None, "got": value}
        ref_function, ref_value, ref_input = reference[index]
        if value != ref_value or function != ref_function:
            return {"function": ref_function, "record": index,
                    "input": ref_input, "expected": ref_value,
                    "got": value}
    return None


def judge(log_text):
    """Verdict on a port's test-runner log (see the module's doc).

    Raises ValueError for input that is not a test-runner log: not a
    str, over MAX_LOG_CHARS, or without any digest line."""
    if not isinstance(log_text, str):
        raise ValueError("the log must be text (str), not %s"
                         % type(log_text).__name__)
    if len(log_text) > MAX_LOG_CHARS:
        raise ValueError("the log has %d characters, more than the %d a "
                         "test-runner log can have"
                         % (len(log_text), MAX_LOG_CHARS))
    digests, overall, traces = _parse(log_text)
    if not digests and overall is None:
        raise ValueError("not a test-runner log: no line 'golden digest of "
                         "<part>: 0x........' or '*** GOLDEN DIGEST: "
                         "0x........'")
    reference = _reference_digests()
    modules = []
    for k, (name, expected) in enumerate(reference.items()):
        got = digests.get(name)
        entry = {"name": name, "expected": expected, "got": got,
                 "verdict": "missing", "first_difference": None}
        if got == expected:
            entry["verdict"] = "equal"
        elif got is not None:
            entry["verdict"] = "differs"
            entry["first_difference"] = _first_difference(
                k, traces.get(name, {}))
        modules.append(entry)
    verdicts = {m["verdict"] for m in modules}
    if "differs" in verdicts or (overall is not None
                                 and overall != reference_digest()):
        verdict = "differs"
    elif "missing" in verdicts or overall is None:
        verdict = "incomplete"
    else:
        verdict = "conforms"
    return {"verdict": verdict,
            "digest": {"expected": reference_digest(), "got": overall},
            "modules": modules}
