#!/usr/bin/env bash
# ThreadSanitizer over the tests of the layers whose work crosses threads
# (label "threaded": a link on its thread with its robot, the bridge, MQTT). Builds them in
# build-tsan (ROOMBA_SANITIZE=thread) and runs them; any report fails.
#
#   tests/tsan.sh [--build-only | --run-only] [ctest -R regex]
#                                       default: build, then run every test
#                                       labelled threaded
#
# Qt itself is not built with ThreadSanitizer, so the hand-over of a queued
# call from one thread to another (under Qt's own futex mutex) is invisible;
# tests/tsan.supp names the places in Qt where that shows as a report. A
# race between our threads outside Qt's hand-over is still reported.
set -euo pipefail
cd "$(dirname "$0")/.."
phase=all
if [[ ${1:-} == --build-only || ${1:-} == --run-only ]]; then
    phase=$1
    shift
fi
select=(-L threaded)
[[ $# -gt 0 ]] && select=(-R "$1")

if [[ $phase != --run-only ]]; then
    launcher=()
    command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    # No benchmarks: nothing here runs them.
    cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-g1 -DROOMBA_SANITIZE=thread \
        -DROOMBA_BUILD_BENCHMARKS=OFF "${launcher[@]}" >/dev/null
    mapfile -t targets < <(ctest --test-dir build-tsan -N "${select[@]}" | sed -n 's/^ *Test *#[0-9]*: *//p')
    [[ ${#targets[@]} -gt 0 ]] || { echo "tsan.sh: no test matches ${select[*]}" >&2; exit 2; }
    nice cmake --build build-tsan --target "${targets[@]}"
fi
[[ $phase == --build-only ]] && exit 0

# QT_NO_GLIB: Qt's own event dispatcher, not glib's (whose wake-ups are
# invisible too). die_after_fork=0: QProcess forks roomba-sim and roomba-ctl.
# One test per core: under ThreadSanitizer they are busy, not waiting.
export TSAN_OPTIONS="halt_on_error=1:abort_on_error=1:die_after_fork=0:second_deadlock_stack=1:suppressions=$PWD/tests/tsan.supp"
QT_NO_GLIB=1 QT_QPA_PLATFORM=offscreen ctest --test-dir build-tsan "${select[@]}" --output-on-failure --timeout 900 -j "$(nproc)"
