#!/usr/bin/env bash
# Installs, from Debian 12's own packages, what ServoDesk needs to build and run (and, with --tests, to
# run its tests). Idempotent: packages already present are not touched, so a second run is quick.
set -euo pipefail

build_deps=(
  build-essential cmake ninja-build ccache pkg-config
  qt6-base-dev qt6-base-dev-tools qt6-serialport-dev libqscintilla2-qt6-dev libqcustomplot-dev
  libeigen3-dev libfftw3-dev libgl-dev qt6-qpa-plugins libqt6svg6 fonts-dejavu-core
)
test_deps=(
  desktop-file-utils appstream dpkg-dev file lintian
  libgtest-dev libgmock-dev xvfb xauth python3 python3-serial socat picocom clang libclang-rt-14-dev
)

wanted=("${build_deps[@]}")
if [[ "${1:-}" == "--tests" ]]; then wanted+=("${test_deps[@]}"); fi

missing=()
for pkg in "${wanted[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$pkg")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#wanted[@]} packages already installed"
  exit 0
fi

if [[ $(id -u) -ne 0 ]]; then
  SUDO=sudo
else
  SUDO=
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
