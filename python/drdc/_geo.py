# SPDX-License-Identifier: BSD-2-Clause
"""Geodesy (core/include/drdc/geo.h, geo_mgrs.h): geographic <-> UTM/UPS,
transverse Mercator, MGRS. Latitude and longitude in nas (nano-arcseconds,
int64), eastings and northings in Q47.16 metres (int64), convergence in
nas, point scale in Q5.58 (int64), as the C functions take them."""
import ctypes
from collections import namedtuple

import numpy as np

from . import _check
from ._lib import GeoUtm, lib
from ._status import Status, check

ZONE_STANDARD = -1  # DRDC_GEO_ZONE_STANDARD: the point's standard zone
ZONE_UPS = 0        # DRDC_GEO_ZONE_UPS: the polar caps
MGRS_PREC_MIN = -1  # DRDC_GEO_MGRS_PREC_MIN
MGRS_PREC_MAX = 11  # DRDC_GEO_MGRS_PREC_MAX
MGRS_SIZE = 28      # DRDC_GEO_MGRS_SIZE, with the terminating NUL

Utm = namedtuple("Utm", "zone north easting_q47_16 northing_q47_16 "
                 "convergence_nas scale_q5_58")
UtmPosition = namedtuple("UtmPosition",
                         "zone north easting_q47_16 northing_q47_16")
Geographic = namedtuple("Geographic",
                        "lat_nas lon_nas convergence_nas scale_q5_58")
TransverseMercator = namedtuple("TransverseMercator",
                                "x_q47_16 y_q47_16 convergence_nas "
                                "scale_q5_58")
Mgrs = namedtuple("Mgrs", "corner centre prec")
UtmArrays = namedtuple("UtmArrays", Utm._fields + ("status",))
GeographicArrays = namedtuple("GeographicArrays",
                              Geographic._fields + ("status",))
MgrsArrays = namedtuple("MgrsArrays", "text status")
ZoneArrays = namedtuple("ZoneArrays", "zone status")
TransverseMercatorArrays = namedtuple(
    "TransverseMercatorArrays", TransverseMercator._fields + ("status",))
MgrsDecodeArrays = namedtuple("MgrsDecodeArrays", UtmPosition._fields
                              + ("prec", "status"))

_I64 = ctypes.c_int64


def _utm_in(zone, north, easting_q47_16, northing_q47_16):
    if not isinstance(north, (bool, np.bool_)):
        _check.integer(north, "north", (0, 1))
    return GeoUtm(_check.integer(zone, "zone", _check.INT32), bool(north),
                  _check.integer(easting_q47_16, "easting_q47_16",
                                 _check.INT64),
                  _check.integer(northing_q47_16, "northing_q47_16",
                                 _check.INT64))


def geo_utm_zone(lat_nas, lon_nas):
    """drdc_geo_utm_zone: the standard UTM zone 1..60 of a point, 0 in the
    polar caps (UPS)."""
    zone = ctypes.c_int32()
    check(lib.drdc_geo_utm_zone(_check.integer(lat_nas, "lat_nas",
                                               _check.INT64),
                                _check.integer(lon_nas, "lon_nas",
                                               _check.INT64),
                                ctypes.byref(zone)), "drdc_geo_utm_zone")
    return zone.value


def geo_tm_forward(lat_nas, dlon_nas):
    """drdc_geo_tm_forward: transverse Mercator (k0 0.9996, no false
    origin) of a latitude and a longitude from the central meridian."""
    x, y, conv, scale = _I64(), _I64(), _I64(), _I64()
    check(lib.drdc_geo_tm_forward(
        _check.integer(lat_nas, "lat_nas", _check.INT64),
        _check.integer(dlon_nas, "dlon_nas", _check.INT64),
        ctypes.byref(x), ctypes.byref(y), ctypes.byref(conv),
        ctypes.byref(scale)), "drdc_geo_tm_forward")
    return TransverseMercator(x.value, y.value, conv.value, scale.value)


def geo_to_utm(lat_nas, lon_nas, zone=ZONE_STANDARD):
    """drdc_geo_to_utm: geographic -> UTM/UPS (GeoConvert -u), in the
    standard zone, or in `zone` (0 forces UPS, 1..60 a UTM zone)."""
    out, conv, scale = GeoUtm(), _I64(), _I64()
    check(lib.drdc_geo_to_utm(
        _check.integer(lat_nas, "lat_nas", _check.INT64),
        _check.integer(lon_nas, "lon_nas", _check.INT64),
        _check.integer(zone, "zone", _check.INT32),
        ctypes.byref(out), ctypes.byref(conv), ctypes.byref(scale)),
        "drdc_geo_to_utm")
    return Utm(out.zone, out.north, out.easting, out.northing, conv.value,
               scale.value)


def geo_from_utm(zone, north, easting_q47_16, northing_q47_16,
                 with_scale=False):
    """drdc_geo_from_utm: UTM/UPS (zone 0) -> geographic. The meridian
    convergence and the point scale only when asked (with_scale=True;
    else None, and the library skips computing them, a third of the
    time)."""
    u = _utm_in(zone, north, easting_q47_16, northing_q47_16)
    lat, lon, conv, scale = _I64(), _I64(), _I64(), _I64()
    check(lib.drdc_geo_from_utm(
        ctypes.byref(u), ctypes.byref(lat), ctypes.byref(lon),
        ctypes.byref(conv) if with_scale else None,
        ctypes.byref(scale) if with_scale else None), "drdc_geo_from_utm")
    if not with_scale:
        return Geographic(lat.value, lon.value, None, None)
    return Geographic(lat.value, lon.value, conv.value, scale.value)


def geo_mgrs_encode(lat_nas, lon_nas, prec=5):
    """drdc_geo_mgrs_encode: MGRS of a point (GeoConvert -m), `prec`
    digits per coordinate (-1..11; 5 is 1 m), truncated."""
    text = ctypes.create_string_buffer(MGRS_SIZE)
    check(lib.drdc_geo_mgrs_encode(
        _check.integer(lat_nas, "lat_nas", _check.INT64),
        _check.integer(lon_nas, "lon_nas", _check.INT64),
        _check.integer(prec, "prec", _check.INT32), text, MGRS_SIZE),
        "drdc_geo_mgrs_encode")
    return text.value.decode("ascii")


def geo_mgrs_from_utm(zone, north, easting_q47_16, northing_q47_16, prec=5):
    """drdc_geo_mgrs_from_utm: MGRS of a UTM/UPS position in its own zone."""
    u = _utm_in(zone, north, easting_q47_16, northing_q47_16)
    text = ctypes.create_string_buffer(MGRS_SIZE)
    check(lib.drdc_geo_mgrs_from_utm(
        ctypes.byref(u), _check.integer(prec, "prec", _check.INT32), text,
        MGRS_SIZE), "drdc_geo_mgrs_from_utm")
    return text.value.decode("ascii")


def geo_mgrs_decode(text):
    """drdc_geo_mgrs_decode: MGRS text -> Mgrs(corner, centre, prec), the
    south-west corner and the centre of the cell as UtmPosition."""
    if not isinstance(text, str):
        raise TypeError("text: a str, not %s" % type(text).__name__)
    try:
        raw = text.encode("ascii")
    except UnicodeEncodeError:
        raise ValueError("text: MGRS is ASCII, %r is not" % text) from None
    if b"\0" in raw:
        raise ValueError("text: a NUL character would end the C string")
    corner, centre, prec = GeoUtm(), GeoUtm(), ctypes.c_int32()
    check(lib.drdc_geo_mgrs_decode(raw, ctypes.byref(corner),
                                   ctypes.byref(centre), ctypes.byref(prec)),
          "drdc_geo_mgrs_decode")

    def position(u):
        return UtmPosition(u.zone, u.north, u.easting, u.northing)
    return Mgrs(position(corner), position(centre), prec.value)


# ---- arrays: one status per element, outputs 0 where it is an error ----

def geo_to_utm_array(lat_nas, lon_nas, zone=ZONE_STANDARD):
    """drdc_geo_to_utm over arrays (broadcast together): UtmArrays of
    zone (int32), north (bool), easting_q47_16, northing_q47_16,
    convergence_nas, scale_q5_58 (int64) and status (int32)."""
    (lat, lon, zones), shape = _check.broadcast(
        _check.integer_array(lat_nas, "lat_nas", _check.INT64, np.int64),
        _check.integer_array(lon_nas, "lon_nas", _check.INT64, np.int64),
        _check.integer_array(zone, "zone", _check.INT32, np.int32))
    n = lat.size
    z = np.zeros(n, np.int32)
    north = np.zeros(n, np.uint8)
    e, nn, conv, scale = (np.zeros(n, np.int64) for _ in range(4))
    status = np.zeros(n, np.int32)
    lib.drdc_batch_geo_to_utm(n, *(a.ctypes.data for a in (
        lat, lon, zones, z, north, e, nn, conv, scale, status)))
    return UtmArrays(*(a.reshape(shape) for a in
                       (z, north.astype(np.bool_), e, nn, conv, scale,
                        status)))


def _utm_arrays(zone, north, easting_q47_16, northing_q47_16, *more):
    north = np.asarray(north)
    if north.dtype.kind == "b":
        north = north.astype(np.int32)
    return _check.broadcast(
        _check.integer_array(zone, "zone", _check.INT32, np.int32),
        _check.integer_array(north, "north", (0, 1), np.int32),
        _check.integer_array(easting_q47_16, "easting_q47_16", _check.INT64,
                             np.int64),
        _check.integer_array(northing_q47_16, "northing_q47_16",
                             _check.INT64, np.int64), *more)


def geo_from_utm_array(zone, north, easting_q47_16, northing_q47_16,
                       with_scale=False):
    """drdc_geo_from_utm over arrays (broadcast together; north: bool or
    0/1): GeographicArrays of lat_nas, lon_nas (int64) and status (int32);
    convergence_nas and scale_q5_58 (int64) only with with_scale=True,
    else None (the library then skips computing them)."""
    (zones, norths, es, ns), shape = _utm_arrays(zone, north, easting_q47_16,
                                                 northing_q47_16)
    n = zones.size
    lat, lon = np.zeros(n, np.int64), np.zeros(n, np.int64)
    conv = np.zeros(n, np.int64) if with_scale else None
    scale = np.zeros(n, np.int64) if with_scale else None
    status = np.zeros(n, np.int32)
    lib.drdc_batch_geo_from_utm(
        n, zones.ctypes.data, norths.ctypes.data, es.ctypes.data,
        ns.ctypes.data, lat.ctypes.data, lon.ctypes.data,
        conv.ctypes.data if with_scale else None,
        scale.ctypes.data if with_scale else None, status.ctypes.data)
    return GeographicArrays(*(None if a is None else a.reshape(shape)
                              for a in (lat, lon, conv, scale, status)))


def geo_utm_zone_array(lat_nas, lon_nas):
    """drdc_geo_utm_zone over arrays: ZoneArrays of zone (int32, 1..60, 0
    for UPS) and status."""
    (lat, lon), shape = _check.broadcast(
        _check.integer_array(lat_nas, "lat_nas", _check.INT64, np.int64),
        _check.integer_array(lon_nas, "lon_nas", _check.INT64, np.int64))
    zone = np.zeros(lat.size, np.int32)
    status = np.zeros(lat.size, np.int32)
    lib.drdc_batch_geo_utm_zone(lat.size, lat.ctypes.data, lon.ctypes.data,
                                zone.ctypes.data, status.ctypes.data)
    return ZoneArrays(zone.reshape(shape), status.reshape(shape))


def geo_tm_forward_array(lat_nas, dlon_nas):
    """drdc_geo_tm_forward over arrays: TransverseMercatorArrays of
    x_q47_16, y_q47_16, convergence_nas, scale_q5_58 and status."""
    (lat, dlon), shape = _check.broadcast(
        _check.integer_array(lat_nas, "lat_nas", _check.INT64, np.int64),
        _check.integer_array(dlon_nas, "dlon_nas", _check.INT64, np.int64))
    outs = [np.zeros(lat.size, np.int64) for _ in range(4)]
    status = np.zeros(lat.size, np.int32)
    lib.drdc_batch_geo_tm_forward(lat.size, lat.ctypes.data,
                                  dlon.ctypes.data,
                                  *(a.ctypes.data for a in outs + [status]))
    return TransverseMercatorArrays(*(a.reshape(shape)
                                      for a in outs + [status]))


def _mgrs_text(rows, shape):
    return rows.astype(np.str_).reshape(shape)


def geo_mgrs_encode_array(lat_nas, lon_nas, prec=5):
    """drdc_geo_mgrs_encode over arrays, the loop in C: MgrsArrays of text
    (numpy str array, "" where the status is an error) and status
    (int32)."""
    (lat, lon, precs), shape = _check.broadcast(
        _check.integer_array(lat_nas, "lat_nas", _check.INT64, np.int64),
        _check.integer_array(lon_nas, "lon_nas", _check.INT64, np.int64),
        _check.integer_array(prec, "prec", _check.INT32, np.int32))
    rows = np.zeros(lat.size, "S%d" % MGRS_SIZE)
    status = np.zeros(lat.size, np.int32)
    lib.drdc_batch_geo_mgrs_encode(lat.size, lat.ctypes.data,
                                   lon.ctypes.data, precs.ctypes.data,
                                   rows.ctypes.data, status.ctypes.data)
    return MgrsArrays(_mgrs_text(rows, shape), status.reshape(shape))


def geo_mgrs_from_utm_array(zone, north, easting_q47_16, northing_q47_16,
                            prec=5):
    """drdc_geo_mgrs_from_utm over arrays (broadcast together), the loop in
    C: MgrsArrays of text and status."""
    (zones, norths, es, ns, precs), shape = _utm_arrays(
        zone, north, easting_q47_16, northing_q47_16,
        _check.integer_array(prec, "prec", _check.INT32, np.int32))
    rows = np.zeros(zones.size, "S%d" % MGRS_SIZE)
    status = np.zeros(zones.size, np.int32)
    lib.drdc_batch_geo_mgrs_from_utm(
        zones.size, zones.ctypes.data, norths.ctypes.data, es.ctypes.data,
        ns.ctypes.data, precs.ctypes.data, rows.ctypes.data,
        status.ctypes.data)
    return MgrsArrays(_mgrs_text(rows, shape), status.reshape(shape))


def text_rows(text, name):
    """An array of str as NUL-padded ASCII rows for C, and a mask of the
    elements C could not read as the text they are (beyond ASCII, or
    holding a NUL): (rows, width, bad, shape)."""
    texts = np.asarray(text)
    if texts.dtype.kind != "U":
        raise TypeError("%s: an array of str, not dtype %s"
                        % (name, texts.dtype))
    shape = texts.shape
    flat = texts.ravel()
    try:
        rows = flat.astype("S")
        bad = np.zeros(flat.size, bool)
    except UnicodeEncodeError:
        bad = np.array([not t.isascii() for t in flat.tolist()], bool)
        rows = np.where(bad, "", flat).astype("S")
    if flat.size and flat.dtype.itemsize:
        # a NUL inside a text: fewer non-zero code points than characters
        # (numpy keeps no NUL at a text's end)
        codes = np.ascontiguousarray(flat).view(np.uint32).reshape(
            flat.size, -1)
        nul = np.count_nonzero(codes, axis=1) != np.char.str_len(flat)
        bad |= nul
        rows = np.where(nul, b"", rows)
    width = max(rows.dtype.itemsize, 1)
    rows = np.ascontiguousarray(rows.astype("S%d" % width))
    return rows, width, bad, shape


def geo_mgrs_decode_array(text):
    """drdc_geo_mgrs_decode over an array of str (any shape), the loop in C:
    MgrsDecodeArrays of the cell's centre (zone int32, north bool,
    easting_q47_16, northing_q47_16 int64), prec (int32) and status
    (int32; a text that is not ASCII, or holds a NUL, is DRDC_E_MGRS)."""
    rows, width, bad, shape = text_rows(text, "text")
    n = rows.size
    zone = np.zeros(n, np.int32)
    north = np.zeros(n, np.uint8)
    e = np.zeros(n, np.int64)
    nn = np.zeros(n, np.int64)
    prec = np.zeros(n, np.int32)
    status = np.zeros(n, np.int32)
    scratch = ctypes.create_string_buffer(width + 1)
    lib.drdc_batch_geo_mgrs_decode(
        n, rows.ctypes.data, width, scratch, zone.ctypes.data,
        north.ctypes.data, e.ctypes.data, nn.ctypes.data, prec.ctypes.data,
        status.ctypes.data)
    if bad.any():
        # C could not read it as the text it is: malformed MGRS
        status[bad] = Status.DRDC_E_MGRS
        for a in (zone, north, e, nn, prec):
            a[bad] = 0
    return MgrsDecodeArrays(*(a.reshape(shape) for a in
                              (zone, north.astype(np.bool_), e, nn, prec,
                               status)))
