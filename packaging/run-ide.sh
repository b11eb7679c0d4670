#!/usr/bin/env bash
# Quick start 1: install what is needed, build, and open the IDE on the simulated BDS5.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
bash "$here/install-deps.sh"
bash "$here/build.sh"
exec "$here/../build/bin/servodesk" "$@"
