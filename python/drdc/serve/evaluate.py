# SPDX-License-Identifier: BSD-2-Clause
"""POST /v1/eval's work: check a decoded JSON request against the function
table, call the package's array function, and turn its arrays into JSON
lists. Every way a request can be wrong is a RequestError with an HTTP
status and a reason, so nothing in the input can reach the library in a
form the package would have to refuse with an unplanned exception."""
import numpy as np

import drdc
from .functions import BY_NAME, DISPLAYS, RANGES, quantity

TEXT_MAX = 64  # characters of one text value: MGRS needs 27, units less


class RequestError(Exception):
    """A request the service refuses: HTTP status and reason."""

    def __init__(self, status, reason):
        super().__init__(reason)
        self.status = status
        self.reason = reason


def _bad(reason):
    return RequestError(400, reason)


def _integer(v, where, ctype):
    # JSON true/false would pass isinstance(v, int): only the hemisphere
    # takes them
    if isinstance(v, bool):
        if ctype != "bool":
            raise _bad("%s: an integer, not a boolean" % where)
        return int(v)
    if not isinstance(v, int):
        raise _bad("%s: an integer (the fixed-point format), not %s"
                   % (where, type(v).__name__))
    lo, hi = RANGES[ctype]
    if not lo <= v <= hi:
        raise _bad("%s = %d does not fit %s [%d, %d]"
                   % (where, v, ctype, lo, hi))
    return v


def _text(v, where):
    if not isinstance(v, str):
        raise _bad("%s: a string, not %s" % (where, type(v).__name__))
    if len(v) > TEXT_MAX:
        raise _bad("%s: at most %d characters" % (where, TEXT_MAX))
    return v


def _quantity(arg, v, where):
    """{"degrees": "50.27"} (or "metres", "utc") as the argument's
    integer, converted exactly; a utc gives (sec, nsec)."""
    q = quantity(arg) if arg.kind == "int" else None
    if q is None:
        raise _bad("%s: an integer (the fixed-point format), not an object"
                   % where)
    name, unit, convert = q
    if set(v) != {name}:
        raise _bad("%s: {\"%s\": text} (%s), the only quantity this "
                   "argument takes" % (where, name, unit))
    text = _text(v[name], "%s.%s" % (where, name))
    try:
        value = convert(text)
    except drdc.DrdcError as e:
        raise _bad("%s.%s: %r is refused: %s (%s)" % (where, name, text,
                                                     e.reason, e.name))
    except (ValueError, TypeError) as e:
        raise _bad("%s.%s: %s" % (where, name, e))
    if name == "utc":
        return tuple(value)
    return _integer(value, where, arg.ctype)


def _element(arg, v, where):
    if isinstance(v, dict):
        return _quantity(arg, v, where)
    if arg.kind in ("int", "scalar-int"):
        return _integer(v, where, arg.ctype)
    return _text(v, where)


def _split_utc(f, inputs, values):
    """A sec given as {"utc": ...} carries its nanoseconds: they become
    the nsec argument, which the request must then leave out."""
    sec = values.get("sec")
    elements = sec if isinstance(sec, list) else [sec]
    if not any(isinstance(x, tuple) for x in elements):
        return
    if "nsec" in inputs:
        raise _bad("inputs.nsec: a sec given as utc carries its "
                   "nanoseconds; leave nsec out")
    if not all(isinstance(x, tuple) for x in elements):
        raise _bad("inputs.sec: every element utc, or none")
    if isinstance(sec, list):
        values["sec"] = [x[0] for x in sec]
        values["nsec"] = [x[1] for x in sec]
    else:
        values["sec"], values["nsec"] = sec


def _arguments(f, inputs, max_batch):
    """The function's arguments from the request's "inputs": per-element
    ones as equal-length lists, scalars as they are, and the batch size."""
    if not isinstance(inputs, dict):
        raise _bad("inputs: an object of the function's arguments")
    known = {a.name for a in f.inputs}
    extra = sorted(set(inputs) - known)
    if extra:
        raise _bad("inputs: %s takes no argument %s (it takes %s)"
                   % (f.name, ", ".join(extra), ", ".join(
                       a.name for a in f.inputs)))
    values, n = {}, None
    for a in f.inputs:
        if a.name in inputs:
            v = inputs[a.name]
        elif a.default is not None:
            v = a.default
        else:
            raise _bad("inputs.%s: missing" % a.name)
        where = "inputs." + a.name
        if isinstance(v, list) and a.kind in ("int", "text"):
            if len(v) > max_batch:
                # 422, not 413: the body may be small, the work is not
                raise RequestError(422, "%s: %d elements, at most %d a "
                                   "request" % (where, len(v), max_batch))
            if n is not None and len(v) != n:
                raise _bad("%s: %d elements, the other lists have %d"
                           % (where, len(v), n))
            n = len(v)
            values[a.name] = [_element(a, x, "%s[%d]" % (where, i))
                              for i, x in enumerate(v)]
        else:
            values[a.name] = _element(a, v, where)
    _split_utc(f, inputs, values)
    return values, (1 if n is None else n)


def _array(arg, v, n):
    if arg.kind == "text":
        return np.array(v if isinstance(v, list) else [v] * n, dtype=str) \
            if n else np.zeros(0, "U1")
    if arg.kind == "int":
        return np.array(v if isinstance(v, list) else [v] * n, np.int64)
    return v  # one value for the whole batch


def _json_list(a):
    if a.dtype.kind == "b":
        return [bool(x) for x in a.tolist()]
    return a.tolist()


def evaluate(body, max_batch):
    """The response of POST /v1/eval for a decoded JSON body."""
    if not isinstance(body, dict):
        raise _bad("the body is a JSON object {\"function\", \"inputs\"}")
    extra = sorted(set(body) - {"function", "inputs"})
    if extra:
        raise _bad("unknown member %s (expected function, inputs)"
                   % ", ".join(extra))
    name = body.get("function")
    if not isinstance(name, str) or name not in BY_NAME:
        raise RequestError(404 if isinstance(name, str) else 400,
                           "function: one of GET /v1/functions's names")
    f = BY_NAME[name]
    values, n = _arguments(f, body.get("inputs", {}), max_batch)
    arrays = {a.name: _array(a, values[a.name], n) for a in f.inputs}
    try:
        result = f.call(arrays)
    except drdc.DrdcError as e:
        # a scalar argument of the whole batch is refused (an unknown unit)
        raise RequestError(422, "%s: %s" % (e.function, e.name)) from None
    except (TypeError, ValueError, OverflowError) as e:
        raise _bad(str(e)) from None
    outputs = {o.name: _json_list(getattr(result, o.name))
               for o in f.outputs}
    status = [int(s) for s in result.status.tolist()]
    return {"function": name, "count": n, "outputs": outputs,
            "status": status,
            "status_name": [drdc.status_name(s) for s in status],
            "display": _display(f, arrays, result, status),
            "exact": {o.name: [str(x) for x in outputs[o.name]]
                      for o in f.outputs if o.ctype not in ("string",
                                                             "bool")}}


def _display(f, arrays, result, status):
    """Each output a person reads as a quantity, as exact decimal text
    with its unit ("487884.96875 m"; None where the element's status is an
    error), by the output's format; a unit conversion's value in its
    unit."""
    shown = {}
    raw = {o.name: getattr(result, o.name) for o in f.outputs}
    for o in f.outputs:
        if f.name in ("units_convert", "units_convert_expr"):
            frac = arrays["to_frac"]
            unit = arrays.get("to_unit", arrays.get("to_expr"))
            text = drdc.format_fixed_array(raw[o.name], frac,
                                           None if frac <= 18 else 18)
            texts = [t + " " + unit for t in text.tolist()]
        elif o.format in DISPLAYS:
            texts = DISPLAYS[o.format](raw[o.name], raw)
        else:
            continue
        shown[o.name] = [None if drdc.is_error(s) else t
                         for s, t in zip(status, texts)]
    return shown
