#!/usr/bin/env bash
# Quick start 2: install what the tests need, build, and run every test with CTest (GUI tests run under
# Xvfb by themselves). .ci/run calls exactly this.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
bash "$here/install-deps.sh" --tests
start=$(date +%s)
bash "$here/build.sh"
echo "build: $(( $(date +%s) - start )) s on $(nproc) cores"
cd "$here/.."
# The engines and protocol code under ASan + UBSan.
bash packaging/run-sanitizers.sh
# Every libFuzzer target for a bounded time (clang + ASan + UBSan); executions and findings are printed.
bash packaging/run-fuzzers.sh
# The .deb, installed with apt and run from its installed paths (as root only: it installs system-wide).
if [[ $(id -u) -eq 0 ]]; then bash packaging/check-installed.sh build; fi
# Every test; one that fails is run once more and, if it then passes, printed as FLAKY: <name>.
bash packaging/ctest-rerun.sh
