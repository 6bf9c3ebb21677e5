# SPDX-License-Identifier: BSD-2-Clause
"""Generator of core/geo/geo_consts.h and core/geo/geo_consts.c, the
WGS-84, UTM and UPS constants of core/geo as exact integers (written by
tools/generate.py, which ./waf check runs with --check).

mpmath at 60 digits, rounded to nearest (ties away from zero). Krueger's series coefficients alpha_j (forward) and
beta_j (inverse) to 6th order in the third flattening n (the published
series, Karney 2011, eqs. 35 and 36); the Fourier coefficients of the
conformal latitude chi(phi) - phi and phi(chi) - chi are computed
numerically (a 256-point discrete sine transform of the exact functions,
exact to working precision), 8 terms each. Q5.58 unless named otherwise."""
from fractions import Fraction as F

import mpmath

mpmath.mp.dps = 60
ONE = mpmath.mpf(2) ** 58

A = mpmath.mpf(6378137)
FL = 1 / mpmath.mpf("298.257223563")
N = FL / (2 - FL)
E2 = FL * (2 - FL)
E = mpmath.sqrt(E2)
K0 = mpmath.mpf("0.9996")

ALPHA = [
    [F(1, 2), F(-2, 3), F(5, 16), F(41, 180), F(-127, 288), F(7891, 37800)],
    [F(13, 48), F(-3, 5), F(557, 1440), F(281, 630), F(-1983433, 1935360)],
    [F(61, 240), F(-103, 140), F(15061, 26880), F(167603, 181440)],
    [F(49561, 161280), F(-179, 168), F(6601661, 7257600)],
    [F(34729, 80640), F(-3418889, 1995840)],
    [F(212378941, 319334400)],
]
BETA = [
    [F(1, 2), F(-2, 3), F(37, 96), F(-1, 360), F(-81, 512), F(96199, 604800)],
    [F(1, 48), F(1, 15), F(-437, 1440), F(46, 105), F(-1118711, 3870720)],
    [F(17, 480), F(-37, 840), F(-209, 4480), F(5569, 90720)],
    [F(4397, 161280), F(-11, 504), F(-830251, 7257600)],
    [F(4583, 161280), F(-108847, 3991680)],
    [F(20648693, 638668800)],
]


def rnd(x):
    return int(mpmath.sign(x) * mpmath.floor(abs(x) + mpmath.mpf(1) / 2))


def series(rows):
    out = []
    for j, row in enumerate(rows):
        v = mpmath.mpf(0)
        for k, c in enumerate(row):
            v += mpmath.mpf(c.numerator) / c.denominator * N ** (j + 1 + k)
        out.append(v)
    return out


def chi_of_phi(phi):
    return mpmath.asin(mpmath.tanh(mpmath.atanh(mpmath.sin(phi))
                                   - E * mpmath.atanh(E * mpmath.sin(phi))))


def phi_of_chi(chi):
    # Newton on chi_of_phi
    phi = chi
    for _ in range(60):
        d = chi_of_phi(phi) - chi
        if abs(d) < mpmath.mpf(10) ** -55:
            break
        phi -= d * (1 - E2 * mpmath.sin(phi) ** 2) * mpmath.cos(phi) \
            / ((1 - E2) * mpmath.cos(chi_of_phi(phi)))
    return phi


def fourier(f, terms, m=256):
    # f(x) - x is odd and pi-periodic: coefficients of sin(2 j x)
    # g(pi - x) = -g(x): sum over the midpoints in (0, pi/2) only
    xs = [mpmath.pi * (k + mpmath.mpf(1) / 2) / m for k in range(m // 2)]
    vals = [f(x) - x for x in xs]
    return [4 * sum(v * mpmath.sin(2 * j * x) for v, x in zip(vals, xs)) / m
            for j in range(1, terms + 1)]


def consts():
    """(name, value, comment) of every scalar constant"""
    rect = A / (1 + N) * (1 + N ** 2 / 4 + N ** 4 / 64 + N ** 6 / 256)
    k0_ups = mpmath.mpf("0.994")
    c_ups = mpmath.sqrt(1 - E2) * ((1 + E) / (1 - E)) ** (E / 2)
    eta_max = mpmath.mpf("0.34")
    nas_rad = mpmath.pi * ONE / 648000000000000
    assert mpmath.floor(nas_rad) == 1397
    return [
        ("GEO_E2", rnd(E2 * ONE),
         "WGS-84 first eccentricity squared e^2 = f (2 - f),\n"
         " *  f = 1/298.257223563."),
        ("GEO_E", rnd(E * ONE), "WGS-84 first eccentricity e."),
        ("GEO_B_OVER_A", rnd((1 - FL) * ONE),
         "b / a = 1 - f (polar over equatorial radius)."),
        ("GEO_E2A_Q36", rnd(E2 * A * mpmath.mpf(2) ** 36),
         "e^2 a in metres, Q27.36 (Bowring's step, ecef.c)."),
        ("GEO_EP2B_Q36", rnd(E2 / (1 - E2) * A * (1 - FL) * mpmath.mpf(2) ** 36),
         "e'^2 b = e^2 a / sqrt(1 - e^2) in metres, Q27.36 (Bowring's\n"
         " *  step, ecef.c)."),
        ("GEO_K0A_Q40", rnd(K0 * rect * mpmath.mpf(2) ** 40),
         "k0 A in metres, Q23.40: k0 = 0.9996 times the rectifying\n"
         " *  radius A = a / (1 + n) (1 + n^2/4 + n^4/64 + n^6/256),\n"
         " *  a = 6 378 137 m."),
        ("GEO_K0A_OVER_A", rnd(K0 * rect / A * ONE), "k0 A / a."),
        ("GEO_POLE_RATIO", rnd(((1 + E) / (1 - E)) ** (E / 2) * ONE),
         "lim cos(chi) / cos(phi) at the poles: ((1 + e) / (1 - e))^(e/2)."),
        ("GEO_TM_MAX_TANH_ETA", rnd(mpmath.tanh(eta_max) * ONE),
         "Largest cos(chi) |sin(lambda)| the series accept: tanh(0.34),\n"
         " *  so that cosh(12 eta') stays below 32 (the Q5.58 range)."),
        ("GEO_TM_MAX_ETA", rnd(eta_max * ONE),
         "Largest |eta| of the inverse series (same reason): 0.34."),
        ("GEO_UPS_K_Q39", rnd(2 * k0_ups * A / c_ups * mpmath.mpf(2) ** 39),
         "UPS: 2 k0 a / c in metres, Q24.39 (k0 = 0.994,\n"
         " *  c = sqrt(1 - e^2) ((1 + e) / (1 - e))^(e/2))."),
        ("GEO_UPS_2K0_OVER_C", rnd(2 * k0_ups / c_ups * ONE), "UPS: 2 k0 / c."),
        ("GEO_NAS_RAD_FRACTION", rnd((nas_rad - 1397) * ONE),
         "Radians per nano-arcsecond in Q5.58 is 1397 plus this\n"
         " *  fraction (pi 2^58 / 648e12 = 1397.38029...)."),
    ]


def tables():
    return [("drdc__geo_chi_from_phi", "GEO_CHI_TERMS", fourier(chi_of_phi, 8)),
            ("drdc__geo_phi_from_chi", "GEO_CHI_TERMS", fourier(phi_of_chi, 8)),
            ("drdc__geo_alpha", "GEO_KRUEGER_TERMS", series(ALPHA)),
            ("drdc__geo_beta", "GEO_KRUEGER_TERMS", series(BETA))]


HEAD = """/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief %s (generated: do not edit;
 *        run tools/generate.py). mpmath at 60 digits, rounded
 *        to nearest; Q5.58 unless named otherwise.
 */
"""


def header_text():
    out = [HEAD % "WGS-84, UTM and UPS constants of core/geo",
           "#ifndef DRDC_GEO_CONSTS_H", "#define DRDC_GEO_CONSTS_H", "",
           "#include <stdint.h>", ""]
    for name, value, comment in consts():
        out.append("/** %s */" % comment)
        out.append("#define %s INT64_C(%d)" % (name, value))
    out += ["", "#endif /* DRDC_GEO_CONSTS_H */", ""]
    return "\n".join(out)


def source_text():
    out = [HEAD % "Series coefficients of core/geo: conformal latitude\n"
           " *        and Krueger's alpha and beta",
           '#include "geo_projection.h"', ""]
    for name, size, values in tables():
        items = ["INT64_C(%d)" % rnd(v * ONE) for v in values]
        out.append("const int64_t %s[%s] = {" % (name, size))
        line = " "
        for item in items:
            if len(line) + len(item) + 2 > 78:
                out.append(line.rstrip())
                line = " "
            line += " " + item + ","
        out.append(line.rstrip().rstrip(","))
        out.append("};")
    out.append("")
    return "\n".join(out)


def generate():
    """{path from the top of the tree: text} of the generated files"""
    return {"core/geo/geo_consts.h": header_text(),
            "core/geo/geo_consts.c": source_text()}
