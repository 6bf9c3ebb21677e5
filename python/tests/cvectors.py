# SPDX-License-Identifier: BSD-2-Clause
"""Reads the committed reference vectors (tests/<module>/vectors_*.h, C
headers written by tools/generate.py from independent oracles) and
the tolerances of the Unity suites (#define lines of tests/<module>/
test_*.c), so that the Python tests assert the very expected values and
bounds the C suites assert, without copying a number.

The headers' C subset: #define NAME value; struct definitions whose
fields are integers, strings or arrays of them; static const arrays of
those structures or of integers, initialised with integer literals
(INT64_C(...), 10u), string literals, macros, drdc_status_t names and
the enumerators of the public headers."""
import functools
import os
import re

TOP = os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))

_COMMENT = re.compile(r"/\*.*?\*/|//[^\n]*", re.S)
_DEFINE = re.compile(r"^\s*#\s*define\s+(\w+)\s+(.+?)\s*$", re.M)
_STRUCT = re.compile(r"\bstruct\s+(\w+)\s*\{([^{}]*)\}\s*;")
_ARRAY = re.compile(r"\bstatic\s+const\s+(?:struct\s+(\w+)|(\w+))\s+"
                    r"(\w+)\s*((?:\[[^\]]*\]\s*)+)=\s*\{")
_TOKEN = re.compile(r'\s*(?:("(?:[^"\\]|\\.)*")'          # string
                    r"|(U?INT\d+_C\s*\(\s*-?\s*\w+\s*\))"  # INT64_C(-5)
                    r"|(-?\s*(?:0[xX][0-9a-fA-F]+|\d+))[uUlL]*"  # literal
                    r"|([A-Za-z_]\w*)"                     # macro, enum
                    r"|([{},()-]))")
_INTEGER = re.compile(r"-?\s*(?:0[xX][0-9a-fA-F]+|\d+)")


# <stdint.h> limits that vectors use
_LIMITS = {"INT8_MIN": -(1 << 7), "INT8_MAX": (1 << 7) - 1,
           "INT16_MIN": -(1 << 15), "INT16_MAX": (1 << 15) - 1,
           "INT32_MIN": -(1 << 31), "INT32_MAX": (1 << 31) - 1,
           "INT64_MIN": -(1 << 63), "INT64_MAX": (1 << 63) - 1,
           "UINT8_MAX": (1 << 8) - 1, "UINT16_MAX": (1 << 16) - 1,
           "UINT32_MAX": (1 << 32) - 1, "UINT64_MAX": (1 << 64) - 1}


def _int(text):
    return int(text.replace(" ", ""), 0)


@functools.lru_cache(maxsize=None)
def status_codes():
    """drdc_status_t names and values, from fixed/include/drdc/status.h."""
    path = os.path.join(TOP, "fixed/include/drdc/status.h")
    with open(path) as f:
        text = _COMMENT.sub(" ", f.read())
    return {n: int(v) for n, v in re.findall(r"\b(DRDC_\w+)\s*=\s*(\d+)",
                                             text)}


@functools.lru_cache(maxsize=None)
def enum_constants():
    """Every enumerator of the public headers with a value
    (DRDC_JAUS_FORM_RA3 = 0, DRDC_NMEA_GGA = 0, ...), read from
    core/include/drdc/ and fixed/include/drdc/."""
    found = {}
    for folder in ("core/include/drdc", "fixed/include/drdc"):
        path = os.path.join(TOP, folder)
        for name in sorted(os.listdir(path)):
            with open(os.path.join(path, name)) as f:
                text = _COMMENT.sub(" ", f.read())
            for body in re.findall(r"\benum\s+\w*\s*\{([^}]*)\}", text):
                for n, v in re.findall(r"\b(DRDC_\w+)\s*=\s*(\d+)", body):
                    found[n] = int(v)
    return found


def _constant(text, defines):
    """The integer of a #define value or an identifier."""
    text = text.strip()
    while text.startswith("(") and text.endswith(")"):
        text = text[1:-1].strip()
    m = re.fullmatch(r"U?INT\d+_C\s*\((.*)\)", text)
    if m:
        text = m.group(1).strip()
    if _INTEGER.fullmatch(text.rstrip("uUlL")):
        return _int(text.rstrip("uUlL"))
    if text.startswith("-") and not _INTEGER.fullmatch(text):
        return -_constant(text[1:], defines)
    if text in defines:
        return defines[text]
    if text in _LIMITS:
        return _LIMITS[text]
    codes = status_codes()
    if text in codes:
        return codes[text]
    if text in enum_constants():
        return enum_constants()[text]
    raise ValueError("not a constant: %r" % text)


def _tokens(text, pos):
    """Tokens from pos up to the brace that closes the one just before pos,
    as nested lists of values."""
    stack = [[]]
    negate = False
    while True:
        m = _TOKEN.match(text, pos)
        if not m:
            raise ValueError("cannot read %r" % text[pos:pos + 40])
        pos = m.end()
        string, macro, literal, ident, punct = m.groups()
        if punct == "-":
            negate = True
            continue
        if negate and ident is not None:
            ident = "-" + ident
        elif negate and (literal or macro):
            raise ValueError("a minus sign before %s" % (literal or macro))
        negate = False
        if string is not None:
            stack[-1].append(bytes(string[1:-1], "ascii")
                             .decode("unicode_escape"))
        elif macro is not None:
            stack[-1].append(_int(re.search(r"\(\s*(.*?)\s*\)",
                                            macro).group(1)))
        elif literal is not None:
            stack[-1].append(_int(literal))
        elif ident is not None:
            stack[-1].append(("ident", ident))
        elif punct == "{":
            stack.append([])
        elif punct == "}":
            done = stack.pop()
            if not stack:
                return done, pos
            stack[-1].append(done)
        # commas separate the values


def _fields(body):
    """[(name, is_array)] of a structure's body."""
    fields = []
    for decl in body.split(";"):
        decl = decl.strip()
        if not decl:
            continue
        for k, part in enumerate(decl.split(",")):
            words = re.findall(r"\w+|\[[^\]]*\]", part)
            names = [w for w in words if not w.startswith("[")]
            fields.append((names[-1], "[" in part))
    return fields


def _defines(text):
    """{name: int} of the #define lines of C text (comments removed) whose
    value is a constant, each able to use those before it; include guards
    and function-like macros are left out."""
    found = {}
    for name, value in _DEFINE.findall(text):
        try:
            found[name] = _constant(value, found)
        except ValueError:
            pass
    return found


@functools.lru_cache(maxsize=None)
def load(rel):
    """Everything a vectors header defines: {"defines": {name: int},
    array name: [row, ...]} where a row of a structure array is a dict of
    its fields (an array field a list) and a row of an integer array an
    int or a list."""
    with open(os.path.join(TOP, rel)) as f:
        text = _COMMENT.sub(" ", f.read())
    defines = _defines(text)
    structs = {n: _fields(b) for n, b in _STRUCT.findall(text)}

    def resolve(v):
        if isinstance(v, list):
            return [resolve(x) for x in v]
        if isinstance(v, tuple):
            return _constant(v[1], defines)
        return v

    out = {"defines": defines}
    for m in _ARRAY.finditer(text):
        struct, _, name, _ = m.groups()
        rows, _ = _tokens(text, m.end())
        rows = resolve(rows)
        if struct:
            fields = structs[struct]
            rows = [{f: v for (f, _), v in zip(fields, row)} for row in rows]
            for row in rows:
                if len(row) != len(fields):
                    raise ValueError("%s: a row of %d fields" % (name,
                                                                  len(row)))
        out[name] = rows
    return out


def tolerances(rel):
    """{name: int} of the #define lines of a C test file whose value is a
    constant: the bounds its Unity assertions use."""
    with open(os.path.join(TOP, rel)) as f:
        return _defines(_COMMENT.sub(" ", f.read()))
