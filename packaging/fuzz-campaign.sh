#!/usr/bin/env bash
# A long fuzzing run of one target toward issue 20's goal (10 million executions per target in total
# without a finding), with libFuzzer choosing the seed. Its work corpus lives in the fuzz build and
# grows from run to run; what it found that adds coverage is merged into the kept corpus under tests/
# (replayed by CTest from then on). Each run adds a row to tests/fuzz/campaigns.md, the ledger that sums
# the executions per target.
#   packaging/fuzz-campaign.sh TARGET EXECUTIONS     e.g. fuzz-campaign.sh capture_files_fuzz 10000000
#   packaging/fuzz-campaign.sh --totals              the ledger's sums
# Two runs of one target may go side by side, one a core, when each has its own SERVODESK_FUZZ_RUN (a
# suffix for its work corpus and log, e.g. 2); each adds its own row.
# Exit status 0 when the run ended without a finding; 1 with a finding (the reproducer is in
# build-fuzz/<name>-artifacts/, the row says FINDING); 2 on bad arguments. A run stopped early (SIGINT to
# the fuzzer, e.g. `pkill -INT -f build-fuzz/.*/NAME` to free the machine for CI) is no finding: its row
# counts the executions it did and says where it stopped, and what it found is merged as usual.
# The whole script is one block, read before it runs: editing this file during a campaign (hours long) cannot
# change what the running one does next.
{
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
build=${SERVODESK_FUZZ_BUILD:-$root/build-fuzz}
ledger=$root/tests/fuzz/campaigns.md
# shellcheck source=fuzz-targets.sh
source "$root/packaging/fuzz-targets.sh"

totals() {
    awk -F'|' '/^\| 20/ { gsub(/ /, "", $4); gsub(/ /, "", $5); n[$4] += $5; if ($6 ~ /FINDING/) f[$4]++ }
        END { for (t in n) printf "fuzz-campaign: %s: %d executions in total%s\n", t, n[t], (f[t] ? ", " f[t] " with a finding" : "") }' \
        "$ledger" | sort
}
if [ "${1:-}" = --totals ]; then totals; exit 0; fi
if [ $# -ne 2 ]; then
    echo "usage: $0 TARGET EXECUTIONS | --totals (targets: ${fuzz_target_names[*]})" >&2
    exit 2
fi
target=$1
executions=$2
line=
for t in "${fuzz_targets[@]}"; do [ "${t%% *}" = "$target" ] && line=$t; done
if [ -z "$line" ]; then
    echo "fuzz-campaign: no target $target (targets: ${fuzz_target_names[*]})" >&2
    exit 2
fi
read -r name dir corpus seeds flags <<<"$line"
commit=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?') # the code the run fuzzes
build_fuzzers "$name"

run=${SERVODESK_FUZZ_RUN:-}
work=$build/$name-campaign$run
artifacts=$build/$name-artifacts$run/
log=$build/$name-campaign$run.log
mkdir -p "$work" "$artifacts" "$root/$corpus"
more=()
[ "$seeds" != - ] && more=("$root/$seeds")
found=0
# No allocation and free stacks in ASan's reports: recording them (StackDepot::Put on every malloc and free)
# took a quarter of host_parsers_fuzz's CPU, and more as the depot grew with the stacks the run explored (its
# rate fell from ~1,000 to ~400 a second and its memory to 1 GB). A finding keeps its reproducer; running the
# target on it (or ctest's replay) prints the full stacks.
export ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}malloc_context_size=0
stopped=0
# shellcheck disable=SC2086
"$build/$dir/$name" "$work" "$root/$corpus" "${more[@]}" $flags -seed=0 -runs="$executions" -timeout=10 \
    -rss_limit_mb=2048 -artifact_prefix="$artifacts" -print_final_stats=1 -interrupt_exit_code=72 \
    >"$log" 2>&1 || { [ $? = 72 ] && grep -aq 'run interrupted' "$log" && stopped=1; } || found=1
done_runs=$(grep -a -m1 -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
seed=$(grep -a -m1 -o 'Seed: [0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')
kept=0
if [ "$found" = 0 ]; then
    before=$(find "$root/$corpus" -type f | wc -l)
    # shellcheck disable=SC2086
    "$build/$dir/$name" -merge=1 "$root/$corpus" "$work" $flags >"$build/$name-merge$run.log" 2>&1
    kept=$(( $(find "$root/$corpus" -type f | wc -l) - before ))
fi
[ -f "$ledger" ] || printf '%s\n' \
    '# Fuzzing campaigns (issue 20): one row per run of packaging/fuzz-campaign.sh' '' \
    'Executions are libFuzzer'"'"'s own count; the commit is the one the run started at.' \
    '`packaging/fuzz-campaign.sh --totals` sums them per target.' '' \
    '| date | commit | target | executions | result | seed | kept |' \
    '| --- | --- | --- | --- | --- | --- | --- |' >"$ledger"
result=$([ "$found" = 0 ] && echo "no finding" || echo "FINDING (see $name-artifacts$run)")
[ "$stopped" = 1 ] && result="no finding (stopped at $done_runs of $executions)"
printf '| %s | %s | %s | %s | %s | %s | %s |\n' "$(date -u +%F)" "$commit" "$name" "$done_runs" "$result" "$seed" \
    "$kept" >>"$ledger"
echo "fuzz-campaign: $name: $done_runs executions, $result; $kept inputs merged into $corpus"
[ "$found" = 0 ] || tail -n 40 "$log"
totals
exit "$found"
exit
}
