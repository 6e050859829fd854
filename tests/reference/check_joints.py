#!/usr/bin/python3
"""Check reference cams in 50-digit arithmetic against the validity rules of
spec/project-format.md:

  * windows ascending, contiguous (same decimal literal) and covering one turn;
  * every joint, including last -> first, closes within 1e-6 mm (C0);
  * arcs: the ray meets the circle (D >= 0) with r > 0 across the window;
  * lines: do not pass through the origin, r > 0 across the window, and the
    window equals the polar angles of from/to;
  * bezier/hermite: end points off the origin, r > 0 across the window, the
    window equals the polar angles of P0/P3 (less than one turn), and the ray
    meets the curve (s in [0, 1], in front of the origin) exactly once at
    SPLINE_RAY_ANGLES angles strictly inside the window.

Also prints, for information, the jump of dr/dphi at each joint (a tangent
break; 0 for tangent joints).

Usage: /usr/bin/python3 check_joints.py [PROJECT.cam.json ...]
(default: every tests/data/reference/*.cam.json). Exit status 1 on failure.
"""

import glob
import json
import os
import sys

import mpmath
from mpmath import mpf

sys.dont_write_bytecode = True  # keep tests/reference free of __pycache__
import polar_reference as ref  # noqa: E402

C0_TOLERANCE_MM = mpf("1e-6")
SAMPLES_PER_WINDOW = 400
SPLINE_RAY_ANGLES = 401
# Roots of u x B(s) = 0 count as inside [0, 1] up to this (root-finder noise).
SPLINE_PARAMETER_NOISE = mpf("1e-30")
HERE = os.path.dirname(os.path.abspath(__file__))


def point_at(seg, phi):
    r = seg["r"](phi)
    return r * mpmath.cos(phi), r * mpmath.sin(phi)


def angle_difference(a, b):
    """a - b folded into (-pi, pi]."""
    d = (a - b) % (2 * mpmath.pi)
    return d - 2 * mpmath.pi if d > mpmath.pi else d


def check_spline(seg, where):
    """Window on the polar angles of P0/P3; exactly one ray hit inside it."""
    problems = []
    points = seg["points"]
    for end, k in (("start", 0), ("end", 3)):
        a = points[k]
        if mpmath.hypot(a[0], a[1]) <= C0_TOLERANCE_MM:
            problems.append(f"{where}: end point P{k} lies on the rotation centre")
            return problems
        off = angle_difference(mpmath.atan2(a[1], a[0]), seg[end])
        if abs(off) > mpf("1e-12"):
            problems.append(f"{where}: window {end} is {mpmath.nstr(mpmath.degrees(off), 3)}"
                            f" deg away from the polar angle of P{k}")
    if not seg["end"] - seg["start"] < 2 * mpmath.pi:
        problems.append(f"{where}: spline window spans a full turn or more")
    counts = {}
    first_bad = None
    for k in range(SPLINE_RAY_ANGLES):
        phi = seg["start"] + (seg["end"] - seg["start"]) * (k + 1) / (SPLINE_RAY_ANGLES + 1)
        try:
            hits = [h for h in ref.spline_ray_hits(points, phi)
                    if -SPLINE_PARAMETER_NOISE <= h[0] <= 1 + SPLINE_PARAMETER_NOISE]
        except ref.ReferenceError as error:
            problems.append(f"{where}: {error}")
            break
        counts[len(hits)] = counts.get(len(hits), 0) + 1
        if len(hits) != 1 and first_bad is None:
            first_bad = (len(hits), phi)
    if first_bad is not None:
        bad = SPLINE_RAY_ANGLES - counts.get(1, 0)
        problems.append(f"{where}: the ray meets the curve {first_bad[0]} times at "
                        f"{mpmath.nstr(mpmath.degrees(first_bad[1]), 10)} deg, and not exactly "
                        f"once at {bad} of {SPLINE_RAY_ANGLES} angles (need exactly once)")
    print(f"  {where} ({seg['type']}): ray hits per angle at {SPLINE_RAY_ANGLES} angles "
          f"inside the window: {dict(sorted(counts.items()))}")
    return problems


def check_file(path):
    problems = []
    project = ref.load_project(path)
    segments = project["segments"]
    with open(path, encoding="utf-8") as f:
        raw = json.load(f, parse_float=str, parse_int=str)["contour"]

    # Windows: ascending, same literal at every shared boundary, one turn.
    for i, seg in enumerate(raw):
        nxt = raw[(i + 1) % len(raw)]
        if i + 1 < len(raw) and seg.get("phi_end") != nxt.get("phi_start"):
            problems.append(f"contour[{i}]/contour[{i + 1}]: phi_end {seg.get('phi_end')} "
                            f"!= phi_start {nxt.get('phi_start')}")
    coverage = segments[-1]["end"] - segments[0]["start"] - project["turn"]
    if abs(coverage) > mpf("1e-15"):
        problems.append(f"windows cover one turn {mpmath.nstr(coverage, 3)} rad off")

    # Joints.
    max_gap = mpf(0)
    print(f"{os.path.basename(path)}: {len(segments)} segments")
    for i, seg in enumerate(segments):
        nxt = segments[(i + 1) % len(segments)]
        p = point_at(seg, seg["end"])
        q = point_at(nxt, nxt["start"])
        gap = mpmath.hypot(p[0] - q[0], p[1] - q[1])
        slope_jump = mpmath.diff(nxt["r"], nxt["start"]) - mpmath.diff(seg["r"], seg["end"])
        max_gap = max(max_gap, gap)
        print(f"  joint {i}->{nxt['index']} at {mpmath.nstr(mpmath.degrees(seg['end']), 12):>16} deg:"
              f"  gap {mpmath.nstr(gap, 3):>9} mm,  dr/dphi jump {mpmath.nstr(slope_jump, 3):>9} mm/rad")
        if gap > C0_TOLERANCE_MM:
            problems.append(f"contour[{i}]/contour[{nxt['index']}]: C0 gap {mpmath.nstr(gap, 3)} mm")

    # Each segment across its whole window.
    for seg in segments:
        where = f"contour[{seg['index']}]"
        for k in range(SAMPLES_PER_WINDOW + 1):
            phi = seg["start"] + (seg["end"] - seg["start"]) * k / SAMPLES_PER_WINDOW
            try:
                r = seg["r"](phi)
            except ref.ReferenceError as error:
                problems.append(f"{where}: {error}")
                break
            if not r > 0:
                problems.append(f"{where}: r = {mpmath.nstr(r, 6)} <= 0 at "
                                f"{mpmath.nstr(mpmath.degrees(phi), 10)} deg")
                break
        if seg["type"] == "line":
            for end, key in (("start", "from"), ("end", "to")):
                a = seg[key]
                off = angle_difference(mpmath.atan2(a[1], a[0]), seg[end])
                if abs(off) > mpf("1e-12"):
                    problems.append(f"{where}: window {end} is {mpmath.nstr(mpmath.degrees(off), 3)}"
                                    f" deg away from the polar angle of '{key}'")
            if not seg["end"] - seg["start"] < mpmath.pi:
                problems.append(f"{where}: line window spans 180 deg or more")
        if seg["type"] in ("bezier", "hermite"):
            problems += check_spline(seg, where)

    print(f"  max C0 gap {mpmath.nstr(max_gap, 3)} mm")
    for problem in problems:
        print(f"  ERROR {problem}")
    return not problems


def main(paths):
    if not paths:
        paths = sorted(glob.glob(os.path.join(HERE, "..", "data", "reference", "*.cam.json")))
    ok = True
    for path in paths:
        ok = check_file(path) and ok
    print("all joints and windows OK" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
