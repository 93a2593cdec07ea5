#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The performance table in one command: runs the benchmarks and prints today's
# figures beside the ones the project keeps (tests/bench/perf_budget.json) and
# their targets, and says which slid by more than their noise and which miss
# their target.
#
#   tests/bench/perf_table.sh [--build DIR] [--seconds S] [--keep] [--build-times]
#
# --build DIR    the build directory; the benchmarks are turned on and built
#                there (default: build)
# --seconds S    how long each dashboard run lasts (default 600: the table's
#                "10 minutes after start"; shorter runs are noisier)
# --keep         today's figures become the kept ones, and the kept ones
#                the run before: written to tests/bench/perf_budget.json and
#                README's performance table, which shows both (commit both). Keep a run on a quiet machine (load average
#                under 1) with the default 600 s.
# --build-times  also time README's first command (configure and build the
#                window, without ccache) and the ordinary build and tests of
#                .ci/run in fresh build directories: many minutes on 2 cores
#
# The dashboard runs under Xvfb at 1600x1000 (bench_dashboard --xvfb). While
# the 30-robot run goes on, bench_teleop_latency measures input to wire, so
# that figure is "busy". Load from other programs skews every figure: the
# load average is printed with the table.
set -euo pipefail
cd "$(dirname "$0")/../.."

build=build
seconds=600
build_times=0
keep=0
while [ $# -gt 0 ]; do
    case "$1" in
        --build) build="$2"; shift 2 ;;
        --seconds) seconds="$2"; shift 2 ;;
        --keep) keep=1; shift ;;
        --build-times) build_times=1; shift ;;
        *) echo "usage: $0 [--build DIR] [--seconds S] [--keep] [--build-times]" >&2; exit 2 ;;
    esac
done
python=/usr/bin/python3
[ -x "$python" ] || python=python3

# The benchmarks are built only when asked for: turn them on in the build
# directory and build the ones this table runs (quick when they are current).
bench="$build/tests/bench"
benchmarks=(bench_dashboard bench_recording bench_history_memory bench_teleop_latency bench_wake_cost bench_battery_health)
generator=()
[ -f "$build/CMakeCache.txt" ] || generator=(-G Ninja)
cmake -S . -B "$build" "${generator[@]}" -DROOMBA_BUILD_BENCHMARKS=ON > /dev/null
cmake --build "$build" --target "${benchmarks[@]}"

log=$(mktemp -d)
trap 'rm -rf "$log"' EXIT

field() { # field FILE REGEX: the first capture group of the last matching line
    sed -nE "s/$2/\1/p" "$1" | tail -1
}

echo "Running: one robot (default docks, then every dock), 30 robots with the teleop benchmark beside,"
echo "the recording, history and wake-up benchmarks; about $((seconds * 3 / 60 + 4)) minutes."

"$bench/bench_dashboard" --xvfb --seconds "$seconds" > "$log/one.txt"
"$bench/bench_dashboard" --xvfb --seconds "$seconds" --every-dock > "$log/every.txt"

"$bench/bench_dashboard" --xvfb --seconds "$seconds" --fleet > "$log/fleet.txt" &
fleet_pid=$!
# Input to wire while 30 robots stream and draw: after they have started.
sleep $((seconds < 60 ? seconds / 4 : 15))
QT_QPA_PLATFORM=offscreen "$bench/bench_teleop_latency" > "$log/teleop_busy.txt"
wait "$fleet_pid"
QT_QPA_PLATFORM=offscreen "$bench/bench_teleop_latency" > "$log/teleop_quiet.txt"

"$bench/bench_recording" > "$log/recording.txt"
"$bench/bench_wake_cost" > "$log/wake.txt"
"$bench/bench_battery_health" > "$log/battery.txt"
"$bench/bench_history_memory" --minutes 60 --robots 30 > "$log/history.txt"

cpu_one=$(field "$log/one.txt" '^result:.* cpu ([0-9.]+) %.*')
cpu_every=$(field "$log/every.txt" '^result:.* cpu ([0-9.]+) %.*')
cpu_fleet=$(field "$log/fleet.txt" '^result:.* cpu ([0-9.]+) %.*')
start_one=$(field "$log/one.txt" '^result:.* first live frame ([0-9-]+) ms.*')
start_fleet=$(field "$log/fleet.txt" '^result:.* first live frame ([0-9-]+) ms.*')
rss_fleet=$(field "$log/fleet.txt" '^result:.* rss ([0-9.]+) MiB.*')
history30=$(field "$log/history.txt" '^30 robots .*: ([0-9.]+) MiB in all, RSS ([0-9.]+) MiB.*')
history30_rss=$(field "$log/history.txt" '^30 robots .*RSS ([0-9.]+) MiB.*')
open_s=$(field "$log/recording.txt" '^open +([0-9.]+) s.*')
seek=$(field "$log/recording.txt" '^seek .*p99 ([0-9.]+) ms.*')
teleop_busy=$(grep -E '^all ' "$log/teleop_busy.txt" | sed -nE 's/.*p99 +([0-9.]+) ms.*/\1/p' | sort -n | tail -1)
teleop_quiet=$(grep -E '^all ' "$log/teleop_quiet.txt" | sed -nE 's/.*p99 +([0-9.]+) ms.*/\1/p' | sort -n | tail -1)

figures=(cpu_one="$cpu_one" cpu_every="$cpu_every" cpu_fleet="$cpu_fleet" rss_fleet="$rss_fleet"
         history30="$history30" open_s="$open_s" seek_p99="$seek" teleop_quiet="$teleop_quiet"
         teleop_busy="$teleop_busy" start_one="$start_one" start_fleet="$start_fleet")
load=$(cut -d' ' -f1-3 /proc/loadavg)
echo
echo "Figures after ${seconds} s runs under Xvfb 1600x1000; load average $load (30 robots: histories ${history30} MiB, RSS ${history30_rss} MiB)"
# The machine's floor: one robot wakes the robots' thread 66.7 times a
# second and the window's 5 times at rest (the display's quiet pace),
# whatever each wake-up then does.
wake_bare=$(field "$log/wake.txt" '^result: wake-up ([0-9.]+) us bare.*')
wake_qt=$(field "$log/wake.txt" '^result: .* ([0-9.]+) us in a Qt event loop.*')
echo "A wake-up costs ${wake_bare} us of CPU here (${wake_qt} us in a Qt event loop): one robot's ~72 a second" \
    "are $("$python" -c "print(f'{71.7 * $wake_qt / 1e4:.2f}')") % of a core before any work"
battery_ns=$(field "$log/battery.txt" '^result: battery health ([0-9.]+) ns per frame.*')
battery_us=$(field "$log/battery.txt" '^result: .* ([0-9.]+) us per report.*')
echo "The pack's health costs ${battery_ns} ns per frame (${battery_us} us for the report, once a second)"
if [ "$keep" = 1 ]; then
    "$python" tests/bench/perf_budget.py keep tests/bench/perf_budget.json README.md "${figures[@]}" \
        --date "$(date -u +%Y-%m-%d)" --commit "$(git rev-parse --short HEAD 2>/dev/null || echo '?')" \
        --seconds "$seconds" --load "$load"
else
    "$python" tests/bench/perf_budget.py compare tests/bench/perf_budget.json "${figures[@]}"
fi

row() { printf '| %-58s | %-26s | %-22s |\n' "$1" "$2" "$3"; }
if [ "$build_times" = 1 ]; then
    fresh=$(mktemp -d)
    start=$SECONDS
    cmake -S . -B "$fresh/window" -G Ninja > /dev/null
    cmake --build "$fresh/window" --target roomba-dashboard > /dev/null
    window_s=$((SECONDS - start))
    start=$SECONDS
    cmake -S . -B "$fresh/all" -G Ninja -DROOMBA_BUILD_BENCHMARKS=OFF > /dev/null # as CI builds
    cmake --build "$fresh/all" > /dev/null
    QT_QPA_PLATFORM=offscreen ctest --test-dir "$fresh/all" -j "$(nproc)" --timeout 600 > "$log/ctest.txt" \
        || echo "ctest failed: see the tests' output with ctest --test-dir $fresh/all --rerun-failed"
    tests_s=$((SECONDS - start))
    row "README's first command: build to the window (no ccache)" "${window_s} s" "<= 150 s"
    row "ordinary build and tests, as CI (no ccache)" "${tests_s} s" "<= 300 s"
    rm -rf "$fresh"
fi
