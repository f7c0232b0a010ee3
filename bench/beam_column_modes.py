#!/usr/bin/env python3
"""The reference of bench/mode_shape_chart.sh: the lowest eigenpairs of a
clamped-free Euler-Bernoulli column (EI = 1, L = 1) under an axial dead
load P at its free end,

    w'''' + P w'' = mu w,   w(0) = w'(0) = 0,   w''(1) = 0,   w'''(1) + P w'(1) = 0

(the last: no transverse force at the tip, the load keeping its direction).
With a^2, b^2 = (sqrt(P^2 + 4 mu) +- P) / 2, w = cos ax - cosh bx +
s (sin ax - a/b sinh bx) meets the clamp; mu is an eigenvalue where the two
tip conditions have a nonzero s. At P = 0 these are the cantilever's
mu = (beta L)^4, beta L = 1.8751, 4.6941, 7.8548, 10.9955.

Usage: bench/beam_column_modes.py P COUNT
Prints per mode a line "# mode k mu" and rows "x w" (w scaled to +1 at the
tip, where every mode of the cantilever has its largest deflection), modes
separated by two blank lines (gnuplot's index).
"""
import math
import sys


def tip_conditions(mu, load):
    """Both tip conditions as rows (cos/cosh part, sin/sinh part)."""
    root = math.sqrt(load * load + 4 * mu)
    a, b = math.sqrt((root + load) / 2), math.sqrt((root - load) / 2)
    ca, sa, ch, sh = math.cos(a), math.sin(a), math.cosh(b), math.sinh(b)
    moment = (-a * a * ca - b * b * ch, -a * a * sa - a * b * sh)
    shear = (a**3 * sa - b**3 * sh - load * (a * sa + b * sh),
             -a**3 * ca - a * b * b * ch + load * a * (ca - ch))
    return a, b, moment, shear


def determinant(mu, load):
    # Divided by cosh b, which would otherwise swamp the sign changes.
    a, b, m, s = tip_conditions(mu, load)
    return (m[0] * s[1] - m[1] * s[0]) / math.cosh(b)


def eigenvalues(load, count):
    """The lowest count roots, bracketed on a geometric grid, bisected."""
    found, mu = [], 1e-9
    f = determinant(mu, load)
    while len(found) < count:
        upper = mu * 1.002 + 1e-4
        g = determinant(upper, load)
        if f * g < 0:
            low, high = mu, upper
            for _ in range(100):
                middle = (low + high) / 2
                if determinant(low, load) * determinant(middle, load) <= 0:
                    high = middle
                else:
                    low = middle
            found.append((low + high) / 2)
        mu, f = upper, g
    return found


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    load, count = float(sys.argv[1]), int(sys.argv[2])
    for k, mu in enumerate(eigenvalues(load, count), 1):
        a, b, moment, _ = tip_conditions(mu, load)
        s = -moment[0] / moment[1]

        def w(x):
            return (math.cos(a * x) - math.cosh(b * x) +
                    s * (math.sin(a * x) - a / b * math.sinh(b * x)))
        tip = w(1)
        print("# mode %d %.10g" % (k, mu))
        for i in range(201):
            print("%.5f %.7g" % (i / 200, w(i / 200) / tip))
        print("\n")


if __name__ == "__main__":
    main()
