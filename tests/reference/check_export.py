#!/usr/bin/python3
"""Checks Camwright's exports with the programs that read them, against an independent profile.

    check_export.py dxf      PROJECT.cam.json FILE.dxf [--tolerance MM] [--tool-radius MM]
    check_export.py svg      PROJECT.cam.json FILE.svg [--tolerance MM]
    check_export.py camtable PROJECT.cam.json FILE.csv

The exact profile comes from polar_reference.py (the ray meets each segment's circle, line or
cubic, computed with mpmath), not from the engine. The files are read by the real consumers:
ezdxf for DXF (with its audit), svgelements for the SVG path, Python's csv for the cam table.

Prints a JSON summary on stdout; exits 0 when every check holds, 1 with the reasons on stderr.
"""

import argparse
import json
import math
import re
import sys

import mpmath
from mpmath import mp, mpf

import polar_reference as ref

mp.dps = 30

problems = []


def fail(message):
    problems.append(message)


def exact_point(segment, phi):
    r = segment["r"](mpf(phi))
    return (float(r * mpmath.cos(phi)), float(r * mpmath.sin(phi)))


def ends(segment):
    return exact_point(segment, segment["start"]), exact_point(segment, segment["end"])


def dist(p, q):
    return math.hypot(p[0] - q[0], p[1] - q[1])


def polar_angle_in(segment, p):
    """The polar angle of p, moved by whole turns into the segment's window (or near it)."""
    phi = math.atan2(p[1], p[0])
    start = float(segment["start"])
    while phi < start - 1e-9:
        phi += 2 * math.pi
    while phi > start + 2 * math.pi - 1e-9:
        phi -= 2 * math.pi
    return phi


def bezier(points, s):
    t = 1 - s
    w = (t * t * t, 3 * s * t * t, 3 * s * s * t, s * s * s)
    return (sum(wi * float(p[0]) for wi, p in zip(w, points)),
            sum(wi * float(p[1]) for wi, p in zip(w, points)))


def distance_to_bezier(points, p, samples=400):
    """Nearest distance from p to the cubic on s in [0, 1]: a dense scan, then golden section."""
    best = min(range(samples + 1), key=lambda i: dist(bezier(points, i / samples), p))
    lo, hi = max(0.0, (best - 1) / samples), min(1.0, (best + 1) / samples)
    g = (math.sqrt(5) - 1) / 2
    for _ in range(80):
        a, b = hi - g * (hi - lo), lo + g * (hi - lo)
        if dist(bezier(points, a), p) < dist(bezier(points, b), p):
            hi = b
        else:
            lo = a
    return dist(bezier(points, (lo + hi) / 2), p)


def radial_error(segment, p):
    """| |p| - r(phi) | at p's polar angle: at least the distance from p to the profile."""
    phi = polar_angle_in(segment, p)
    return abs(math.hypot(*p) - float(segment["r"](mpf(phi))))


# ---------------------------------------------------------------------------
# DXF
# ---------------------------------------------------------------------------

def arc_points(center, radius, a_deg, b_deg, n):
    """n+1 points of the counter-clockwise arc from a_deg to b_deg."""
    sweep = (b_deg - a_deg) % 360.0
    return [(center[0] + radius * math.cos(math.radians(a_deg + sweep * i / n)),
             center[1] + radius * math.sin(math.radians(a_deg + sweep * i / n)))
            for i in range(n + 1)]


def entity_shape(e):
    """(start, end, points along) of a LINE/ARC in the file's own direction."""
    t = e.dxftype()
    if t == "LINE":
        a, b = (e.dxf.start.x, e.dxf.start.y), (e.dxf.end.x, e.dxf.end.y)
        return a, b, [a, ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2), b]
    if t == "ARC":
        pts = arc_points((e.dxf.center.x, e.dxf.center.y), e.dxf.radius,
                         e.dxf.start_angle, e.dxf.end_angle, 16)
        return pts[0], pts[-1], pts
    if t == "CIRCLE":
        pts = arc_points((e.dxf.center.x, e.dxf.center.y), e.dxf.radius, 0, 360 - 1e-12, 16)
        return pts[0], pts[0], pts
    raise ValueError(t)


def sampled_points(e):
    """Points of an entity, arcs sampled densely: what its extents are read from."""
    t = e.dxftype()
    if t == "POINT":
        return [(e.dxf.location.x, e.dxf.location.y)]
    if t == "LINE":
        return [(e.dxf.start.x, e.dxf.start.y), (e.dxf.end.x, e.dxf.end.y)]
    if t == "ARC":
        return arc_points((e.dxf.center.x, e.dxf.center.y), e.dxf.radius,
                          e.dxf.start_angle, e.dxf.end_angle, 20000)
    if t == "CIRCLE":
        return arc_points((e.dxf.center.x, e.dxf.center.y), e.dxf.radius, 0, 360 - 1e-12, 20000)
    if t == "SPLINE":
        return [(p.x, p.y) for p in e.construction_tool().approximate(20000)]
    if t == "LWPOLYLINE":
        return [p for v in e.virtual_entities() for p in sampled_points(v)]
    raise ValueError(t)


def check_extents(doc, msp, summary):
    """$EXTMIN/$EXTMAX are the drawing's own box (a viewer opens there), and the active
    viewport is centred on it and at least as high."""
    pts = [p for e in msp for p in sampled_points(e)]
    lo = (min(p[0] for p in pts), min(p[1] for p in pts))
    hi = (max(p[0] for p in pts), max(p[1] for p in pts))
    got_lo, got_hi = doc.header.get("$EXTMIN"), doc.header.get("$EXTMAX")
    error = max(abs(got_lo[0] - lo[0]), abs(got_lo[1] - lo[1]),
                abs(got_hi[0] - hi[0]), abs(got_hi[1] - hi[1]))
    summary["extents_error_mm"] = error
    # 20,000 points per arc miss an extreme by at most r·(1 − cos(π/20000)) < 1e-6 mm for
    # r < 100 mm.
    if error > 1e-6:
        fail(f"$EXTMIN/$EXTMAX {got_lo[:2]} … {got_hi[:2]} are not the drawing's box "
             f"{lo} … {hi} (off by {error} mm)")
    vport = doc.viewports.get("*Active")[0]
    centre = (vport.dxf.center.x, vport.dxf.center.y)
    if dist(centre, ((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2)) > 1e-6:
        fail(f"the active view is centred at {centre}, not on the drawing")
    if vport.dxf.height < hi[1] - lo[1] or vport.dxf.height * vport.dxf.aspect_ratio < hi[0] - lo[0]:
        fail(f"the active view ({vport.dxf.height} high) does not show the whole drawing")


def check_dxf(project, path, tolerance, tool_radius, groove=None):
    import ezdxf

    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    summary = {"audit_errors": len(auditor.errors), "audit_fixes": len(auditor.fixes)}
    if auditor.errors or auditor.fixes:
        fail(f"ezdxf audit: {len(auditor.errors)} errors, {len(auditor.fixes)} fixes")
    if doc.dxfversion != "AC1015":
        fail(f"version {doc.dxfversion}, not AC1015 (R2000)")
    if doc.header.get("$INSUNITS") != 4:
        fail(f"$INSUNITS {doc.header.get('$INSUNITS')}, not 4 (mm)")

    msp = doc.modelspace()
    check_extents(doc, msp, summary)
    # A grooved cam's contour is its inner flank (closure: groove).
    layer = "FLANK_INNER" if groove else "CONTOUR"
    contour = [e for e in msp if e.dxf.layer == layer]
    summary["contour_entities"] = len(contour)
    summary["types"] = sorted({e.dxftype() for e in contour})
    segments = project["segments"]
    worst_exact = 0.0
    worst_spline = 0.0
    chain = []  # (start, end) of every piece in travel order
    i = 0
    if len(contour) == 1 and contour[0].dxftype() == "LWPOLYLINE":
        summary["polyline"] = True
        return check_polyline(project, contour[0], tolerance, summary)
    for k, seg in enumerate(segments):
        p_start, p_end = ends(seg)
        if seg["type"] in ("arc", "line"):
            if i >= len(contour):
                fail(f"contour[{k}]: no entity left")
                break
            e = contour[i]
            i += 1
            want = {"arc": ("ARC", "CIRCLE"), "line": ("LINE",)}[seg["type"]]
            if e.dxftype() not in want:
                fail(f"contour[{k}]: a {seg['type']} written as {e.dxftype()}")
                continue
            a, b, along = entity_shape(e)
            if e.dxftype() == "CIRCLE":
                # A whole turn on the circle: it starts wherever the profile does, if that
                # point is on it (checked below with the centre and radius).
                c = (e.dxf.center.x, e.dxf.center.y)
                worst_exact = max(worst_exact, abs(dist(p_start, c) - e.dxf.radius))
                a = b = p_start
            # An arc runs counter-clockwise in DXF; the profile may run the other way.
            if dist(a, p_start) + dist(b, p_end) > dist(b, p_start) + dist(a, p_end):
                a, b = b, a
            worst_exact = max(worst_exact, dist(a, p_start), dist(b, p_end))
            if seg["type"] == "arc":
                c = (float(seg["center"][0]), float(seg["center"][1]))
                worst_exact = max(worst_exact, dist((e.dxf.center.x, e.dxf.center.y), c),
                                  abs(e.dxf.radius - float(seg["radius"])))
            for p in along:  # the right part of the circle, not its complement
                worst_exact = max(worst_exact, radial_error(seg, p))
            chain.append((a, b))
        else:
            # A spline: a SPLINE entity, or tangent arcs and lines until its end point.
            if i < len(contour) and contour[i].dxftype() == "SPLINE":
                s = contour[i]
                i += 1
                control = [(p[0], p[1]) for p in s.control_points]
                want = [(float(x), float(y)) for x, y in seg["points"]]
                off = max(dist(p, q) for p, q in zip(control, want))
                worst_exact = max(worst_exact, off)
                if s.dxf.degree != 3 or len(control) != 4:
                    fail(f"contour[{k}]: SPLINE of degree {s.dxf.degree}, "
                         f"{len(control)} control points")
                chain.append((control[0], control[-1]))
                continue
            position = p_start
            pieces = 0
            while i < len(contour) and (pieces == 0 or dist(position, p_end) > 1e-6):
                a, b, along = entity_shape(contour[i])
                if dist(b, position) < dist(a, position):
                    a, b = b, a
                for p in along:
                    worst_spline = max(worst_spline, distance_to_bezier(seg["points"], p))
                chain.append((a, b))
                position = b
                pieces += 1
                i += 1
            if dist(position, p_end) > 1e-6:
                fail(f"contour[{k}]: its arcs end {dist(position, p_end)} mm from its end")
    if i != len(contour):
        fail(f"{len(contour) - i} CONTOUR entities beyond the last segment")
    summary["worst_exact_mm"] = worst_exact
    summary["worst_spline_mm"] = worst_spline
    if worst_exact > 1e-9:
        fail(f"an arc or line is {worst_exact} mm from the exact profile (limit 1e-9)")
    if worst_spline > tolerance:
        fail(f"a spline's arcs are {worst_spline} mm from it (tolerance {tolerance})")
    gaps = [dist(chain[j][1], chain[(j + 1) % len(chain)][0]) for j in range(len(chain))]
    summary["worst_gap_mm"] = max(gaps) if gaps else None
    if gaps and max(gaps) > 1e-6:
        fail(f"the chain does not close: a gap of {max(gaps)} mm")

    centres = [(e.dxf.location.x, e.dxf.location.y) for e in msp if e.dxf.layer == "CENTRES"]
    arc_centres = [(float(s["center"][0]), float(s["center"][1]))
                   for s in segments if s["type"] == "arc"]
    if centres:
        summary["centres"] = len(centres)
        if len(centres) != len(arc_centres) or any(
                dist(p, q) > 1e-9 for p, q in zip(centres, arc_centres)):
            fail("CENTRES are not the arcs' centres")

    toolpath = [e for e in msp if e.dxf.layer == "TOOLPATH"]
    summary["toolpath_entities"] = len(toolpath)
    if tool_radius is not None:
        check_toolpath(project, toolpath, tool_radius, summary)
    if groove:
        check_groove(project, msp, groove[0], groove[1], summary)
    return summary


def check_groove(project, msp, roller, clearance, summary):
    """A groove's FLANK_OUTER and PITCH of an arc cam: per profile arc one ARC about the same
    centre, its radius grown (convex arc) or shrunk (concave) by 2*roller + clearance (PITCH:
    by roller), spanning the same angles about the centre - so every point of it lies that far
    from the profile along the profile's normal, to 1e-9 mm. Then, independently of the arcs,
    dense points of both layers against a dense profile (to the sampling's error)."""
    width = 2 * roller + clearance
    segments = project["segments"]
    profile = dense_profile(project)
    for layer, offset in (("FLANK_OUTER", width), ("PITCH", roller)):
        entities = [e for e in msp if e.dxf.layer == layer]
        key = layer.lower()
        summary[key + "_entities"] = len(entities)
        if len(entities) != len(segments):
            fail(f"{layer}: {len(entities)} entities for {len(segments)} segments")
            continue
        worst = 0.0
        for k, (seg, e) in enumerate(zip(segments, entities)):
            if seg["type"] != "arc" or e.dxftype() not in ("ARC", "CIRCLE"):
                fail(f"{layer}: contour[{k}] is not an arc written as an arc")
                continue
            c = (float(seg["center"][0]), float(seg["center"][1]))
            grown = float(seg["radius"]) + (offset if seg["branch"] == "outer" else -offset)
            worst = max(worst, dist((e.dxf.center.x, e.dxf.center.y), c),
                        abs(e.dxf.radius - grown))
            if e.dxftype() == "ARC":
                # Its ends on the normals through the profile arc's ends.
                a, b, _ = entity_shape(e)
                p_start, p_end = ends(seg)
                on_normal = [
                    (c[0] + grown * (p[0] - c[0]) / dist(p, c),
                     c[1] + grown * (p[1] - c[1]) / dist(p, c)) for p in (p_start, p_end)]
                if dist(a, on_normal[0]) + dist(b, on_normal[1]) > \
                        dist(b, on_normal[0]) + dist(a, on_normal[1]):
                    a, b = b, a
                worst = max(worst, dist(a, on_normal[0]), dist(b, on_normal[1]))
        summary["worst_" + key + "_exact_mm"] = worst
        if worst > 1e-9:
            fail(f"{layer}: an arc is {worst} mm from the profile's offset by {offset} mm")
        dense = 0.0
        for e in entities:
            for p in sampled_points(e)[::400]:
                dense = max(dense, abs(min(dist(p, q) for q in profile) - offset))
        summary["worst_" + key + "_dense_mm"] = dense
        if dense > 1e-2:
            fail(f"{layer}: a point is {dense} mm off {offset} mm from the dense profile")


def check_polyline(project, poly, tolerance, summary):
    """A closed LWPOLYLINE: every piece (line or bulge arc) on the profile."""
    import ezdxf.math

    if not poly.closed:
        fail("the LWPOLYLINE is not closed")
    points = list(poly.get_points("xyb"))
    worst = 0.0
    for j, (x, y, bulge) in enumerate(points):
        nx, ny, _ = points[(j + 1) % len(points)]
        a, b = (x, y), (nx, ny)
        if abs(bulge) < 1e-15:
            along = [a, ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2), b]
        else:
            center, start, end, radius = ezdxf.math.bulge_to_arc(a, b, bulge)
            along = arc_points((center.x, center.y), radius, math.degrees(start),
                               math.degrees(end), 16)
        for p in along:
            seg = find_segment(project, p)
            if seg["type"] in ("arc", "line"):
                worst = max(worst, radial_error(seg, p))
            else:
                worst = max(worst, distance_to_bezier(seg["points"], p) - tolerance + 1e-9)
    summary["worst_exact_mm"] = worst
    if worst > 1e-9:
        fail(f"a polyline piece is {worst} mm off the profile")
    return summary


def find_segment(project, p):
    phi = math.atan2(p[1], p[0])
    seg, _ = ref.find_segment(project, mpf(phi))
    return seg


def dense_profile(project, n=20000):
    points = []
    for seg in project["segments"]:
        start, end = float(seg["start"]), float(seg["end"])
        m = max(8, int(n * (end - start) / (2 * math.pi)))
        for i in range(m):
            points.append(exact_point(seg, start + (end - start) * i / m))
    return points


def check_toolpath(project, toolpath, tool_radius, summary):
    """Every tool-path point keeps the tool radius from the profile (to the sampling's error)."""
    profile = dense_profile(project)
    worst = 0.0
    for e in toolpath:
        _, _, along = entity_shape(e)
        for p in along:
            d = min(dist(p, q) for q in profile)
            worst = max(worst, abs(d - tool_radius))
    summary["toolpath_worst_mm"] = worst
    if not toolpath:
        fail("no TOOLPATH entities")
    if worst > 1e-3:
        fail(f"a tool-path point is {worst} mm off the tool radius from the profile")


# ---------------------------------------------------------------------------
# SVG
# ---------------------------------------------------------------------------

def distance_to_arc(seg, p):
    """The exact distance from p to an arc segment of the profile: radial within its span about
    its centre (counter-clockwise for a convex arc, clockwise for a concave one), else its
    nearer end."""
    c = (float(seg["center"][0]), float(seg["center"][1]))
    a, b = ends(seg)
    angle = lambda q: math.atan2(q[1] - c[1], q[0] - c[0])
    ccw = seg["branch"] == "outer"
    span = (angle(b) - angle(a)) if ccw else (angle(a) - angle(b))
    along = (angle(p) - angle(a)) if ccw else (angle(a) - angle(p))
    span %= 2 * math.pi
    if span < 1e-12:
        span = 2 * math.pi
    if along % (2 * math.pi) <= span:
        return abs(dist(p, c) - float(seg["radius"]))
    return min(dist(p, a), dist(p, b))


def check_svg_groove(project, paths, roller, clearance, summary):
    """A groove's outer flank and pitch paths of an arc cam: every point lies 2*roller +
    clearance (roller) from the profile, measured exactly against its arcs."""
    import svgelements

    for name, offset in (("outer-flank", 2 * roller + clearance), ("pitch", roller)):
        found = [q for q in paths if q.get("id") == name]
        if len(found) != 1:
            fail(f"{len(found)} paths with id={name}")
            continue
        worst = 0.0
        for piece in svgelements.Path(found[0].get("d")):
            if isinstance(piece, svgelements.Move):
                continue
            for i in range(9):
                q = piece.point(i / 8)
                point = (q.x, -q.y)
                d = min(distance_to_arc(seg, point) for seg in project["segments"])
                worst = max(worst, abs(d - offset))
        summary["worst_" + name.replace("-", "_") + "_mm"] = worst
        if worst > 1e-6:
            fail(f"{name}: a point is {worst} mm off {offset} mm from the profile")


def check_svg(project, path, tolerance, groove=None):
    import xml.etree.ElementTree as ET

    import svgelements

    root = ET.parse(path).getroot()
    ns = {"svg": "http://www.w3.org/2000/svg"}
    summary = {}
    width, height = root.get("width"), root.get("height")
    if not (width.endswith("mm") and height.endswith("mm")):
        fail(f"width/height not in mm: {width}, {height}")
    view = [float(v) for v in root.get("viewBox").split()]
    if abs(view[2] - float(width[:-2])) > 1e-9 or abs(view[3] - float(height[:-2])) > 1e-9:
        fail("the viewBox is not the width and height in mm (1 user unit = 1 mm)")
    title = root.find("svg:title", ns)
    summary["title"] = title.text if title is not None else None
    profile = [p for p in root.iter("{http://www.w3.org/2000/svg}path") if p.get("id") == "profile"]
    if len(profile) != 1:
        fail(f"{len(profile)} paths with id=profile")
        return summary
    d = profile[0].get("d")
    commands = set(re.findall(r"[A-DF-Za-df-z]", d))  # letters, not a number's exponent
    summary["commands"] = sorted(commands)
    if not commands <= {"M", "L", "A", "Z"} or not d.strip().endswith("Z"):
        fail(f"the profile path uses {sorted(commands)}; only M, L, A and a closing Z")
    parsed = svgelements.Path(d)
    worst = 0.0
    pieces = 0
    for piece in parsed:
        if isinstance(piece, svgelements.Move):
            continue
        pieces += 1
        for i in range(9):
            q = piece.point(i / 8)
            p = (q.x, -q.y)  # SVG's y is ours negated
            seg = find_segment(project, p)
            if seg["type"] in ("arc", "line"):
                worst = max(worst, radial_error(seg, p))
            else:
                worst = max(worst, distance_to_bezier(seg["points"], p))
    summary["pieces"] = pieces
    summary["worst_mm"] = worst
    if worst > max(tolerance, 1e-6):
        fail(f"the path is {worst} mm from the profile (limit {max(tolerance, 1e-6)})")
    if groove:
        check_svg_groove(project, list(root.iter("{http://www.w3.org/2000/svg}path")),
                         groove[0], groove[1], summary)
    return summary


# ---------------------------------------------------------------------------
# Cam table
# ---------------------------------------------------------------------------

def reference_min_r(project):
    """min r over the turn: a scan inside each window, then golden section around the least."""
    best = None
    for seg in project["segments"]:
        start, end = seg["start"], seg["end"]
        n = 200
        # Inside the window only: at its ends a spline's ray may graze the curve, and the
        # neighbouring segment takes that value anyway.
        at = [start + (end - start) * (i + mpf("0.5")) / (n + 1) for i in range(n + 1)]
        values = [(seg["r"](phi), i) for i, phi in enumerate(at)]
        _, i = min(values)
        lo = at[max(0, i - 1)]
        hi = at[min(n, i + 1)]
        g = (mpf(5).sqrt() - 1) / 2
        for _ in range(120):
            a, b = hi - g * (hi - lo), lo + g * (hi - lo)
            if seg["r"](a) < seg["r"](b):
                hi = b
            else:
                lo = a
        value = seg["r"]((lo + hi) / 2)
        for edge in (start, end):
            try:
                value = min(value, seg["r"](edge))
            except ref.ReferenceError:
                pass
        best = value if best is None else min(best, value)
    return best


def one_sided_slope(seg, phi):
    """r'(phi) of the segment, from inside its window at the window's ends."""
    h = mpf("1e-12")
    if phi - seg["start"] < h:
        return (seg["r"](phi + h) - seg["r"](phi)) / h
    if seg["end"] - phi < h:
        return (seg["r"](phi) - seg["r"](phi - h)) / h
    return mpmath.diff(seg["r"], phi, 1)


def check_camtable(project, path):
    with open(path, encoding="ascii") as f:
        lines = f.read().splitlines()
    header = {}
    rows = []
    for line in lines:
        if line.startswith("#"):
            if "=" in line:
                key, value = line[1:].strip().split("=", 1)
                header[key] = value
            continue
        if line.startswith("master_deg"):
            if line != "master_deg,position,velocity_per_deg,acceleration_per_deg2":
                fail(f"column header: {line}")
            continue
        rows.append([float(v) for v in line.split(",")])
    n = int(header.get("points", "0"))
    summary = {"points": n, "rows": len(rows), "header": header}
    if header.get("master_start_deg") != "0" or header.get("periodic") != "true" or \
            header.get("slave") != "lift_mm":
        fail(f"header comments: {header}")
    if len(rows) != n:
        fail(f"{len(rows)} rows for points={n}")
    if abs(float(header.get("master_step_deg", "nan")) - 360.0 / n) > 1e-12:
        fail("master_step_deg is not 360/points")
    min_r = reference_min_r(project)
    lifts = []
    worst_position = 0.0
    worst_velocity = 0.0
    velocities = []
    for i, (master, position, velocity, _) in enumerate(rows):
        if abs(master - 360.0 * i / n) > 1e-12:
            fail(f"row {i}: master {master}, not {360.0 * i / n}")
        best = None
        for lift, slope_deg in lift_and_slopes(project, min_r, mpf(360) * i / n):
            error = (abs(position - lift), abs(velocity - slope_deg))
            # Both sides have the same position to the joint's C0 tolerance (1e-6 mm); the
            # velocity tells them apart at a corner.
            if best is None or (error[0] <= 1e-6 and error[1] < best[0][1]):
                best = (error, lift, slope_deg)
        (position_error, velocity_error), lift, slope_deg = best
        lifts.append(lift)
        velocities.append(slope_deg)
        worst_position = max(worst_position, position_error)
        worst_velocity = max(worst_velocity, velocity_error)
    stroke = float(max(lifts) - min(lifts)) if lifts else 0.0
    summary["stroke_mm"] = stroke
    summary["worst_position_rel"] = worst_position / stroke if stroke else None
    summary["worst_velocity_rel"] = worst_velocity / max(map(abs, velocities)) if rows else None
    if stroke and worst_position > 1e-9 * stroke:
        fail(f"a position is {worst_position} mm from the lift (limit 1e-9 of {stroke} mm)")
    if rows and worst_velocity > 1e-7 * max(map(abs, velocities)):
        fail(f"a velocity is {worst_velocity} mm/deg from r'(phi)")
    if min(lifts) < -1e-9 * stroke:
        fail(f"a lift is negative: {float(min(lifts))}")
    return summary


def lift_and_slopes(project, min_r, deg):
    """Every (lift, r' per degree, r'' per degree^2) the profile has at a master angle: one, or
    both sides' within a rounding of a joint."""
    phi = mpmath.radians(mpf(deg))
    try:
        seg, phi_n = ref.find_segment(project, phi)
    except ref.ReferenceError:
        seg, phi_n = ref.find_segment(project, phi + mpf("1e-25"))
    candidates = [(seg, phi_n)]
    segments = project["segments"]
    k = seg["index"]
    if abs(phi_n - seg["start"]) < mpf("1e-12"):
        candidates.append((segments[k - 1], phi_n if k > 0 else phi_n + project["turn"]))
    if abs(phi_n - seg["end"]) < mpf("1e-12"):
        candidates.append((segments[(k + 1) % len(segments)],
                           phi_n if k + 1 < len(segments) else phi_n - project["turn"]))
    per_deg = math.pi / 180
    return [(float(c["r"](at) - min_r), float(one_sided_slope(c, at)) * per_deg)
            for c, at in candidates]


def quintic(x0, x1, k0, k1, x):
    """The fifth-order polynomial through two XYVA knots (position, slope, curvature at both
    ends), evaluated at x: the interpolation of an XYVA cam (CODESYS byType 3)."""
    h = x1 - x0
    t = (x - x0) / h
    # Hermite basis of degree five on [0, 1] for value, first and second derivative.
    h00 = 1 - 10 * t**3 + 15 * t**4 - 6 * t**5
    h10 = t - 6 * t**3 + 8 * t**4 - 3 * t**5
    h20 = 0.5 * t**2 - 1.5 * t**3 + 1.5 * t**4 - 0.5 * t**5
    h01 = 10 * t**3 - 15 * t**4 + 6 * t**5
    h11 = -4 * t**3 + 7 * t**4 - 3 * t**5
    h21 = 0.5 * t**3 - t**4 + 0.5 * t**5
    return (h00 * k0[1] + h * h10 * k0[2] + h * h * h20 * k0[3] +
            h01 * k1[1] + h * h11 * k1[2] + h * h * h21 * k1[3])


def check_codesys(project, path):
    text = open(path, encoding="ascii").read()
    knots = [tuple(float(v) for v in m) for m in re.findall(
        r"\(dX := ([^,]+), dY := ([^,]+), dV := ([^,]+), dA := ([^)]+)\)", text)]
    declared = re.search(r"ARRAY\[0\.\.(\d+)\] OF SMC_CAMXYVA", text)
    ref_block = re.search(r"(\w+) : MC_CAM_REF := \(([^;]*)\);", text, re.S)
    summary = {"knots": len(knots)}
    if not declared or int(declared.group(1)) + 1 != len(knots):
        fail("ARRAY[0..n] does not declare the knots written")
    if not ref_block:
        fail("no MC_CAM_REF")
        return summary
    fields = dict(re.findall(r"(\w+) := ([^,\n)]+\)?)", ref_block.group(2)))
    summary["cam_ref"] = fields
    want = {"byType": "3", "byVarType": "6", "nElements": str(len(knots)), "xStart": "0.0",
            "xEnd": "360.0"}
    for key, value in want.items():
        if fields.get(key) != value:
            fail(f"MC_CAM_REF {key} is {fields.get(key)}, not {value}")
    if "pce" not in fields or not fields["pce"].startswith("ADR("):
        fail("MC_CAM_REF.pce is not ADR(the knots)")
    for literal in re.findall(r"d[XYVA] := ([^,)]+)", text):
        if "." not in literal:
            fail(f"{literal} is not an LREAL literal (no decimal point)")
            break
    min_r = reference_min_r(project)
    lifts = [min(lift_and_slopes(project, min_r, k[0]), key=lambda c: abs(c[0] - k[1]))
             for k in knots]
    stroke = max(l for l, _ in lifts) - min(l for l, _ in lifts)
    worst = max(abs(k[1] - l[0]) for k, l in zip(knots, lifts))
    summary["worst_knot_rel"] = worst / stroke
    if worst > 1e-9 * stroke:
        fail(f"a knot is {worst} mm from the lift")
    if knots[-1][0] != 360.0 or knots[-1][1:] != knots[0][1:]:
        fail("the last knot is not the first at 360 deg")
    # Between knots the drive follows the quintic: it must follow the profile, which it does
    # only if dV and dA are per master degree.
    # Where a joint lies in the interval (the curvature jumps there) no quintic can follow;
    # elsewhere it must, to the interpolation's own error: at most 8e-6 of the stroke on the
    # test cams at 1 degree (the tight notch of notch-flat), where slopes per radian instead of
    # per degree would be off by a good part of the stroke.
    joints = [float(mpmath.degrees(seg["start"])) % 360.0 for seg in project["segments"]]
    worst_mid = worst_smooth = 0.0
    for k0, k1 in zip(knots, knots[1:]):
        x = (k0[0] + k1[0]) / 2
        exact = lift_and_slopes(project, min_r, x)[0][0]
        error = abs(quintic(k0[0], k1[0], k0, k1, x) - exact)
        worst_mid = max(worst_mid, error)
        if not any(k0[0] - 1e-9 <= j <= k1[0] + 1e-9 or k0[0] - 1e-9 <= j + 360 <= k1[0] + 1e-9
                   for j in joints):
            worst_smooth = max(worst_smooth, error)
    summary["worst_midpoint_rel"] = worst_mid / stroke
    summary["worst_smooth_midpoint_rel"] = worst_smooth / stroke
    if worst_smooth > 1e-4 * stroke:
        fail(f"between knots away from joints the quintic is {worst_smooth} mm off the lift")
    return summary


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("kind", choices=["dxf", "svg", "camtable", "codesys"])
    parser.add_argument("project")
    parser.add_argument("file")
    parser.add_argument("--tolerance", type=float, default=0.001)
    parser.add_argument("--tool-radius", type=float)
    parser.add_argument("--groove", type=float, nargs=2, metavar=("ROLLER", "CLEARANCE"))
    args = parser.parse_args()
    project = ref.load_project(args.project)
    if args.kind == "dxf":
        summary = check_dxf(project, args.file, args.tolerance, args.tool_radius, args.groove)
    elif args.kind == "svg":
        summary = check_svg(project, args.file, args.tolerance, args.groove)
    elif args.kind == "codesys":
        summary = check_codesys(project, args.file)
    else:
        summary = check_camtable(project, args.file)
    summary["problems"] = problems
    print(json.dumps(summary, default=str))
    for p in problems:
        print(p, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
