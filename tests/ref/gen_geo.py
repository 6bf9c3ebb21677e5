# SPDX-License-Identifier: BSD-2-Clause
"""Reference vectors of core/geo (UTM, UPS, transverse Mercator).

Oracle: GeographicLib 2.1.2 (Debian `geographiclib-tools`, pinned in
waftools/deps.py): `GeoConvert -u -p 9` (UTM, 1e-9 m), `GeoConvert -c -p 9`
(convergence 1e-14 degree, scale 1e-16), `GeoConvert -p 9` on UTM input
(1e-14 degree) and `TransverseMercatorProj -s -k 0.9996` (series, as
GeoConvert; 1e-9 m via its -p option). Inputs are decimal degrees with at
most 9 decimals, exact in nano-arcseconds; outputs are converted to exact
integers (Q47.16 metres, nas, Q5.58 scale) rounded to nearest.

Rows: 20 000 random points over every zone and both hemispheres (-80 <=
lat < 84) and 2 000 in the UPS caps, every zone and band edge, the Norway
and Svalbard boundaries, the equator, -80 and 84 degrees, the poles; 600 points forced into a neighbouring
zone; 1 000 points up to 500 km outside their zone through the plain
projection; reverse rows on the forward results."""
import random
import subprocess
from decimal import Decimal, ROUND_HALF_UP

NAS_DEG = 3600 * 10 ** 9
RANDOM_POINTS = 20000


def rnd(d):
    # nearest, ties away from zero
    q = abs(d).quantize(Decimal(1), rounding=ROUND_HALF_UP)
    return int(q) if d >= 0 else -int(q)


def nas(text):
    return rnd(Decimal(text) * NAS_DEG)


def q16(text):
    return rnd(Decimal(text) * 65536)


def q58(text):
    return rnd(Decimal(text) * (1 << 58))


def deg(n):
    # exact decimal degrees of a nas value with at most 9 decimals
    return "{:f}".format(Decimal(n) / NAS_DEG)


def run(args, lines):
    out = subprocess.run(args, input="\n".join(lines) + "\n", text=True,
                         capture_output=True, check=False).stdout
    out = out.splitlines()
    bad = [(l, o) for l, o in zip(lines, out) if o.startswith("ERROR")]
    if bad or len(out) != len(lines):
        raise SystemExit("%s failed: %s" % (" ".join(args), bad[:3]))
    return out


def lit(v):
    return "INT64_C(%d)" % v


def edge_points():
    pts = set()
    tiny = 3600  # 1e-9 degree
    lats = [-80, -72, -64, -56, -48, -40, -32, -24, -16, -8, 0, 8, 16, 24,
            32, 40, 48, 56, 64, 72, 80, 83]
    for lon in range(-180, 181, 6):
        for lat in (-79.5, -33.25, 0, 17.125, 45.5, 83.5):
            for d in (-tiny, 0, tiny):
                pts.add((int(lat * NAS_DEG), lon * NAS_DEG + d))
    for lat in lats:
        for lon in (-177, -3, 1.5, 5, 14.25, 101):
            for d in (-tiny, 0, tiny):
                pts.add((lat * NAS_DEG + d, int(lon * NAS_DEG)))
    # Norway 32V and Svalbard 31X-37X boundaries
    for lat in (56, 60, 64, 72, 78, 84):
        for lon in (0, 3, 6, 9, 12, 21, 33, 36, 42):
            for dl in (-tiny, 0, tiny):
                for dn in (-tiny, 0, tiny):
                    pts.add((lat * NAS_DEG + dl, lon * NAS_DEG + dn))
    # equator, the UTM latitude limits, longitudes beyond +-180
    for lon in (-539.5, -360, -181, 179.999999999, 200, 539.999999999):
        pts.add((0, int(Decimal(str(lon)) * NAS_DEG)))
    pts.add((-80 * NAS_DEG, 0))
    pts.add((84 * NAS_DEG - tiny, 0))
    # the UPS caps: their edges and the poles
    for lat in (-90, -89, -80, 84, 89, 90):
        for lon in (-180, -90, -45, 0, 45, 90, 135, 179.999999999):
            for d in ((-tiny, 0, tiny) if abs(lat) != 90 else (0,)):
                pts.add((lat * NAS_DEG + d, int(Decimal(str(lon)) * NAS_DEG)))
    return [p for p in sorted(pts) if -90 * NAS_DEG <= p[0] <= 90 * NAS_DEG]


def forward_rows(points, zone_args=None):
    """[(lat, lon, zone, north, e, n, conv, k)]; zone_args: forced zones."""
    rows = []
    groups = {}
    for i, p in enumerate(points):
        z = zone_args[i] if zone_args else None
        groups.setdefault(z, []).append(p)
    for z, pts in groups.items():
        extra = ["-z", str(z)] if z else []
        lines = ["%s %s" % (deg(a), deg(b)) for a, b in pts]
        u = run(["GeoConvert", "-u", "-p", "9"] + extra, lines)
        c = run(["GeoConvert", "-c", "-p", "9"] + extra, lines)
        for (a, b), ul, cl in zip(pts, u, c):
            zn, e, n = ul.split()
            g, k = cl.split()
            rows.append((a, b, int(zn[:-1]) if len(zn) > 1 else 0,
                         1 if zn[-1] == "n" else 0,
                         q16(e), q16(n), nas(g), q58(k)))
    return rows


def reverse_rows(fwd):
    lines = ["%s%s %s %s" % ("%d" % r[2] if r[2] else "", "n" if r[3] else "s",
                             "{:f}".format(Decimal(r[4]) / 65536),
                             "{:f}".format(Decimal(r[5]) / 65536))
             for r in fwd]
    g = run(["GeoConvert", "-p", "9"], lines)
    out = []
    for r, gl in zip(fwd, g):
        la, lo = gl.split()
        out.append((r[2], r[3], r[4], r[5], nas(la), nas(lo)))
    return out


def generate():
    rng = random.Random(6)
    pts = [(rng.randrange(-80 * NAS_DEG, 84 * NAS_DEG, 3600),
            rng.randrange(-180 * NAS_DEG, 180 * NAS_DEG, 3600))
           for _ in range(RANDOM_POINTS)]
    # the UPS caps: 2 000 random points beyond 84 N and 80 S
    for _ in range(2000):
        north = rng.random() < 0.5
        lat = rng.randrange(84 * NAS_DEG, 90 * NAS_DEG, 3600) if north else \
            -rng.randrange(80 * NAS_DEG + 3600, 90 * NAS_DEG, 3600)
        pts.append((lat, rng.randrange(-180 * NAS_DEG, 180 * NAS_DEG, 3600)))
    fwd = forward_rows(pts)
    edges = forward_rows(edge_points())
    # forced neighbouring zones (GeoConvert -z)
    forced_pts = []
    forced_zones = []
    while len(forced_pts) < 600:
        lat = rng.randrange(-80 * NAS_DEG, 84 * NAS_DEG, 3600)
        zone = rng.randint(1, 60)
        side = rng.choice([-1, 1])
        lon = (6 * zone - 183) * NAS_DEG + side * rng.randrange(
            3 * NAS_DEG // 2, 3 * NAS_DEG, 3600)
        other = (zone - 1 + side) % 60 + 1
        forced_pts.append((lat, lon))
        forced_zones.append(other)
    forced = forward_rows(forced_pts, forced_zones)
    # up to 500 km outside a zone: the plain projection
    tm_in = []
    while len(tm_in) < 1000:
        lat = rng.randrange(-80 * NAS_DEG, 84 * NAS_DEG, 3600)
        coslat = float(abs(Decimal(lat) / NAS_DEG))
        import math
        c = math.cos(math.radians(coslat))
        extra = 500.0 / (111.32 * c)
        span = min(3 + extra, 60)
        dlon = rng.randrange(0, int(span * 1e9)) * 3600
        dlon = dlon if rng.random() < 0.5 else -dlon
        tm_in.append((lat, dlon))
    tm_out = run(["TransverseMercatorProj", "-s", "-k", "0.9996", "-p", "9"],
                 ["%s %s" % (deg(a), deg(b)) for a, b in tm_in])
    tm_rows = []
    for (a, b), line in zip(tm_in, tm_out):
        x, y, g, k = line.split()
        tm_rows.append((a, b, q16(x), q16(y), nas(g), q58(k)))
    revs = [reverse_rows(rows) for rows in (fwd, edges, forced)]

    def fwd_text(name, rows):
        return "static const struct geo_fwd_vector %s[%d] = {\n%s\n};\n" % (
            name, len(rows), "\n".join(
                "  { %s, %s, %d, %d, %s, %s, %s, %s }," % (
                    lit(r[0]), lit(r[1]), r[2], r[3], lit(r[4]), lit(r[5]),
                    lit(r[6]), lit(r[7])) for r in rows))

    def rev_text(name, rows):
        return "static const struct geo_rev_vector %s[%d] = {\n%s\n};\n" % (
            name, len(rows), "\n".join("  { %s, %s }," % (lit(r[4]), lit(r[5]))
                                       for r in rows))

    text = """/* SPDX-License-Identifier: BSD-2-Clause */
/* Generated by tests/ref/gen_geo.py from GeographicLib 2.1.2 (GeoConvert,
 * TransverseMercatorProj -s): UTM forward and reverse, convergence and
 * scale, zones. Do not edit; run tools/generate.py. */
#ifndef VECTORS_GEO_H
#define VECTORS_GEO_H

#include <stdint.h>

/* lat, lon (nas) -> zone, north, easting, northing (Q47.16 m),
 * convergence (nas), scale (Q5.58) */
struct geo_fwd_vector {
  int64_t lat;
  int64_t lon;
  int32_t zone;
  int32_t north;
  int64_t easting;
  int64_t northing;
  int64_t convergence;
  int64_t scale;
};

/* the UTM of the forward row of the same index (rounded to Q47.16 m)
 * -> lat, lon (nas) */
struct geo_rev_vector {
  int64_t lat;
  int64_t lon;
};

/* lat, dlon (nas) -> x, y (Q47.16 m), convergence (nas), scale (Q5.58) */
struct geo_tm_vector {
  int64_t lat;
  int64_t dlon;
  int64_t x;
  int64_t y;
  int64_t convergence;
  int64_t scale;
};

%s
%s
/* forced into the neighbouring zone (GeoConvert -z) */
%s
%s

/* up to 500 km outside the zone (TransverseMercatorProj -s -k 0.9996) */
static const struct geo_tm_vector geo_tm_vectors[%d] = {
%s
};

#endif
""" % (fwd_text("geo_random_vectors", fwd), fwd_text("geo_edge_vectors", edges),
       fwd_text("geo_forced_vectors", forced),
       "\n".join(rev_text(n, r) for n, r in zip(
           ("geo_random_rev", "geo_edge_rev", "geo_forced_rev"), revs)),
       len(tm_rows),
       "\n".join("  { %s, %s, %s, %s, %s, %s }," % tuple(lit(v) for v in r)
                 for r in tm_rows))
    return {"tests/geo/vectors_geo.h": text}
