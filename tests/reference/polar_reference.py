#!/usr/bin/python3
"""Independent 50-digit reference for Camwright's polar kinematics.

Reads a Camwright project file (spec/project-format.md) and prints, for each
requested time t, the state of a knife-edge follower on a fixed radial ray
(spec/math.md §1-2) as JSON.

Independence from the C++ engine is the point of this script:
  * r(phi) is computed directly from the geometry (intersect the ray with the
    circle or the line), with mpmath at 50 significant digits;
  * r', r'', r''' are NOT taken from the closed forms of math.md; they come
    from mpmath.diff, a high-precision numerical derivative of our own r(phi)
    of the segment that owns phi.

Usage:
    /usr/bin/python3 polar_reference.py PROJECT.cam.json --t 0.05 --t 0.15

Only arcs and lines are supported (no Bézier/Hermite segments).
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


def load_project(path):
    """Return {"omega": rad/s, "turn": rad, "segments": [...]}.

    Each segment is a dict with "index", "type", "r" (function of phi in rad),
    "start" and "end" (window in rad), and its geometry in mm ("center",
    "radius", "branch" for arcs; "from", "to" for lines).
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
                angle_from = mpmath.atan2(a[1], a[0])
                start = previous_end if previous_end is not None else angle_from
                sweep = (mpmath.atan2(b[1], b[0]) - angle_from) % (2 * mpmath.pi)
                end = start + sweep
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
