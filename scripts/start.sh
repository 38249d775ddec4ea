#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# README command 1: install dependencies, build a release and start LayerPaint on the built-in
# trefoil knot. Arguments are passed to layerpaint (e.g. a model file).
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release -j"$(nproc)"
exec ./build/release/app/layerpaint "$@"
