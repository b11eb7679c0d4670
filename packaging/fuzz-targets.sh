# The libFuzzer targets, for run-fuzzers.sh and fuzz-campaign.sh (sourced; needs $root). One line each:
#   name  binary folder (under the fuzz build)  kept corpus (under tests: new finds are merged here)
#   other seed folder (or -)  extra flags
# bds5_drive_fuzz runs without the entropic schedule: over its ~3,800 kept inputs and ~18,000 features, the
# schedule's per-run bookkeeping (InputCorpus::UpdateFeatureFrequency) took a third of the CPU; without it
# the same seed ran 1,265 mutations a second against 971, and kept twice as many new inputs (issue 20).
# host_parsers_fuzz likewise: perf showed UpdateFeatureFrequency at 42% of its CPU over ~1,400 inputs.
fuzz_targets=(
    "bds5_drive_fuzz tests/fuzz tests/fuzz/corpus/bds5 - -dict=$root/tests/fuzz/bds5.dict -max_len=4096 -entropic=0"
    "host_parsers_fuzz tests/fuzz tests/fuzz/corpus/host - -max_len=4096 -entropic=0"
    "capture_files_fuzz tests/fuzz tests/fuzz/corpus/capture - -max_len=8192"
    "pmc960_drive_fuzz tests/fuzz tests/drive_core/pmc960/fuzz_corpus - -max_len=4096"
    "sc750_compiler_fuzz tests/drive_core tests/fuzz/corpus/sc750-compiler tests/drive_core/sc750/examples -max_len=8192"
)
fuzz_target_names=()
for t in "${fuzz_targets[@]}"; do fuzz_target_names+=("${t%% *}"); done

# Configures the clang + ASan + UBSan build in $build and builds the named targets (all when none named).
# One at a time: campaigns of two targets may run side by side, one a core, over the same build.
build_fuzzers() {
    mkdir -p "$build"
    exec 9>"$build/.build-lock"
    flock 9
    export CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=1
    local launcher=()
    command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
    CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DSERVODESK_FUZZ=ON -DSERVODESK_BUILD_TESTS=ON "${launcher[@]}" >/dev/null
    if [ $# -eq 0 ]; then set -- "${fuzz_target_names[@]}"; fi
    cmake --build "$build" -j "$(nproc)" --target "$@"
    flock -u 9
}
