#!/usr/bin/env bash
# BM_KinematicsTurn/1000000 against the numpy baseline, in one run on one machine.
# Usage: tests/bench/compare_numpy.sh [BUILD_DIR]   (default build/release)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build/release}
example=$here/../../resources/examples/six-lobe-arc-cam.cam.json

numpy_ms=$(/usr/bin/python3 "$here/numpy_baseline.py" "$example" 1000000 7)
cpp_ms=$("$build/tests/bench/camwright_bench" --benchmark_filter='BM_KinematicsTurn/1000000$' \
    --benchmark_repetitions=5 --benchmark_report_aggregates_only=true --benchmark_format=json |
    /usr/bin/python3 -c 'import json,sys; b=json.load(sys.stdin)["benchmarks"]; print(next(x["real_time"] for x in b if x["aggregate_name"]=="median"))')
/usr/bin/python3 - "$numpy_ms" "$cpp_ms" <<'PY'
import sys
numpy_ms, cpp_ms = float(sys.argv[1]), float(sys.argv[2])
print(f"numpy baseline (best of 7):        {numpy_ms:8.2f} ms")
print(f"BM_KinematicsTurn/1000000 (median): {cpp_ms:8.2f} ms")
print(f"speed-up:                           {numpy_ms / cpp_ms:8.1f}x")
PY
