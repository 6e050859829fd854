#!/usr/bin/python3
"""Independent 50-digit reference for a follower placed by contact (math.md §7).

Reads a Camwright project with a `follower` section and prints, for each requested time t, the
follower's s, its time derivatives, the roller centre (or knife tip, or the face on its axis),
the contact point and the pressure angle, as JSON.

Independence from the C++ engine: nothing here offsets arcs or lines or uses a support-function
formula. The profile is the curve p(a) = r(a)·(cos a, sin a) of polar_reference.py (50 digits);
its normal comes from mpmath.diff of p. The follower is placed by its contact condition alone:
  * knife: a profile point on the follower's line (p·n = e); the outermost one;
  * roller: a profile point whose normal, ρ long, ends on the line ((p + ρ·ν)·n = e), or a
    joint point ρ from the line's point; the outermost one; and no profile point nearer the
    centre than ρ (checked over 4000 points per segment);
  * flat face: the profile point with the largest p·u (p'·u = 0 with the outside facing u, or a
    joint point);
  * swinging arm (knife or roller): a profile point whose normal, ρ long, ends L from the
    turned pivot A(φ) (|p + ρ·ν − A(φ)| = L), or a roller centre ρ from a joint and L from the
    pivot; of these the first the arm meets swinging in from its side (the largest angle θ from
    the line pivot → cam centre, measured away from the cam); its angle ψ in the follower frame.
    The pressure angle is taken from its definition: the normal (contact → centre, or the
    profile's at a knife) against the direction the tip moves away from the cam.
The derivatives of s are mpmath.diff of that placement as a function of φ (the contact found
at φ re-solved from its parameter at the nearby angles mpmath.diff asks for).

Usage:
    /usr/bin/python3 follower_reference.py PROJECT.cam.json --t 0.05 --t 0.15
"""

import argparse
import json
import os
import sys

import mpmath
from mpmath import mp, mpf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import polar_reference as pr  # noqa: E402

mp.dps = 50
SCAN = 96  # samples per segment when looking for roots


def point(seg, a):
    r = seg["r"](a)
    return (r * mpmath.cos(a), r * mpmath.sin(a))


def tangent(seg, a):
    """dp/da (the contour runs counter-clockwise with a)."""
    return (mpmath.diff(lambda x: point(seg, x)[0], a), mpmath.diff(lambda x: point(seg, x)[1], a))


def outward(seg, a):
    """The unit normal out of the cam: the tangent turned clockwise."""
    tx, ty = tangent(seg, a)
    length = mpmath.hypot(tx, ty)
    return (ty / length, -tx / length)


def inside(seg, a):
    """a slightly inside the window: the ends belong to the joints."""
    return seg["start"] <= a <= seg["end"]


def roots(f, lo, hi):
    """Every sign change of f on [lo, hi] (found at 15 digits), polished to 50 digits."""
    found = []
    # Just inside the window: at its very ends a spline's ray may miss it by a rounding, and
    # contacts there belong to the joints.
    margin = (hi - lo) * mpf("1e-9")
    lo, hi = lo + margin, hi - margin
    xs = [lo + (hi - lo) * k / SCAN for k in range(SCAN + 1)]
    with mpmath.workdps(15):
        fs = [f(mpf(x)) for x in xs]
    for k in range(SCAN):
        if fs[k] == 0:
            found.append(xs[k])
        elif fs[k] * fs[k + 1] < 0:
            found.append(mpmath.findroot(f, (xs[k], xs[k + 1]), solver="anderson"))
    return found


class Follower:
    def __init__(self, path):
        self.project = pr.load_project(path)
        with open(path, encoding="utf-8") as f:
            doc = json.load(f, parse_float=mpf, parse_int=mpf)
        spec = doc.get("follower", {})
        scale = mpf(1000) if doc.get("units", {}).get("length", "mm") == "m" else mpf(1)
        self.arm = spec.get("motion", "translating") == "oscillating"
        if self.arm:
            self.pivot = (spec["pivot"][0] * scale, spec["pivot"][1] * scale)
            self.length = spec["arm_length"] * scale
            self.sigma = mpf(-1) if spec.get("arm", "ccw") == "cw" else mpf(1)
            self.beta = mpmath.atan2(-self.pivot[1], -self.pivot[0])
        self.type = spec.get("type", "knife")
        self.e = spec.get("offset", mpf(0)) * scale
        self.rho = spec.get("radius", mpf(0)) * scale if self.type == "roller" else mpf(0)
        self.segments = self.project["segments"]
        self.joints = [point(seg, seg["end"]) for seg in self.segments]

    def candidates(self, phi):
        """(s, contact, centre) of every contact the condition allows at φ."""
        u = (mpmath.cos(phi), mpmath.sin(phi))
        n = (-u[1], u[0])
        e, rho = self.e, self.rho
        out = []
        for seg in self.segments:
            if self.type == "flat":
                def g(a, seg=seg):
                    t = tangent(seg, a)
                    return t[0] * u[0] + t[1] * u[1]
                for a in roots(g, seg["start"], seg["end"]):
                    nu = outward(seg, a)
                    if nu[0] * u[0] + nu[1] * u[1] <= 0:
                        continue
                    p = point(seg, a)
                    s = p[0] * u[0] + p[1] * u[1]
                    out.append((s, p, (e * n[0] + s * u[0], e * n[1] + s * u[1]), ("seg", seg, a)))
            else:
                def centre(a, seg=seg):
                    p = point(seg, a)
                    if rho == 0:
                        return p
                    nu = outward(seg, a)
                    return (p[0] + rho * nu[0], p[1] + rho * nu[1])

                def g(a):
                    c = centre(a)
                    return c[0] * n[0] + c[1] * n[1] - e
                for a in roots(g, seg["start"], seg["end"]):
                    c = centre(a)
                    s = c[0] * u[0] + c[1] * u[1]
                    out.append((s, point(seg, a), c, ("seg", seg, a)))
        for v in self.joints:
            if self.type == "flat" or rho > 0:
                s = self.joint_s(v, phi)
                if s is not None:
                    out.append((s, v, (e * n[0] + s * u[0], e * n[1] + s * u[1]), ("joint", v)))
        return out

    def joint_s(self, v, phi):
        """s when the follower rests on the joint point v: the face through v, or the roller
        centre on the line at distance rho from v (the outer of the two)."""
        u = (mpmath.cos(phi), mpmath.sin(phi))
        n = (-u[1], u[0])
        if self.type == "flat":
            return v[0] * u[0] + v[1] * u[1]
        w = self.e - (v[0] * n[0] + v[1] * n[1])
        disc = self.rho * self.rho - w * w
        if disc < 0:
            return None
        return v[0] * u[0] + v[1] * u[1] + mpmath.sqrt(disc)

    def local_s(self, how, phi):
        """s at phi from the same contact as `how`, re-solved from its parameter (for
        mpmath.diff: the contact moves smoothly with phi)."""
        if how[0] == "joint":
            return self.joint_s(how[1], phi)
        seg, a0 = how[1], how[2]
        u = (mpmath.cos(phi), mpmath.sin(phi))
        n = (-u[1], u[0])
        if self.type == "flat":
            def g(a):
                t = tangent(seg, a)
                return t[0] * u[0] + t[1] * u[1]
            a = mpmath.findroot(g, (a0, a0 + mpf("1e-12")))
            p = point(seg, a)
            return p[0] * u[0] + p[1] * u[1]

        def centre(a):
            p = point(seg, a)
            if self.rho == 0:
                return p
            nu = outward(seg, a)
            return (p[0] + self.rho * nu[0], p[1] + self.rho * nu[1])
        # Secant from a0 and a point 1e-12 beside it (findroot's default second point is a0 + 1/4,
        # which may leave the segment's window).
        a = mpmath.findroot(lambda x: centre(x)[0] * n[0] + centre(x)[1] * n[1] - self.e,
                            (a0, a0 + mpf("1e-12")))
        c = centre(a)
        return c[0] * u[0] + c[1] * u[1]

    def place(self, phi):
        best = max(self.candidates(phi), key=lambda c: c[0])
        return best

    # --- the swinging arm -------------------------------------------------------------------

    def pivot_at(self, phi):
        c, s = mpmath.cos(phi), mpmath.sin(phi)
        return (c * self.pivot[0] - s * self.pivot[1], s * self.pivot[0] + c * self.pivot[1])

    def arm_angle(self, centre, phi):
        """(θ, ψ): the arm's angle from the line pivot → centre, growing away from the cam, in
        (−π, π]; and ψ = β + σθ in the follower frame."""
        a = self.pivot_at(phi)
        psi = mpmath.atan2(centre[1] - a[1], centre[0] - a[0]) - phi
        theta = self.sigma * (psi - self.beta)
        theta = theta - 2 * mpmath.pi * mpmath.floor((theta + mpmath.pi) / (2 * mpmath.pi))
        if theta <= -mpmath.pi:
            theta += 2 * mpmath.pi
        return theta, self.beta + self.sigma * theta

    def centre_of(self, seg, a):
        p = point(seg, a)
        if self.rho == 0:
            return p
        nu = outward(seg, a)
        return (p[0] + self.rho * nu[0], p[1] + self.rho * nu[1])

    def arm_joint_centres(self, v, phi):
        """Roller centres ρ from the joint v and L from the pivot (0, 1 or 2)."""
        a = self.pivot_at(phi)
        dx, dy = v[0] - a[0], v[1] - a[1]
        d = mpmath.hypot(dx, dy)
        along = (self.length ** 2 - self.rho ** 2 + d * d) / (2 * d)
        h2 = self.length ** 2 - along ** 2
        if h2 < 0:
            return []
        h = mpmath.sqrt(h2)
        return [(a[0] + (along * dx - side * h * dy) / d, a[1] + (along * dy + side * h * dx) / d)
                for side in (1, -1)]

    def arm_candidates(self, phi):
        """(θ, contact, centre, how) of every contact the arm's condition allows at φ."""
        a = self.pivot_at(phi)
        out = []
        for seg in self.segments:
            def g(x, seg=seg):
                c = self.centre_of(seg, x)
                return (c[0] - a[0]) ** 2 + (c[1] - a[1]) ** 2 - self.length ** 2
            for x in roots(g, seg["start"], seg["end"]):
                c = self.centre_of(seg, x)
                out.append((self.arm_angle(c, phi)[0], point(seg, x), c, ("seg", seg, x)))
        if self.rho > 0:
            for v in self.joints:
                for k, c in enumerate(self.arm_joint_centres(v, phi)):
                    out.append((self.arm_angle(c, phi)[0], v, c, ("joint", v, k)))
        return out

    def local_psi(self, how, phi):
        """ψ at phi from the same contact as `how`, re-solved from its parameter."""
        if how[0] == "joint":
            return self.arm_angle(self.arm_joint_centres(how[1], phi)[how[2]], phi)[1]
        seg, x0 = how[1], how[2]
        a = self.pivot_at(phi)

        def g(x):
            c = self.centre_of(seg, x)
            return (c[0] - a[0]) ** 2 + (c[1] - a[1]) ** 2 - self.length ** 2
        x = mpmath.findroot(g, (x0, x0 + mpf("1e-12")))
        return self.arm_angle(self.centre_of(seg, x), phi)[1]

    def arm_state(self, t, phi, omega):
        theta, contact, centre, how = max(self.arm_candidates(phi), key=lambda c: c[0])
        self.check_clearance(phi, centre)
        psi = self.arm_angle(centre, phi)[1]
        d1, d2, d3 = (mpmath.diff(lambda x: self.local_psi(how, x), phi, k) for k in (1, 2, 3))
        # The contact normal: contact → centre for a roller; the profile's own at a knife.
        if self.rho > 0:
            nx, ny = (centre[0] - contact[0]) / self.rho, (centre[1] - contact[1]) / self.rho
        else:
            nx, ny = outward(how[1], how[2])
        big = phi + psi  # the arm's direction in the cam frame
        along = (mpmath.cos(big), mpmath.sin(big))
        across = (-along[1], along[0])
        away = (self.sigma * across[0], self.sigma * across[1])
        # The cam's surface slides past the tip along −J·centre; the normal leaning that way is
        # a positive angle.
        if centre[0] * across[0] + centre[1] * across[1] >= 0:
            slide = along
        else:
            slide = (-along[0], -along[1])
        pressure = mpmath.atan2(nx * slide[0] + ny * slide[1], nx * away[0] + ny * away[1])
        return {"t": t, "phi_deg": mpmath.degrees(phi), "psi_deg": mpmath.degrees(psi),
                "omega_arm": omega * d1, "alpha_arm": omega ** 2 * d2, "jerk_arm": omega ** 3 * d3,
                "center_x": centre[0], "center_y": centre[1],
                "contact_x": contact[0], "contact_y": contact[1],
                "pressure_angle_deg": mpmath.degrees(pressure)}

    def check_clearance(self, phi, centre):
        """No profile point nearer the roller centre than its radius (a penetration means the
        outermost contact was missed)."""
        if self.type != "roller":
            return
        cx, cy = float(centre[0]), float(centre[1])
        nearest = float("inf")
        with mpmath.workdps(15):
            for seg in self.segments:
                width = seg["end"] - seg["start"]
                for k in range(1001):
                    a = seg["start"] + width * (mpf("1e-9") + (1 - mpf("2e-9")) * k / 1000)
                    p = point(seg, a)
                    nearest = min(nearest,
                                  ((float(p[0]) - cx) ** 2 + (float(p[1]) - cy) ** 2) ** 0.5)
        if nearest < float(self.rho) - 1e-7:
            raise pr.ReferenceError(f"roller penetrates the profile at phi = {float(phi)}")

    def state(self, t):
        omega = self.project["omega"]
        phi = omega * t
        first = self.segments[0]["start"]
        phi = phi - 2 * mpmath.pi * mpmath.floor((phi - first) / (2 * mpmath.pi))
        if self.arm:
            return self.arm_state(t, phi, omega)
        s, contact, centre, how = self.place(phi)
        self.check_clearance(phi, centre)
        d1, d2, d3 = (mpmath.diff(lambda x: self.local_s(how, x), phi, k) for k in (1, 2, 3))
        pressure = mpf(0) if self.type == "flat" else mpmath.atan2(d1 - self.e, s)
        return {"t": t, "phi_deg": mpmath.degrees(phi), "s": s, "v": omega * d1,
                "a": omega ** 2 * d2, "j": omega ** 3 * d3,
                "center_x": centre[0], "center_y": centre[1],
                "contact_x": contact[0], "contact_y": contact[1],
                "pressure_angle_deg": mpmath.degrees(pressure)}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("project")
    parser.add_argument("--t", action="append", required=True, metavar="SECONDS")
    args = parser.parse_args(argv)
    try:
        follower = Follower(args.project)
        states = [follower.state(mpf(t)) for t in args.t]
    except (pr.ReferenceError, KeyError, ValueError) as error:
        print(f"follower_reference: {args.project}: {error}", file=sys.stderr)
        return 1
    sys.stdout.write(pr.states_to_json(states))
    return 0


if __name__ == "__main__":
    sys.exit(main())
