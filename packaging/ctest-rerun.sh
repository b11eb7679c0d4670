#!/usr/bin/env bash
# Runs every test with CTest (the "default" preset, extra arguments passed on); a test that fails is run
# once more, and one that then passes is printed as `FLAKY: <name>`, so a one-off does not throw away a
# session's work while a test that fails twice still fails the run. Every FLAKY line is a defect to fix
# (packaging/flake-hunt.sh finds them before a release), never a state to live with.
#   packaging/ctest-rerun.sh [ctest arguments...]
set -uo pipefail
cd "$(dirname "$0")/.."
failed_log=build/Testing/Temporary/LastTestsFailed.log
rm -f "$failed_log"
ctest --preset default -j "$(nproc)" "$@"
status=$?
[ "$status" -eq 0 ] && exit 0
if [ ! -s "$failed_log" ]; then
    echo "ctest failed (status $status) without naming a failed test" >&2
    exit "$status"
fi
first=$(cut -d: -f2- "$failed_log" | sort)
echo
echo "Running the $(wc -l <<<"$first") failed test(s) once more:"
sed 's/^/    /' <<<"$first"
cp "$failed_log" build/Testing/Temporary/LastTestsFailed.first
ctest --preset default -j "$(nproc)" --rerun-failed "$@"
status=$?
again=""
[ "$status" -ne 0 ] && [ -s "$failed_log" ] && again=$(cut -d: -f2- "$failed_log" | sort)
echo
while read -r name; do
    [ -z "$name" ] && continue
    if grep -qxF "$name" <<<"$again"; then echo "FAILED TWICE: $name"; else echo "FLAKY: $name"; fi
done <<<"$first"
exit "$status"
