#!/usr/bin/env bash
# Configures and builds ServoDesk in ./build with the "default" preset (Ninja, RelWithDebInfo, ccache).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset default >/dev/null
cmake --build --preset default -j "$(nproc)"
