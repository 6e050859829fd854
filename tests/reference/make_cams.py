#!/usr/bin/python3
"""Construct the reference cams in tests/data/reference/*.cam.json.

Every window boundary is the polar angle of the true joint point of the two
neighbouring curves, solved in 50-digit arithmetic and written with 17
significant digits, so that the contour is C0 well inside 1e-6 mm. Run
check_joints.py afterwards to verify.

Usage: /usr/bin/python3 make_cams.py [OUTPUT_DIR]
"""

import os
import sys

import mpmath
from mpmath import mp, mpf

mp.dps = 50

PI = mpmath.pi
HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_OUT = os.path.join(HERE, "..", "data", "reference")


# ---------------------------------------------------------------------------
# Plane geometry (mm, radians)
# ---------------------------------------------------------------------------

def polar(radius, angle):
    return (radius * mpmath.cos(angle), radius * mpmath.sin(angle))


def add(p, q):
    return (p[0] + q[0], p[1] + q[1])


def sub(p, q):
    return (p[0] - q[0], p[1] - q[1])


def scale(k, p):
    return (k * p[0], k * p[1])


def norm(p):
    return mpmath.hypot(p[0], p[1])


def unit(p):
    return scale(1 / norm(p), p)


def right_normal(p):
    """p turned by -90 degrees (outward normal of a counter-clockwise edge)."""
    return (p[1], -p[0])


def angle_of(p):
    return mpmath.atan2(p[1], p[0])


def ray_hits_circle(center, radius, angle, branch):
    """Point where the ray at `angle` meets the circle on the given branch."""
    u = polar(1, angle)
    mu = center[0] * u[0] + center[1] * u[1]
    disc = mu * mu - norm(center) ** 2 + radius ** 2
    r = mu + (1 if branch == "outer" else -1) * mpmath.sqrt(disc)
    return scale(r, u)


def circle_circle(c0, r0, c1, r1):
    """The two intersection points, left then right of the line c0 -> c1."""
    d = norm(sub(c1, c0))
    along = (d * d + r0 * r0 - r1 * r1) / (2 * d)
    across = mpmath.sqrt(r0 * r0 - along * along)
    e = unit(sub(c1, c0))
    foot = add(c0, scale(along, e))
    left = (-e[1], e[0])
    return add(foot, scale(across, left)), sub(foot, scale(across, left))


def tangent_point_external(c_convex, r_convex, c_concave, r_concave):
    """Touching point of two externally tangent circles."""
    assert abs(norm(sub(c_concave, c_convex)) - r_convex - r_concave) < mpf("1e-40")
    return add(c_convex, scale(r_convex, unit(sub(c_concave, c_convex))))


def common_outer_tangents(c0, r0, c1, r1):
    """Outer common tangents of two circles; returns [(t0, t1), (t0, t1)]:
    first the line with both circles on its left when walking c0 -> c1
    (right-hand side of the contour), then the other one."""
    d = sub(c1, c0)
    e = unit(d)
    cos_a = (r0 - r1) / norm(d)
    sin_a = mpmath.sqrt(1 - cos_a ** 2)
    result = []
    for side in (-1, 1):
        n = (e[0] * cos_a - side * e[1] * sin_a, e[1] * cos_a + side * e[0] * sin_a)
        result.append((add(c0, scale(r0, n)), add(c1, scale(r1, n))))
    return result


def unwrap_after(angle, previous):
    """angle + k*2pi, the smallest such value > previous."""
    while angle <= previous:
        angle += 2 * PI
    while angle - 2 * PI > previous:
        angle -= 2 * PI
    return angle


# ---------------------------------------------------------------------------
# Writing project files
# ---------------------------------------------------------------------------

def number(x):
    if isinstance(x, str):
        return x
    x = mpf(x)
    if abs(x) < mpf("1e-30"):
        return "0.0"
    return mpmath.nstr(x, 17)


def point(p, length_scale):
    return f"[{number(p[0] / length_scale)}, {number(p[1] / length_scale)}]"


def write_cam(out_dir, file_name, name, length_unit, angle_unit, motion, segments):
    """segments: dicts with type, geometry in mm, and window start/end in rad
    (or a str literal in the file's angle unit, for clean values like -30)."""
    length_scale = mpf(1000) if length_unit == "m" else mpf(1)

    def angle(a):
        if isinstance(a, str):
            return a
        return number(mpmath.degrees(a) if angle_unit == "deg" else a)

    motion_key, motion_value = motion
    items = []
    for seg in segments:
        if seg["type"] == "arc":
            fields = [
                '"type": "arc"',
                f'"center": {point(seg["center"], length_scale)}',
                f'"radius": {number(seg["radius"] / length_scale)}',
                f'"branch": "{seg["branch"]}"',
            ]
        else:
            fields = [
                '"type": "line"',
                f'"from": {point(seg["from"], length_scale)}',
                f'"to": {point(seg["to"], length_scale)}',
            ]
        fields += [f'"phi_start": {angle(seg["start"])}', f'"phi_end": {angle(seg["end"])}']
        items.append("    {\n      " + ",\n      ".join(fields) + "\n    }")

    # Window boundaries shared by neighbours must be the same literal.
    for a, b in zip(segments, segments[1:]):
        assert angle(a["end"]) == angle(b["start"]), (file_name, a, b)

    text = (
        "{\n"
        '  "format": "camwright",\n'
        '  "version": 1,\n'
        f'  "name": "{name}",\n'
        f'  "units": {{ "length": "{length_unit}", "angle": "{angle_unit}" }},\n'
        f'  "motion": {{ "{motion_key}": {motion_value} }},\n'
        '  "contour": [\n' + ",\n".join(items) + "\n  ]\n"
        "}\n"
    )
    path = os.path.join(out_dir, file_name)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    print("wrote", os.path.normpath(path))


def arc(center, radius, branch, start, end):
    return {"type": "arc", "center": center, "radius": radius, "branch": branch,
            "start": start, "end": end}


def line(p_from, p_to, start, end):
    return {"type": "line", "from": p_from, "to": p_to, "start": start, "end": end}


def deg(x):
    return mpmath.radians(mpf(x))


# ---------------------------------------------------------------------------
# The cams
# ---------------------------------------------------------------------------

def d_flat(out_dir):
    """D-shaped cam: eccentric circle with a flat chord from -40 deg to 40 deg.
    The first window starts at a negative angle."""
    c, radius = (mpf(3), mpf(2)), mpf(30)
    p_start = ray_hits_circle(c, radius, deg(-40), "outer")
    p_end = ray_hits_circle(c, radius, deg(40), "outer")
    write_cam(out_dir, "d-flat.cam.json", "D cam: eccentric circle with a flat",
              "mm", "deg", ("omega_rad_s", "12.5"), [
                  line(p_start, p_end, "-40.0", "40.0"),
                  arc(c, radius, "outer", "40.0", "320.0"),
              ])


def eccentric_split(out_dir):
    """One eccentric circle split into three outer arcs; lengths in metres."""
    c, radius = (mpf(6), mpf(-4)), mpf(25)
    write_cam(out_dir, "eccentric-split.cam.json", "Eccentric circle in three arcs (metres)",
              "m", "deg", ("rpm", "300"), [
                  arc(c, radius, "outer", "0.0", "137.5"),
                  arc(c, radius, "outer", "137.5", "251.25"),
                  arc(c, radius, "outer", "251.25", "360.0"),
              ])


def five_lobe(out_dir):
    """Five convex lobes (outer arcs) tangent to five concave notches (inner
    arcs), like the six-lobe example with other numbers. The contour starts
    at -30 deg, inside the lobe centred at -36 deg. Turns clockwise."""
    d_lobe, r_lobe, d_notch = mpf(16), mpf(11), mpf(30)
    lobe = [polar(d_lobe, deg(36 + 72 * k)) for k in range(-1, 4)]   # -36 .. 252
    lobe.append(lobe[0])                                             # 324 = -36
    notch = [polar(d_notch, deg(72 * k)) for k in range(0, 5)]       # 0 .. 288
    r_notch = norm(sub(notch[0], lobe[1])) - r_lobe

    segments = []
    previous = deg(-30)
    start = "-30.0"
    # Walk: lobe[-36], notch[0], lobe[36], notch[72], ..., notch[288], lobe[324].
    for k in range(5):
        left_lobe, this_notch, right_lobe = lobe[k], notch[k], lobe[k + 1]
        t_in = unwrap_after(angle_of(tangent_point_external(left_lobe, r_lobe, this_notch, r_notch)), previous)
        t_out = unwrap_after(angle_of(tangent_point_external(right_lobe, r_lobe, this_notch, r_notch)), t_in)
        segments.append(arc(left_lobe, r_lobe, "outer", start, t_in))
        segments.append(arc(this_notch, r_notch, "inner", t_in, t_out))
        start, previous = t_out, t_out
    segments.append(arc(lobe[5], r_lobe, "outer", start, "330.0"))
    write_cam(out_dir, "five-lobe.cam.json", "Five-lobe arc cam, clockwise",
              "mm", "deg", ("rpm", "-240"), segments)


def pear_tangent(out_dir):
    """Classic tangent cam: base circle, nose circle, two tangent flanks.
    Angles in radians."""
    c_base, r_base = (mpf(1), mpf("-0.5")), mpf(20)
    c_nose, r_nose = (mpf(4), mpf(26)), mpf(7)
    (base_right, nose_right), (base_left, nose_left) = common_outer_tangents(
        c_base, r_base, c_nose, r_nose)
    a1 = angle_of(base_right)
    a2 = unwrap_after(angle_of(nose_right), a1)
    a3 = unwrap_after(angle_of(nose_left), a2)
    a4 = unwrap_after(angle_of(base_left), a3)
    assert 0 < a1 < a2 < a3 < a4 < 2 * PI
    write_cam(out_dir, "pear-tangent.cam.json", "Tangent cam: base circle, flanks, nose (radians)",
              "mm", "rad", ("period_s", "0.25"), [
                  arc(c_base, r_base, "outer", "0.0", a1),
                  line(base_right, nose_right, a1, a2),
                  arc(c_nose, r_nose, "outer", a2, a3),
                  line(nose_left, base_left, a3, a4),
                  arc(c_base, r_base, "outer", a4, 2 * PI),
              ])


def notch_flat(out_dir):
    """Eccentric base circle with a concave notch (inner arc of a second
    circle, meeting the base circle at sharp corners) and a flat chord.
    Metres and radians; turns clockwise (negative omega)."""
    c_base, r_base = (mpf(2), mpf("1.5")), mpf(28)
    c_notch, r_notch = (mpf(-3), mpf(34)), mpf(9)
    corners = sorted(circle_circle(c_base, r_base, c_notch, r_notch), key=angle_of)
    a1, a2 = angle_of(corners[0]), angle_of(corners[1])
    a3, a4 = deg(200), deg(250)
    flat_from = ray_hits_circle(c_base, r_base, a3, "outer")
    flat_to = ray_hits_circle(c_base, r_base, a4, "outer")
    assert 0 < a1 < a2 < a3 < a4 < 2 * PI
    write_cam(out_dir, "notch-flat.cam.json", "Base circle with a notch and a flat (metres, radians)",
              "m", "rad", ("omega_rad_s", "-8"), [
                  arc(c_base, r_base, "outer", "0.0", a1),
                  arc(c_notch, r_notch, "inner", a1, a2),
                  arc(c_base, r_base, "outer", a2, a3),
                  line(flat_from, flat_to, a3, a4),
                  arc(c_base, r_base, "outer", a4, 2 * PI),
              ])


def rounded_triangle(out_dir):
    """Triangle with corners rounded by outer arcs of radius 6, origin off
    centre. The first window starts at 10 deg (inside the first fillet), so
    the last window ends at 370 deg."""
    corners = [(mpf(22), mpf(3)), (mpf(-9), mpf(17)), (mpf(-8), mpf(-19))]
    rho = mpf(6)
    # Tangent points of edge k (corner k -> corner k+1), offset outwards.
    edges = []
    for k in range(3):
        q0, q1 = corners[k], corners[(k + 1) % 3]
        n = unit(right_normal(sub(q1, q0)))
        edges.append((add(q0, scale(rho, n)), add(q1, scale(rho, n))))

    segments = []
    start, previous = "10.0", deg(10)
    for k in range(3):
        edge_from, edge_to = edges[k]
        a_from = unwrap_after(angle_of(edge_from), previous)
        a_to = unwrap_after(angle_of(edge_to), a_from)
        segments.append(arc(corners[k], rho, "outer", start, a_from))
        segments.append(line(edge_from, edge_to, a_from, a_to))
        start, previous = a_to, a_to
    segments.append(arc(corners[0], rho, "outer", start, "370.0"))
    write_cam(out_dir, "rounded-triangle.cam.json", "Rounded triangle, windows 10 .. 370 deg",
              "mm", "deg", ("period_s", "0.04"), segments)


def main():
    out_dir = sys.argv[1] if len(sys.argv) > 1 else DEFAULT_OUT
    os.makedirs(out_dir, exist_ok=True)
    for make in (d_flat, eccentric_split, five_lobe, pear_tangent, notch_flat, rounded_triangle):
        make(out_dir)


if __name__ == "__main__":
    main()
