#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# How long the GUI's window stops answering at each step of a short session on a large model:
# runs the GUI under Xvfb with LAYERPAINT_STALL_MS (ui/shell/stall_meter.h), drives it with
# xdotool (open, orbit, a stroke, undo, redo) and prints the longest stall of each step and
# the GUI's peak resident memory. A benchmark for docs/performance.md, not a test: the figures
# depend on the machine.
#
#   scripts/measure-stalls.sh [--build DIR] [--triangles N] [--settle SECONDS]
#
# Needs xvfb (Xvfb) and xdotool. Each step waits --settle seconds (default 10; a 10M-triangle
# model needs more for opening, see --open-wait) before the next.
set -euo pipefail

build=build/dev
triangles=2000000
settle=10
openWait=60
while [[ $# -gt 0 ]]; do
    case "$1" in
    --build) build="$2"; shift 2 ;;
    --triangles) triangles="$2"; shift 2 ;;
    --settle) settle="$2"; shift 2 ;;
    --open-wait) openWait="$2"; shift 2 ;;
    *) echo "measure-stalls.sh: unknown option $1" >&2; exit 2 ;;
    esac
done
for tool in Xvfb xdotool; do
    command -v "$tool" >/dev/null || { echo "measure-stalls.sh: $tool is missing" >&2; exit 2; }
done

display=:$((90 + RANDOM % 100))
work=$(mktemp -d)
Xvfb "$display" -screen 0 1280x800x24 >/dev/null 2>&1 &
xvfb=$!
cleanup() {
    [[ -n "${gui:-}" ]] && kill "$gui" 2>/dev/null || true
    kill "$xvfb" 2>/dev/null || true
    rm -rf "$work"
}
trap cleanup EXIT
export DISPLAY=$display
sleep 1

# Settings of a fresh user, so no saved layout or recovery dialog gets in the way.
export XDG_CONFIG_HOME="$work/config" XDG_DATA_HOME="$work/data"
LAYERPAINT_STALL_MS=50 "$build/app/layerpaint" "builtin:knot?triangles=$triangles" \
    2>"$work/log" &
gui=$!

steps=()
times=()
step() { # name: marks when the step starts, as Unix time (the log's stalls say theirs)
    steps+=("$1")
    times+=("$(date +%s.%N)")
}

step open
sleep "$openWait"
xdotool key Escape # a first start's Quick Guide
sleep 2
step orbit
xdotool mousemove 640 420 mousedown 2
for i in $(seq 1 15); do xdotool mousemove $((640 + 8 * i)) 420; sleep 0.05; done
xdotool mouseup 2
sleep "$settle"
step stroke
xdotool mousemove 560 400 mousedown 1
for i in $(seq 1 20); do xdotool mousemove $((560 + 3 * i)) 400; sleep 0.05; done
xdotool mouseup 1
sleep "$settle"
step undo
xdotool key ctrl+z
sleep "$settle"
step redo
xdotool key ctrl+shift+z
sleep "$settle"
peak=$(awk '/VmHWM/ {print $2}' "/proc/$gui/status")
step end

printf '%-8s %s\n' step "longest stall (ms)"
for ((i = 0; i + 1 < ${#steps[@]}; ++i)); do
    longest=$(awk -v from="${times[i]}" -v to="${times[i + 1]}" '
        / stall / { ms = $3; at = $6 + 0; if (at >= from && at < to && ms > max) max = ms }
        END { print max + 0 }' "$work/log")
    printf '%-8s %s\n' "${steps[i]}" "$longest"
done
echo "peak resident: $((peak / 1024)) MiB"
echo "every stall of 50 ms and more:"
grep ' stall ' "$work/log" || true
