#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the two .debs from a built tree into a temporary directory and checks
# them: roomba-bridge holds the bridge, the command-line tools and the unit
# and needs no GUI library; roomba-dashboard holds the window and its desktop
# files (which validate) and depends on roomba-bridge; the control fields
# are right and the Qt libraries were found as dependencies.
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
[ ${#debs[@]} -eq 3 ] || fail "expected three .debs in $tmp: ${debs[*]}"
deb=$(ls "$tmp"/roomba-dashboard_*.deb) || fail "no roomba-dashboard package"
bridge_deb=$(ls "$tmp"/roomba-bridge_*.deb) || fail "no roomba-bridge package"
python_deb=$(ls "$tmp"/python3-roomba_*_all.deb) || fail "no python3-roomba package (architecture all)"

# The Python library: the package a student's program imports, and what it needs.
python_contents=$(dpkg-deb -c "$python_deb" | awk '{print $6}')
for f in __init__.py robot.py connection.py practice.py; do
    grep -qx "\./usr/lib/python3/dist-packages/roomba/$f" <<<"$python_contents" || fail "roomba/$f is not in python3-roomba"
done
grep -qx '\./usr/share/doc/python3-roomba/examples/square.py' <<<"$python_contents" || fail "no examples in python3-roomba"
grep -q 'python3-paho-mqtt' <<<"$(dpkg-deb -f "$python_deb" Depends)" || fail "python3-roomba does not depend on python3-paho-mqtt"
dpkg-deb -x "$python_deb" "$tmp/python"
PYTHONPATH="$tmp/python/usr/lib/python3/dist-packages" /usr/bin/python3 -c 'import roomba; roomba.Robot' \
    || fail "the installed roomba library does not import"
echo "built $(basename "$deb") and $(basename "$bridge_deb")"

# Paths only: the sixth column of the listing, "./usr/bin/...".
bridge_contents=$(dpkg-deb -c "$bridge_deb" | awk '{print $6}')
contents=$(dpkg-deb -c "$deb" | awk '{print $6}')
in_bridge() { grep -qx "\./$1" <<<"$bridge_contents" || fail "$1 is not in the roomba-bridge package"; }
for p in roomba-bridge roomba-ctl roomba-sim roomba-classroom; do
    in_bridge "usr/bin/$p"
    in_bridge "usr/share/man/man1/$p.1"
    grep -qx "\./usr/bin/$p" <<<"$contents" && fail "$p is in both packages"
done
in_bridge "usr/lib/systemd/system/roomba-bridge@.service"
for f in mosquitto.conf quickstart.conf acl roomba-bridge.conf; do in_bridge "usr/share/roomba-bridge/mqtt/$f"; done
in_bridge usr/share/doc/roomba-bridge/copyright
[ "$(dpkg-deb -f "$bridge_deb" Package)" = roomba-bridge ] || fail "the bridge's Package is '$(dpkg-deb -f "$bridge_deb" Package)'"
bridge_depends=$(dpkg-deb -f "$bridge_deb" Depends)
echo "roomba-bridge Depends: $bridge_depends"
grep -q 'libqt6core6' <<<"$bridge_depends" || fail "roomba-bridge names no Qt 6 library (shlibdeps off?)"
grep -Eq 'libqt6(gui|widgets)|qcustomplot|libsdl' <<<"$bridge_depends" && fail "roomba-bridge depends on a GUI library"

has() { grep -qx "\./$1" <<<"$contents" || fail "$1 is not in the package"; }
has usr/bin/roomba-dashboard
has usr/share/man/man1/roomba-dashboard.1
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
grep -q "roomba-bridge (= $version)" <<<"$depends" || fail "roomba-dashboard does not depend on roomba-bridge $version"

# Validate the files as installed, and check that they name each other.
dpkg-deb -x "$deb" "$tmp/root"
dpkg-deb -x "$bridge_deb" "$tmp/root"
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
# Each man page reads as one (man's own formatter, where it is installed)
# and carries its program's options.
for page in "$tmp"/root/usr/share/man/man1/*.1; do
    grep -q -- '--help' "$page" || fail "$(basename "$page") does not hold its program's --help"
    if command -v groff >/dev/null; then
        groff -man -Tutf8 -ww -z "$page" 2>&1 | grep . && fail "$(basename "$page") has roff warnings"
    fi
done
grep -q -- '--report-pose' "$tmp/root/usr/share/man/man1/roomba-sim.1" || fail "roomba-sim.1 lacks --report-pose"
echo "PASS"
