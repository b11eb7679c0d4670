#!/usr/bin/env bash
# Every libFuzzer target for a bounded time (issue 11), built with clang + ASan + UBSan in build-fuzz.
# Each starts from its seed corpus under tests/ and keeps what it learns in build-fuzz; a crash,
# hang or sanitizer report fails the run and leaves the reproducer in build-fuzz/<name>-artifacts/.
#   packaging/run-fuzzers.sh [seconds per target, default $SERVODESK_FUZZ_SECONDS or 30]
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
seconds=${1:-${SERVODESK_FUZZ_SECONDS:-30}}
# A fixed seed keeps CI's runs repeatable (a finding there is found again by the same command); give
# another seed (SERVODESK_FUZZ_SEED=0 lets libFuzzer choose) for longer runs that look elsewhere.
seed=${SERVODESK_FUZZ_SEED:-1}
build=${SERVODESK_FUZZ_BUILD:-$root/build-fuzz}
# shellcheck source=fuzz-targets.sh
source "$root/packaging/fuzz-targets.sh"
build_fuzzers

# Per target: executions, wall time and executions per second, and executions per CPU-second (user + sys
# of the fuzzer process, from bash's time): on a shared, loaded machine the wall rate shows the load, the
# CPU rate what the target costs (issue 20: bds5_drive_fuzz aims at 2,000 a second).
TIMEFORMAT='%R %U %S'
status=0
for t in "${fuzz_targets[@]}"; do
    read -r name dir corpus seeds flags <<<"$t"
    work=$build/$name-corpus
    artifacts=$build/$name-artifacts/
    mkdir -p "$work" "$artifacts" "$root/$corpus"
    log=$build/$name.log
    timing=$build/$name.time
    found=0
    more=()
    [ "$seeds" != - ] && more=("$root/$seeds")
    # shellcheck disable=SC2086
    { time "$build/$dir/$name" "$work" "$root/$corpus" "${more[@]}" $flags -seed="$seed" -timeout=10 \
        -rss_limit_mb=2048 -max_total_time="$seconds" -artifact_prefix="$artifacts" -print_final_stats=1 \
        >"$log" 2>&1; } 2>"$timing" || found=1
    runs=$(grep -m1 -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')
    read -r wall user sys <"$timing" || true
    rates=$(awk -v n="$runs" -v w="${wall:-0}" -v u="${user:-0}" -v s="${sys:-0}" 'BEGIN {
        c = u + s
        printf "%.1f s wall, %.0f exec/s; %.1f s CPU, %.0f exec per CPU-second", w, (w > 0 ? n / w : 0), c, (c > 0 ? n / c : 0)
    }')
    if [ "$found" = 0 ]; then
        echo "fuzz: $name: $runs executions in $seconds s ($rates), no findings"
    else
        status=1
        echo "fuzz: $name: FINDING after $runs executions ($rates) (see $log and $artifacts)"
        tail -n 40 "$log"
    fi
done
exit "$status"
