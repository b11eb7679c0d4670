#!/usr/bin/env bash
# The drive engines and the protocol code under AddressSanitizer + UndefinedBehaviorSanitizer: builds the
# "asan" preset's non-GUI tests (drive_core, the fuzz corpus replay, serialport) and runs them.
set -euo pipefail
cd "$(dirname "$0")/.."
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
cmake --preset asan >/dev/null
cmake --build --preset asan -j "$(nproc)" --target drive_core_tests bds5_fuzz_replay bds5_session_test fault_link_test \
    bds5_protocol_test
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
log=build-asan/sanitizers.log
status=0
ctest --test-dir build-asan -R '^(Bds5|Profile|fuzz\.|serialport\.(bds5_session|fault_link|Bds5Protocol))' \
    --output-on-failure -j "$(nproc)" > "$log" 2>&1 || status=$?
grep -E 'tests passed|\*\*\*|Failed' "$log" | sed 's/^/sanitizers (ASan+UBSan): /'
[ "$status" -eq 0 ] || { tail -n 60 "$log"; exit "$status"; }
