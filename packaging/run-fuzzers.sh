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

# Per target, two figures. First the kept corpus is replayed alone (-runs=0) and timed: thousands of kept
# inputs, many near the length limit, take a good part of a 30 s run. Then the fuzzing run, which replays
# them again before it mutates: its executions after that replay (libFuzzer's INITED count) over its CPU
# time after it are the mutation rate, what a long campaign runs at (issue 20, item 12: bds5_drive_fuzz
# aims at 2,000 a second). CPU time is user + sys of the fuzzer process, from bash's time: on a shared,
# loaded machine the wall rate shows the load, the CPU rate what the target costs.
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
    replay=$build/$name-replay
    rm -rf "$replay"
    mkdir -p "$replay"
    # shellcheck disable=SC2086
    { time "$build/$dir/$name" "$replay" "$root/$corpus" "${more[@]}" $flags -runs=0 -timeout=10 \
        -rss_limit_mb=2048 >"$log" 2>&1; } 2>"$timing" || found=1
    kept=$(grep -a -m1 -o '^#[0-9]*.INITED' "$log" | grep -o '[0-9]*' || echo 0)
    read -r _ load_user load_sys <"$timing" || true
    if [ "$found" = 0 ]; then
        # shellcheck disable=SC2086
        { time "$build/$dir/$name" "$work" "$root/$corpus" "${more[@]}" $flags -seed="$seed" -timeout=10 \
            -rss_limit_mb=2048 -max_total_time="$seconds" -artifact_prefix="$artifacts" -print_final_stats=1 \
            >"$log" 2>&1; } 2>"$timing" || found=1
    fi
    runs=$(grep -a -m1 -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
    inited=$(grep -a -m1 -o '^#[0-9]*.INITED' "$log" | grep -o '[0-9]*' || echo 0)
    read -r wall user sys <"$timing" || true
    rates=$(awk -v n="$runs" -v i="${inited:-0}" -v k="${kept:-0}" -v w="${wall:-0}" -v u="${user:-0}" -v s="${sys:-0}" \
        -v lu="${load_user:-0}" -v ls="${load_sys:-0}" 'BEGIN {
        c = u + s; l = lu + ls; m = c - l
        printf "%.1f s wall, %.1f s CPU; the %d kept inputs replay in %.1f s CPU; then %d mutations at %.0f exec per CPU-second",
            w, c, k, l, n - i, (m > 0 ? (n - i) / m : 0)
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
