#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Measures how well the plain and the surface connection tests follow the mesh on the built-in
# and real models from several views (README "Connectivity quality"). Needs a build (build/dev
# or $BUILD) and assimp-testmodels. Prints a Markdown table.
set -euo pipefail
cd "$(dirname "$0")/.."
cli=${BUILD:-build/dev}/app/layerpaint-cli
models=(builtin:trefoil builtin:hexring builtin:row
        /usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
        /usr/share/assimp/models/OBJ/WusonOBJ.obj /usr/share/assimp/models/OBJ/spider.obj)
views=("0,0,1.6" "30,20,1.6" "120,-35,1.2" "210,60,2")
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for model in "${models[@]}"; do
    for view in "${views[@]}"; do
        dir="$out/$(basename "$model")_${view//,/_}"
        "$cli" layers "$model" --orbit "$view" --size 1280x720 --out "$dir" >/dev/null
    done
done
python3 - "$out" <<'PY'
import json, pathlib, sys, collections
rows = collections.OrderedDict()
for summary in sorted(pathlib.Path(sys.argv[1]).glob("*/summary.json")):
    s = json.loads(summary.read_text())
    name = s["model"].split("/")[-1]
    for test, q in s["connectivity_quality"].items():
        r = rows.setdefault((name, test), collections.Counter())
        r["same"] += q["same_triangle_pairs"]
        r["same_broken"] += round(q["same_triangle_disconnected_share"] * q["same_triangle_pairs"])
        r["adjacent"] += q["adjacent_triangle_pairs"]
        r["adjacent_broken"] += round(q["adjacent_triangle_disconnected_share"] * q["adjacent_triangle_pairs"])
        r["connected"] += q["connected_pairs"]
        r["cross"] += round(q["cross_component_share"] * q["connected_pairs"])
print("| model | test | same-triangle pairs broken | adjacent-triangle pairs broken | connected pairs across components |")
print("|---|---|---|---|---|")
pct = lambda a, b: f"{100.0 * a / b:.3f} % ({a:,} of {b:,})" if b else "–"
for (name, test), r in rows.items():
    print(f"| {name} | {test} | {pct(r['same_broken'], r['same'])} | {pct(r['adjacent_broken'], r['adjacent'])} | {pct(r['cross'], r['connected'])} |")
PY
