# SPDX-License-Identifier: BSD-2-Clause
"""Units of measure (core/include/drdc/units.h): fixed-point values as an
int64 raw with `frac` fraction bits (real value raw / 2^frac, frac
0..62), converted between units of the table (GNU units' names: "ft",
"knot", "degC") or unit expressions ("km/h", "ft*lbf"), rounded once to
nearest, ties away from zero."""
import ctypes
from collections import namedtuple

import numpy as np

from . import _check
from ._lib import UnitsExpr, lib
from ._status import DrdcError, Status, check

FRAC_MAX = 62  # DRDC_UNITS_FRAC_MAX
ValueArrays = namedtuple("ValueArrays", "value status")


def _text(name, what):
    if not isinstance(name, str):
        raise TypeError("%s: a str, not %s" % (what, type(name).__name__))
    try:
        raw = name.encode("ascii")
    except UnicodeEncodeError:
        # the table's names are ASCII: no other name can be a unit
        raise DrdcError(Status.DRDC_E_UNKNOWN_UNIT, "drdc_units_find") \
            from None
    return raw


def _unit(name, what):
    raw = _text(name, what)
    unit = ctypes.c_void_p()
    check(lib.drdc_units_find(raw, len(raw), ctypes.byref(unit)),
          "drdc_units_find")
    return unit


def _expr(text, what):
    raw = _text(text, what)
    expr = UnitsExpr()
    check(lib.drdc_units_parse(raw, len(raw), ctypes.byref(expr)),
          "drdc_units_parse")
    return expr


def _frac(value, what):
    # unsigned in C: a negative count would wrap to a huge one
    return _check.integer(value, what, _check.UINT32)


def units_convert(raw, from_frac, from_unit, to_frac, to_unit):
    """drdc_units_convert: raw / 2^from_frac in unit `from_unit` (a table
    name) -> the int64 raw of to_unit with to_frac fraction bits."""
    out = ctypes.c_int64()
    check(lib.drdc_units_convert(
        _check.integer(raw, "raw", _check.INT64),
        _frac(from_frac, "from_frac"), _unit(from_unit, "from_unit"),
        _frac(to_frac, "to_frac"), _unit(to_unit, "to_unit"),
        ctypes.byref(out)), "drdc_units_convert")
    return out.value


def units_convert_expr(raw, from_frac, from_expr, to_frac, to_expr):
    """drdc_units_parse and drdc_units_convert_expr: as units_convert, for
    unit expressions ("km/h", "kg m/s^2")."""
    a, b = _expr(from_expr, "from_expr"), _expr(to_expr, "to_expr")
    out = ctypes.c_int64()
    check(lib.drdc_units_convert_expr(
        _check.integer(raw, "raw", _check.INT64),
        _frac(from_frac, "from_frac"), ctypes.byref(a),
        _frac(to_frac, "to_frac"), ctypes.byref(b), ctypes.byref(out)),
        "drdc_units_convert_expr")
    return out.value


def _raw_array(raw):
    values = _check.integer_array(raw, "raw", _check.INT64, np.int64)
    flat = np.ascontiguousarray(values).ravel()
    return flat, values.shape, np.zeros(flat.size, np.int64), \
        np.zeros(flat.size, np.int32)


def units_convert_array(raw, from_frac, from_unit, to_frac, to_unit):
    """drdc_units_convert over an int64 array of raw values (the units and
    formats are scalars; an unknown unit raises DrdcError): ValueArrays of
    value (int64) and status (int32)."""
    a, b = _unit(from_unit, "from_unit"), _unit(to_unit, "to_unit")
    ff, tf = _frac(from_frac, "from_frac"), _frac(to_frac, "to_frac")
    values, shape, out, status = _raw_array(raw)
    lib.drdc_batch_units_convert(values.size, values.ctypes.data, ff, a, tf,
                                 b, out.ctypes.data, status.ctypes.data)
    return ValueArrays(out.reshape(shape), status.reshape(shape))


def units_convert_expr_array(raw, from_frac, from_expr, to_frac, to_expr):
    """drdc_units_convert_expr over an int64 array of raw values:
    ValueArrays of value (int64) and status (int32)."""
    a, b = _expr(from_expr, "from_expr"), _expr(to_expr, "to_expr")
    ff, tf = _frac(from_frac, "from_frac"), _frac(to_frac, "to_frac")
    values, shape, out, status = _raw_array(raw)
    lib.drdc_batch_units_convert_expr(values.size, values.ctypes.data, ff,
                                      ctypes.byref(a), tf, ctypes.byref(b),
                                      out.ctypes.data, status.ctypes.data)
    return ValueArrays(out.reshape(shape), status.reshape(shape))
