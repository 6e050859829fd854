#!/usr/bin/python3
"""Independent 50-digit reference for Camwright's polar kinematics.

Reads a Camwright project file (spec/project-format.md) and prints, for each
requested time t, the state of a knife-edge follower on a fixed radial ray
(spec/math.md §1-2) as JSON.

Independence from the C++ engine is the point of this script:
  * r(phi) is computed directly from the geometry (intersect the ray with the
    circle, the line, or the cubic Bezier / Hermite curve), with mpmath at 50
    significant digits;
  * r', r'', r''' are NOT taken from the closed forms of math.md; they come
    from mpmath.diff, a high-precision numerical derivative of our own r(phi)
    of the segment that owns phi.

Usage:
    /usr/bin/python3 polar_reference.py PROJECT.cam.json --t 0.05 --t 0.15

Segment types: "arc", "line", "bezier" and "hermite" (a Hermite segment is
the Bezier with P1 = p0 + t0/3, P2 = p3 - t1/3, spec/math.md §4).
"""

import argparse
import json
import sys

import mpmath
from mpmath import mp, mpf

mp.dps = 50

# Values smaller than this (in mm, mm/s, ...) are the numerical noise of an
# exact zero (e.g. v_r on a symmetry axis) and are written as 0.
ZERO_NOISE = mpf("1e-30")


class ReferenceError(Exception):
    pass


# ---------------------------------------------------------------------------
# Reading the project file
# ---------------------------------------------------------------------------

def _read_json(path):
    """Load JSON with every number as an exact mpf of its decimal literal."""
    with open(path, encoding="utf-8") as f:
        return json.load(f, parse_float=mpf, parse_int=mpf)


def _point(value, scale, where):
    if not isinstance(value, list) or len(value) != 2:
        raise ReferenceError(f"{where}: expected [x, y]")
    return (value[0] * scale, value[1] * scale)


def _cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def arc_radius_function(center, radius, branch):
    """r(phi) of the ray from the origin meeting the circle |p - c| = R.

    Points r*u on the ray with |r*u - c|^2 = R^2 solve
    r^2 - 2 r (c.u) + |c|^2 - R^2 = 0; "outer" is the larger root,
    "inner" the smaller one.
    """
    cx, cy = center
    sign = {"outer": 1, "inner": -1}[branch]

    def r(phi):
        ux, uy = mpmath.cos(phi), mpmath.sin(phi)
        half_b = cx * ux + cy * uy
        disc = half_b * half_b - (cx * cx + cy * cy) + radius * radius
        if disc < 0:
            raise ReferenceError(
                f"ray at {mpmath.nstr(mpmath.degrees(phi), 12)} deg misses the circle")
        return half_b + sign * mpmath.sqrt(disc)

    return r


def line_radius_function(a, b):
    """r(phi) of the ray from the origin meeting the line through a and b.

    r*u = a + lambda*(b - a); crossing both sides with (b - a) gives
    r * (u x (b - a)) = a x (b - a).
    """
    direction = (b[0] - a[0], b[1] - a[1])
    numerator = _cross(a, direction)
    if numerator == 0:
        raise ReferenceError("line passes through the origin")

    def r(phi):
        u = (mpmath.cos(phi), mpmath.sin(phi))
        return numerator / _cross(u, direction)

    return r


def _cubic_real_roots(coefficients):
    """Real roots of sum(coefficients[i] * s**i), to the working precision.

    mpmath.polyroots locates the roots; each real one is then polished by
    Newton's method on the full cubic (which also undoes the effect of
    dropping a leading coefficient that vanishes at the working precision).
    """
    def value_and_slope(s):
        value = slope = mpf(0)
        for c in reversed(coefficients):
            slope = slope * s + value
            value = value * s + c
        return value, slope

    size = max(abs(c) for c in coefficients)
    if size == 0:
        return None  # identically zero: the ray runs along the curve
    reduced = list(reversed(coefficients))  # highest degree first
    while abs(reduced[0]) <= size * mp.eps * 2 ** 20:
        reduced = reduced[1:]
    if len(reduced) == 1:
        return []
    try:
        roots = mpmath.polyroots(reduced, maxsteps=500, extraprec=2 * mp.prec)
    except mpmath.libmp.NoConvergence as error:
        raise ReferenceError(f"cubic root finder did not converge: {error}") from None
    imaginary_tolerance = mpf(10) ** (-(mp.dps // 2))
    real_roots = []
    for z in roots:
        if abs(mpmath.im(z)) > imaginary_tolerance * (1 + abs(z)):
            continue
        s = mpmath.re(z)
        for _ in range(60):
            value, slope = value_and_slope(s)
            if slope == 0:
                break
            step = value / slope
            s -= step
            if abs(step) <= mp.eps * 4 * (1 + abs(s)):
                break
        real_roots.append(s)
    return real_roots


def bezier_point(points, s):
    """B(s) = sum of the cubic Bernstein polynomials times P0..P3."""
    t = 1 - s
    weights = (t * t * t, 3 * s * t * t, 3 * s * s * t, s * s * s)
    return (sum(w * p[0] for w, p in zip(weights, points)),
            sum(w * p[1] for w, p in zip(weights, points)))


def spline_ray_hits(points, phi):
    """Every (s, r) where the full ray at phi meets the cubic B(s), s real.

    u x B(s) is a cubic in s whose Bernstein coefficients are u x P_i; its
    real roots with u.B(s) > 0 are on the ray (not behind the origin), and r
    is u.B(s). s is not restricted to [0, 1] here; callers select.
    """
    u = (mpmath.cos(phi), mpmath.sin(phi))
    c0, c1, c2, c3 = (_cross(u, p) for p in points)
    power = [c0, 3 * (c1 - c0), 3 * (c0 - 2 * c1 + c2), c3 - 3 * c2 + 3 * c1 - c0]
    roots = _cubic_real_roots(power)
    if roots is None:
        raise ReferenceError(
            f"ray at {mpmath.nstr(mpmath.degrees(phi), 12)} deg runs along the curve")
    hits = []
    for s in roots:
        b = bezier_point(points, s)
        r = u[0] * b[0] + u[1] * b[1]
        if r > 0:
            hits.append((s, r))
    return sorted(hits)


# A root this close outside [0, 1] still belongs to the segment: the end
# points come out as s = -1e-50 or so, and mpmath.diff steps a hair outside
# the window at a joint (by ~1e-56 in phi, so in s as well).
SPLINE_PARAMETER_SLACK = mpf("1e-20")


def spline_radius_function(points):
    """r(phi) of the ray from the origin meeting the cubic Bezier P0..P3.

    The unique s in [0, 1] (within SPLINE_PARAMETER_SLACK) with u x B(s) = 0
    and u.B(s) > 0; r = u.B(s). No hit or more than one is an error.
    """
    def r(phi):
        inside = [(s, r) for s, r in spline_ray_hits(points, phi)
                  if -SPLINE_PARAMETER_SLACK <= s <= 1 + SPLINE_PARAMETER_SLACK]
        if len(inside) != 1:
            raise ReferenceError(
                f"ray at {mpmath.nstr(mpmath.degrees(phi), 12)} deg meets the curve "
                f"{len(inside)} times (need exactly once)")
        return inside[0][1]

    return r


def _default_window(a, b, previous_end):
    """Window from the polar angles of a and b, counter-clockwise, continuing
    from the previous segment's window (lines and splines without one)."""
    angle_from = mpmath.atan2(a[1], a[0])
    start = previous_end if previous_end is not None else angle_from
    sweep = (mpmath.atan2(b[1], b[0]) - angle_from) % (2 * mpmath.pi)
    return start, start + sweep


def load_project(path):
    """Return {"omega": rad/s, "turn": rad, "segments": [...]}.

    Each segment is a dict with "index", "type", "r" (function of phi in rad),
    "start" and "end" (window in rad), and its geometry in mm ("center",
    "radius", "branch" for arcs; "from", "to" for lines; "points" = the four
    Bezier control points for bezier and hermite, plus "p0", "t0", "p3",
    "t1" for hermite).
    """
    doc = _read_json(path)
    units = doc.get("units", {})
    length_unit = units.get("length", "mm")
    angle_unit = units.get("angle", "deg")
    if length_unit not in ("mm", "m"):
        raise ReferenceError(f"units.length: unknown unit {length_unit!r}")
    if angle_unit not in ("deg", "rad"):
        raise ReferenceError(f"units.angle: unknown unit {angle_unit!r}")
    scale = mpf(1000) if length_unit == "m" else mpf(1)
    to_rad = (mpmath.pi / 180) if angle_unit == "deg" else mpf(1)

    motion = doc.get("motion", {})
    given = [k for k in ("omega_rad_s", "rpm", "period_s") if k in motion]
    if len(given) != 1:
        raise ReferenceError("motion: need exactly one of omega_rad_s, rpm, period_s")
    if "omega_rad_s" in motion:
        omega = motion["omega_rad_s"]
    elif "rpm" in motion:
        omega = motion["rpm"] * 2 * mpmath.pi / 60
    else:
        omega = 2 * mpmath.pi / motion["period_s"]
    if omega == 0:
        raise ReferenceError("motion: angular speed must not be zero")

    segments = []
    previous_end = None
    for i, seg in enumerate(doc["contour"]):
        where = f"contour[{i}]"
        kind = seg.get("type")
        if kind == "arc":
            center = _point(seg["center"], scale, where + ".center")
            radius = seg["radius"] * scale
            branch = seg["branch"]
            if branch not in ("outer", "inner"):
                raise ReferenceError(f"{where}.branch: unknown branch {branch!r}")
            r = arc_radius_function(center, radius, branch)
            geometry = {"center": center, "radius": radius, "branch": branch}
            start = seg["phi_start"] * to_rad
            end = seg["phi_end"] * to_rad
        elif kind == "line":
            a = _point(seg["from"], scale, where + ".from")
            b = _point(seg["to"], scale, where + ".to")
            r = line_radius_function(a, b)
            geometry = {"from": a, "to": b}
            if "phi_start" in seg and "phi_end" in seg:
                start = seg["phi_start"] * to_rad
                end = seg["phi_end"] * to_rad
            else:
                # Default window: polar angles of from/to, counter-clockwise,
                # continuing from the previous segment's window.
                start, end = _default_window(a, b, previous_end)
        elif kind in ("bezier", "hermite"):
            if kind == "bezier":
                raw = seg["points"]
                if not isinstance(raw, list) or len(raw) != 4:
                    raise ReferenceError(f"{where}.points: expected four points [x, y]")
                points = [_point(p, scale, f"{where}.points[{k}]") for k, p in enumerate(raw)]
                geometry = {"points": points}
            else:
                p0, t0, p3, t1 = (_point(seg[key], scale, f"{where}.{key}")
                                  for key in ("p0", "t0", "p3", "t1"))
                # spec/math.md §4: same curve as the Bezier P1 = p0 + t0/3, P2 = p3 - t1/3.
                points = [p0, (p0[0] + t0[0] / 3, p0[1] + t0[1] / 3),
                          (p3[0] - t1[0] / 3, p3[1] - t1[1] / 3), p3]
                geometry = {"points": points, "p0": p0, "t0": t0, "p3": p3, "t1": t1}
            r = spline_radius_function(points)
            if "phi_start" in seg and "phi_end" in seg:
                start = seg["phi_start"] * to_rad
                end = seg["phi_end"] * to_rad
            else:
                # Default window: polar angles of P0/P3, as for lines.
                start, end = _default_window(points[0], points[3], previous_end)
        else:
            raise ReferenceError(f"{where}.type: {kind!r} is not supported by this reference")
        if not start < end:
            raise ReferenceError(f"{where}: empty or reversed window")
        segments.append({"index": i, "type": kind, "r": r, "start": start, "end": end,
                         **geometry})
        previous_end = end

    return {"omega": omega, "turn": 2 * mpmath.pi, "segments": segments}


# ---------------------------------------------------------------------------
# Kinematics
# ---------------------------------------------------------------------------

def find_segment(project, phi):
    """Normalise phi into [first start, first start + turn) and find its window."""
    segments = project["segments"]
    first = segments[0]["start"]
    turn = project["turn"]
    phi_n = phi - turn * mpmath.floor((phi - first) / turn)
    for seg in segments:
        if seg["start"] <= phi_n < seg["end"]:
            return seg, phi_n
    # Only reachable in the rounding sliver between a decimal last phi_end
    # (e.g. 6.2831853071795865 rad) and the exact end of the turn.
    last = segments[-1]
    if phi_n >= last["end"] and phi_n - last["end"] < mpf("1e-12"):
        return last, phi_n
    raise ReferenceError(
        f"phi = {mpmath.nstr(mpmath.degrees(phi_n), 17)} deg lies in no window")


def polar_derivatives(r, phi):
    """r, r', r'', r''' at phi by high-precision numerical differentiation."""
    return [r(phi)] + [mpmath.diff(r, phi, n) for n in (1, 2, 3)]


def state_at(project, t):
    omega = project["omega"]
    phi = omega * t
    seg, phi_n = find_segment(project, phi)
    r, r1, r2, r3 = polar_derivatives(seg["r"], phi_n)

    r_dot = omega * r1
    r_ddot = omega ** 2 * r2
    r_dddot = omega ** 3 * r3

    v_r = r_dot
    v_phi = r * omega
    a_r = r_ddot - r * omega ** 2
    a_phi = 2 * r_dot * omega
    j_r = r_dddot - 3 * r_dot * omega ** 2
    j_phi = 3 * r_ddot * omega - r * omega ** 3

    return {
        "t": t,
        "phi_deg": mpmath.degrees(phi),
        "segment": seg["index"],
        "r": r,
        "v_r": v_r, "v_phi": v_phi, "v": mpmath.hypot(v_r, v_phi),
        "a_r": a_r, "a_phi": a_phi, "a": mpmath.hypot(a_r, a_phi),
        "j_r": j_r, "j_phi": j_phi, "j": mpmath.hypot(j_r, j_phi),
    }


# ---------------------------------------------------------------------------
# Output
# ---------------------------------------------------------------------------

def format_number(x):
    """17 significant digits, valid JSON; exact-zero noise written as 0."""
    if isinstance(x, int):
        return str(x)
    if abs(x) < ZERO_NOISE:
        return "0.0"
    return mpmath.nstr(x, 17)


def states_to_json(states):
    lines = ["["]
    for i, state in enumerate(states):
        fields = [f'    "{key}": {format_number(value)}' for key, value in state.items()]
        closing = "  }," if i + 1 < len(states) else "  }"
        lines += ["  {", ",\n".join(fields), closing]
    lines.append("]")
    return "\n".join(lines) + "\n"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("project", help="Camwright project file (.cam.json)")
    parser.add_argument("--t", action="append", required=True, metavar="SECONDS",
                        help="time instant; repeat for several")
    args = parser.parse_args(argv)
    try:
        project = load_project(args.project)
        states = [state_at(project, mpf(t)) for t in args.t]
    except (ReferenceError, KeyError, ValueError) as error:
        print(f"polar_reference: {args.project}: {error}", file=sys.stderr)
        return 1
    sys.stdout.write(states_to_json(states))
    return 0


if __name__ == "__main__":
    sys.exit(main())
