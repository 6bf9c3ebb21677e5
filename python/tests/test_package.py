# SPDX-License-Identifier: BSD-2-Clause
"""The package as a whole: its statuses are status.h's, its version is
version.h's, and arrays of any layout give the bits of native ones."""
import re

import numpy as np

import drdc
from cvectors import TOP, status_codes


def test_status_enumeration_is_status_h():
    want = {n: v for n, v in status_codes().items()
            if n != "DRDC_STATUS_COUNT"}
    assert {s.name: int(s) for s in drdc.Status} == want
    assert drdc.status_name(len(want)) == "DRDC_E_?"
    assert drdc.is_error(drdc.Status.DRDC_E_RANGE)
    assert not drdc.is_error(drdc.Status.DRDC_W_LEAP_EXPIRED)
    assert not drdc.is_error(drdc.Status.DRDC_OK)


def test_version_is_version_h():
    with open(TOP + "/core/include/drdc/version.h") as f:
        want = re.search(r'DRDC_VERSION_STRING "([^"]+)"', f.read()).group(1)
    assert drdc.__version__ == want


def test_byte_order_and_strides_do_not_change_the_bits():
    deg = drdc.NAS_PER_DEGREE
    lat = np.arange(-70, 80, 7, dtype=np.int64) * deg + 123456789
    lon = np.arange(-170, 180, 16, dtype=np.int64)[:lat.size] * deg - 98765
    native = drdc.geo_to_utm_array(lat, lon)
    swapped = drdc.geo_to_utm_array(lat.astype(">i8"), lon.astype(">i8"))
    wide = np.zeros((lat.size, 3), np.int64)
    wide[:, 1] = lon
    wide[:, 2] = lat
    # columns of a row-major array: a stride of 24 bytes each
    assert wide[:, 2].strides == (24,)
    strided = drdc.geo_to_utm_array(wide[:, 2], wide[:, 1])
    for a, b, c in zip(native, swapped, strided):
        assert (a == b).all() and (a == c).all()
    # narrow integer types widen: 10 nas from the equator, as int8
    small = drdc.geo_to_utm_array(np.array([10, -10], np.int8), 0)
    assert (small.status == 0).all()
    assert list(small.northing_q47_16) == [
        drdc.geo_to_utm(10, 0).northing_q47_16,
        drdc.geo_to_utm(-10, 0).northing_q47_16]


def test_only_drdc_names_leave_the_shared_library():
    """libdrdc.so also holds the golden parts for drdc.conformance; as
    libdrdc.a, it exports nothing but drdc_ names (symbols of the C
    library it imports are undefined, not listed)."""
    import os
    import subprocess
    from drdc import _lib
    out = subprocess.run(["nm", "-D", "--defined-only", _lib.LIBRARY],
                         capture_output=True, text=True, check=True).stdout
    names = [line.split()[-1] for line in out.splitlines() if line.strip()]
    assert os.path.exists(_lib.LIBRARY)
    assert any(n.startswith("drdc_") for n in names)
    assert [n for n in names if not n.startswith("drdc_")] == []
