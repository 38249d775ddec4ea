#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs LayerPaint's build, run and test dependencies from Debian's archive (Debian 12).
# Usage: scripts/install-deps.sh [--test]   (--test adds what the headless test suite needs)
# Idempotent: when everything is installed already it touches nothing.
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config git
    qt6-base-dev libqt6opengl6-dev qt6-l10n-tools qt6-tools-dev qt6-tools-dev-tools
    libglm-dev libopenimageio-dev libtinygltf-dev libassimp-dev libepoxy-dev libegl-dev
    libgl-dev nlohmann-json3-dev libcli11-dev libgtest-dev libbenchmark-dev libeigen3-dev
    libdraco-dev libmeshoptimizer-dev
    libegl1 libgl1-mesa-dri qt6-qpa-plugins libqt6svg6 qt6-translations-l10n
)
if [[ "${1:-}" == "--test" ]]; then
    # qt6-base-private-dev: the widget tests deliver pen events through QWindowSystemInterface.
    # clang and its runtime (libFuzzer, sanitizers) for the fuzz targets (scripts/fuzz.sh).
    packages+=(xvfb xauth assimp-testmodels clang-format appstream desktop-file-utils
        qt6-base-private-dev clang libclang-rt-14-dev)
    # dpkg-dev (dpkg-shlibdeps) and lintian for the Debian package test (tests/app/deb_test.cmake).
    packages+=(dpkg-dev lintian)
fi

sudo=()
if [[ $(id -u) -ne 0 ]]; then
    sudo=(sudo)
fi

# The Khronos glTF validator (tests/tools/validate-gltf.cjs) the material tests run on written
# files, from the npm registry, with --test. Node.js and npm are the machine's own where it has
# them (Debian's npm package conflicts with other Node.js builds), else Debian's; without either
# the validator checks are skipped (they say so) and nothing else needs them.
install_validator() {
    [[ "${1:-}" == "--test" ]] || return 0
    if ! command -v npm >/dev/null; then
        echo "Installing: npm"
        "${sudo[@]}" apt-get update -qq || true
        DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends npm ||
            { echo "npm could not be installed: the tests that run the glTF validator will be skipped" >&2; return 0; }
    fi
    if ! NODE_PATH="$(npm root -g)" node -e "require('gltf-validator')" 2>/dev/null; then
        echo "Installing: gltf-validator (npm)"
        npm install -g --no-fund --no-audit gltf-validator ||
            echo "gltf-validator could not be installed: the tests that run it will be skipped" >&2
    fi
}

missing=()
for p in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
    [[ "$status" == "installed" ]] || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
    install_validator "${1:-}"
    exit 0
fi

echo "Installing: ${missing[*]}"
"${sudo[@]}" apt-get update -qq
# The downloaded .deb files go to a folder of their own, removed once they are installed (about
# 1.5 GB that the builds need more); apt's own cache is left as it was.
archives=$(mktemp -d)
trap '"${sudo[@]}" rm -rf "$archives"' EXIT
mkdir -p "$archives/partial" && chmod 755 "$archives"
DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends \
    -o Dir::Cache::Archives="$archives" "${missing[@]}"
install_validator "${1:-}"
