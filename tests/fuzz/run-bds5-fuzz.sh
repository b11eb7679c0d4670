#!/usr/bin/env bash
# Builds the BDS5 input fuzzer with clang (libFuzzer + ASan + UBSan) in build-fuzz and runs it over
# tests/fuzz/corpus/bds5 for a number of seconds (default 60). New interesting inputs go to build-fuzz's
# own corpus directory, crashes to build-fuzz/bds5-artifacts/; copy a minimised reproducer into the
# source corpus as crash-<name> so bds5_fuzz_replay keeps running it.
#   tests/fuzz/run-bds5-fuzz.sh [seconds] [extra libFuzzer flags...]
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
seconds=${1:-60}
shift || true
build=${SERVODESK_FUZZ_BUILD:-$root/build-fuzz}
seeds=$root/tests/fuzz/corpus/bds5
work=$build/bds5-corpus          # grows as the fuzzer finds new coverage
artifacts=$build/bds5-artifacts/

CC=${CC:-clang} CXX=${CXX:-clang++} cmake -S "$root" -B "$build" -G Ninja \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSERVODESK_FUZZ=ON -DSERVODESK_BUILD_TESTS=ON >/dev/null
cmake --build "$build" --target bds5_drive_fuzz

mkdir -p "$work" "$artifacts"
"$build/tests/fuzz/bds5_drive_fuzz" "$work" "$seeds" \
    -dict="$root/tests/fuzz/bds5.dict" \
    -max_len=4096 -timeout=5 -rss_limit_mb=2048 -max_total_time="$seconds" \
    -artifact_prefix="$artifacts" -print_final_stats=1 "$@"
