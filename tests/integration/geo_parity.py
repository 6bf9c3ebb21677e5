# SPDX-License-Identifier: BSD-2-Clause
"""drdc geo against GeoConvert, byte for byte, and the rule that explains
every line that is not identical (tests/integration/test_drdc.py runs it in ./waf
check; `python3 tests/integration/geo_parity.py` prints the table of docs/accuracy.md).

A line of drdc geo is accepted when it is byte-identical to GeoConvert's,
or else when exactly one of these documented rules holds:

  cap     the option's output is a value computed by the library (not the
          input itself) and PREC is above the digits the library resolves:
          drdc prints what GeoConvert prints at the capped PREC (-g, -c
          convergence: 7, 12 decimals of a degree; -d: 8, 9 decimals of a
          second; -u: 4, 4 decimals of a metre; -m from metres: 4, 9
          digits), and that line is then held to these same rules;
  lsb     numbers differ by one unit of their last digit and GeoConvert's
          own value (printed at its finest PREC) lies within the library's
          documented accuracy of the rounding boundary between the two
          (the midpoint; for MGRS, which truncates, the boundary itself):
          2^-16 m for metres, 1 nas (1/3.6e12 degree) for angles, 1.2e-15
          for the point scale, each plus half a unit of GeoConvert's last
          printed digit;
  exact   the value is the input itself (-g and -d of 'LAT LON' text):
          drdc prints its exact decimal rounded half to even, which the
          test computes with Python fractions, while GeoConvert's double
          differs from it by one unit of the last digit (its 53-bit
          mantissa carries 15 to 17 significant digits);
  input   the value is the grid input itself (-u of UTM/UPS or MGRS input
          in its own zone, -m of it): drdc writes the exact decimal of the
          input (an MGRS cell's centre or corner), rounded half to even
          (-u) or truncated (-m), which the test computes with Python
          fractions, while GeoConvert's double of it, or of the
          micrometres it forms, is one unit of the last digit off (at 16
          significant digits and more).

ERROR lines are byte-identical: every one of the random lines above, of
BAD_INPUTS (check_errors()) and of fuzz_lines() (check_fuzz()), where
one more rule is counted:

  own-limit  drdc's own limits, where GeoConvert reads on: 'angle beyond
          1000000d in TOKEN' (drdc holds 1 000 000 degrees), 'Cannot
          decode TOKEN (beyond 1e12 m)', and a minutes or seconds
          component of more than 15 digits, quoted as 1e+15.
"""
import math
import os
import random
import re
import subprocess
import sys
from fractions import Fraction

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, TOP)
from tests.integration import drdc_tool  # noqa: E402  (host, or win64 under Wine)
DRDC = drdc_tool.COMMAND

# GeoConvert's finest PREC per output, and drdc's cap for computed values
FINEST = {"-g": 9, "-d": 10, "-:": 10, "-u": 9, "-m": 6, "-c": 8}
CAP = {"-g": 7, "-d": 8, "-:": 8, "-u": 4, "-m": 4, "-c": 7}
NAS = Fraction(1, 3600 * 10 ** 9)          # degrees
BOUND = {"deg": NAS, "m": Fraction(1, 65536), "scale": Fraction(12, 10 ** 16)}


def run(prog, args, lines):
    r = subprocess.run(prog + args, input="".join(l + "\n" for l in lines),
                       capture_output=True, text=True)
    out = r.stdout.split("\n")[:-1]
    assert len(out) == len(lines), (prog, args, r.returncode, r.stdout[-300:],
                                    r.stderr[-300:])
    return out


def drdc(args, lines):
    return run(DRDC + ["geo"], args, lines)


def geoconvert(args, lines):
    return run(["GeoConvert"], args, lines)


def mode_of(args):
    for a in args:
        if a in FINEST:
            return a
    return "-g"


def with_prec(args, p):
    return [a for a in args] + ["-p", str(p)]


def decimal(tok):
    """A decimal token -> (value, unit of its last digit)."""
    m = re.fullmatch(r"-?(\d+)(?:\.(\d+))?", tok)
    if m is None:
        return None
    frac = m.group(2) or ""
    return Fraction(tok), Fraction(1, 10 ** len(frac))


def dms(tok):
    """A -d or -: token -> (signed degrees, unit of its last digit)."""
    m = re.fullmatch(r"(\d+)(?:[d:](\d+)(?:['\:](\d+))?)?(?:\.(\d+))?['\"]?"
                     r"([NSEW])", tok)
    if m is None:
        return None
    d, mi, s, f, h = m.groups()
    parts = [x for x in (d, mi, s) if x is not None]
    scale = [Fraction(1), Fraction(1, 60), Fraction(1, 3600)][len(parts) - 1]
    value = sum(Fraction(int(x)) * [1, Fraction(1, 60), Fraction(1, 3600)][i]
                for i, x in enumerate(parts))
    unit = scale / 10 ** len(f or "")
    value += Fraction(int(f)) * unit if f else 0
    return (-value if h in "SW" else value), unit


def mgrs(tok):
    """An MGRS token -> (prefix, easting digits, northing digits, unit m)."""
    m = re.fullmatch(r"(\d*[A-Z]+)(\d*)", tok)
    digits = m.group(2)
    n = len(digits) // 2
    if n == 0:
        return m.group(1), 0, 0, None
    return (m.group(1), int(digits[:n]), int(digits[n:]),
            Fraction(10) ** (5 - n))


PIECE = re.compile(r"([NSEW])?([+-])?(\d+(?:\.\d+)?)(?:[d:](\d+(?:\.\d+)?))?"
                   r"(?:['\:](\d+(?:\.\d+)?))?['\"]?([NSEW])?")


def angle(word):
    """The exact value of an angle of the inputs here (decimal degrees,
    d ' " or : components, hemisphere letters, interior signs), or None.
    A value drdc holds exactly: at most 11 decimals of a degree, 9 of a
    second."""
    total, neg = Fraction(0), True
    for m in re.finditer(r"[+-]?[^+-]+", word):
        p = PIECE.fullmatch(m.group(0))
        if p is None:
            return None
        h1, sign, d, mi, sec, h2 = p.groups()
        v = Fraction(d) + Fraction(mi or 0) / 60 + Fraction(sec or 0) / 3600
        if (v * 3600 * 10 ** 9).denominator != 1:
            return None
        s = -1 if (sign == "-") != ((h1 or h2 or "N") in "SW") else 1
        total += s * v
        neg = neg and s < 0
    return total, (total < 0 or (total == 0 and neg))


def plain(word):
    """An angle of 'LAT LON' input whose value drdc holds exactly."""
    return angle(word) is not None


def exact_geo(text, decimals):
    """-g of an exact angle: rounded half to even, as drdc prints it."""
    v, negative = angle(text)
    q = round(v * 10 ** decimals)
    s = "-" if negative else ""
    q = abs(q)
    if decimals == 0:
        return "%s%d" % (s, q)
    return "%s%d.%0*d" % (s, q // 10 ** decimals, decimals, q % 10 ** decimals)


def exact_dms(text, prec, hemis, sep):
    v, negative = angle(text)
    last = 0 if prec < 2 else (1 if prec < 4 else 2)
    dec = prec - 2 * last
    total = round(abs(v) * [1, 60, 3600][last] * 10 ** dec)
    whole, frac = divmod(total, 10 ** dec)
    width = 2 if hemis == "SN" else 3
    f = ".%0*d" % (dec, frac) if dec else ""
    if last == 0:
        s = "%0*d%s" % (width, whole, f)
    elif last == 1:
        s = "%0*d%s%02d%s%s" % (width, whole // 60, sep or "d", whole % 60, f,
                               "" if sep else "'")
    else:
        s = "%0*d%s%02d%s%02d%s%s" % (width, whole // 3600, sep or "d",
                                      whole // 60 % 60, sep or "'",
                                      whole % 60, f, "" if sep else '"')
    return s + hemis[0 if negative else 1]  # hemis: "SN" or "WE"


def double_close(a, b, exact):
    """drdc's a (value, unit of the last digit) is the exact angle rounded;
    GeoConvert's b is its double of the angle, which is off by up to two
    spacings of doubles there (its reading and its one multiplication by
    60 or 3600 each round once), printed rounded: |a - b| is at most that
    plus one unit."""
    spacing = Fraction(math.ulp(float(abs(exact)) or 1.0))
    return a[1] == b[1] and abs(a[0] - b[0]) <= 2 * spacing + a[1]


def near_boundary(a, b, ref, bound, truncate=False):
    """a, b: (value, unit) one unit apart; ref: GeoConvert's finest
    (value, unit). True when ref lies within bound of the boundary."""
    (va, ua), (vb, ub) = a, b
    if ua != ub or abs(va - vb) != ua:
        return False
    edge = max(va, vb) if truncate else (va + vb) / 2
    return abs(ref[0] - edge) <= bound + ref[1] / 2


def grid_input(args, line, ref):
    """The exact easting and northing (Fractions) of grid input (UTM/UPS
    or an MGRS cell's centre, or corner with -n) where drdc writes it in
    the input's own zone, in the hemisphere GeoConvert writes (ref: its
    -u -p 9 line); None for other lines."""
    words, rw = line.split(), ref.split()
    if len(rw) != 3 or not re.fullmatch(r"\d*[ns]", rw[0]):
        return None
    zone = int(rw[0][:-1] or 0)
    approx = [Fraction(x) for x in rw[1:]]
    if len(words) == 3:
        z = words[0] if words[0][-1:].isalpha() else words[2]
        metres = words[1:] if z == words[0] else words[:2]
        if int(re.match(r"\d*", z).group(0) or 0) != zone:
            return None
        e, n = [Fraction(x) for x in metres]
        # GeoConvert moves a northing to its latitude's hemisphere
        n += 10 ** 7 * round((approx[1] - n) / 10 ** 7)
        return e, n
    m = re.fullmatch(r"(\d*)[A-Za-z]+(\d*)", line.strip())
    if len(words) != 1 or m is None or not m.group(2) or \
            int(m.group(1) or 0) != zone:
        return None
    unit = Fraction(10) ** (5 - len(m.group(2)) // 2)
    half = 0 if "-n" in args else unit / 2
    return tuple(round((v - half) / unit) * unit + half for v in approx)


def grid_text(value, prec):
    """A coordinate as drdc writes the input's own: half to even at PREC
    decimals, or for a negative PREC in units of 10^-PREC m with -PREC
    zeros appended when not 0."""
    scale = Fraction(10) ** prec
    q = round(value * scale)
    sign = "-" if value < 0 else ""
    if prec <= 0:
        text = "%s%d" % (sign, abs(q))
        return text + "0" * -prec if q != 0 else text
    return "%s%d.%0*d" % (sign, abs(q) // 10 ** prec, prec,
                          abs(q) % 10 ** prec)


def classify(args, line, got, want, want_cap, ref):
    """Which rule explains drdc's `got` (GeoConvert: `want`, at the capped
    PREC `want_cap` or None, at the finest PREC `ref`), or None."""
    mode = mode_of(args)
    if got == want:
        return "identical"
    gw, ww, rw = got.split(), want.split(), ref.split()
    cw = want_cap.split() if want_cap is not None else ww
    if len(gw) != len(ww) or len(cw) != len(gw) or \
            (mode != "-m" and len(rw) != len(gw)):
        return None
    words = line.split() if len(line.split()) == 2 else ["x", "x"]
    grid = grid_input(args, line, ref) if mode in ("-u", "-m") else None
    rules = set()
    for i, g in enumerate(gw):
        exact = mode in ("-g", "-d", "-:") and plain(words[i])
        # the input itself is printed in full; computed values are capped
        own = exact or (grid is not None and (mode == "-m" or i > 0))
        w = ww[i] if own else cw[i]
        capped = not own and want_cap is not None and cw[i] != ww[i]
        if g == w:
            rules.add("cap" if capped else "identical")
            continue
        rule = "cap+lsb" if capped else "lsb"
        if mode in ("-d", "-:"):
            a, b, c = dms(g), dms(w), dms(rw[i])
            if exact:
                ok = exact_dms(words[i], max(0, min(10, int(args[-1])) + 5),
                               "SN" if g[-1] in "NS" else "WE",
                               ":" if mode == "-:" else "") == g
                if ok and a and b and double_close(a, b, angle(words[i])[0]):
                    rules.add("exact")
                    continue
            if not (a and b and c and near_boundary(a, b, c, BOUND["deg"])):
                return None
        elif mode == "-m":
            pg, eg, ng, ug = mgrs(g)
            pw, ew, nw, uw = mgrs(w)
            if pg != pw or ug != uw or ug is None or len(rw) != 3:
                return None
            re_, rn = [Fraction(x) % 100000 for x in rw[1:3]]
            for j, (dg, dw, rv) in enumerate(((eg, ew, re_), (ng, nw, rn))):
                if dg != dw and grid is not None and abs(dg - dw) == 1 and \
                        dg == (grid[j] % 100000) // ug:
                    rule = "input"
                elif dg != dw and not near_boundary(
                        (dg * ug, ug), (dw * ug, ug),
                        (rv, Fraction(1, 10 ** 9)), BOUND["m"],
                        truncate=True):
                    return None
        else:
            a, b, c = decimal(g), decimal(w), decimal(rw[i])
            if a is None or b is None or c is None:
                return None
            if exact:
                places = len(g.split(".")[1]) if "." in g else 0
                if exact_geo(words[i], places) == g and \
                        double_close(a, b, angle(words[i])[0]):
                    rules.add("exact")
                    continue
            if mode == "-u" and grid is not None and i > 0 and \
                    a[1] == b[1] and abs(a[0] - b[0]) == a[1] and \
                    g == grid_text(grid[i - 1],
                                   max(-5, min(9, int(args[-1])))):
                rules.add("input")
                continue
            bound = (BOUND["m"] if mode == "-u" else
                     BOUND["scale"] if (mode == "-c" and i == 1) else
                     BOUND["deg"])
            if not near_boundary(a, b, c, bound):
                return None
        rules.add(rule)
    for rule in ("exact", "input", "cap+lsb", "lsb", "cap"):
        if rule in rules:
            return rule
    return "identical"


def inputs(seed, kind, n=120):
    rng = random.Random(seed)
    if kind == "zone31":
        pts = ["%.9f %.9f" % (rng.uniform(-80, 84), rng.uniform(-2.5, 8.5))
               for _ in range(n)]
    elif kind == "polar":
        # the caps, mostly where UTM still reaches (-t)
        pts = ["%.9f %.9f" % (rng.choice([-1, 1]) * rng.uniform(79, 86)
                              if i % 4 else rng.uniform(-90, 90),
                              rng.uniform(-180, 180)) for i in range(n)]
    else:
        pts = []
        for _ in range(n):
            lat = rng.uniform(-90, 90) if rng.random() < 0.2 else \
                rng.uniform(-80, 84)
            lon = rng.uniform(-180, 180)
            d = rng.choice([1, 2, 4, 6, 9])
            pts.append("%.*f %.*f" % (d, lat, d, lon))
        # halfway values and DMS input
        pts += ["5.5 6.5", "-2.5 -3.5", "0.125 0.375", "33d20'N 44d24E",
                "44:24 33:20:00N", "39N 70W+0:0:15E", "-0 -0", "-0 10",
                "0S 3", "-0.0000000000001 10"]
    if kind == "lonlat":  # -w: longitude first
        return [" ".join(reversed(p.split())) for p in inputs(seed, "geo")]
    if kind != "geographic":
        return pts
    # grid input given finer than Q47.16 metres, which drdc carries in
    # full: UTM/UPS metres to the centimetre and the millimetre
    # (GeoConvert -u -p 4, cut), a few in sixteenths, and MGRS of 5 to 8
    # digits
    utm = []
    for i, u in enumerate(geoconvert(["-u", "-p", "4"], pts[:30])):
        z, e, n = u.split()
        cut = [sixteenths, centimetres, millimetres][i % 3]
        utm.append("%s %s %s" % (z, cut(e), cut(n)))
    utm += ["32n 500000.5 6000000.5", "31n 500000.25 4000000.75",
            "500000.5 6000000.5 32n"]
    mgrs_in = geoconvert(["-m", "-p", "-2"], pts[30:45])
    mgrs_in += geoconvert(["-m", "-p", "0"], pts[45:50])
    for p, lines in ((1, pts[50:55]), (2, pts[55:60]), (3, pts[60:65])):
        mgrs_in += geoconvert(["-m", "-p", str(p)], lines)
    return pts + utm + mgrs_in


def sixteenths(text):
    """Metres rounded to 1/16 m, written exactly (4 decimals)."""
    v = round(Fraction(text) * 16)
    return "%d.%04d" % (v // 16, v % 16 * 625)


def centimetres(text):
    return "%.2f" % Fraction(text)


def millimetres(text):
    return "%.3f" % Fraction(text)


# One line of each kind of input GeoConvert refuses, per option set: the
# ERROR lines must be byte-identical (GeoConvert's wording, the offending
# token and numbers quoted as it quotes them).
BAD_INPUTS = [
    # latitude and longitude text
    "91 0", "-91 0", "90.5 10", "0 1e3", "33d61 44", "33d20'61\" 44",
    "33d61.5 44", "33d20'60.5\" 44", "33x 44", "N33 N44", "33N 44S",
    "E1 W2", "abc 44", "33.5d20 44", "33d20'10\"5 44", "33'20d 44",
    "33d20d 44", "33'20' 44", "1.2.3 44", "33NN 44", "N33S 44", "N33N 44",
    "33N+3E 44", "33+ 44", "d 44", "' 44", "33d' 44", ":33 44", "33::5 44",
    "33: 44", "33:20:10:5 44", "N 44", "- 44", ". 44", "N-33x 44",
    "33x5N 44", "33N+3x 44", "33d20+d 44", "-- 10", "3N3 10",
    # fields
    "33 44 55 66", "a b c", "33 44 x", "31 500000 4000000",
    # UTM/UPS zone and hemisphere
    "31q 500000 0", "61n 500000 0", "0n 500000 0", "00n 500000 0",
    "-31n 500000 0", "+31n 500000 0", "123n 500000 0", "031n 500000 0",
    "31northxx 500000 0", "31nort 500000 0", "3.1n 500000 0",
    # UTM/UPS coordinates
    "31n abc 4000000", "31n 500000 x", "31n 500000 4000000.5x",
    "31n 5000600 4000000", "31n -600 4000000", "31n 500000 -20000600",
    "31s 500000 20000400", "31s 0 899999", "31n 0 9600000.5",
    "n 500000 0", "n 2000000 3000000", "s 3500000 2000000",
    "s 2000000 -500",
    # beyond a limit by less than the Q47.16 LSB, quoted as given
    "31n 1000000.000001 0", "31n -0.000001 4000000", "31n -0.3 4000000",
    "31s 500000 899999.999999", "n 1199999.999999 2000000",
    "31n 500000 9600000.0000001", "31n 99999.999999 4000000",
    # MGRS
    "38", "1", "0", "38SM", "38SMB448", "38SMBX488", "38SMB44X", "38IMB4488",
    "38SIB4488", "61SMB4488", "138SMB4488", "038SMB4488", "00SMB",
    "38ZMB4488", "38SMZ4488", "ZZA00", "ZMB4488", "AAA00", "BZA", "YAA",
    "YZZ", "AJI", "CAA", "cAA", "aB00", "38Sxb", "38S8", "38-S", "3.8SMB",
    "38SMB+4", "38NMB4488", "38nmb4488", "38NMB44X", "38XMB4488", "32VFE00",
    "38SMB4488448844884488448", "38SMB448844884488448844884488",
    "38SMB4414012345678470612345678",
    "01KRH74337", "03T4770494740", "1156086569070SMB", "99999999999",
    # GeoConvert names the fourth ':' component after its separators
    "3\":9 10", "060\":9 11295",
    # kilometres at a tie of the 6th digit, quoted from a double
    "31n 1101085 0", "31n 2033345 0", "31n 500000 7720465",
    "31n 500000 -9365255",
    # letters quoted as given, a hemisphere lower-cased
    "n33N 4", "N33n 4", "s33N 4", "e38.W 1", "1 2 31WWW", "W 31147 0",
]
BAD_OPTIONS = [["-g"], ["-u", "-z", "31"], ["-m", "-z", "31"],
               ["-u", "-z", "0"], ["-m", "-z", "0"], ["-u", "-z", "s"],
               ["-c", "-t"], ["-m", "-t"]]
# points each option set above refuses for the zone it asks for
BAD_ZONE_INPUTS = ["0 20", "0 370", "-0 20", "69.99999 0", "-70 0", "70 0",
                   "80 0", "83 10", "87 45", "-81.9 10", "28.526247014 -1.9",
                   "-89.5 0", "85.7 150", "-81.3 92", "0 510", "0 -200",
                   "0 63.0000001", "0 63", "0 -177", "0 -57.5", "38SMB4488",
                   "31n 500000 0", "n 2000000 1500000"]


def check_errors():
    """The ERROR lines of BAD_INPUTS and BAD_ZONE_INPUTS that are not
    byte-identical to GeoConvert's, and how many ERROR lines were
    compared."""
    bad, errors = [], 0
    for args in BAD_OPTIONS:
        lines = BAD_INPUTS + BAD_ZONE_INPUTS
        for line, got, want in zip(lines, drdc(args, lines),
                                   geoconvert(args, lines)):
            if want.startswith("ERROR: ") or got.startswith("ERROR: "):
                errors += 1
                if got != want:
                    bad.append((args, line, got, want))
    return bad, errors


def fuzz_lines(seed, n=3000):
    """Random lines of DMS-like tokens, MGRS-like and UTM-like strings:
    most of them bad input of some kind."""
    rng = random.Random(seed)

    def token():
        return "".join(rng.choice("0123456789" * 4 + ".d':NSEWnsew+-\"e ")
                       for _ in range(rng.randint(1, 9))).strip() or "0"

    def mgrs_like():
        zone = rng.choice(["", str(rng.randint(0, 62)),
                           "%02d" % rng.randint(1, 60)])
        letters = "".join(rng.choice("ABCDEFGHIJKLMNOPQRSTUVWXYZab")
                          for _ in range(rng.randint(0, 3)))
        return zone + letters + "".join(
            rng.choice("0123456789") for _ in range(rng.randint(0, 12)))

    def utm_like():
        words = [rng.choice(["n", "s", "%d%s" % (rng.randint(0, 61),
                                                 rng.choice("nsNSq"))]),
                 "%d" % rng.randint(-100000, 4000000),
                 "%d" % rng.randint(-10000000, 20000000)]
        return " ".join(words if rng.random() < 0.7 else words[1:] + words[:1])

    def long_digits():
        return "".join(rng.choice("0123456789")
                       for _ in range(rng.randint(10, 40)))

    def long_like():
        """Components and metres of many digits: the products a reader
        forms of them must not overflow."""
        kind = rng.randint(0, 3)
        if kind == 0:
            return "0d%s' 0" % long_digits()
        if kind == 1:
            return "0d0'%s.%s\" 0" % (long_digits(), long_digits())
        if kind == 2:
            return "%dn %se%d 4000000" % (rng.randint(1, 60), long_digits(),
                                          rng.randint(-40, 12))
        return "%s %s" % (long_digits(), long_digits())

    lines = []
    for _ in range(n):
        r = rng.random()
        lines.append(token() + " " + token() if r < 0.4 else
                     mgrs_like() if r < 0.75 else utm_like())
    # drawn after the others, so those stay the same lines
    lines += [long_like() for _ in range(n // 10)]
    return lines


FUZZ_SEED = 7
FUZZ_LINES = 3000  # then FUZZ_LINES // 10 lines of many digits


FUZZ_OPTIONS = [[], ["-d"], ["-u"], ["-m"], ["-c"], ["-u", "-z", "31"],
                ["-m", "-z", "0"], ["-m", "-t"], ["-u", "-z", "31s"], ["-w"]]


OWN_COMPONENT = re.compile(r"ERROR: (Minutes|Seconds) 1e\+15 not in range "
                           r"\[0, 60\)$")
OWN_WANT_COMPONENT = re.compile(r"ERROR: (Minutes|Seconds) (\S+) not in range")


def own_limit(got, want):
    """drdc's own limits, each an error where GeoConvert reads on: angles
    beyond 1 000 000 degrees; metres beyond 10^12 (GeoConvert then
    reports the coordinate out of range); a DMS component read up to
    10^15 and quoted as that, where GeoConvert quotes all its digits."""
    if got.startswith("ERROR: angle beyond 1000000d in "):
        return True
    if got.startswith("ERROR: Cannot decode ") and got.endswith(
            " (beyond 1e12 m)"):
        return True
    m, w = OWN_COMPONENT.match(got), OWN_WANT_COMPONENT.match(want)
    return bool(m and w and m.group(1) == w.group(1)
                and float(w.group(2)) >= 1e15)


def check_fuzz():
    """ERROR lines of fuzz_lines() under FUZZ_OPTIONS: counts of
    'identical' and 'own-limit' (drdc's angles beyond 1 000 000 degrees,
    which GeoConvert reads), and the lines neither explains."""
    counts, bad = {}, []
    lines = fuzz_lines(FUZZ_SEED, FUZZ_LINES)
    for args in FUZZ_OPTIONS:
        for i, (line, got, want) in enumerate(zip(
                lines, drdc(args, lines), geoconvert(args, lines))):
            if not (got.startswith("ERROR: ") or want.startswith("ERROR: ")):
                continue
            rule = ("identical" if got == want else
                    "own-limit" if own_limit(got, want) else None)
            if rule is None:
                bad.append((args, line, got, want))
            else:
                # the lines of many digits, made to reach the limits,
                # counted apart
                key = rule if i < FUZZ_LINES else "long " + rule
                counts[key] = counts.get(key, 0) + 1
    return counts, bad


# option set -> the inputs it is checked on
OPTIONS = [
    (["-g"], "geographic"), (["-u"], "geographic"), (["-m"], "geographic"),
    (["-c"], "geographic"), (["-d"], "geographic"), (["-:"], "geographic"),
    (["-u", "-z", "31"], "zone31"), (["-u", "-z", "31s"], "zone31"),
    (["-m", "-z", "31"], "zone31"), (["-u", "-s"], "geographic"),
    (["-u", "-z", "0"], "polar"), (["-c", "-z", "31"], "zone31"),
    (["-u", "-t"], "polar"), (["-m", "-t"], "polar"),
    (["-c", "-t"], "polar"), (["-g", "-w"], "lonlat"),
    (["-d", "-w"], "lonlat"), (["-u", "-n"], "geographic"),
    (["-u", "-S"], "zone31"), (["-m", "-T"], "polar"),
]
PRECS = range(-5, 11)


def check(args, lines):
    """Counts of each rule over PREC -5..10, and the lines no rule
    explains."""
    mode = mode_of(args)
    # references at the finest PREC: for -m, the metres it truncates
    ref_args = (["-u" if a == "-m" else a for a in args]
                + ["-p", str(FINEST["-u" if mode == "-m" else mode])])
    ref = geoconvert(ref_args, lines)
    counts = {}
    bad = []
    for p in PRECS:
        got = drdc(with_prec(args, p), lines)
        want = geoconvert(with_prec(args, p), lines)
        capped = None
        if p > CAP[mode]:
            capped = geoconvert(with_prec(args, CAP[mode]), lines)
            if mode == "-c":   # the scale is not capped
                capped = [a.split()[0] + " " + b.split()[1]
                          if len(a.split()) == 2 and len(b.split()) == 2
                          else a for a, b in zip(capped, want)]
        for i, line in enumerate(lines):
            rule = classify(with_prec(args, p), line, got[i], want[i],
                            capped[i] if capped else None, ref[i])
            if rule is None:
                bad.append((p, line, got[i], want[i]))
            else:
                counts[rule] = counts.get(rule, 0) + 1
    return counts, bad


def main():
    total = {}
    for n, (args, kind) in enumerate(OPTIONS):
        lines = inputs(24 + n, kind)
        counts, bad = check(args, lines)
        runs = sum(counts.values()) + len(bad)
        print("%-14s %4d lines x 16 PREC = %5d: %s; unexplained %d"
              % (" ".join(args), len(lines), runs,
                 ", ".join("%s %d" % kv for kv in sorted(counts.items())),
                 len(bad)))
        for b in bad[:5]:
            print("   ", b)
        for k, v in counts.items():
            total[k] = total.get(k, 0) + v
    print("total", total)
    bad, errors = check_errors()
    print("error lines of bad inputs: %d, not byte-identical %d"
          % (errors, len(bad)))
    for b in bad[:10]:
        print("   ", b)
    counts, bad = check_fuzz()
    print("error lines of fuzz input: %s; unexplained %d"
          % (", ".join("%s %d" % kv for kv in sorted(counts.items())),
             len(bad)))
    for b in bad[:10]:
        print("   ", b)


if __name__ == "__main__":
    main()
