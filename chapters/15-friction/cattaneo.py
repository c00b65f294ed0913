#!/usr/bin/env python3
# cattaneo.py -- a run of cattaneo2d.scene against Cattaneo-Mindlin
#
#   python3 chapters/15-friction/cattaneo.py RESULT_DIR Q_OVER_MU_P [P]
#
# Reads RESULT_DIR/contact.csv and summary.txt of a run of cattaneo2d.scene
# (P = 7 N/mm or the P given, R = 10 mm, E = 200 GPa, nu = 0.3, mu = 0.3)
# and prints one
# line: the macro-elements in contact, the half-width c of the stick zone
# over Hertz's a (measured, Cattaneo's sqrt(1 - Q/(mu P)), the error in
# %), the relative L2 error of the tangential traction against Cattaneo's
# q(x) (the mean of q over each macro-element against lambda_t), and the
# largest number of iterations of a load step.
#
# The measured c: in the stick zone mu p - |q| = mu p0 (c/a) sqrt(1 - x^2 /
# c^2), so (mu |lambda_n| - |lambda_t|)^2 is A - B x^2 over the sticking
# macro-elements; a least-squares fit gives c = sqrt(A / B).
import csv
import math
import sys

P = float(sys.argv[3]) if len(sys.argv) > 3 else 7.0
R, E, NU, MU = 10.0, 200000.0, 0.3, 0.3
ESTAR = E / (2 * (1 - NU * NU))
A = math.sqrt(4 * P * R / (math.pi * ESTAR))       # Hertz's half-width
P0 = 2 * P / (math.pi * A)


def q_exact(x, c):
    """Cattaneo's tangential traction (>= 0) at x for the stick zone c."""
    if abs(x) >= A:
        return 0.0
    q = MU * P0 * math.sqrt(1 - x * x / (A * A))
    if abs(x) < c:
        q -= MU * P0 * (c / A) * math.sqrt(1 - x * x / (c * c))
    return q


def q_mean(x0, x1, c, n=64):
    """The mean of q over [x0, x1] (midpoint rule on n pieces)."""
    h = (x1 - x0) / n
    return sum(q_exact(x0 + (j + 0.5) * h, c) for j in range(n)) / n


def main():
    out, ratio = sys.argv[1], float(sys.argv[2])
    rows = [r for r in csv.DictReader(open(out + "/contact.csv"))
            if r["multiplier"] and r["status"] in ("stick", "slip")]
    summ = dict(l.rstrip("\n").split(" = ", 1) for l in open(out + "/summary.txt")
                if " = " in l)
    c_exact = A * math.sqrt(1 - ratio)
    sx = sy = sxx = sxy = sxxxx = 0.0               # f^2 = a0 + a1 x^2
    n = 0
    for r in rows:
        if r["status"] != "stick":
            continue
        x = float(r["x"])
        f = MU * abs(float(r["lambda"])) - abs(float(r["lambda_t"]))
        X, Y = x * x, f * f
        sx += X; sy += Y; sxx += X * X; sxy += X * Y; n += 1
    det = n * sxx - sx * sx
    c = float("nan")
    if n >= 2 and det != 0:
        a1 = (n * sxy - sx * sy) / det
        a0 = (sy - a1 * sx) / n
        c = math.sqrt(-a0 / a1) if a1 < 0 < a0 else float("nan")
    num = den = 0.0
    for r in rows:
        x, w = float(r["x"]), float(r["covered"])
        qm = q_mean(x - w / 2, x + w / 2, c_exact)
        num += w * (abs(float(r["lambda_t"])) - qm) ** 2
        den += w * qm * qm
    print("%6d %10.4f %10.4f %9.3f %11.3e %6s" % (
        len(rows), c / A, c_exact / A, 100 * (c - c_exact) / c_exact,
        math.sqrt(num / den), summ.get("max_iterations_per_step", "-")))


main()
