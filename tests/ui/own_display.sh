#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs a command (a widget test) on an X server of its own: a fresh Xvfb on the first free display
# number, which Xvfb itself picks and reports (-displayfd), so that two at once never race for one.
# Widget tests on one shared server take each other's keyboard focus; each on its own, ctest runs
# them side by side with everything else. The server ends with the command; its exit code is the
# command's.
set -uo pipefail
dir=$(mktemp -d "${TMPDIR:-/tmp}/layerpaint-display.XXXXXX") || exit 1
mkfifo "$dir/display"
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp 3>"$dir/display" >"$dir/xvfb.log" 2>&1 &
xvfb=$!
trap 'kill "$xvfb" 2>/dev/null; wait "$xvfb" 2>/dev/null; rm -rf "$dir"' EXIT
trap 'exit 143' TERM INT
read -r display <"$dir/display"
if [[ -z ${display:-} ]]; then
    echo "own_display.sh: Xvfb did not start:" >&2
    cat "$dir/xvfb.log" >&2
    exit 1
fi
DISPLAY=:$display "$@"
