#!/usr/bin/python3
"""The numpy baseline for BM_KinematicsTurn: one turn of a project into the same 15 arrays,
written the way a careful numpy user would (fully vectorised, no Python loop per sample).

Usage: numpy_baseline.py PROJECT N [REPEATS]  -> prints the best time in ms.
Arcs only (the six-lobe example). Run with Debian's /usr/bin/python3 and python3-numpy.
"""
import json
import math
import sys
import time

import numpy as np


def load(path):
    with open(path) as f:
        p = json.load(f)
    m = p["motion"]
    omega = (m["omega_rad_s"] if "omega_rad_s" in m
             else m["rpm"] * 2 * math.pi / 60 if "rpm" in m else 2 * math.pi / m["period_s"])
    segs = p["contour"]
    assert all(s["type"] == "arc" for s in segs), "baseline handles arcs only"
    cx = np.array([s["center"][0] for s in segs])
    cy = np.array([s["center"][1] for s in segs])
    k = np.array([s["radius"] ** 2 for s in segs]) - cx ** 2 - cy ** 2
    sign = np.array([1.0 if s["branch"] == "outer" else -1.0 for s in segs])
    ends = np.radians(np.array([s["phi_end"] for s in segs]))
    begin = math.radians(segs[0]["phi_start"])
    return omega, cx, cy, k, sign, ends, begin


def turn(omega, cx, cy, k, sign, ends, begin, n):
    t = np.arange(n) * (2 * math.pi / abs(omega) / n)
    phi = omega * t
    x = np.mod(phi - begin, 2 * math.pi) + begin
    seg = np.minimum(np.searchsorted(ends, x, side="right"), len(ends) - 1).astype(np.int32)
    c, s = np.cos(phi), np.sin(phi)
    a, b, kk, sg = cx[seg], cy[seg], k[seg], sign[seg]
    mu = a * c + b * s
    mu1 = b * c - a * s
    q = np.sqrt(np.maximum(mu * mu + kk, 0.0))
    p = mu * mu1
    w = mu1 * mu1 - mu * mu
    r = mu + sg * q
    r1 = mu1 + sg * p / q
    r2 = -mu + sg * (w / q - p * p / q ** 3)
    r3 = -mu1 + sg * (-4 * p / q - 3 * p * w / q ** 3 + 3 * p ** 3 / q ** 5)
    w2 = omega * omega
    v_r, v_phi = omega * r1, r * omega
    a_r, a_phi = w2 * r2 - r * w2, 2 * omega * r1 * omega
    j_r = w2 * omega * r3 - 3 * omega * r1 * w2
    j_phi = 3 * w2 * r2 * omega - r * w2 * omega
    return (t, phi, seg, r, r * c, r * s, v_r, v_phi, np.hypot(v_r, v_phi), a_r, a_phi,
            np.hypot(a_r, a_phi), j_r, j_phi, np.hypot(j_r, j_phi))


def main():
    path, n = sys.argv[1], int(sys.argv[2])
    repeats = int(sys.argv[3]) if len(sys.argv) > 3 else 5
    args = load(path)
    best = float("inf")
    for _ in range(repeats):
        start = time.perf_counter()
        turn(*args, n)
        best = min(best, time.perf_counter() - start)
    print(f"{best * 1e3:.3f}")


if __name__ == "__main__":
    main()
