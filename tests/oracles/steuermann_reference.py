#!/usr/bin/env python3
"""Reference values for tests/oracles/test_extreme_inputs.cpp: Steuermann's Eqs. 31-32
exactly as printed, in 250-digit arithmetic (mpmath), at light, study and heavy loads.

Also checks the regrouped bracket that oracles/steuermann.cpp evaluates against the printed
one. Not part of the build; run `python3 steuermann_reference.py` to regenerate the numbers.
"""
from mpmath import mp, mpf, sin, cos, tan, atanh, log, pi, asin

mp.dps = 250


def solve_eq32(b, r_e, P, E, nu):
    """phi0 of Eq. 32 by bisection (geometric while the bracket spans decades)."""
    b, r_e, P, E, nu = map(mpf, (b, r_e, P, E, nu))
    lam = 2 * r_e * (1 - nu**2) * P / (b**2 * E)
    rhs = lambda p0: (pi - 2 * p0) / (2 * sin(p0) ** 2) - cos(p0) / sin(p0)
    lo, hi = mpf(10) ** -200, pi / 2 - mpf(10) ** -200
    for _ in range(9000):
        mid = (lo * hi) ** 0.5 if hi / lo > 4 else (lo + hi) / 2
        lo, hi = (mid, hi) if rhs(mid) > lam else (lo, mid)
        if hi - lo < mpf(10) ** -240 * hi:
            break
    phi0 = (lo + hi) / 2
    return phi0, b / sin(phi0)


def bracket_printed(phi0, phi):
    return (pi - 2 * phi0) * cos(phi) + log(
        abs(sin(phi + phi0) / sin(phi - phi0)) ** sin(phi)
        * abs(tan((phi + phi0) / 2) * tan((phi - phi0) / 2)) ** sin(phi0))


def bracket_regrouped(u, w):
    d = -sin(w) * sin(u) / (1 + cos(u) * cos(w))
    t2 = min(sin(u) / sin(w), sin(w) / sin(u))
    return 2 * u * sin(w) + 2 * cos(w) * atanh(d) + 2 * (cos(w) - cos(u)) * atanh(t2)


def pressure(P, phi0, a, phi):
    return P / a * 2 / pi / (pi - 2 * phi0 - sin(2 * phi0)) * bracket_printed(phi0, phi)


def peak(P, phi0, a):
    h = lambda phi: cos(phi) * log(sin(phi + phi0) / sin(phi - phi0)) - (pi - 2 * phi0) * sin(phi)
    lo, hi = phi0 + (pi / 2 - phi0) * mpf(10) ** -60, pi / 2
    for _ in range(9000):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if h(mid) > 0 else (lo, mid)
        if hi - lo < mpf(10) ** -240:
            break
    phi = (lo + hi) / 2
    return pressure(P, phi0, a, phi), a * sin(phi)


if __name__ == "__main__":
    for u in (mpf("0.3"), mpf("1e-3"), mpf("1.2")):
        for w in (u * mpf("0.3"), u * mpf("1.1"), pi / 2):
            rel = bracket_regrouped(u, w) / bracket_printed(pi / 2 - u, pi / 2 - w) - 1
            assert abs(rel) < mpf(10) ** -200, (u, w, rel)
    cases = [(1, 1, 1e-24, 1, 0.25), (1, 1, 1e-12, 1, 0.25), (1, 1, 4e-3, 1, 0.25),
             (1, 1e40, 1, 1, 0.25), (1, 1e32, 1, 1, 0.25), (2.5, 1e-60, 1e-130, 1, 0.25)]
    for case in cases:
        b = mpf(case[0])
        phi0, a = solve_eq32(*case)
        p_peak, x_peak = peak(mpf(case[2]), phi0, a)
        p_mid = pressure(mpf(case[2]), phi0, a, asin(b / 2 / a))
        print(case, ", ".join(f"{k} {mp.nstr(v, 17)}" for k, v in
                              (("a", a), ("phi0", phi0), ("u", pi / 2 - phi0), ("peak", p_peak),
                               ("x_peak", x_peak), ("p(b/2)", p_mid))))
