#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Prints the WGS-84 constants of core/geo/geo_consts.c as exact integers.

mpmath at 60 digits. Krueger's series coefficients alpha_j (forward) and
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


def main():
    rect = A / (1 + N) * (1 + N ** 2 / 4 + N ** 4 / 64 + N ** 6 / 256)
    print("e2", rnd(E2 * ONE))
    print("e", rnd(E * ONE))
    print("k0a_q40", rnd(K0 * rect * mpmath.mpf(2) ** 40))
    print("k0_rect_over_a", rnd(K0 * rect / A * ONE))
    print("pi", rnd(mpmath.pi * ONE))
    for name, v in (("alpha", series(ALPHA)), ("beta", series(BETA)),
                    ("chi", fourier(chi_of_phi, 8)),
                    ("phi", fourier(phi_of_chi, 8))):
        print(name, " ".join(str(rnd(x * ONE)) for x in v))


if __name__ == "__main__":
    main()
