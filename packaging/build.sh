#!/usr/bin/env bash
# Configures and builds ServoDesk in ./build with the "default" preset (Ninja, RelWithDebInfo, ccache).
set -euo pipefail
cd "$(dirname "$0")/.."
# ccache keys on relative paths, so a fresh clone elsewhere reuses what an earlier build compiled.
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
cmake --preset default >/dev/null
cmake --build --preset default -j "$(nproc)"
