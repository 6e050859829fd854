#!/bin/bash
# Regenerate tests/data/reference/followers/*.expected.json with the 50-digit contact reference
# (follower_reference.py; seconds to 20 s an instant). The cams are copies of reference cams with a
# follower section added.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
data="$here/../data/reference/followers"
py=/usr/bin/python3

generate() {
    local name=$1
    shift
    local args=()
    for t in "$@"; do args+=(--t "$t"); done
    "$py" "$here/follower_reference.py" "$data/$name.cam.json" "${args[@]}" > "$data/$name.expected.json.tmp"
    mv "$data/$name.expected.json.tmp" "$data/$name.expected.json"
    echo "wrote tests/data/reference/followers/$name.expected.json ($# instants)"
}

generate six-lobe-roller-offset 0.013 0.041 0.077 0.1 0.133 0.171 0.222 0.265 0.31 0.377
generate spline-mix-roller-offset 0.011 0.06 0.11 0.16 0.21 0.26 0.31 0.36 0.41 0.46
generate d-flat-knife-offset 0.013 0.05 0.1 0.15 0.21 0.26 0.3 0.36 0.41 0.47
generate eccentric-split-flat 0.004 0.03 0.06 0.09 0.12 0.15 0.18 0.21 0.24
generate pear-tangent-arm-roller 0.011 0.04 0.07 0.1 0.13 0.16 0.19 0.22
generate five-lobe-arm-knife 0.017 0.05 0.083 0.12 0.15 0.18 0.21 0.24
generate spline-offset-arm-roller 0.03 0.13 0.23 0.33 0.43 0.53 0.63 0.73
generate notch-flat-arm-roller 0.02 0.11 0.2 0.29 0.38 0.47 0.56 0.65 0.74
