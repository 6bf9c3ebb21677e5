# SPDX-License-Identifier: BSD-2-Clause
"""drdc_status_t in Python: the Status enumeration (names and values of
fixed/include/drdc/status.h, read from the library itself), the exception
of scalar calls and the warning they give for DRDC_W_* statuses, each
with the reason in words."""
import enum
import warnings

from ._lib import lib
from ._status_text import STATUS_TEXT


def _names():
    """Every status the library names, by value: DRDC_OK = 0 upwards until
    the library answers its name of a non-status."""
    names = {}
    code = 0
    while True:
        name = lib.drdc_status_name(code).decode()
        if name == "DRDC_E_?":
            return names
        names[name] = code
        code += 1


Status = enum.IntEnum("Status", _names())
Status.__doc__ = ("drdc_status_t: the status codes of "
                  "fixed/include/drdc/status.h")

# status.h: the warnings keep their numbers among the errors' (values are
# stable), so they are listed, never a range
WARNINGS = frozenset({Status.DRDC_W_LEAP_EXPIRED, Status.DRDC_W_SATURATED})


def status_name(code):
    """The library's name of a status code ("DRDC_E_RANGE"); "DRDC_E_?"
    for a value that is no status."""
    return lib.drdc_status_name(int(code)).decode()


def is_error(code):
    """True for a DRDC_E_* status (outputs not written), as
    drdc_status_is_error(): False for DRDC_OK and the warnings."""
    return int(code) != 0 and int(code) not in WARNINGS


def reason(code, function=""):
    """Why a status refuses an input, in words: for the NMEA and time
    functions the reason `drdc nmea` and `drdc time` print on their ERROR
    lines (tools/drdc/reasons.c, compiled into the package too); for the
    others, whose `drdc` messages quote the input, the status's meaning as
    fixed/include/drdc/status.h states it."""
    code = int(code)
    if function.startswith("drdc_nmea_"):
        return lib.drdc_tool_nmea_reason(code).decode()
    if function.startswith("drdc_time_"):
        return lib.drdc_tool_time_reason(code).decode()
    return STATUS_TEXT.get(code, "not a status of the library")


class _StatusReport:
    def _fill(self, code, function, why):
        self.code = int(code)
        self.number = self.code
        self.name = status_name(code)
        self.function = function
        self.reason = reason(code, function) if why is None else why
        return "%s: %s (%s, %d)" % (function, self.reason, self.name,
                                    self.code)


class DrdcError(_StatusReport, Exception):
    """A library call returned an error status (DRDC_E_*).

    Attributes: ``reason`` (the words `drdc` prints for it: "checksum does
    not match"), ``name`` ("DRDC_E_CHECKSUM"), ``code`` and ``number``
    (the status's value, 24), ``function`` (the C function,
    "drdc_nmea_parse"). str(): "drdc_nmea_parse: checksum does not match
    (DRDC_E_CHECKSUM, 24)".
    """

    def __init__(self, code, function, reason=None):
        super().__init__(self._fill(code, function, reason))


class DrdcWarning(_StatusReport, UserWarning):
    """A library call returned a warning status (DRDC_W_*): the result is
    returned and this warning is issued. Attributes as DrdcError's. Turn it
    into an exception with warnings.simplefilter("error", DrdcWarning)."""

    def __init__(self, code, function, reason=None):
        super().__init__(self._fill(code, function, reason))


def check(code, function):
    """Raise DrdcError for an error status, warn for a warning status."""
    if code == 0:
        return
    if code in WARNINGS:
        # stacklevel 3: the caller of the public function
        warnings.warn(DrdcWarning(code, function), stacklevel=3)
        return
    raise DrdcError(code, function)
