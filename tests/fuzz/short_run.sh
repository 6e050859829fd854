#!/usr/bin/env bash
# A short libFuzzer run as a regression check (ctest's fuzz_short.* in a build with
# CAMWRIGHT_BUILD_FUZZ and tests, the debug preset): every seed and every saved finding of the
# target first, then new inputs grown from them for the rest of SECONDS.
#   short_run.sh FUZZER NAME SECONDS SOURCE_DIR WORK_DIR
# The seeds in the repository are only read: the corpus the fuzzer grows goes to WORK_DIR, and
# an input that fails is kept there as WORK_DIR/finding-* (the test fails and names it).
set -euo pipefail
fuzzer=$1 name=$2 seconds=$3 source=$4 work=$5

rm -rf "$work"
mkdir -p "$work/grown"
dirs=("$work/grown" "$source/corpus/$name")
[ -d "$source/regressions/$name" ] && dirs+=("$source/regressions/$name")

# -timeout: an input running 10 s is a hang; -rss_limit_mb: one using 2 GiB a leak or a bomb.
if ! "$fuzzer" "${dirs[@]}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
        -max_len=4096 -print_final_stats=1 -artifact_prefix="$work/finding-" 2>"$work/log"; then
    tail -n 60 "$work/log"
    echo "short_run: $name failed; the input is kept as:" $(ls "$work"/finding-* 2>/dev/null)
    exit 1
fi
grep -E "^(stat::number_of_executed_units|stat::peak_rss_mb|INFO: Loaded|#[0-9]+ +DONE)" \
    "$work/log" || true
