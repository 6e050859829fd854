#!/usr/bin/python3
"""Independent 40-digit reference for the motion laws scca, poly7 and table (math.md §8).

Prints C++ constants for tests/core/motion_law_reference_test.cpp (17 significant digits).
Rerun and paste the output over the constants between the "BEGIN/END motion_law_reference.py"
markers of the test:

    /usr/bin/python3 tests/reference/motion_law_reference.py

Independence from the C++ engine (src/core/design):
  * scca: R. L. Norton's definition of the acceleration alone (Cam Design and Manufacturing
    Handbook, 2nd ed., Industrial Press 2009, ch. 3, the SCCA family): unit amplitude, a sine
    ramp sin(pi x / b) on [0, b/2], 1 on [b/2, (1-d)/2], cos(pi (x - (1-d)/2) / d) on
    [(1-d)/2, (1+d)/2], mirrored negative after (a(1-x) = -a(x)). Velocity and lift come from
    mpmath.quad (v = int_0^x a, y = int_0^x (x - t) a(t) dt), the amplitude Ca from y(1) = 1, the
    jerk from mpmath.diff of a. No piecewise closed form is used; the closed form of Ca is
    only checked against the quadrature (and the script fails if they differ).
  * poly7: the 8x8 linear system of the eight boundary values solved with mpmath.lu_solve.
  * table: the quintic spline's conditions (interpolation, v = a = 0 at the ends, C1..C4 at a
    knot without v, v on both sides and C2, C3 at a knot with v) as one 6n x 6n linear system
    in mpmath.
"""

import sys

import mpmath
from mpmath import mp, mpf

mp.dps = 40
PI = mp.pi


def g(x):
    """17 significant digits, C++ literal."""
    if abs(x) < mpf("1e-30"):  # the noise of an exact zero
        return "0.0"
    text = mpmath.nstr(mpf(x), 17, min_fixed=-4, max_fixed=5).replace("+", "")
    return text if any(c in text for c in ".e") else text + ".0"


# ---------------------------------------------------------------------------------------- scca
def scca_unit_a(b, d):
    b, d = mpf(b), mpf(d)

    def a(x):
        x = mpf(x)
        if x > mpf(1) / 2:
            return -a(1 - x)
        if x < b / 2:
            return mpmath.sin(PI * x / b)
        if x < (1 - d) / 2:
            return mpf(1)
        return mpmath.cos(PI * (x - (1 - d) / 2) / d)

    breaks = sorted({mpf(0), b / 2, (1 - d) / 2, mpf(1) / 2, (1 + d) / 2, 1 - b / 2, mpf(1)})
    return a, breaks


def scca(b, d, xs):
    a, breaks = scca_unit_a(b, d)

    def pts(x):
        return [p for p in breaks if p < x] + [x]

    def v_unit(x):
        return mpmath.quad(a, pts(x))

    def y_unit(x):
        return mpmath.quad(lambda t: (x - t) * a(t), pts(x))

    ca = 1 / y_unit(mpf(1))
    b_, d_ = mpf(b), mpf(d)
    closed = 4 * PI**2 / ((PI**2 - 8) * (b_**2 - d_**2) - 2 * PI * (PI - 2) * b_ + PI**2)
    if abs(ca - closed) > mpf("1e-30") * ca:
        sys.exit(f"scca b={b} d={d}: quadrature Ca {ca} differs from the closed form {closed}")
    cv = ca * v_unit(mpf(1) / 2)  # a >= 0 on [0, 1/2]: v is largest at 1/2
    rows = []
    for x in xs:
        x = mpf(x)
        j = ca * mpmath.diff(a, x)
        rows.append((x, ca * y_unit(x), ca * v_unit(x), ca * a(x), j))
    return ca, cv, rows


# --------------------------------------------------------------------------------------- poly7
def poly7(y0, y1, start, end):
    """Coefficients c0..c7 of p(u) on [0, 1] with p, p', p'', p''' given at both ends."""
    rows, rhs = [], []
    for u, vals in ((mpf(0), [y0] + list(start)), (mpf(1), [y1] + list(end))):
        for k in range(4):  # k-th derivative
            row = []
            for n in range(8):
                row.append(mpmath.ff(n, k) * u ** (n - k) if n >= k else mpf(0))
            rows.append(row)
            rhs.append(mpf(vals[k]))
    return mpmath.lu_solve(mpmath.matrix(rows), mpmath.matrix(rhs))


def poly_eval(c, u, k):
    return sum(mpmath.ff(n, k) * c[n] * u ** (n - k) for n in range(k, len(c)))


# --------------------------------------------------------------------------------------- table
def quintic_spline(points):
    """points: (x, y, v or None). Returns pieces [(x0, x1, [c0..c5])] in t = x - x0."""
    xs = [mpf(p[0]) for p in points]
    ys = [mpf(p[1]) for p in points]
    n = len(points) - 1
    size = 6 * n
    A = mpmath.zeros(size, size)
    r = mpmath.zeros(size, 1)
    row = [0]

    def deriv_row(piece, t, k):
        coeffs = [mpf(0)] * size
        for m in range(k, 6):
            coeffs[6 * piece + m] = mpmath.ff(m, k) * t ** (m - k)
        return coeffs

    def add(coeffs, value):
        for c in range(size):
            A[row[0], c] = coeffs[c]
        r[row[0]] = value
        row[0] += 1

    h = [xs[i + 1] - xs[i] for i in range(n)]
    for i in range(n):
        add(deriv_row(i, mpf(0), 0), ys[i])
        add(deriv_row(i, h[i], 0), ys[i + 1])
    v0 = mpf(points[0][2]) if points[0][2] is not None else mpf(0)
    v1 = mpf(points[-1][2]) if points[-1][2] is not None else mpf(0)
    add(deriv_row(0, mpf(0), 1), v0)
    add(deriv_row(0, mpf(0), 2), mpf(0))
    add(deriv_row(n - 1, h[-1], 1), v1)
    add(deriv_row(n - 1, h[-1], 2), mpf(0))
    for k in range(1, n):
        given = points[k][2]
        if given is None:
            orders = (1, 2, 3, 4)
        else:
            add(deriv_row(k - 1, h[k - 1], 1), mpf(given))
            add(deriv_row(k, mpf(0), 1), mpf(given))
            orders = (2, 3)
        for m in orders:
            left = deriv_row(k - 1, h[k - 1], m)
            right = deriv_row(k, mpf(0), m)
            add([a - b for a, b in zip(left, right)], mpf(0))
    assert row[0] == size
    c = mpmath.lu_solve(A, r)
    return [(xs[i], xs[i + 1], [c[6 * i + m] for m in range(6)]) for i in range(n)]


def spline_at(pieces, x):
    x = mpf(x)
    for x0, x1, c in pieces:
        if x <= x1:
            t = x - x0
            return [poly_eval(c, t, k) for k in range(4)]
    raise ValueError(x)


# ------------------------------------------------------------------------------------ printing
def print_rows(name, rows, comment):
    print(f"// {comment}")
    print(f"constexpr RefRow {name}[] = {{")
    for row in rows:
        print("    {" + ", ".join(g(v) for v in row) + "},")
    print("};")


SCCA_CASES = [("kScca30x50", "0.3", "0.5"), ("kScca10x20", "0.1", "0.2"),
              ("kScca60x15", "0.6", "0.15"), ("kScca0x60", "0", "0.6")]
SCCA_XS = ["0.02", "0.04", "0.11", "0.2", "0.26", "0.37", "0.45", "0.5", "0.58", "0.66", "0.73",
           "0.81", "0.89", "0.97", "0.995"]

# Poly7 design: seg 0 from 0 deg to 150 deg, lift 0 -> 12; seg 1 from 150 deg to 360 deg, 12 -> 0.
# Boundary values per degree (v mm/deg, a mm/deg^2, j mm/deg^3), continuous round the turn.
P7_A = ("0.05", "0.002", "-0.0001")
P7_B = ("-0.03", "-0.001", "0.00005")
P7_SEGMENTS = [("kPoly7Rise", 0, 150, "0", "12", P7_A, P7_B),
               ("kPoly7Return", 150, 360, "12", "0", P7_B, P7_A)]
P7_US = ["0.03", "0.1", "0.21", "0.33", "0.4", "0.5", "0.57", "0.68", "0.79", "0.9", "0.97"]

TABLE_6 = [("0", "0"), ("0.15", "0.04"), ("0.4", "0.32"), ("0.55", "0.6"), ("0.8", "0.95"),
           ("1", "1")]
TABLE_6_V = {1: "0.5", 3: "1.9"}  # the same points with velocities at x = 0.15 and 0.55
# A table that starts and ends at speed (y' = 3, a = 0): the second inclined sine of the test's
# design of lines and inclined sines replaced by it.
TABLE_END_V = [("0", "0", "3"), ("0.3", "0.5", None), ("0.7", "0.8", None), ("1", "1", "3")]
TABLE_XS = [str(mpf(k) / 40 + mpf("0.0123")) for k in range(40)]  # 40 points in (0, 1)


def self_checks():
    """The reference against what is known in closed form; exits on a mismatch."""
    tol = mpf("1e-30")
    # scca at the classic laws: Ca by quadrature.
    for b, d, ca in (("0.25", "0.25", 8 * PI / (PI + 2)), ("0.25", "0.75", 4 * PI**2 / (4 + PI)),
                     ("0.5", "0.5", 2 * PI), ("0", "1", PI**2 / 2), ("0", "0", mpf(4))):
        got, _, rows = scca(b, d, ["0.3"])
        if abs(got - ca) > tol:
            sys.exit(f"scca b={b} d={d}: Ca {got}, classic {ca}")
    _, _, rows = scca("0.5", "0.5", ["0.3"])
    x = mpf("0.3")
    if abs(rows[0][1] - (x - mpmath.sin(2 * PI * x) / (2 * PI))) > tol:
        sys.exit("scca b=d=1/2 is not the cycloid")
    # poly7: its boundary values, and at rest poly 4-5-6-7.
    c = poly7(mpf(1), mpf(3), [mpf(2), mpf(-5), mpf(7)], [mpf(-1), mpf(4), mpf(9)])
    want = [1, 2, -5, 7, 3, -1, 4, 9]
    got = [poly_eval(c, mpf(u), k) for u in (0, 1) for k in range(4)]
    if max(abs(g_ - w) for g_, w in zip(got, want)) > tol:
        sys.exit("poly7 misses its boundary values")
    c = poly7(mpf(0), mpf(1), [0, 0, 0], [0, 0, 0])
    if max(abs(c[n] - w) for n, w in enumerate([0, 0, 0, 0, 35, -84, 70, -20])) > tol:
        sys.exit("poly7 at rest is not poly 4-5-6-7")
    # table: each spline meets its own conditions (interpolation, C4 or v and C3 at knots).
    tables = [[(x, y, vmap.get(i)) for i, (x, y) in enumerate(TABLE_6)]
              for vmap in ({}, TABLE_6_V)]
    for pts in tables + [TABLE_END_V]:
        pieces = quintic_spline(pts)
        first, last = pieces[0], pieces[-1]
        ends = [poly_eval(first[2], mpf(0), m) for m in range(3)] + [
            poly_eval(last[2], last[1] - last[0], m) for m in range(3)]
        want = [0, pts[0][2] or 0, 0, 1, pts[-1][2] or 0, 0]
        if max(abs(e - mpf(w)) for e, w in zip(ends, want)) > tol:
            sys.exit("spline misses its end conditions")
        for k in range(1, len(pieces)):
            x0, x1, left = pieces[k - 1]
            l = [poly_eval(left, x1 - x0, m) for m in range(5)]
            r = [poly_eval(pieces[k][2], mpf(0), m) for m in range(5)]
            orders = range(5) if pts[k][2] is None else range(4)
            if max(abs(l[m] - r[m]) for m in orders) > mpf("1e-25"):
                sys.exit(f"spline not smooth at knot {k}")
            if abs(l[0] - mpf(pts[k][1])) > tol or (
                    pts[k][2] is not None and abs(l[1] - mpf(pts[k][2])) > tol):
                sys.exit(f"spline misses point {k}")


def main():
    self_checks()
    print("// BEGIN motion_law_reference.py")
    for name, b, d in SCCA_CASES:
        ca, cv, rows = scca(b, d, SCCA_XS)
        print(f"// scca b = {b}, d = {d}: Ca {g(ca)} (quadrature; equals the closed form), "
              f"Cv {g(cv)}")
        print(f"constexpr double {name}Ca = {g(ca)}, {name}Cv = {g(cv)};")
        print_rows(name, rows, "x, y, y', y'', y''' (Norton's definition, mpmath.quad)")

    for name, deg0, deg1, y0, y1, start, end in P7_SEGMENTS:
        hdeg = mpf(deg1 - deg0)
        hrad = hdeg * PI / 180
        s = [mpf(v) * hdeg ** (k + 1) for k, v in enumerate(start)]
        e = [mpf(v) * hdeg ** (k + 1) for k, v in enumerate(end)]
        c = poly7(mpf(y0), mpf(y1), s, e)
        rows = []
        for u in P7_US:
            u = mpf(u)
            rows.append([u] + [poly_eval(c, u, k) / hrad**k for k in range(4)])
        print_rows(name, rows, f"u, s, s', s'', s''' per rad: poly7 {deg0}..{deg1} deg, "
                   f"lift {y0} -> {y1} (8x8 system, mpmath)")
        # sum_n n!/(n-k)! |c_n| / h^k: what rounding in evaluating s^(k) in double scales with
        # (Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., eq. 5.3).
        terms = [sum(mpmath.ff(n, k) * abs(c[n]) for n in range(k, 8)) / hrad**k
                 for k in range(4)]
        print(f"constexpr double {name}Terms[] = {{" + ", ".join(g(t) for t in terms) + "};")

    for name, vmap in (("kTable6", {}), ("kTable6V", TABLE_6_V)):
        pts = [(x, y, vmap.get(i)) for i, (x, y) in enumerate(TABLE_6)]
        pieces = quintic_spline(pts)
        rows = [[mpf(x)] + spline_at(pieces, x) for x in TABLE_XS]
        print_rows(name, rows, "x, y, y', y'', y''' of the quintic spline (mpmath)")
    pieces = quintic_spline(TABLE_END_V)
    rows = [[mpf(x)] + spline_at(pieces, x) for x in TABLE_XS]
    print_rows("kTableEndV", rows, "x, y, y', y'', y''' of the spline with y'(0) = y'(1) = 3")

    # poly4567 at 21 points: the spline's largest deviation from the polynomial, dense.
    def p4567(x, k):
        c = [0, 0, 0, 0, 35, -84, 70, -20]
        return poly_eval([mpf(v) for v in c], mpf(x), k)

    pts = [(mpf(k) / 20, p4567(mpf(k) / 20, 0), None) for k in range(21)]
    pieces = quintic_spline(pts)
    worst = [mpf(0)] * 4
    for i in range(4001):
        x = mpf(i) / 4000
        s = spline_at(pieces, x)
        for k in range(4):
            worst[k] = max(worst[k], abs(s[k] - p4567(x, k)))
    print("// poly4567 sampled at x = k/20, k = 0..20, through the quintic spline: its largest")
    print("// deviation from the polynomial over 4001 points, for y, y', y'', y'''.")
    print("constexpr double kPoly4567SplineDeviation[] = {" + ", ".join(g(w) for w in worst) +
          "};")
    print("// END motion_law_reference.py")


if __name__ == "__main__":
    main()
