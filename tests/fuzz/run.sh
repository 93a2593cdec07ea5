#!/usr/bin/env bash
# Runs fuzz targets one after another, each for SECONDS (default 600), with
# its seed corpus, its dictionary where there is one and the leak
# suppressions, and prints for each: runs, minutes and findings.
#
#   tests/fuzz/run.sh [--build DIR] [--work DIR] [SECONDS [TARGET...]]
#
# TARGET is a name without the fuzz_ prefix (default: all). The corpus a
# target grows goes to WORK/TARGET (default /tmp/roomba-fuzz), findings to
# WORK/TARGET-findings; the seed corpus in the tree is only read.
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="$here/../../build-fuzz"
work=/tmp/roomba-fuzz
while [[ $# -gt 0 && $1 == --* ]]; do
    case $1 in
    --build) build=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    *) echo "run.sh: unknown option $1" >&2; exit 2 ;;
    esac
done
seconds=${1:-600}
shift || true
targets=("$@")
[[ ${#targets[@]} -eq 0 ]] && targets=(stream_parser script_disassembler command_text command_decoder recording song_files room_file)

status=0
for t in "${targets[@]}"; do
    binary="$build/tests/fuzz/fuzz_$t"
    [[ -x $binary ]] || { echo "run.sh: $binary is not built" >&2; exit 2; }
    mkdir -p "$work/$t" "$work/$t-findings"
    args=(-max_total_time="$seconds" -print_final_stats=1 -artifact_prefix="$work/$t-findings/")
    [[ -f $here/$t.dict ]] && args+=(-dict="$here/$t.dict")
    # libsmf prints a warning for each malformed MIDI file; the reports
    # still come through.
    [[ $t == song_files ]] && args+=(-close_fd_mask=2)
    log="$work/$t.log"
    start=$(date +%s)
    LSAN_OPTIONS="suppressions=$here/lsan.supp:print_suppressions=0" \
        "$binary" "${args[@]}" "$work/$t" "$here/corpus/$t" >"$log" 2>&1
    code=$?
    minutes=$(awk -v s="$(( $(date +%s) - start ))" 'BEGIN { printf "%.1f", s / 60 }')
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    findings=$(find "$work/$t-findings" -type f | wc -l)
    echo "fuzz_$t: ${runs:-?} runs in $minutes minutes, exit $code, findings: $findings (log $log)"
    [[ $code -ne 0 || $findings -ne 0 ]] && status=1
done
exit $status
