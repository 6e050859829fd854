#!/usr/bin/python3
"""Independent reference check of the invalid-project corpus (no C++ needed).

Runs a from-scratch Python reading of project-format.md / math.md §1, §8, §9 over
every file listed in cases.json and over the valid controls, and checks that
  * the valid controls produce no problem at all,
  * every case reports its manifest location (exactly, as a location),
  * files meant to be syntactically broken fail strict JSON parsing and all
    others parse with Python's json module.
Problems other than the intended one are listed as consequences (a validator
may report or suppress them). Usage: /usr/bin/python3 check_corpus.py [-v]
"""
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
MAX_LEN = 1e6
JOINT_TOL = 1e-6
WINDOW_TOL = 1e-9
DEPTH_LIMIT = 512
DUP = "\x00duplicates"


class Problems(list):
    def add(self, location, message):
        self.append((location, message))


# ------------------------------------------------------------------ parsing
def pairs_hook(pairs):
    d, dups = {}, []
    for k, v in pairs:
        if k in d:
            dups.append(k)
        d[k] = v
    if dups:
        d[DUP] = dups
    return d


def bad_constant(name):
    raise ValueError(f"{name} is not JSON")


def max_depth(text):
    depth = best = 0
    in_str = esc = False
    for ch in text:
        if in_str:
            if esc:
                esc = False
            elif ch == "\\":
                esc = True
            elif ch == '"':
                in_str = False
        elif ch == '"':
            in_str = True
        elif ch in "[{":
            depth += 1
            best = max(best, depth)
        elif ch in "]}":
            depth -= 1
    return best


def parse(raw, probs):
    """Strict parse. Returns the document or None (problems added)."""
    text = raw.decode("utf-8")
    if text.startswith("\ufeff"):
        text = text[1:]  # a UTF-8 BOM is valid
    underflow = []

    def parse_float(s):
        v = float(s)
        if not math.isfinite(v):
            raise ValueError(f"number {s} overflows a double")
        if v == 0.0 and any(c in "123456789" for c in s.split("e")[0].split("E")[0]):
            underflow.append(s)
        return v

    old = sys.getrecursionlimit()
    sys.setrecursionlimit(max(old, 100000))
    try:
        doc = json.loads(text, object_pairs_hook=pairs_hook, parse_constant=bad_constant,
                         parse_float=parse_float)
    except json.JSONDecodeError as e:
        probs.add(f"line {e.lineno}, column {e.colno}", e.msg)
        return None
    except ValueError as e:
        probs.add("line ?, column ?", str(e))
        return None
    finally:
        sys.setrecursionlimit(old)
    if max_depth(text) > DEPTH_LIMIT:
        # report the top-level key that holds the deep value
        for k, v in doc.items() if isinstance(doc, dict) else []:
            if max_depth(json.dumps(v)) > DEPTH_LIMIT - 1:
                probs.add(k, f"nested deeper than {DEPTH_LIMIT} levels")
        return None
    if underflow:
        probs.add("(underflow)", f"{underflow} underflow to 0")  # informative only
    return doc


def find_dups(v, path, probs):
    if isinstance(v, dict):
        for k in v.get(DUP, []):
            probs.add(f"{path}.{k}" if path else k, "duplicated key")
        for k, x in v.items():
            if k != DUP:
                find_dups(x, f"{path}.{k}" if path else k, probs)
    elif isinstance(v, list):
        for i, x in enumerate(v):
            find_dups(x, f"{path}[{i}]", probs)


# ------------------------------------------------------------------ typed access
def is_num(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def number(o, key, loc, probs, required=True):
    if key not in o:
        if required:
            probs.add(loc, "missing")
        return None
    v = o[key]
    if not is_num(v):
        probs.add(loc, f"must be a number (got {json.dumps(v)})")
        return None
    if not math.isfinite(v):
        probs.add(loc, "must be finite")
        return None
    return float(v)


def length(o, key, loc, probs, required=True):
    v = number(o, key, loc, probs, required)
    if v is not None and abs(v) > MAX_LEN:
        probs.add(loc, f"magnitude must be at most 1e6 mm (got {v})")
        return None
    return v


def point(o, key, loc, probs):
    if key not in o:
        probs.add(loc, "missing")
        return None
    v = o[key]
    if not isinstance(v, list) or len(v) != 2:
        probs.add(loc, f"must be [x, y] (got {json.dumps(v)})")
        return None
    x = length({"x": v[0]}, "x", f"{loc}", probs)
    y = length({"y": v[1]}, "y", f"{loc}", probs)
    return None if x is None or y is None else (x, y)


def string(o, key, loc, probs, allowed, required=True):
    if key not in o:
        if required:
            probs.add(loc, "missing")
        return None
    v = o[key]
    if not isinstance(v, str):
        probs.add(loc, f"must be a string (got {json.dumps(v)})")
        return None
    if v not in allowed:
        probs.add(loc, f"must be one of {allowed} (got {v!r})")
        return None
    return v


# ------------------------------------------------------------------ geometry (math.md §1)
def arc_r(seg, phi):
    (cx, cy), R, s = seg["c"], seg["R"], 1.0 if seg["branch"] == "outer" else -1.0
    ux, uy = math.cos(phi), math.sin(phi)
    mu = cx * ux + cy * uy
    D = mu * mu - (cx * cx + cy * cy) + R * R
    if D < 0:
        return None, D
    return mu + s * math.sqrt(D), D


def line_r(seg, phi):
    (ax, ay), (bx, by) = seg["from"], seg["to"]
    L = math.hypot(bx - ax, by - ay)
    nx, ny = -(by - ay) / L, (bx - ax) / L
    d = nx * ax + ny * ay
    c = nx * math.cos(phi) + ny * math.sin(phi)
    return (d / c if c != 0 else None), d


def r_at(seg, phi_deg):
    phi = math.radians(phi_deg)
    return (arc_r if seg["type"] == "arc" else line_r)(seg, phi)[0]


def check_conjugate(doc, f, probs):
    """A conjugate yoke's second roller must stand beyond the cam centre at every angle: D less
    the first roller's s(phi) (found by brute force over the contour's points: the largest
    u.p + sqrt(rho^2 - (e - n.p)^2) of the points within rho of the line) exceeds its radius."""
    try:
        rho, e = f["radius"], f.get("offset", 0.0)
        dist, rho2 = f["conjugate_distance_mm"], f["conjugate_radius_mm"]
        points = []
        for seg in doc["contour"]:
            arc = {"type": "arc", "c": seg["center"], "R": seg["radius"],
                   "branch": seg.get("branch", "outer")}
            for i in range(721):
                phi = seg["phi_start"] + (seg["phi_end"] - seg["phi_start"]) * i / 720
                r = r_at(arc, phi)
                points.append((r * math.cos(math.radians(phi)), r * math.sin(math.radians(phi))))
    except (KeyError, TypeError, ValueError):
        return
    for k in range(360):
        phi = math.radians(k)
        u, n = (math.cos(phi), math.sin(phi)), (-math.sin(phi), math.cos(phi))
        s = max((u[0] * x + u[1] * y + math.sqrt(rho * rho - (e - n[0] * x - n[1] * y) ** 2)
                 for x, y in points if abs(e - n[0] * x - n[1] * y) <= rho), default=None)
        if s is not None and not dist - s > rho2:
            probs.add("follower.conjugate_distance_mm",
                      f"the second roller stands {dist - s:.6g} mm beyond the centre at {k} deg")
            return


def check_segment_geometry(k, seg, probs, n=20000):
    at = f"contour[{k}]"
    a, b = seg["a"], seg["b"]
    if seg["type"] == "line":
        _, d = line_r(seg, 0.0)
        if abs(d) <= JOINT_TOL:
            probs.add(at, "the line passes through the rotation centre")
            return
        pa = math.degrees(math.atan2(seg["from"][1], seg["from"][0]))
        pb = math.degrees(math.atan2(seg["to"][1], seg["to"][0]))
        wrap = lambda x: (x + 180.0) % 360.0 - 180.0
        if abs(wrap(a - pa)) > 1e-9 or abs(wrap(b - pb)) > 1e-9:
            probs.add(at, f"window {a}..{b} disagrees with polar angles of from/to {pa}..{pb}")
    miss = neg = 0
    for i in range(n + 1):
        phi = a + (b - a) * i / n
        if seg["type"] == "arc":
            r, D = arc_r(seg, math.radians(phi))
            if D < 0:
                miss += 1
                continue
        else:
            r, _ = line_r(seg, math.radians(phi))
        if r is None or r <= 0:
            neg += 1
    if seg["type"] == "arc" and seg["branch"] == "inner" and \
            math.hypot(*seg["c"]) < seg["R"] and neg:
        probs.add(f"{at}.branch", f"inner branch but the origin is inside the circle "
                                  f"(r <= 0 at {neg}/{n + 1} sample angles)")
    elif neg:
        probs.add(at, f"r <= 0 at {neg}/{n + 1} sample angles")
    if miss:
        probs.add(at, f"the ray misses the circle (D < 0) at {miss}/{n + 1} sample angles")


# ------------------------------------------------------------------ the whole project
def validate(doc, probs):
    if not isinstance(doc, dict):
        probs.add("top level", f"must be an object (got {type(doc).__name__})")
        return
    find_dups(doc, "", probs)
    string(doc, "format", "format", probs, ["camwright"])
    v = doc.get("version")
    if "version" not in doc:
        probs.add("version", "missing")
    elif not (isinstance(v, int) and not isinstance(v, bool)):
        probs.add("version", f"must be an integer (got {json.dumps(v)})")
    elif v != 1:
        probs.add("version", f"version {v} is not known (this reader knows 1)")
    units = doc.get("units", {})
    if not isinstance(units, dict):
        probs.add("units", "must be an object")
        units = {}
    string(units, "length", "units.length", probs, ["mm", "m"], required=False)
    string(units, "angle", "units.angle", probs, ["deg", "rad"], required=False)

    m = doc.get("motion")
    if not isinstance(m, dict):
        probs.add("motion", "missing or not an object")
    else:
        keys = [k for k in ("omega_rad_s", "rpm", "period_s") if k in m]
        if len(keys) != 1:
            probs.add("motion", f"exactly one of omega_rad_s, rpm, period_s (got {keys})")
        for k in keys:
            x = number(m, k, f"motion.{k}", probs)
            if x is None:
                continue
            if k == "period_s" and not x > 0:
                probs.add("motion.period_s", f"must be > 0 (got {x})")
            if k != "period_s" and x == 0:
                probs.add(f"motion.{k}", "must not be 0")

    c = doc.get("contour")
    segs = []
    # A design whose contour was never synthesised is valid with an empty contour.
    if not isinstance(c, list) or (not c and not isinstance(doc.get("design"), dict)):
        probs.add("contour", "missing, not an array or empty")
        c = []
    for k, s in enumerate(c):
        at = f"contour[{k}]"
        if not isinstance(s, dict):
            probs.add(at, "must be an object")
            segs.append(None)
            continue
        t = string(s, "type", f"{at}.type", probs, ["arc", "line", "bezier", "hermite"])
        seg = {"type": t}
        seg["a"] = number(s, "phi_start", f"{at}.phi_start", probs)
        seg["b"] = number(s, "phi_end", f"{at}.phi_end", probs)
        ok = seg["a"] is not None and seg["b"] is not None
        if ok and not seg["b"] > seg["a"]:
            probs.add(f"{at}.phi_end", f"must be > phi_start (got {seg['a']}..{seg['b']})")
            ok = False
        seg["window_ok"] = ok
        if t == "arc":
            seg["c"] = point(s, "center", f"{at}.center", probs)
            seg["R"] = length(s, "radius", f"{at}.radius", probs)
            if seg["R"] is not None and not seg["R"] > 0:
                probs.add(f"{at}.radius", f"must be > 0 (got {seg['R']})")
            seg["branch"] = string(s, "branch", f"{at}.branch", probs, ["outer", "inner"])
            shape_ok = None not in (seg["c"], seg["R"], seg["branch"])
        elif t == "line":
            seg["from"] = point(s, "from", f"{at}.from", probs)
            seg["to"] = point(s, "to", f"{at}.to", probs)
            shape_ok = None not in (seg["from"], seg["to"])
        else:
            shape_ok = False
        if shape_ok and ok:
            check_segment_geometry(k, seg, probs)
        seg["ok"] = shape_ok and ok
        segs.append(seg)

    if segs and all(s is not None and s["window_ok"] for s in segs):
        for k in range(len(segs) - 1):
            diff = segs[k + 1]["a"] - segs[k]["b"]
            if abs(diff) > WINDOW_TOL:
                probs.add(f"contour[{k}]/contour[{k + 1}]",
                          f"{'gap' if diff > 0 else 'overlap'} of {abs(diff)}°")
        span = segs[-1]["b"] - segs[0]["a"]
        if abs(span - 360.0) > WINDOW_TOL:
            probs.add("contour", f"windows cover {span}°, not 360°")
    if segs and all(s is not None and s["ok"] for s in segs):
        n = len(segs)
        for k in range(n):
            j = (k + 1) % n
            pk, pj = segs[k]["b"], segs[j]["a"]
            rk, rj = r_at(segs[k], pk), r_at(segs[j], pj)
            if rk is None or rj is None:
                probs.add(f"contour[{k}]/contour[{j}]", "joint point undefined")
                continue
            xk = (rk * math.cos(math.radians(pk)), rk * math.sin(math.radians(pk)))
            xj = (rj * math.cos(math.radians(pj)), rj * math.sin(math.radians(pj)))
            gap = math.dist(xk, xj)
            if gap > JOINT_TOL:
                probs.add(f"contour[{k}]/contour[{j}]", f"C0 gap {gap:.12g} mm at {pk}°")

    f = doc.get("follower")
    if f is not None:
        t = string(f, "type", "follower.type", probs, ["knife", "roller", "flat"], required=False)
        motion = string(f, "motion", "follower.motion", probs, ["translating", "oscillating"],
                        required=False)
        length(f, "offset", "follower.offset", probs, required=False)
        if "max_pressure_angle_deg" in f:
            a = number(f, "max_pressure_angle_deg", "follower.max_pressure_angle_deg", probs)
            if a is not None and not 0 < a <= 89:
                probs.add("follower.max_pressure_angle_deg", f"must be in (0, 89] (got {a})")
        if motion == "oscillating":
            if t == "flat":
                probs.add("follower.type", "a flat face only translates")
            point(f, "pivot", "follower.pivot", probs)
            arm = length(f, "arm_length", "follower.arm_length", probs)
            if arm is not None and not arm > 0:
                probs.add("follower.arm_length", f"must be > 0 (got {arm})")
        if t == "roller":
            r = length(f, "radius", "follower.radius", probs)
            if r is not None and not r > 0:
                probs.add("follower.radius", f"must be > 0 (got {r})")
            # The roller must enter every concave arc: an arc is concave where the contour,
            # running with phi, turns clockwise round the arc's centre (found from two points
            # of its own r(phi) just inside the window).
            for k, seg in enumerate(doc.get("contour") or []):
                if r is None or not isinstance(seg, dict) or seg.get("type") != "arc":
                    continue
                try:
                    p0, p1 = seg["phi_start"], seg["phi_end"]
                    a0, a1 = p0 + 1e-4 * (p1 - p0), p0 + 2e-4 * (p1 - p0)
                    arc = {"type": "arc", "c": seg["center"], "R": seg["radius"],
                           "branch": seg.get("branch", "outer")}
                    ra, rb = r_at(arc, a0), r_at(arc, a1)
                    xa = (ra * math.cos(math.radians(a0)), ra * math.sin(math.radians(a0)))
                    xb = (rb * math.cos(math.radians(a1)), rb * math.sin(math.radians(a1)))
                    c = seg["center"]
                    cross = (xa[0] - c[0]) * (xb[1] - xa[1]) - (xa[1] - c[1]) * (xb[0] - xa[0])
                except (KeyError, TypeError, ValueError, IndexError):
                    continue
                if cross < 0 and r >= seg["radius"]:
                    probs.add("follower.radius",
                              f"not smaller than the concave arc contour[{k}] (R {seg['radius']})")
        if t == "roller" and f.get("closure") == "conjugate":
            check_conjugate(doc, f, probs)
    s = doc.get("sampling")
    if s is not None:
        n = s.get("samples_per_turn")
        if not (isinstance(n, int) and not isinstance(n, bool)):
            probs.add("sampling.samples_per_turn", f"must be an integer (got {json.dumps(n)})")
        elif not 16 <= n <= 10_000_000:
            probs.add("sampling.samples_per_turn", f"must be in 16..10000000 (got {n})")
    mc = doc.get("machining")
    if mc is not None:
        for key in ("axis_accel", "axis_vmax"):
            if key in mc:
                for i, x in enumerate(mc[key]):
                    v = number({"v": x}, "v", f"machining.{key}[{i}]", probs)
                    if v is not None and not v > 0:
                        probs.add(f"machining.{key}[{i}]", f"must be > 0 (got {v})")
        for key in ("feed_max", "step"):
            v = number(mc, key, f"machining.{key}", probs, required=False)
            if v is not None and not v > 0:
                probs.add(f"machining.{key}", f"must be > 0 (got {v})")
        v = length(mc, "tool_radius", "machining.tool_radius", probs, required=False)
        if v is not None and v < 0:
            probs.add("machining.tool_radius", f"must be >= 0 (got {v})")
    if "design" in doc:
        check_design(doc["design"], probs)
    if "dynamics" in doc:
        check_dynamics(doc["dynamics"], doc.get("follower"), probs)


# project-format.md's `dynamics` row and math.md §9. Each key's rule: "pos" > 0, "nonneg" >= 0,
# "any" finite of either sign; every value at most DYN_MAX in magnitude.
DYN_MAX = 1e12
DYN_TRANSLATING = {"mass_kg": "pos", "spring_rate_N_per_mm": "pos", "spring_preload_N": "any",
                   "external_force_N": "any", "damping_Ns_per_m": "nonneg"}
DYN_ARM = {"inertia_kg_m2": "pos", "spring_rate_Nm_per_rad": "pos", "spring_preload_Nm": "any",
           "external_moment_Nm": "any", "damping_Nms_per_rad": "nonneg"}
DYN_CONTACT = {"contact_width_mm": "pos", "allowable_contact_stress_MPa": "pos",
               "spring_safety_factor": "pos"}
DYN_MATERIALS = ("cam_material", "follower_material")


def dyn_number(o, key, loc, rule, probs):
    v = number(o, key, loc, probs)
    if v is None:
        return
    if abs(v) > DYN_MAX:
        probs.add(loc, f"magnitude must be at most {DYN_MAX:g} (got {v:g})")
    elif rule == "pos" and not v > 0:
        probs.add(loc, f"must be > 0 (got {v:g})")
    elif rule == "nonneg" and not v >= 0:
        probs.add(loc, f"must be >= 0 (got {v:g})")


def check_dynamics(d, follower, probs):
    """The follower train and the contact: the translating keys only on a translating follower
    (the default, also with no follower at all), the arm's keys only on an oscillating one;
    materials are {E_MPa, poisson}, both required; nothing else is allowed."""
    if not isinstance(d, dict):
        probs.add("dynamics", "must be an object")
        return
    motion = follower.get("motion", "translating") if isinstance(follower, dict) else "translating"
    for key in d:
        at = f"dynamics.{key}"
        if key in DYN_MATERIALS:
            mat = d[key]
            if not isinstance(mat, dict):
                probs.add(at, f"must be an object {{E_MPa, poisson}} (got {json.dumps(mat)})")
                continue
            for k in mat:
                if k not in ("E_MPa", "poisson"):
                    probs.add(f"{at}.{k}", "unknown key")
            dyn_number(mat, "E_MPa", f"{at}.E_MPa", "pos", probs)
            nu = number(mat, "poisson", f"{at}.poisson", probs)
            if nu is not None and not 0 <= nu < 0.5:
                probs.add(f"{at}.poisson", f"must be in [0, 0.5) (got {nu:g})")
            continue
        rule = DYN_TRANSLATING.get(key) or DYN_ARM.get(key) or DYN_CONTACT.get(key)
        if rule is None:
            probs.add(at, "unknown key")
            continue
        if key in DYN_ARM and motion == "translating":
            probs.add(at, "a swinging arm's key, but the follower translates")
        elif key in DYN_TRANSLATING and motion == "oscillating":
            probs.add(at, "a translating follower's key, but the follower swings on an arm")
        dyn_number(d, key, at, rule, probs)


# The laws of math.md §8 and those docs/cli.md's table adds (issue 33), which the spec does not
# list yet, with the keys each takes besides law, to_deg and lift.
LAW_KEYS = {"dwell": set(), "harmonic": set(), "cycloidal": set(),
            "modified-trapezoid": {"lambda"}, "modified-sine": {"lambda"}, "poly345": set(),
            "poly4567": set(), "poly5": {"v0", "a0", "v1", "a1"}, "line": set(),
            "inclined-sine": {"v0"}, "scca": {"b", "d"},
            "poly7": {"v0", "a0", "j0", "v1", "a1", "j1"}, "table": {"points"}}
LAWS = list(LAW_KEYS)


def check_design(d, probs):
    """project-format.md's `design` row and math.md §8: segments contiguous from 0° to 360°,
    each from the previous lift (0 first) to its own; a dwell keeps it, other laws change it,
    the last returns to 0; only poly5 takes boundary values."""
    if not isinstance(d, dict):
        probs.add("design", "must be an object")
        return
    for key in d:
        if key not in ("base_radius", "segments", "tolerance", "strict_pressure_angle"):
            probs.add(f"design.{key}", "unknown key")
    if "strict_pressure_angle" in d and not isinstance(d["strict_pressure_angle"], bool):
        probs.add("design.strict_pressure_angle", "must be true or false")
    rb = length(d, "base_radius", "design.base_radius", probs)
    if rb is not None and not rb > 0:
        probs.add("design.base_radius", f"must be > 0 (got {rb})")
    if "tolerance" in d:
        tol = length(d, "tolerance", "design.tolerance", probs)
        if tol is not None and not tol > 0:
            probs.add("design.tolerance", f"must be > 0 (got {tol})")
    segs = d.get("segments")
    if not isinstance(segs, list):
        probs.add("design.segments", "missing or not an array")
        return
    if not segs:
        probs.add("design.segments", "must have at least one segment")
        return
    start_deg, start_lift = 0.0, 0.0
    for k, s in enumerate(segs):
        at = f"design.segments[{k}]"
        if not isinstance(s, dict):
            probs.add(at, "must be an object")
            continue
        law = string(s, "law", f"{at}.law", probs, LAWS)
        allowed = {"law", "to_deg", "lift"} | LAW_KEYS.get(law, set())
        for key in s:
            if key not in allowed:
                probs.add(f"{at}.{key}", "unknown key")
        for key in ("v0", "a0", "j0", "v1", "a1", "j1", "lambda", "b", "d"):
            if key in s and key in allowed:
                number(s, key, f"{at}.{key}", probs)
        to = number(s, "to_deg", f"{at}.to_deg", probs)
        lift = number(s, "lift", f"{at}.lift", probs, required=law != "dwell")
        if lift is None and law == "dwell" and "lift" not in s:
            lift = start_lift
        if to is not None and not to > start_deg:
            probs.add(f"{at}.to_deg", f"must be after {start_deg}° (got {to})")
        if lift is not None:
            if law == "dwell" and lift != start_lift:
                probs.add(f"{at}.lift", f"a dwell keeps the lift {start_lift} (got {lift})")
            if law not in (None, "dwell", "poly5", "poly7") and lift == start_lift:
                probs.add(f"{at}.lift", f"{law} must change the lift {start_lift}")
        if to is not None:
            start_deg = to
        if lift is not None:
            start_lift = lift
    last = f"design.segments[{len(segs) - 1}]"
    if start_deg != 360:
        probs.add(f"{last}.to_deg", f"the last segment must end at 360° (got {start_deg})")
    if start_lift != 0:
        probs.add(f"{last}.lift", f"the motion must return to lift 0 (got {start_lift})")


def check_file(path):
    probs = Problems()
    with open(path, "rb") as fh:
        raw = fh.read()
    doc = parse(raw, probs)
    if doc is not None:
        validate(doc, probs)
    return [p for p in probs if p[0] != "(underflow)"], doc is not None or not probs or \
        not probs[0][0].startswith("line ")


def main():
    verbose = "-v" in sys.argv
    failures = 0
    for name in ("valid-base.cam.json", "valid-bom.cam.json", "valid-design.cam.json",
                 "valid-dynamics.cam.json"):
        probs, _ = check_file(os.path.join(HERE, name))
        print(f"{'ok ' if not probs else 'BAD'} {name}: valid control" +
              ("" if not probs else f" -> {probs}"))
        failures += bool(probs)
    with open(os.path.join(HERE, "cases.json"), encoding="utf-8") as fh:
        cases = json.load(fh)
    for case in cases:
        path = os.path.join(HERE, case["file"])
        probs, parsed = check_file(path)
        want = case["location"]
        syntax = want.startswith("line ")
        # Python's json: syntax cases must fail strictly; all others must parse (default module).
        with open(path, "rb") as fh:
            raw = fh.read().decode("utf-8")
        try:
            sys.setrecursionlimit(100000)
            json.loads(raw, parse_constant=bad_constant)
            strict_ok = True
        except ValueError:
            strict_ok = False
        if syntax:
            hit = any(loc.startswith("line ") for loc, _ in probs)
            py_ok = "1e400" in raw or not strict_ok  # 1e400 is grammatical, only overflows
        else:
            hit = any(loc == want for loc, _ in probs)
            py_ok = strict_ok
        others = [p for p in probs if p[0] != want and not (syntax and p[0].startswith("line "))]
        good = hit and py_ok
        failures += not good
        tag = "ok " if good else "BAD"
        print(f"{tag} {case['file']}: expect {want!r}" + ("" if py_ok else " [python json!]"))
        if verbose or not good:
            for loc, msg in probs:
                print(f"      {'*' if loc == want or (syntax and loc.startswith('line ')) else '+'}"
                      f" {loc}: {msg[:150]}")
        elif others:
            print(f"      + consequences: {sorted({p[0] for p in others})}")
    with open(os.path.join(HERE, "cli_cases.json"), encoding="utf-8") as fh:
        cli = json.load(fh)
    for c in cli:
        assert c["exit"] in (1, 2) and isinstance(c["args"], list) and c["stderr_contains"]
        for a in c["args"]:
            if a.startswith("@DATA@/") and a.endswith(".cam.json") and "does-not" not in a:
                assert os.path.exists(os.path.join(HERE, a[len("@DATA@/"):])), a
    print(f"{len(cases)} file cases, {len(cli)} cli cases, {failures} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
