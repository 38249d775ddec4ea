#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Fuzzes the model loaders and the project reader with libFuzzer (the two targets side by side),
# as the importer process runs them (in process, ASan/UBSan), starting from a seed corpus made
# here from Debian's assimp-testmodels (and, when the dev build exists, projects written by its
# layerpaint-cli). Any crash, sanitizer report, timeout or out-of-memory fails.
#
#   scripts/fuzz.sh --runs N      CI: N inputs per target from seed 1 and a seed corpus listed in
#                                 sorted order (no wall-clock budget); then the regression corpus
#                                 (tests/data/crashers) and any finding through the dev build's
#                                 layerpaint-cli, out of process: each must give a clean error. A
#                                 finding fails if it is in our code or the importer process does
#                                 not contain it; one in a third-party parser is reported (add it
#                                 to tests/data/crashers).
#   scripts/fuzz.sh [SECONDS]     exploration: SECONDS per target (default 1800), seed
#                                 LAYERPAINT_FUZZ_SEED (default: random, printed). What it finds is
#                                 in build/fuzz/run/artifacts and is replayed through the dev
#                                 build's layerpaint-cli: a crash there is one the importer process
#                                 turns into an error (add it to tests/data/crashers, see README).
#
# Inputs of tests/data/crashers are skipped by the targets (LAYERPAINT_FUZZ_KNOWN_CRASHERS): they
# crash third-party parsers, which only the importer process can contain.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=
seconds=1800
case ${1:-} in
    --runs) runs=${2:?--runs needs a number} ;;
    '') ;;
    *) seconds=$1 ;;
esac
models=${LAYERPAINT_ASSIMP_MODELS:-/usr/share/assimp/models}
cli=build/dev/app/layerpaint-cli

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
    name=$(printf '%s' "${file#"$models"/}" | md5sum | cut -c1-16)
    { printf "\\x$(printf %02x "$selector")"; cat "$file"; } >"$work/seeds-loaders/$name"
    seeds=$((seeds + 1))
done < <({
    find "$models" -type f -size -64k \( -iname '*.glb' -o -iname '*.gltf' -o -iname '*.obj' \
        -o -iname '*.ply' -o -iname '*.stl' -o -iname '*.off' \) -print0 2>/dev/null
    # Compressed glTF (Draco, meshopt) made by tests/core/io/gltf_compression_test.cpp, and the
    # damaged ones of the regression corpus: the targets skip those exact bytes, not their mutants.
    find tests/data/gltf tests/data/crashers -type f -iname '*.glb' -print0
} | sort -z)

# Seeds for fuzz_project: binary glTF files, LayerPaint projects and their JSON.
while IFS= read -r -d '' file; do
    cp "$file" "$work/seeds-project/$(printf '%s' "${file#"$models"/}" | md5sum | cut -c1-16).glb"
done < <(find "$models" -type f -iname '*.glb' -size -256k -print0 2>/dev/null | sort -z)
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
    rm -f "$work"/seeds-project/*.bak
    for project in "$work/seeds-project/row-texture.glb" "$work/seeds-project/ring-colors.glb"; do
        length=$(od -An -t u4 -j 12 -N 4 "$project" | tr -d ' ')
        dd if="$project" of="${project%.glb}.json" bs=1 skip=20 count="$length" status=none
    done
fi
# The seed lists in a fixed order (libFuzzer reads a folder in the file system's order), comma
# separated as -seed_inputs=@FILE wants them.
for name in loaders project; do
    (cd "$work/seeds-$name" && ls | LC_ALL=C sort | sed "s|^|$PWD/|" | paste -sd,) \
        >"$work/seeds-$name.txt"
done
echo "seeds: $seeds model files, $(ls "$work/seeds-project" | wc -l) project inputs"

export LAYERPAINT_FUZZ_KNOWN_CRASHERS=$PWD/tests/data/crashers
# Leaks inside Assimp's error paths are not ours to fix; everything else is checked.
# Allocations beyond 3 GiB fail the same way everywhere (not by what the machine can map).
export ASAN_OPTIONS=detect_leaks=0:allocator_may_return_null=1:max_allocation_size_mb=3072
export UBSAN_OPTIONS=print_stacktrace=1
if [[ -n $runs ]]; then
    seed=1
    echo "seed $seed, $runs runs per target"
else
    seed=${LAYERPAINT_FUZZ_SEED:-$((RANDOM * 32768 + RANDOM + 1))}
    echo "seed $seed, $seconds s per target (LAYERPAINT_FUZZ_SEED=$seed repeats the start)"
fi
# The targets' scratch files: the same path on every machine (see tests/fuzz/fuzz_input.h), so
# one run at a time per machine.
exec 9>/tmp/layerpaint-fuzz.lock
flock -n 9 || { echo "another scripts/fuzz.sh is running on this machine" >&2; exit 1; }
run() {
    local name=$1 target=${1#fuzz_} mode
    if [[ -n $runs ]]; then
        mode=(-runs="$runs" -seed_inputs=@"$work/seeds-$target.txt")
    else
        # Goes on after a finding (in child processes) to use the whole time.
        mode=(-max_total_time="$seconds" -fork=1 -ignore_crashes=1 -ignore_timeouts=1
            -ignore_ooms=1 "$work/seeds-$target")
    fi
    LAYERPAINT_FUZZ_SCRATCH=/tmp/layerpaint-fuzz-$target \
        "build/fuzz/tests/fuzz/$name" -seed="$seed" -timeout=20 -rss_limit_mb=3072 -max_len=65536 \
        -close_fd_mask=1 -print_final_stats=1 -artifact_prefix="$work/artifacts/$name-" \
        "$work/corpus-$target" "${mode[@]}" >"$work/$name.log" 2>&1
}
status=0
run fuzz_loaders &
loaders=$!
run fuzz_project &
project=$!
# A finding makes libFuzzer exit non-zero; whether it fails is decided below by where it is. A
# run that ended non-zero without a finding (it could not start, ...) fails.
declare -A exited
wait "$loaders" && exited[fuzz_loaders]=0 || exited[fuzz_loaders]=$?
wait "$project" && exited[fuzz_project]=0 || exited[fuzz_project]=$?
# Where a finding failed: the innermost stack frame that is not the sanitizer's, libFuzzer's or
# the C/C++ runtime's. "ours" (core/ or the targets) is a bug of this code; anything else is
# in a third-party parser, which only the importer process can contain (checked below).
origin() {
    awk '/ERROR: |CHECK failed|deadly signal|runtime error|Test unit written/ { on = 1 }
        on && /#[0-9]+ 0x[0-9a-f]+ / {
        if ($0 ~ /compiler-rt|sanitizer|fuzzer::|__interceptor|libc\.so|libc-start|sysdeps|libio\/|nptl|csu\/|libstdc\+\+|libgcc|LLVMFuzzerTestOneInput|\/c\+\+\/[0-9]+\/|\/usr\/include\/c\+\+|fuzz_(loaders|project)\+0x|asan_|operator (new|delete)/) next
        print ($0 ~ /\/(core|tests\/fuzz)\/([a-z_]+\/)*[a-z_]+\.(cpp|h):/ ? "ours" : "third-party"); exit }' "$1"
}
for name in fuzz_loaders fuzz_project; do
    echo "== $name"
    grep -E '^(#[0-9]+ +DONE|Done|stat::number_of_executed_units|stat::peak_rss_mb|INFO: fuzzed for)' \
        "$work/$name.log" | tail -n 4 || true
    if grep -qE 'ERROR: (AddressSanitizer|libFuzzer|LeakSanitizer)|Sanitizer: CHECK failed|runtime error|Test unit written' \
        "$work/$name.log"; then
        where=$(origin "$work/$name.log")
        echo "finding in ${where:-unknown} code:"
        grep -E 'ERROR: |runtime error|#[0-9]+ 0x[0-9a-f]+ in ' "$work/$name.log" | head -n 30
        # In CI a finding in our code fails; one in a third-party parser fails only if the
        # importer process does not contain it (below): it then belongs in tests/data/crashers.
        [[ -n $runs && $where != third-party ]] && status=1
    elif ((exited[$name] != 0)); then
        echo "$name ended with status ${exited[$name]} without a finding:"
        tail -n 20 "$work/$name.log"
        status=1
    fi
done
# Exploring, findings are expected (third-party parsers): what counts is whether the
# application contains them, checked below.
[[ -z $runs ]] && status=0

# A file through the public, out-of-process loader: a one-line error or a model, never a crash.
# Prints the outcome; returns 1 if the CLI itself died or printed more than one line.
contained() {
    local file=$1 out code
    out=$("$cli" info "$file" 2>&1 >/dev/null) && code=0 || code=$?
    if ((code >= 128)) || [[ $(printf '%s' "$out" | wc -l) -gt 0 ]]; then
        echo "NOT CONTAINED (exit $code): $file: $out"
        return 1
    fi
    echo "  ${out:-loaded}"
}
if [[ -x $cli ]]; then
    if [[ -n $runs ]]; then
        echo "== regression corpus through $cli (importer process)"
        while IFS= read -r -d '' file; do
            contained "$file" || status=1
        done < <(find tests/data/crashers -type f -print0 | sort -z)
    fi
    # What the fuzzers found, as the application would open it.
    extensions=(glb gltf obj ply stl off)
    found=0 turned=0
    for artifact in "$work"/artifacts/fuzz_loaders-*; do
        [[ -f $artifact ]] || continue
        selector=$(od -An -t u1 -N 1 "$artifact" | tr -d ' ')
        file="$work/replay-$(basename "$artifact").${extensions[selector % 6]}"
        tail -c +2 "$artifact" >"$file"
        found=$((found + 1))
        if out=$(contained "$file"); then
            [[ $out == *"the importer stopped"* ]] && turned=$((turned + 1))
            echo "$out"
        else
            echo "$out"
            status=1
        fi
    done
    for artifact in "$work"/artifacts/fuzz_project-*; do
        [[ -f $artifact ]] || continue
        found=$((found + 1))
        if [[ $(head -c 4 "$artifact") == glTF ]]; then
            file="$work/replay-$(basename "$artifact").glb"
            cp "$artifact" "$file"
            out=$("$cli" export "$file" --out "$work/replay-out.glb" 2>&1 >/dev/null) && code=0 ||
                code=$?
            if ((code >= 128)); then
                echo "NOT CONTAINED (exit $code): $file: $out"
                status=1
            else
                [[ $out == *"the importer stopped"* ]] && turned=$((turned + 1))
                echo "  ${out:-loaded}"
            fi
        else
            echo "IN PROCESS: $artifact (project JSON, read by the application itself)"
            status=1
        fi
    done
    echo "$found inputs failed in process; the importer process turned $turned of them (crashes" \
        "or hangs) into errors"
else
    echo "(no dev build: the regression corpus and the findings are not replayed out of process)"
fi
if ((status != 0)); then
    echo "fuzzing found a problem: see $work/*.log and $work/artifacts" >&2
fi
exit "$status"
