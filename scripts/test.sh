#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# README command 2: install dependencies, build, and run the whole test suite headless: GL tests on
# EGL (llvmpipe), widget tests each on an Xvfb of its own (tests/ui/own_session.sh); then the
# core/render/CLI tests again under ASan/UBSan; then the loaders and the project reader are fuzzed
# for a fixed number of runs from fixed seeds, going on after each finding (one in our code fails;
# one in a third-party parser must be turned into an error by the importer process) and the
# regression corpus is opened through the importer process. Exits non-zero on any failure. A
# second run reuses the builds.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh --test
jobs=$(nproc)

echo "== format check"
bash scripts/check-format.sh

echo "== dev build (warnings are errors)"
cmake --preset dev
cmake --build --preset dev -j"$jobs"

echo "== tests"
ctest --preset dev -j"$jobs"

echo "== ASan/UBSan build and tests (no GUI)"
cmake --preset asan
cmake --build --preset asan -j"$jobs"
ASAN_OPTIONS=detect_leaks=0 ctest --preset asan -j"$jobs"

echo "== fuzzing (libFuzzer, 30000 runs per target from seeds 1, 2, ..., both at once)"
bash scripts/fuzz.sh --runs 30000
