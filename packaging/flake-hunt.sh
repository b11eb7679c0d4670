#!/usr/bin/env bash
# Runs the whole test suite N times under load and prints each test's failure count, for anyone to use
# before a release (issue 23). The load: CTest runs twice as many tests as there are cores, and a CPU hog
# (one busy process per core) runs beside them, so a test that reads the wall clock or races shows itself.
#   packaging/flake-hunt.sh [N=5] [ctest arguments, e.g. -R '^app\.']
# Builds nothing: run packaging/build.sh first. Exit status 0 when every run passed, 1 otherwise.
set -uo pipefail
cd "$(dirname "$0")/.."
runs=${1:-5}
shift || true
jobs=$(( $(nproc) * 2 ))
hogs=()
cleanup() { for pid in "${hogs[@]}"; do kill "$pid" 2>/dev/null; done; }
trap cleanup EXIT
for _ in $(seq "$(nproc)"); do (while :; do :; done) & hogs+=("$!"); done

declare -A failures=()
failed_log=build/Testing/Temporary/LastTestsFailed.log
bad_runs=0
for run in $(seq "$runs"); do
    rm -f "$failed_log"
    start=$(date +%s)
    if ctest --test-dir build -j "$jobs" --timeout 600 --output-on-failure "$@" >"build/flake-hunt-$run.log" 2>&1; then
        echo "run $run/$runs: all passed ($(( $(date +%s) - start )) s)"
    else
        bad_runs=$((bad_runs + 1))
        names=$(cut -d: -f2- "$failed_log" 2>/dev/null)
        echo "run $run/$runs: failed: $(tr '\n' ' ' <<<"$names")($(( $(date +%s) - start )) s, log build/flake-hunt-$run.log)"
        while read -r name; do
            [ -n "$name" ] && failures[$name]=$(( ${failures[$name]:-0} + 1 ))
        done <<<"$names"
    fi
done
echo
echo "flake-hunt: $runs runs of the suite, ctest -j $jobs beside $(nproc) CPU hogs on $(nproc) cores"
if [ "${#failures[@]}" -eq 0 ]; then
    echo "flake-hunt: no test failed"
else
    for name in "${!failures[@]}"; do echo "flake-hunt: ${failures[$name]} of $runs failed: $name"; done | sort -t: -k2 -rn
fi
[ "$bad_runs" -eq 0 ]
