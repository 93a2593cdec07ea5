#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the .deb from a built tree into a temporary directory and checks it:
# the programs and desktop files are in it, the control fields are right, the
# Qt libraries were found as dependencies, and the desktop files validate.
# Usage: check_deb.sh BUILD_DIR VERSION [CPACK]
set -euo pipefail
build=$1 version=$2 cpack=${3:-cpack}
app_id=io.github.roombadashboard.RoombaDashboard

fail() { echo "FAIL: $*" >&2; exit 1; }
for tool in dpkg-deb dpkg-shlibdeps desktop-file-validate appstreamcli; do
    command -v "$tool" >/dev/null || fail "$tool is missing (bash .ci/install-deps installs it)"
done

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$cpack" -G DEB -B "$tmp" --config "$build/CPackConfig.cmake" >"$tmp/cpack.log" 2>&1 \
    || { cat "$tmp/cpack.log"; fail "cpack -G DEB failed"; }
debs=("$tmp"/*.deb)
[ ${#debs[@]} -eq 1 ] && [ -f "${debs[0]}" ] || fail "expected one .deb in $tmp"
deb=${debs[0]}
echo "built $(basename "$deb")"

# Paths only: the sixth column of the listing, "./usr/bin/...".
contents=$(dpkg-deb -c "$deb" | awk '{print $6}')
has() { grep -qx "\./$1" <<<"$contents" || fail "$1 is not in the package"; }
has usr/bin/roomba-dashboard
has usr/bin/roomba-sim
has usr/bin/roomba-ctl
has usr/bin/roomba-bridge
has "usr/lib/systemd/system/roomba-bridge@.service"
for f in mosquitto.conf acl roomba-bridge.conf; do has "usr/share/roomba-dashboard/mqtt/$f"; done
has "usr/share/applications/$app_id.desktop"
has "usr/share/icons/hicolor/scalable/apps/$app_id.svg"
has "usr/share/metainfo/$app_id.metainfo.xml"
grep -q '^\./usr/share/roomba-dashboard/songs/.*\.json$' <<<"$contents" \
    || fail "no example songs in usr/share/roomba-dashboard/songs"
has usr/share/roomba-dashboard/rooms/table_top.json
has usr/share/roomba-dashboard/lessons/cliff_sensors.json

field() { dpkg-deb -f "$deb" "$1"; }
[ "$(field Package)" = roomba-dashboard ] || fail "Package is '$(field Package)'"
[ "$(field Version)" = "$version" ] || fail "Version is '$(field Version)', project() says $version"
[ "$(field Section)" = science ] || fail "Section is '$(field Section)'"
[ -n "$(field Maintainer)" ] || fail "no Maintainer"
depends=$(field Depends)
echo "Depends: $depends"
grep -q 'libqt6widgets6' <<<"$depends" || fail "Depends names no Qt 6 library (shlibdeps off?)"

# Validate the files as installed, and check that they name each other.
dpkg-deb -x "$deb" "$tmp/root"
share=$tmp/root/usr/share
desktop=$share/applications/$app_id.desktop
desktop-file-validate "$desktop" || fail "desktop-file-validate"
appstreamcli validate --no-net "$share/metainfo/$app_id.metainfo.xml" || fail "appstreamcli validate"
exec_name=$(sed -n 's/^Exec=\([^ ]*\).*/\1/p' "$desktop")
icon_name=$(sed -n 's/^Icon=//p' "$desktop")
[ -x "$tmp/root/usr/bin/$exec_name" ] || fail "Exec=$exec_name is not a packaged program"
[ "$icon_name" = "$app_id" ] || fail "Icon=$icon_name, expected $app_id"
release=$(grep -o '<release version="[^"]*"' "$share/metainfo/$app_id.metainfo.xml" | head -1 | cut -d'"' -f2)
[ "$release" = "$version" ] || fail "newest metainfo release is $release, project() says $version"

# The packaged (stripped) program still runs; --version needs no display.
out=$("$tmp/root/usr/bin/roomba-dashboard" --version)
[ "$out" = "roomba-dashboard $version" ] || fail "packaged roomba-dashboard --version says '$out'"
out=$("$tmp/root/usr/bin/roomba-bridge" --version)
[ "$out" = "roomba-bridge $version" ] || fail "packaged roomba-bridge --version says '$out'"
unit=$tmp/root/usr/lib/systemd/system/roomba-bridge@.service
exec_start=$(sed -n 's/^ExecStart=\([^ ]*\).*/\1/p' "$unit")
[ -x "$tmp/root$exec_start" ] || fail "the unit's ExecStart=$exec_start is not a packaged program"
echo "PASS"
