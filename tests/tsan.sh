#!/usr/bin/env bash
# ThreadSanitizer over the link tests: the link runs on a worker thread and
# hands snapshots, bytes and statistics to the GUI thread. Builds them in
# build-tsan (ROOMBA_SANITIZE=thread) and runs them; any report fails.
#
#   tests/tsan.sh [ctest -R regex]      default: the link tests
#
# Qt itself is not built with ThreadSanitizer, so the hand-over of a queued
# call from one thread to another (under Qt's own futex mutex) is invisible;
# tests/tsan.supp names the places in Qt where that shows as a report. A
# race between the link's threads outside Qt's hand-over is still reported.
set -euo pipefail
cd "$(dirname "$0")/.."
tests=${1:-^tst_(robot_link|recording|roomba_ctl_link)}

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-g1 -DROOMBA_SANITIZE=thread "${launcher[@]}" >/dev/null
mapfile -t targets < <(ctest --test-dir build-tsan -N -R "$tests" | sed -n 's/^ *Test *#[0-9]*: *//p')
[[ ${#targets[@]} -gt 0 ]] || { echo "tsan.sh: no test matches '$tests'" >&2; exit 2; }
nice cmake --build build-tsan --target "${targets[@]}"

# QT_NO_GLIB: Qt's own event dispatcher, not glib's (whose wake-ups are
# invisible too). die_after_fork=0: QProcess forks roomba-sim and roomba-ctl.
export TSAN_OPTIONS="halt_on_error=1:die_after_fork=0:second_deadlock_stack=1:suppressions=$PWD/tests/tsan.supp"
QT_NO_GLIB=1 QT_QPA_PLATFORM=offscreen ctest --test-dir build-tsan -R "$tests" --output-on-failure --timeout 900
