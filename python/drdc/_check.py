# SPDX-License-Identifier: BSD-2-Clause
"""Validation of the arguments before they reach C: each must be an integer
that fits the C parameter's type. Whether the value is in the function's
domain (a latitude within +-90 degrees) is the library's to say, by its
status; a value that does not even fit the C type is refused here, so it
never wraps silently on its way into the call.

Scalars: Python int or numpy integer (not bool, not float: fixed-point
formats are integers, and a float would be rounded by someone).
Arrays: anything numpy.asarray turns into an integer array (dtype kind
'i' or 'u'); arrays of one call are broadcast together."""
import operator

import numpy as np

INT32 = (-(1 << 31), (1 << 31) - 1)
INT64 = (-(1 << 63), (1 << 63) - 1)
# a binary angle: uint32, or its int32 reading ([-180, 180) degrees)
BAM32 = (-(1 << 31), (1 << 32) - 1)
UINT32 = (0, (1 << 32) - 1)


def integer(value, name, limits):
    """value as a Python int within limits = (lo, hi), or TypeError /
    ValueError naming the argument."""
    if isinstance(value, (bool, np.bool_)):
        raise TypeError("%s: an integer, not a bool" % name)
    try:
        v = operator.index(value)
    except TypeError:
        raise TypeError("%s: an integer (the library's fixed-point format), "
                        "not %s" % (name, type(value).__name__)) from None
    lo, hi = limits
    if not lo <= v <= hi:
        raise ValueError("%s = %d does not fit the C type [%d, %d]"
                         % (name, v, lo, hi))
    return v


def integer_array(value, name, limits, dtype):
    """value as a numpy array of dtype, every element within limits; a
    TypeError for a non-integer array, a ValueError naming the first
    element out of range."""
    a = np.asarray(value)
    if a.dtype.kind not in "iu":
        raise TypeError("%s: an integer array (the library's fixed-point "
                        "format), not dtype %s" % (name, a.dtype))
    lo, hi = limits
    info = np.iinfo(a.dtype)
    if a.size and (info.min < lo or info.max > hi):
        # compared as Python ints: no mixed-signedness promotion
        low, high = int(a.min()), int(a.max())
        if low < lo or high > hi:
            # the error path only: find the first offender for the message
            for i, v in enumerate(a.ravel().tolist()):
                if not lo <= v <= hi:
                    raise ValueError(
                        "%s[%d] = %d does not fit the C type [%d, %d]"
                        % (name, i, v, lo, hi))
    return a.astype(dtype, copy=False)


def broadcast(*arrays):
    """The arrays broadcast to one shape, each flattened to a contiguous
    1-D array, and that shape."""
    try:
        b = np.broadcast_arrays(*arrays)
    except ValueError as e:
        raise ValueError("array arguments of different shapes: %s" % e) \
            from None
    shape = b[0].shape
    return [np.ascontiguousarray(x).ravel() for x in b], shape
