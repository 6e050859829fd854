#!/usr/bin/python3
"""Check reference cams in 50-digit arithmetic against the validity rules of
spec/project-format.md:

  * windows ascending, contiguous (same decimal literal) and covering one turn;
  * every joint, including last -> first, closes within 1e-6 mm (C0);
  * arcs: the ray meets the circle (D >= 0) with r > 0 across the window;
  * lines: do not pass through the origin, r > 0 across the window, and the
    window equals the polar angles of from/to.

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
HERE = os.path.dirname(os.path.abspath(__file__))


def point_at(seg, phi):
    r = seg["r"](phi)
    return r * mpmath.cos(phi), r * mpmath.sin(phi)


def angle_difference(a, b):
    """a - b folded into (-pi, pi]."""
    d = (a - b) % (2 * mpmath.pi)
    return d - 2 * mpmath.pi if d > mpmath.pi else d


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
