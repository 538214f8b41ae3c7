#!/usr/bin/env bash
# The numbers of techniques/reconstruction/README.md: silhouette maps against standard at equal
# map resolution (256² and the default 2048²) on basic, columns and the straight-edged boxes
# scene, and forward shadow mapping's holes against its splat size. One interleaved bench run per
# scene (ms_ratio relative to the first entry). Needs a built build/shadowlab ($SHADOWLAB overrides).
set -euo pipefail
cd "$(dirname "$0")/.."
bench() { "${SHADOWLAB:-build/shadowlab}" bench "$@"; }
out=docs/bench/reconstruction
mkdir -p "$out"
for scene in basic columns techniques/reconstruction/boxes.json; do
  name=$(basename "$scene" .json)
  bench --scene "$scene" --techniques standard,silhouette --sweep shadowmap.size=256,2048 \
    --size 640x360 --frames 10 --json "$out/$name.json"
  python3 scripts/bench-table.py "$out/$name.json" > "$out/$name.md"
done
bench --scene basic --techniques standard,forward --set shadowmap.size=512 --set forward.grow=off \
  --sweep forward.splat=1,2,4,8 \
  --size 640x360 --frames 5 --json "$out/forward-basic.json"
python3 scripts/bench-table.py "$out/forward-basic.json" > "$out/forward-basic.md"
