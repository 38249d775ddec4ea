#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Fuzzes the model loaders and the project reader with libFuzzer for a bounded time (the two
# targets side by side), starting from a seed corpus made here from Debian's assimp-testmodels
# (and, when the dev build exists, projects written by its layerpaint-cli). Any crash, sanitizer
# report, timeout or out-of-memory fails. Inputs that fail are kept in build/fuzz/run/artifacts.
# Usage: scripts/fuzz.sh [SECONDS]   (per target, default 40)
# The random seed is fixed (LAYERPAINT_FUZZ_SEED, default 1) so a CI run can be repeated; set it
# to explore other paths.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-40}
models=${LAYERPAINT_ASSIMP_MODELS:-/usr/share/assimp/models}

echo "== fuzz build (clang, libFuzzer, ASan/UBSan)"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz

work=build/fuzz/run
rm -rf "$work"
mkdir -p "$work/seeds-loaders" "$work/seeds-project" "$work/corpus-loaders" \
    "$work/corpus-project" "$work/artifacts"

# Seeds for fuzz_loaders: the first byte picks the loader (its kExtensions order).
seeds=0
while IFS= read -r -d '' file; do
    ext=${file##*.}
    case ${ext,,} in
        glb) selector=0 ;;
        gltf) selector=1 ;;
        obj) selector=2 ;;
        ply) selector=3 ;;
        stl) selector=4 ;;
        off) selector=5 ;;
        *) continue ;;
    esac
    name=$(printf '%s' "$file" | md5sum | cut -c1-16)
    { printf "\\x$(printf %02x "$selector")"; cat "$file"; } >"$work/seeds-loaders/$name"
    seeds=$((seeds + 1))
done < <(find "$models" -type f -size -64k \( -iname '*.glb' -o -iname '*.gltf' -o -iname '*.obj' \
    -o -iname '*.ply' -o -iname '*.stl' -o -iname '*.off' \) -print0 2>/dev/null)

# Seeds for fuzz_project: binary glTF files, LayerPaint projects and their JSON.
while IFS= read -r -d '' file; do
    cp "$file" "$work/seeds-project/$(printf '%s' "$file" | md5sum | cut -c1-16).glb"
done < <(find "$models" -type f -iname '*.glb' -size -256k -print0 2>/dev/null)
cli=build/dev/app/layerpaint-cli
if [[ -x "$cli" ]]; then
    printf '%s' '{"size":"96x72","target":{"kind":"texture","resolution":512},"operations":[
        {"op":"set-brush","color":"#2060ff","radius":6},{"op":"stroke","points":[[30,30],[60,40]]}]}' \
        >"$work/texture.json"
    printf '%s' '{"size":"96x72","target":{"kind":"vertex-colors"},"operations":[
        {"op":"set-mode","layer_aware":false},{"op":"stroke","points":[[40,30],[50,40]]}]}' \
        >"$work/colors.json"
    "$cli" paint builtin:row --cpu --script "$work/texture.json" \
        --out "$work/seeds-project/row-texture.glb" >/dev/null
    "$cli" paint builtin:hexring --cpu --script "$work/colors.json" \
        --out "$work/seeds-project/ring-colors.glb" >/dev/null
    for project in "$work/seeds-project/row-texture.glb" "$work/seeds-project/ring-colors.glb"; do
        length=$(od -An -t u4 -j 12 -N 4 "$project" | tr -d ' ')
        dd if="$project" of="${project%.glb}.json" bs=1 skip=20 count="$length" status=none
    done
fi
echo "seeds: $seeds model files, $(ls "$work/seeds-project" | wc -l) project inputs"

# Leaks inside Assimp's error paths are not ours to fix; everything else is checked.
export ASAN_OPTIONS=detect_leaks=0:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1
run() {
    local name=$1
    "build/fuzz/tests/fuzz/$name" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=3072 \
        -max_len=65536 -close_fd_mask=1 -print_final_stats=1 -seed="${LAYERPAINT_FUZZ_SEED:-1}" \
        -artifact_prefix="$work/artifacts/$name-" "$work/corpus-${name#fuzz_}" \
        "$work/seeds-${name#fuzz_}" >"$work/$name.log" 2>&1
}
status=0
run fuzz_loaders &
loaders=$!
run fuzz_project &
project=$!
wait "$loaders" || status=1
wait "$project" || status=1
for name in fuzz_loaders fuzz_project; do
    echo "== $name"
    grep -E '^(#[0-9]+ +DONE|Done|stat::number_of_executed_units|stat::peak_rss_mb)' \
        "$work/$name.log" || true
    if grep -qE 'ERROR: (AddressSanitizer|libFuzzer|LeakSanitizer)|runtime error|Test unit written' \
        "$work/$name.log"; then
        status=1
        tail -n 60 "$work/$name.log"
    fi
done
if ((status != 0)); then
    echo "fuzzing found a problem: see $work/*.log and $work/artifacts" >&2
fi
exit "$status"
