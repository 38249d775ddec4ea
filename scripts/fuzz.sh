#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Fuzzes the model loaders and the project reader with libFuzzer (the two targets side by side),
# as the importer process runs them (in process, ASan/UBSan), starting from a seed corpus made
# here from Debian's assimp-testmodels (and, when the dev build exists, projects written by its
# layerpaint-cli).
#
# libFuzzer stops at its first finding (crash, sanitizer report, timeout, out-of-memory). So
# that a finding does not end the search, each target runs in segments: after a finding the next
# segment starts with the next seed, from the seed files and everything the earlier segments
# added to the corpus (listed in sorted order), skipping the inputs found so far, until the
# budget is spent (at most 32 segments). Every finding is classified by the innermost frame of
# its stack: "ours" (core/, the targets) or "third-party" (a parser only the importer process can
# contain). A finding of ours is run again alone, in a fresh process of its target: one that
# passes there is "after an earlier input" (see alone() below). Every finding is replayed through
# the dev build's layerpaint-cli, out of process, which must give a one-line error naming the
# file (or load it) and not crash. A summary ends the output.
#
#   scripts/fuzz.sh --runs N      CI: N inputs per target in all (the segments' executed inputs,
#                                 each restart's corpus replay included), seeds 1, 2, ... (no
#                                 wall-clock budget). Fails on a finding in our code that fails
#                                 alone too, on a replay (of a finding or of tests/data/crashers)
#                                 that crashes or does not give a clean error, on a budget not
#                                 spent in 32 segments, and on a run that ends without a finding
#                                 but not cleanly. A third-party finding the importer process
#                                 contains is only reported (add it to tests/data/crashers), as is
#                                 one after an earlier input.
#   scripts/fuzz.sh [SECONDS]     exploration: SECONDS per target in all (default 1800), seeds
#                                 from LAYERPAINT_FUZZ_SEED (default: random, printed). Findings
#                                 are in build/fuzz/run/artifacts; the script fails only if a
#                                 replay through layerpaint-cli is not contained.
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
    # A project under the inputs' 64 KiB with what restorePaintLayers reads: a paint layer with a
    # mask, a fill layer with a blend mode, and a brush tip loaded from an image.
    "$cli" export "$work/seeds-project/row-texture.glb" --format png --out "$work/tip.png" \
        >/dev/null
    printf '%s' '{"size":"96x72","target":{"kind":"texture","resolution":512},"operations":[
        {"op":"set-brush","color":"#2060ff","radius":6,"tip":"'"$PWD/$work/tip.png"'"},
        {"op":"stroke","points":[[30,30],[60,40]]},{"op":"layer-add","name":"paint"},
        {"op":"stroke","points":[[20,30],[70,35]]},{"op":"mask-add"},
        {"op":"set-brush","color":"#000000"},{"op":"stroke","points":[[40,20],[45,50]]},
        {"op":"layer-add","name":"fill","kind":"fill","values":{"base_color":"#ff8000"}},
        {"op":"layer-set","blend":"multiply","opacity":0.5}]}' >"$work/layers.json"
    "$cli" paint 'builtin:knot?triangles=1000' --cpu --script "$work/layers.json" \
        --out "$work/seeds-project/knot-layers.glb" >/dev/null
    rm -f "$work"/seeds-project/*.bak
    for project in "$work/seeds-project/row-texture.glb" "$work/seeds-project/ring-colors.glb" \
        "$work/seeds-project/knot-layers.glb"; do
        length=$(od -An -t u4 -j 12 -N 4 "$project" | tr -d ' ')
        dd if="$project" of="${project%.glb}.json" bs=1 skip=20 count="$length" status=none
    done
fi
# The seed lists in a fixed order (libFuzzer reads a folder in the file system's order).
for name in loaders project; do
    (cd "$work/seeds-$name" && ls | LC_ALL=C sort | sed "s|^|$PWD/|") >"$work/seeds-$name.list"
done
echo "seeds: $seeds model files, $(ls "$work/seeds-project" | wc -l) project inputs"

# Leaks inside Assimp's error paths are not ours to fix; everything else is checked.
# Allocations beyond 3 GiB fail the same way everywhere (not by what the machine can map).
export ASAN_OPTIONS=detect_leaks=0:allocator_may_return_null=1:max_allocation_size_mb=3072
export UBSAN_OPTIONS=print_stacktrace=1
# The targets decode images in process, through the image codecs module of the fuzz build.
export LAYERPAINT_IMAGE_CODECS=$PWD/build/fuzz/app/layerpaint-image-codecs.so
if [[ -n $runs ]]; then
    seed=1
    echo "seeds from $seed, $runs runs per target"
else
    seed=${LAYERPAINT_FUZZ_SEED:-$((RANDOM * 32768 + RANDOM + 1))}
    echo "seeds from $seed, $seconds s per target (LAYERPAINT_FUZZ_SEED=$seed repeats the start)"
fi
# A cap on restarts, so that a shallow crash cannot turn the run into restarts only.
max_segments=32
# What makes two runs of the same tree part, as far as it can be switched off: address space
# randomization (heap addresses reach libFuzzer's table of compared values through pointer
# comparisons, and the table's slots are picked by the caller's address), reading the corpus
# folder again every second and giving memory back to the system when the resident size is high.
norandom=()
if setarch "$(uname -m)" -R true 2>/dev/null; then
    norandom=(setarch "$(uname -m)" -R)
else
    echo "(setarch -R is not available: runs with address space randomization)"
fi
[[ -z $runs ]] && max_segments=1000
# The targets' scratch files: the same path on every machine (see tests/fuzz/fuzz_input.h), so
# one run at a time per machine.
exec 9>/tmp/layerpaint-fuzz.lock
flock -n 9 || { echo "another scripts/fuzz.sh is running on this machine" >&2; exit 1; }

# A finding as the file a user would open: for fuzz_loaders the input without its first byte,
# with the extension that byte picks; for fuzz_project the input, .glb or .json.
extensions=(glb gltf obj ply stl off)
user_file() {
    local name=$1 artifact=$2 out=$3 selector
    if [[ $name == fuzz_loaders ]]; then
        selector=$(od -An -t u1 -N 1 "$artifact" | tr -d ' ')
        tail -c +2 "$artifact" >"$out.${extensions[${selector:-0} % 6]}"
        echo "$out.${extensions[${selector:-0} % 6]}"
    elif [[ $(head -c 4 "$artifact") == glTF ]]; then
        cp "$artifact" "$out.glb" && echo "$out.glb"
    else
        cp "$artifact" "$out.json" && echo "$out.json"
    fi
}

# One target, segment after segment until its budget is spent. Writes per segment
# $work/NAME-K.log, and $work/NAME.findings (segment, inputs run before it ended, artifact),
# $work/NAME.runs and $work/NAME.end (why it stopped: "budget", "segments" or "error").
fuzz_target() {
    local name=$1 target=${1#fuzz_} segment=0 executed=0 started=$SECONDS code ran log artifact
    local known=$work/known-$target budget dict=()
    # The project state's keys, for the byte mutations (the target's own mutator edits the JSON).
    [[ $target == project ]] && dict=(-dict=tests/fuzz/fuzz_project.dict)
    mkdir -p "$known"
    cp tests/data/crashers/* "$known/"
    : >"$work/$name.findings"
    echo budget >"$work/$name.end"
    while :; do
        segment=$((segment + 1))
        if [[ -n $runs ]]; then
            budget=(-runs=$((runs - executed)))
        else
            budget=(-max_total_time=$((seconds - (SECONDS - started))))
        fi
        mkdir -p "$work/corpus-$target/$segment"
        { cat "$work/seeds-$target.list"
          find "$work/corpus-$target" -type f | LC_ALL=C sort; } | paste -sd, \
            >"$work/inputs-$target-$segment.txt"
        log=$work/$name-$segment.log
        LAYERPAINT_FUZZ_KNOWN_CRASHERS=$known LAYERPAINT_FUZZ_SCRATCH=/tmp/layerpaint-fuzz-$target \
            "${norandom[@]}" "build/fuzz/tests/fuzz/$name" -seed=$((seed + segment - 1)) \
            -timeout=20 -rss_limit_mb=3072 -max_len=65536 -close_fd_mask=1 -print_final_stats=1 \
            -reload=0 -purge_allocator_interval=-1 \
            -artifact_prefix="$work/artifacts/$name-" "${budget[@]}" "${dict[@]}" \
            -seed_inputs=@"$work/inputs-$target-$segment.txt" "$work/corpus-$target/$segment" \
            >"$log" 2>&1 && code=0 || code=$?
        ran=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
        executed=$((executed + ${ran:-0}))
        artifact=$(sed -n 's/.*Test unit written to //p' "$log" | tail -n 1)
        if [[ -n $artifact && -f $artifact ]]; then
            echo "$segment $executed $artifact" >>"$work/$name.findings"
            # The next segments skip this exact input (not its mutants).
            user_file "$name" "$artifact" "$known/finding-$segment" >/dev/null
        elif ((code != 0)); then
            echo error >"$work/$name.end"
            break
        else
            break # the budget is spent
        fi
        if [[ -n $runs ]] && ((executed >= runs)); then break; fi
        if [[ -z $runs ]] && ((SECONDS - started >= seconds)); then break; fi
        if ((segment >= max_segments)); then
            echo segments >"$work/$name.end"
            break
        fi
    done
    echo "$executed $segment" >"$work/$name.runs"
}
# A file through the public, out-of-process loader: a one-line error naming the file and a
# non-zero exit (or a model, exit 0), never a crash. Prints the outcome; returns 1 otherwise.
contained() {
    local file=$1 out code
    out=$("$cli" info "$file" 2>&1 >/dev/null) && code=0 || code=$?
    if ((code >= 128)) || [[ $(printf '%s' "$out" | wc -l) -gt 0 ]] ||
        { ((code != 0)) && [[ $out != *"$file"* ]]; }; then
        echo "NOT CONTAINED (exit $code): $file: $out"
        return 1
    fi
    echo "${out:-loaded (exit 0)}"
}
# A project through the CLI (it opens the project out of process as the application does).
contained_project() {
    local file=$1 out code
    out=$("$cli" export "$file" --out "$work/replay-out.glb" 2>&1 >/dev/null) && code=0 || code=$?
    if ((code >= 128)) || [[ $(printf '%s' "$out" | wc -l) -gt 0 ]] ||
        { ((code != 0)) && [[ $out != *"$file"* ]]; }; then
        echo "NOT CONTAINED (exit $code): $file: $out"
        return 1
    fi
    echo "${out:-loaded (exit 0)}"
}
have_cli=0
[[ -x $cli ]] && have_cli=1
# The regression corpus through the importer process, beside the fuzzing (the importer's
# 30-second hang limit is waiting, not work).
if ((have_cli)) && [[ -n $runs ]]; then
    (
        corpus=0
        while IFS= read -r -d '' file; do
            if out=$(contained "$file"); then echo "  $out"; else echo "$out"; corpus=1; fi
        done < <(find tests/data/crashers -type f -print0 | sort -z)
        exit "$corpus"
    ) >"$work/corpus-replay.log" 2>&1 &
    corpus_replay=$!
fi
fuzz_target fuzz_loaders &
loaders=$!
fuzz_target fuzz_project &
project=$!
wait "$loaders" || true
wait "$project" || true
status=0
if [[ -n ${corpus_replay:-} ]]; then
    echo "== regression corpus through $cli (importer process)"
    wait "$corpus_replay" || status=1
    cat "$work/corpus-replay.log"
fi

# Where a finding failed: the innermost stack frame that is not the sanitizer's, libFuzzer's or
# the C/C++ runtime's. "ours" (core/ or the targets) is a bug of this code; anything else is
# in a third-party parser, which only the importer process can contain (checked below). A
# finding without such a frame (an out-of-memory seen by libFuzzer's RSS watch) counts as ours.
origin() {
    local where
    where=$(awk '/ERROR: |CHECK failed|deadly signal|runtime error|Test unit written/ { on = 1 }
        on && /#[0-9]+ 0x[0-9a-f]+ / {
        if ($0 ~ /compiler-rt|sanitizer|fuzzer::|__interceptor|libc\.so|libc-start|sysdeps|libio\/|nptl|csu\/|libstdc\+\+|libgcc|LLVMFuzzerTestOneInput|\/c\+\+\/[0-9]+\/|\/usr\/include\/c\+\+|fuzz_(loaders|project)\+0x|asan_|operator (new|delete)/) next
        print ($0 ~ /\/(core|tests\/fuzz)\/([a-z_]+\/)*[a-z_]+\.(cpp|h):/ ? "ours" : "third-party"); exit }' "$1")
    echo "${where:-ours}"
}

# A finding of ours, run again alone in a fresh process of its target (without the skip list,
# which holds it). The targets keep nothing from one input to the next, so a bug of our code
# fails there too. One that passes is the after-effect of an earlier input of the same process:
# Assimp is not instrumented, so its writes to freed or foreign heap memory go unseen until
# whatever next touches that memory fails (ASan's quarantine, libFuzzer's own tables or our
# code). Returns 0 if the input passes alone.
alone() {
    local name=$1 artifact=$2
    LAYERPAINT_FUZZ_SCRATCH=/tmp/layerpaint-fuzz-alone "${norandom[@]}" \
        "build/fuzz/tests/fuzz/$name" -timeout=20 -rss_limit_mb=3072 -max_len=65536 \
        "$artifact" >"$work/alone-$(basename "$artifact").log" 2>&1
}

summary=()
for name in fuzz_loaders fuzz_project; do
    if [[ ! -f $work/$name.runs ]]; then
        echo "$name: the fuzzing loop itself failed"
        status=1
        continue
    fi
    read -r executed segments <"$work/$name.runs"
    declare -A count=()
    lines=()
    echo "== $name: findings"
    while read -r -u 3 segment at artifact; do
        # By what happened, not the artifact's name (libFuzzer calls ASan's refused
        # allocations crashes).
        log=$work/$name-$segment.log
        if grep -q 'ERROR: libFuzzer: timeout' "$log"; then
            kind=timeout
        elif grep -qE 'out-of-memory|out of memory|allocation-size-too-big' "$log"; then
            kind=oom
        else
            kind=crash
        fi
        where=$(origin "$work/$name-$segment.log")
        if [[ $where == ours ]] && alone "$name" "$artifact"; then
            where=earlier
        fi
        count[$where-$kind]=$((${count[$where-$kind]:-0} + 1))
        echo "-- $where $kind (segment $segment, seed $((seed + segment - 1)), by input $at):" \
            "$artifact"
        [[ $where == earlier ]] &&
            echo "   (in our code, but it passes alone: $work/alone-$(basename "$artifact").log)"
        grep -E 'ERROR: |runtime error|#[0-9]+ 0x[0-9a-f]+ in ' "$work/$name-$segment.log" |
            head -n 12 || true
        [[ -n $runs && $where == ours ]] && status=1
        if ((have_cli)); then
            file=$(user_file "$name" "$artifact" "$work/replay-$(basename "$artifact")")
            if [[ $name == fuzz_project && $file == *.json ]]; then
                out="project JSON, read by the application itself (in process)"
            elif [[ $name == fuzz_project ]]; then
                out=$(contained_project "$file") || status=1
            else
                out=$(contained "$file") || status=1
            fi
            echo "   replay: $out"
            [[ $where != ours ]] && lines+=("    $where $kind $(basename "$artifact"): $out")
        else
            [[ -n $runs && $where != ours ]] && status=1
            [[ $where != ours ]] &&
                lines+=("    $where $kind $(basename "$artifact"): not replayed (no dev build)")
        fi
    done 3<"$work/$name.findings"
    end=$(cat "$work/$name.end")
    case $end in
        segments)
            [[ -n $runs ]] && status=1
            echo "$name: the budget was not spent in $max_segments segments (too many findings:" \
                "add them to tests/data/crashers or fix them)" ;;
        error)
            echo "$name ended without a finding but not cleanly:"
            tail -n 20 "$work/$name-$segments.log"
            status=1 ;;
    esac
    f() { echo "crash ${count[$1-crash]:-0}, oom ${count[$1-oom]:-0}, timeout ${count[$1-timeout]:-0}"; }
    summary+=("$name: $executed inputs run in $segments segment(s) (seeds $seed-$((seed + segments - 1)))$( [[ $end == budget ]] || echo ", stopped: $end")")
    summary+=("    ours: $(f ours); third-party: $(f third-party); after an earlier input: $(f earlier)")
    summary+=("${lines[@]}")
    unset count
done
echo "== summary"
printf '%s\n' "${summary[@]}"
# Exploring, findings are expected: what counts is whether the application contains them.
if [[ -z $runs ]]; then
    ((status != 0)) && echo "a finding is not contained by the application" >&2
elif ((status != 0)); then
    echo "fuzzing found a problem: see $work/*.log and $work/artifacts" >&2
fi
exit "$status"
