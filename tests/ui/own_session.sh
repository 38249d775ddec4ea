#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs a command (a widget test) in a session of its own: a fresh Xvfb on the first free display
# number, which Xvfb itself picks and reports (-displayfd), so that two at once never race for one,
# and a fresh home folder, so that settings, recent files and autosave recovery files (Qt's test
# mode keeps them under $HOME/.qttest) are never shared. Widget tests sharing a server take each
# other's keyboard focus, and sharing a home they remove each other's autosave locks; each in a
# session of its own, ctest runs them side by side with everything else. Mesa's shader cache stays
# where it was, for every test to reuse. The session ends with the command; its exit code is the
# command's.
set -uo pipefail
dir=$(mktemp -d "${TMPDIR:-/tmp}/layerpaint-session.XXXXXX") || exit 1
mkfifo "$dir/display"
mkdir -m 700 "$dir/home" "$dir/runtime"
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp 3>"$dir/display" >"$dir/xvfb.log" 2>&1 &
xvfb=$!
trap 'kill "$xvfb" 2>/dev/null; wait "$xvfb" 2>/dev/null; rm -rf "$dir"' EXIT
trap 'exit 143' TERM INT
read -r display <"$dir/display"
if [[ -z ${display:-} ]]; then
    echo "own_session.sh: Xvfb did not start:" >&2
    cat "$dir/xvfb.log" >&2
    exit 1
fi
export XDG_CACHE_HOME="${XDG_CACHE_HOME:-${HOME:-/tmp}/.cache}"
HOME="$dir/home" XDG_RUNTIME_DIR="$dir/runtime" DISPLAY=:$display "$@"
