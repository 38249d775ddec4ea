#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Rewrites the committed compressed glTF files (tests/data/gltf/grid-*.glb and
# tests/data/crashers/glb-*.glb) with tests/tools/make_gltf_compression_data, built in the dev
# preset. The encoders are deterministic: on the same Draco and meshoptimizer versions the files
# come out byte for byte the same, and git shows no change.
set -euo pipefail
cd "$(dirname "$0")/.."
[[ -f build/dev/CMakeCache.txt ]] || cmake --preset dev
cmake --build --preset dev --target make_gltf_compression_data
build/dev/tests/tools/make_gltf_compression_data tests/data
git status --short tests/data/gltf tests/data/crashers
