#!/usr/bin/env python3
"""An independent reader of camwright's servo cam tables (`export --format camtable`).

    check_camtable.py DIALECT PROJECT.cam.json FILE [--report REPORT.json]

Written from the vendors' documentation, not from the writer (src/core/export/cam_table.cpp):
it parses FILE as DIALECT's controller would, rebuilds the controller's interpolation between
the points and compares it, at every knot and 15 points evenly inside each interval, with the
closed form of the project's motion design (cycloidal segments and dwells only):

    y(x) = L0 + (L1 - L0) * (x - sin(2 pi x) / (2 pi)),  x = (theta - theta0) / beta.

Dialects and the documentation each follows:
- csv: camwright's own (exports.md); rows master_deg,position,velocity_per_deg,
  acceleration_per_deg2; read as quintic Hermite knots like the XYVA dialects.
- codesys: CODESYS SoftMotion SMC_CAMXYVA knots in an MC_CAM_REF with byType 3, "polynomial
  description on particular points consisting of master position, slave position, slave
  velocity and slave acceleration" (https://content.helpme-codesys.com/en/libs/SM3_Basic/
  Current/SM3_Basic/DataTypes/CAM/MC_CAM_REF.html): a fifth-order polynomial between knots
  matching position, velocity and acceleration at both.
- beckhoff: TwinCAT NC camming MC_MotionFunctionPoint (https://infosys.beckhoff.com/content/
  1033/tf5050_tc3_nc_camming/1003721995.html): PointIndex strictly increasing from 1 without
  gaps, RelIndexNextPoint usually 1; FunctionType MOTIONFUNCTYPE_POLYNOM5_MM = 15, "polynom
  with order 5 (motion <-> motion)" (.../1003744011.html): the same quintic.
- rockwell: Logix CAM data type (MOTION-RM002H-EN-P, chapter 10): Master, Slave : REAL,
  SegmentType 0 linear / 1 cubic; REAL is IEEE single precision, so the values are rounded to
  float32 as the controller holds them; "cubic" read as a C2 cubic spline whose end slopes are
  the MCCP start and end slope the file names in its comment.
- kollmorgen: KAS IDE "Import Cam Profile" CSV (CYCLIC;YES; TABLE_BEGIN;; X;Y;SPLINE rows
  TABLE_END;;, at least 4 spline segments); a spline segment is "3rd order polynomial" through
  the given positions (KAS "CAM Profile Segments"); read as a periodic C2 cubic spline, the
  profile being cyclic.

The spline systems are solved here by Gauss-Seidel iteration (the writer uses a direct
solver), so the two share no code and no algorithm.

Prints a JSON summary: points, the re-evaluated largest errors, and with --report whether
the CLI's report agrees. Exit 1 with the reasons on stderr when a check fails.
"""

import argparse
import json
import math
import re
import struct
import sys

FAILURES = []


def fail(message):
    FAILURES.append(message)


# ---- the closed form of the design ---------------------------------------------------------

def design_segments(project):
    design = project["design"]
    segments = []
    start, lift = 0.0, 0.0
    for seg in design["segments"]:
        law = seg["law"]
        if law not in ("cycloidal", "dwell"):
            raise SystemExit(f"check_camtable.py knows cycloidal and dwell only, not {law}")
        end = float(seg["to_deg"])
        to_lift = lift if law == "dwell" else float(seg["lift"])
        segments.append((start, end, lift, to_lift, law))
        start, lift = end, to_lift
    return segments


def exact(segments, deg):
    """Lift and its first two derivatives per degree at master angle deg (0 <= deg < 360)."""
    deg = deg % 360.0
    for start, end, l0, l1, law in segments:
        if start <= deg < end or (deg == end == 360.0):
            if law == "dwell":
                return (l0, 0.0, 0.0)
            beta = end - start
            h = l1 - l0
            x = (deg - start) / beta
            two_pi = 2.0 * math.pi
            return (l0 + h * (x - math.sin(two_pi * x) / two_pi),
                    h / beta * (1.0 - math.cos(two_pi * x)),
                    h * two_pi / beta ** 2 * math.sin(two_pi * x))
    raise ValueError(deg)


# ---- the controllers' interpolation --------------------------------------------------------

def quintic_at(k0, k1, x):
    """The fifth-order polynomial through knots (x, p, v, a) matching p, v, a at both ends,
    from its Hermite basis functions."""
    x0, p0, v0, a0 = k0
    x1, p1, v1, a1 = k1
    h = x1 - x0
    t = (x - x0) / h
    t2, t3, t4, t5 = t * t, t ** 3, t ** 4, t ** 5
    basis = [1 - 10 * t3 + 15 * t4 - 6 * t5, t - 6 * t3 + 8 * t4 - 3 * t5,
             0.5 * (t2 - 3 * t3 + 3 * t4 - t5), 10 * t3 - 15 * t4 + 6 * t5,
             -4 * t3 + 7 * t4 - 3 * t5, 0.5 * (t3 - 2 * t4 + t5)]
    d1 = [-30 * t2 + 60 * t3 - 30 * t4, 1 - 18 * t2 + 32 * t3 - 15 * t4,
          0.5 * (2 * t - 9 * t2 + 12 * t3 - 5 * t4), 30 * t2 - 60 * t3 + 30 * t4,
          -12 * t2 + 28 * t3 - 15 * t4, 0.5 * (3 * t2 - 8 * t3 + 5 * t4)]
    d2 = [-60 * t + 180 * t2 - 120 * t3, -36 * t + 96 * t2 - 60 * t3,
          0.5 * (2 - 18 * t + 36 * t2 - 20 * t3), 60 * t - 180 * t2 + 120 * t3,
          -24 * t + 84 * t2 - 60 * t3, 0.5 * (6 * t - 24 * t2 + 20 * t3)]
    w = [p0, h * v0, h * h * a0, p1, h * v1, h * h * a1]
    return (sum(c * b for c, b in zip(w, basis)),
            sum(c * b for c, b in zip(w, d1)) / h,
            sum(c * b for c, b in zip(w, d2)) / (h * h))


def spline_moments(xs, ys, periodic, slopes=None):
    """Second derivatives M of the C2 cubic spline through (xs, ys) by Gauss-Seidel on
    h[i-1] M[i-1] + 2 (h[i-1] + h[i]) M[i] + h[i] M[i+1] = 6 (d[i] - d[i-1]), d the chords'
    slopes; periodic (M[n] = M[0], ys[n] = ys[0]) or clamped to slopes (s0, s1)."""
    n = len(xs) - 1
    h = [xs[i + 1] - xs[i] for i in range(n)]
    d = [(ys[i + 1] - ys[i]) / h[i] for i in range(n)]
    m = [0.0] * (n + 1)
    for _ in range(2000):
        change = 0.0
        if periodic:
            for i in range(n):
                hp = h[i - 1]
                new = (6 * (d[i] - d[i - 1]) - hp * m[(i - 1) % n] - h[i] * m[(i + 1) % n]) / (
                    2 * (hp + h[i]))
                change = max(change, abs(new - m[i]))
                m[i] = new
            m[n] = m[0]
        else:
            s0, s1 = slopes
            new = (6 * (d[0] - s0) - h[0] * m[1]) / (2 * h[0])
            change, m[0] = abs(new - m[0]), new
            for i in range(1, n):
                new = (6 * (d[i] - d[i - 1]) - h[i - 1] * m[i - 1] - h[i] * m[i + 1]) / (
                    2 * (h[i - 1] + h[i]))
                change = max(change, abs(new - m[i]))
                m[i] = new
            new = (6 * (s1 - d[n - 1]) - h[n - 1] * m[n - 1]) / (2 * h[n - 1])
            change, m[n] = max(change, abs(new - m[n])), new
        if change <= 1e-17 * (1.0 + max(abs(v) for v in m)):
            break
    return m


def spline_at(xs, ys, m, i, x):
    """The cubic of interval i at x, from its values and second derivatives at both ends."""
    h = xs[i + 1] - xs[i]
    u = (x - xs[i]) / h
    # y = (1-u) y0 + u y1 + h^2/6 [((1-u)^3 - (1-u)) M0 + (u^3 - u) M1]
    p = (1 - u) * ys[i] + u * ys[i + 1] + h * h / 6 * (((1 - u) ** 3 - (1 - u)) * m[i] +
                                                      (u ** 3 - u) * m[i + 1])
    dp = (ys[i + 1] - ys[i]) / h + h / 6 * ((1 - 3 * (1 - u) ** 2) * m[i] +
                                            (3 * u * u - 1) * m[i + 1])
    d2p = (1 - u) * m[i] + u * m[i + 1]
    return (p, dp, d2p)


# ---- readers -------------------------------------------------------------------------------

def read_csv(text):
    rows = []
    for line in text.splitlines():
        if line.startswith("#") or line.startswith("master_deg"):
            continue
        rows.append(tuple(float(v) for v in line.split(",")))
    knots = rows + [(360.0,) + rows[0][1:]]
    return knots


def read_codesys(text):
    knots = [tuple(float(v) for v in m) for m in re.findall(
        r"\(dX := ([^,]+), dY := ([^,]+), dV := ([^,]+), dA := ([^)]+)\)", text)]
    declared = re.search(r"ARRAY\[0\.\.(\d+)\] OF SMC_CAMXYVA", text)
    if not declared or int(declared.group(1)) + 1 != len(knots):
        fail("ARRAY[0..n] OF SMC_CAMXYVA does not declare the knots written")
    if "byType := 3" not in text:
        fail("MC_CAM_REF is not byType 3 (XYVA)")
    return knots


def read_beckhoff(text):
    declared = re.search(r"(\w+) : ARRAY\[1\.\.(\d+)\] OF MC_MotionFunctionPoint := \[", text)
    points = re.findall(
        r"\(PointIndex := (\d+), FunctionType := (\w+), PointType := (\w+),\s*"
        r"RelIndexNextPoint := (\d+), MasterPos := ([^,]+), SlavePos := ([^,]+),\s*"
        r"SlaveVelo := ([^,]+), SlaveAcc := ([^,]+), SlaveJerk := ([^)]+)\)", text)
    if not declared or int(declared.group(2)) != len(points):
        fail("ARRAY[1..n] OF MC_MotionFunctionPoint does not declare the points written")
    knots = []
    for i, p in enumerate(points):
        if int(p[0]) != i + 1:
            fail(f"PointIndex {p[0]} where {i + 1} is due (from 1, no gaps)")
        if p[1] != "MOTIONFUNCTYPE_POLYNOM5_MM":
            fail(f"point {i + 1}: FunctionType {p[1]}")
        if p[2] == "MOTIONPOINTTYPE_IGNORE" and i in (0, len(points) - 1):
            fail("the first or last point is MOTIONPOINTTYPE_IGNORE")
        if p[3] != "1":
            fail(f"point {i + 1}: RelIndexNextPoint {p[3]}")
        for literal in p[4:]:
            if "." not in literal:
                fail(f"{literal} is not an LREAL literal")
        knots.append(tuple(float(v) for v in p[4:8]))
    return knots


def as_real(value):
    return struct.unpack("f", struct.pack("f", value))[0]


def read_rockwell(text):
    elements = re.findall(
        r"(\w+)\[(\d+)\]\.Master := ([^;]+); \1\[\2\]\.Slave := ([^;]+); "
        r"\1\[\2\]\.SegmentType := (\d+);", text)
    slopes = re.search(r"MCCP StartSlope := ([^,]+), EndSlope := ([^ ]+)", text)
    declared = re.search(r"tag: (\w+) : CAM\[(\d+)\]", text)
    if not declared or int(declared.group(2)) != len(elements):
        fail("the CAM tag's size is not the number of elements written")
    xs, ys = [], []
    for i, e in enumerate(elements):
        if int(e[1]) != i:
            fail(f"element {e[1]} where {i} is due")
        if e[4] != "1":
            fail(f"element {i}: SegmentType {e[4]}, not 1 (cubic)")
        xs.append(as_real(float(e[2])))
        ys.append(as_real(float(e[3])))
        for literal in (e[2], e[3]):
            if "." not in literal:
                fail(f"{literal} is not a REAL literal (no decimal point)")
    if not slopes:
        fail("no MCCP start and end slope")
        return xs, ys, (0.0, 0.0)
    return xs, ys, (as_real(float(slopes.group(1))), as_real(float(slopes.group(2))))


def read_kollmorgen(text):
    lines = text.splitlines()
    if lines[:2] != ["CYCLIC;YES;", "TABLE_BEGIN;;"] or lines[-1] != "TABLE_END;;":
        fail(f"not a KAS cam profile CSV: {lines[:2]} ... {lines[-1:]}")
    xs, ys = [], []
    for line in lines[2:-1]:
        x, y, kind = line.split(";")
        if kind != "SPLINE":
            fail(f"segment type {kind}")
        xs.append(float(x))
        ys.append(float(y))
    if len(xs) < 5:
        fail("fewer than 4 spline segments")
    return xs, ys


# ---- the check -----------------------------------------------------------------------------

def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("dialect", choices=["csv", "codesys", "beckhoff", "rockwell",
                                            "kollmorgen"])
    parser.add_argument("project")
    parser.add_argument("file")
    parser.add_argument("--report")
    args = parser.parse_args()
    project = json.load(open(args.project, encoding="utf-8"))
    segments = design_segments(project)
    text = open(args.file, encoding="ascii").read()

    if args.dialect in ("csv", "codesys", "beckhoff"):
        knots = {"csv": read_csv, "codesys": read_codesys,
                 "beckhoff": read_beckhoff}[args.dialect](text)
        masters = [k[0] for k in knots]

        def interpolant(i, x):
            return quintic_at(knots[i], knots[i + 1], x)
        interpolation = "quintic"
    elif args.dialect == "rockwell":
        masters, ys, slopes = read_rockwell(text)
        m = spline_moments(masters, ys, False, slopes)

        def interpolant(i, x):
            return spline_at(masters, ys, m, i, x)
        interpolation = "cubic-spline-clamped"
    else:
        masters, ys = read_kollmorgen(text)
        m = spline_moments(masters, ys, True)

        def interpolant(i, x):
            return spline_at(masters, ys, m, i, x)
        interpolation = "cubic-spline-periodic"

    n = len(masters) - 1
    if masters[-1] != 360.0 or masters[0] != 0.0:
        fail(f"the master runs from {masters[0]} to {masters[-1]}, not 0 to 360")
    for i, x in enumerate(masters[:-1]):
        want = 360.0 * i / n
        if abs(x - want) > (1e-4 if args.dialect == "rockwell" else 1e-12):
            fail(f"point {i}: master {x}, not {want}")
    worst = [0.0, 0.0, 0.0]
    worst_at = 0.0
    knot_error = 0.0
    for i in range(n):
        for k in range(16):
            x = 360.0 * (16 * i + k) / (16 * n)
            want = exact(segments, x)
            got = interpolant(i, x)
            for d in range(3):
                error = abs(got[d] - want[d])
                if d == 0 and error > worst[0]:
                    worst_at = x
                worst[d] = max(worst[d], error)
            if k == 0:
                knot_error = max(knot_error, abs(got[0] - want[0]))
    summary = {"points": n, "interpolation": interpolation,
               "max_error": {"position": worst[0], "position_at_deg": worst_at,
                             "velocity_per_deg": worst[1], "acceleration_per_deg2": worst[2]},
               "knot_error": knot_error}

    if args.report:
        report = json.load(open(args.report, encoding="utf-8"))
        summary["report_agrees"] = True
        if report["points"] != n or report["interpolation"] != interpolation:
            fail(f"report: {report['points']} points, {report['interpolation']}")
        # Both evaluate the same polynomials at the same angles; they differ by rounding: of
        # the positions (1e-14 of the stroke) over the step h to the power of the derivative.
        stroke = max(abs(s[3]) for s in segments)
        step = 360.0 / n
        for d, key in enumerate(["position", "velocity_per_deg", "acceleration_per_deg2"]):
            got, want = report["max_error"][key], summary["max_error"][key]
            if abs(got - want) > 1e-6 * want + 1e-14 * stroke / step ** d:
                summary["report_agrees"] = False
                fail(f"report: max_error.{key} is {got}, re-evaluated {want}")
        # The characteristics from the closed form: cycloidal extremes h·2/β, 2πh/β², 4π²h/β³.
        strokes = [(s[1] - s[0], s[3] - s[2]) for s in segments if s[4] == "cycloidal"]
        c = report["characteristics"]
        v = max(abs(2 * h / b) for b, h in strokes)
        a = max(abs(2 * math.pi * h / b ** 2) for b, h in strokes)
        j = max(abs(4 * math.pi ** 2 * h / b ** 3) for b, h in strokes)
        lifts = [s[2] for s in segments] + [s[3] for s in segments]
        expected = {"position": (min(lifts), max(lifts)), "velocity_per_deg": (-v, v),
                    "acceleration_per_deg2": (-a, a), "jerk_per_deg3": (-j, j)}
        for key, (lo, hi) in expected.items():
            scale = max(abs(lo), abs(hi))
            if abs(c[key]["min"] - lo) > 1e-9 * scale or abs(c[key]["max"] - hi) > 1e-9 * scale:
                fail(f"characteristics.{key}: {c[key]}, not {lo} .. {hi}")
            # Where each extreme occurs: the closed form takes that value there.
            order = ["position", "velocity_per_deg", "acceleration_per_deg2"].index(key) \
                if key != "jerk_per_deg3" else None
            for side in ("min", "max"):
                at = c[key][side + "_at_deg"]
                if not 0 <= at < 360:
                    fail(f"characteristics.{key}.{side}_at_deg {at}")
                elif order is not None and \
                        abs(exact(segments, at)[order] - c[key][side]) > 1e-9 * scale:
                    fail(f"characteristics.{key}.{side}_at_deg {at}: the motion is "
                         f"{exact(segments, at)[order]} there")
    print(json.dumps(summary, indent=2))
    if FAILURES:
        for f in FAILURES:
            print(f, file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
