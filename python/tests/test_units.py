# SPDX-License-Identifier: BSD-2-Clause
"""Unit conversion against the GNU units vectors of
tests/units/vectors_units.h (every unit of the table to and from its SI
unit): within 1 LSB, as tests/units/test_units.c allows (GNU units prints
15 significant digits)."""
import numpy as np
import pytest

import drdc
from cvectors import load

ROWS = load("tests/units/vectors_units.h")["units_vectors"]
GNU_UNITS_LSB = 1


def test_every_unit_matches_gnu_units():
    worst = 0
    for r in ROWS:
        got = drdc.units_convert(r["raw"], r["from_frac"], r["from"],
                                 r["to_frac"], r["to"])
        worst = max(worst, abs(got - r["expect"]))
    assert worst <= GNU_UNITS_LSB


def test_arrays_give_the_scalar_bits():
    # one array call per unit pair of the table
    pairs = {}
    for r in ROWS:
        pairs.setdefault((r["from"], r["to"], r["from_frac"], r["to_frac"]),
                         []).append(r)
    for (a, b, ff, tf), rows in list(pairs.items())[::7]:
        raw = np.array([r["raw"] for r in rows], np.int64)
        v = drdc.units_convert_array(raw, ff, a, tf, b)
        assert (v.status == 0).all()
        assert list(v.value) == [drdc.units_convert(int(x), ff, a, tf, b)
                                 for x in raw]
        assert np.abs(v.value - [r["expect"] for r in rows]).max() \
            <= GNU_UNITS_LSB


def test_statuses():
    with pytest.raises(drdc.DrdcError) as e:
        drdc.units_convert(1, 0, "furlongs-per-nothing", 0, "m")
    assert e.value.name == "DRDC_E_UNKNOWN_UNIT"
    with pytest.raises(drdc.DrdcError) as e:
        drdc.units_convert(1, 0, "m", 0, "s")
    assert e.value.code == drdc.Status.DRDC_E_DIMENSION
    v = drdc.units_convert_array([1, (1 << 62)], 0, "km", 0, "mm")
    assert list(v.status) == [0, drdc.Status.DRDC_E_OVERFLOW]
    assert list(v.value) == [1000000, 0]


def test_header_examples():
    # units.h: 10 ft = 3.048 m in Q47.16; 100 km/h = 27.77... m/s
    assert drdc.units_convert(10 << 16, 16, "ft", 16, "m") == 199754
    assert drdc.units_convert_expr(100 << 16, 16, "km/h", 16, "m/s") \
        == 1820444
