#!/usr/bin/env bash
# CI step: build the .deb, check it with lintian (Debian's package checker), install it with apt on this
# machine, and run the installed executables from their installed paths (servodesk-cli against the
# simulated drive, the IDE's screenshot tour under Xvfb).
# Needs root (apt). Usage: check-installed.sh BUILD_DIR
set -euo pipefail
build="$(cd "$1" && pwd)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
(cd "$work" && cpack --config "$build/CPackConfig.cmake" -G DEB > cpack.log 2>&1) || { cat "$work/cpack.log"; exit 1; }
deb=$(ls "$work"/servodesk_*.deb)
DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --reinstall "$deb" > "$work/apt.log" 2>&1 || { cat "$work/apt.log"; exit 1; }
passed=0
failed=0
check() { if eval "$2"; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL: $1"; fi; }
# Any lintian error or warning fails; its output is printed either way. Lintian warns on stderr that it runs
# as root: that is a message, not a tag, and does not change its exit status.
check "lintian: no errors or warnings" 'lintian --fail-on error,warning "$deb" > "$work/lintian.log" 2>&1; status=$?; cat "$work/lintian.log"; [ "$status" -eq 0 ]'
check "changelog version = package version" '[ "$(zcat /usr/share/doc/servodesk/changelog.gz | dpkg-parsechangelog -l - -S Version)" = "$(dpkg-deb -f "$deb" Version)" ]'
check "copyright file" '[ -f /usr/share/doc/servodesk/copyright ]'
check "servodesk-cli on PATH" '[ "$(command -v servodesk-cli)" = /usr/bin/servodesk-cli ]'
check "servodesk-cli --sim send" '[ "$(/usr/bin/servodesk-cli --sim send '"'"'P "HELLO"'"'"')" = HELLO ]'
check "servodesk-sim --stdio" 'printf "P 6*7\n" | /usr/bin/servodesk-sim --stdio | grep -q "          42"'
check "screenshot tour" 'xvfb-run -a -s "-screen 0 1920x1200x24" /usr/bin/servodesk --screenshot-tour "$work/tour" > "$work/tour.log" 2>&1 && [ -s "$work/tour/main-window.png" ] || { echo "tour log (last 40 lines):"; tail -n 40 "$work/tour.log"; false; }'
check "man pages" '[ -f /usr/share/man/man1/servodesk.1.gz ] && [ -f /usr/share/man/man1/servodesk-cli.1.gz ] && [ -f /usr/share/man/man1/servodesk-sim.1.gz ]'
check "desktop entry" '[ -f /usr/share/applications/org.servodesk.ServoDesk.desktop ]'
echo "installed $(basename "$deb"): $passed checks passed, $failed failed"
[ "$failed" -eq 0 ]
