#!/usr/bin/env bash
# Builds the .deb with CPack in a scratch folder and checks what it holds and depends on.
set -euo pipefail
build="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
(cd "$work" && cpack --config "$build/CPackConfig.cmake" -G DEB > cpack.log 2>&1) || { cat "$work/cpack.log"; exit 1; }
deb=$(ls "$work"/servodesk_*.deb)
contents=$(dpkg-deb -c "$deb")
depends=$(dpkg-deb -f "$deb" Depends)
fail=0
for path in ./usr/bin/servodesk ./usr/bin/servodesk-sim ./usr/bin/servodesk-cli \
            ./usr/share/applications/org.servodesk.ServoDesk.desktop \
            ./usr/share/metainfo/org.servodesk.ServoDesk.metainfo.xml \
            ./usr/share/mime/packages/org.servodesk.ServoDesk.xml \
            ./usr/share/icons/hicolor/scalable/apps/org.servodesk.ServoDesk.svg \
            ./usr/share/man/man1/servodesk.1.gz ./usr/share/man/man1/servodesk-sim.1.gz ./usr/share/man/man1/servodesk-cli.1.gz \
            ./usr/share/doc/servodesk/copyright ./usr/share/doc/servodesk/changelog.gz; do
  if ! grep -q " ${path}\$" <<<"$contents"; then echo "missing in the package: $path"; fail=1; fi
done
for dep in libqt6widgets6 libqt6serialport6 libqscintilla2-qt6 qt6-qpa-plugins; do
  if ! grep -q "$dep" <<<"$depends"; then echo "not a dependency: $dep (Depends: $depends)"; fail=1; fi
done
# Debian's package checker: no error and no warning (issue 19, item 15). It says "running with root
# privileges is not recommended" on stderr as root; that changes nothing.
if ! lintian --fail-on error,warning "$deb" > "$work/lintian.log" 2>&1; then
  grep -v "root privileges" "$work/lintian.log"
  echo "lintian: the package has errors or warnings"
  fail=1
fi
echo "$(basename "$deb"): $(wc -l <<<"$contents") entries; Depends: $depends"
exit $fail
