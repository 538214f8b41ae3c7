#!/usr/bin/env bash
# Reproduces the termination-criteria table of techniques/adaptive/README.md: the four criteria
# over one page machinery (virtual = footprint, tiled = distance, adaptive = edges,
# fitted-virtual = grid + CPU quadtree) and the focused 4096² map, on columns, terrain and
# Sponza (skipped with a message where shared/scenes-real is absent). Writes
# docs/bench/adaptive/criteria-<scene>.json and the table docs/bench/adaptive/criteria.md.
set -euo pipefail
cd "$(dirname "$0")/.."
out=docs/bench/adaptive
mkdir -p "$out"
scenes=()
for scene in columns terrain sponza; do
  if [ "$scene" = sponza ] && [ ! -d ../shared/scenes-real ]; then
    echo "bench-criteria: ../shared/scenes-real not found, sponza skipped" >&2
    continue
  fi
  "${SHADOWLAB:-build/shadowlab}" bench --scene "$scene" --techniques virtual,tiled,adaptive,fitted-virtual,standard \
    --set shadowmap.size=4096 --size 640x360 --frames 6 --warmup 2 --json "$out/criteria-$scene.json"
  scenes+=("$out/criteria-$scene.json")
done
python3 - "$out/criteria.md" "${scenes[@]}" <<'PY'
import json, re, sys
rows = ["| scene | technique | wrong pixels | pages requested | leaves / CPU fit ms | marking pass ms | ms_ratio (p25-p75) |",
        "|---|---|---|---|---|---|---|"]
for path in sys.argv[2:]:
    d = json.load(open(path))
    for e in d["entries"]:
        status = e.get("status", {}).get("layout", "") if isinstance(e.get("status"), dict) else e.get("status", "")
        req = re.search(r"requested (\d+)", status)
        fit = re.search(r"(\d+) leaves, finest level -?\d+, ([\d.]+) ms", status)
        mark = [p["ms"] for p in e.get("passes", []) if p["name"].startswith("virtual.pages")]
        r = e["ms_ratio"]
        rows.append("| %s | %s | %.3f %% | %s | %s | %s | %.2f (%.2f-%.2f) |" % (
            d["scene"], e["label"], e["error"]["wrong_pixel_pct"], req.group(1) if req else "",
            "%s / %s" % fit.groups() if fit else "", "%.1f" % mark[0] if mark else "",
            r["median"], r["p25"], r["p75"]))
open(sys.argv[1], "w").write("\n".join(rows) + "\n")
print("\n".join(rows))
PY
