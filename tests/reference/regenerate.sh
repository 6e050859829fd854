#!/bin/bash
# Regenerate tests/data/reference/*.expected.json with the 50-digit reference.
# Checks the reference against the math.md §3 table and the cams' joints first.
# The cams themselves are made by make_cams.py (not run here, so hand edits
# to a .cam.json are not overwritten).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
data="$here/../data/reference"
py=/usr/bin/python3

"$py" "$here/check_math_md_table.py" > /dev/null || { echo "math.md table check failed" >&2; exit 1; }
"$py" "$here/check_joints.py" > /dev/null || { echo "joint check failed (run check_joints.py)" >&2; exit 1; }

# generate NAME T1 T2 ... : reference states of NAME.cam.json at those times
generate() {
    local name=$1
    shift
    local args=()
    for t in "$@"; do args+=(--t "$t"); done
    "$py" "$here/polar_reference.py" "$data/$name.cam.json" "${args[@]}" > "$data/$name.expected.json.tmp"
    mv "$data/$name.expected.json.tmp" "$data/$name.expected.json"
    echo "wrote tests/data/reference/$name.expected.json ($# instants)"
}

# Instants are at least 0.5 deg away from every window boundary; each list
# visits every segment and ends with one instant in the second turn.
generate d-flat            0 0.02 0.07 0.12 0.17 0.22 0.27 0.32 0.38 0.43 0.48 0.55
generate eccentric-split   0.005 0.025 0.05 0.07 0.08 0.1 0.13 0.145 0.17 0.195 0.23
generate five-lobe         0 0.01 0.025 0.045 0.06 0.1 0.125 0.15 0.175 0.2 0.225 0.3
generate pear-tangent      0.005 0.02 0.04 0.05 0.06 0.08 0.11 0.15 0.2 0.24 0.27
generate notch-flat        0.05 0.15 0.25 0.3 0.4 0.5 0.58 0.6 0.65 0.75 0.9
generate rounded-triangle  0 0.0015 0.004 0.008 0.013 0.018 0.023 0.0275 0.032 0.037 0.0408 0.0455
generate spline-mix        0.02 0.05 0.08 0.12 0.18 0.22 0.26 0.31 0.35 0.39 0.43
generate spline-offset     0 0.02 0.06 0.12 0.2 0.3 0.42 0.46 0.56 0.66 0.77 0.86
