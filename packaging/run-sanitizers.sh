#!/usr/bin/env bash
# The drive engines and the protocol code under AddressSanitizer + UndefinedBehaviorSanitizer: builds the
# "asan" preset's non-GUI tests (the three drive engines, every fuzz corpus replay, the sessions of all
# three families, the scope's analysis) and runs them.
set -euo pipefail
cd "$(dirname "$0")/.."
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
cmake --preset asan >/dev/null
cmake --build --preset asan -j "$(nproc)" --target drive_core_tests sc750_tests pmc960_tests scope_tests \
    bds5_fuzz_replay host_parsers_fuzz_replay capture_files_fuzz_replay pmc960_fuzz_replay sc750_compiler_fuzz_replay bds5_session_test \
    bds5_transfer_test bds5_record_play_test sc750_session_test pmc960_session_test fault_link_test bds5_protocol_test
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
log=build-asan/sanitizers.log
status=0
ctest --test-dir build-asan \
    -R '^(Bds5|Profile|Plant|SimulatorCommands|sc750\.|pmc960\.|scope\.|fuzz\.|serialport\.(bds5_session|bds5_transfer|bds5_record_play|sc750_session|pmc960_session|fault_link|Bds5Protocol))' \
    --output-on-failure -j "$(nproc)" > "$log" 2>&1 || status=$?
grep -E 'tests passed|\*\*\*|Failed' "$log" | sed 's/^/sanitizers (ASan+UBSan): /'
[ "$status" -eq 0 ] || { tail -n 60 "$log"; exit "$status"; }
