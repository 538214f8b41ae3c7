#!/usr/bin/env bash
# Reproduces the tables of techniques/irregular/README.md: accuracy and cost of alias-free
# against standard per scene, then its growth with the image size and with the triangle count.
# Needs a built build/shadowlab ($SHADOWLAB overrides) and, for Sponza, ../shared/scenes-real.
set -euo pipefail
cd "$(dirname "$0")/../.."
bench() { "${SHADOWLAB:-build/shadowlab}" bench "$@"; }
out=techniques/irregular/bench
tmp=$(mktemp -d)
mkdir -p "$out"

for scene in basic columns thin-casters terrain spotlight sponza techniques/irregular/sponza-sun.json; do
  name=$(basename "$scene" .json)
  bench --scene "$scene" --techniques standard,alias-free --size 320x180 --frames 5 --warmup 2 \
    --json "$out/scene-$name.json"
done
for size in 160x90 320x180 640x360 1280x720; do
  bench --scene basic --techniques standard,alias-free --size "$size" --frames 5 --warmup 2 --json "$out/size-basic-$size.json"
done
for size in 160x90 320x180 640x360; do
  bench --scene techniques/irregular/sponza-sun.json --techniques standard,alias-free --size "$size" --frames 3 \
    --warmup 1 --json "$out/size-sponza-sun-$size.json"
done
# basic with its sphere tessellated finer: segments² triangles (2 k, 16 k, 66 k, 262 k).
for seg in 48 128 256 512; do
  python3 - "$seg" "$tmp/basic-$seg.json" <<'PY'
import json, sys
s = json.load(open("assets/scenes/basic.json"))
for o in s["objects"]:
    if o.get("shape") == "sphere": o["segments"] = int(sys.argv[1])
s["name"] = "basic-sphere-%s" % sys.argv[1]
json.dump(s, open(sys.argv[2], "w"))
PY
  bench --scene "$tmp/basic-$seg.json" --techniques standard,alias-free --size 320x180 --frames 5 --warmup 2 \
    --json "$out/tris-basic-$seg.json"
done
# The grid's light view: the focused map's against LiSPSM's (the preset's), at 1280x720.
for scene in basic columns terrain sponza; do
  bench --scene "$scene" --techniques standard,alias-free --sweep technique.layout=focused,lispsm --size 1280x720 \
    --frames 6 --warmup 2 --samples 1 --json "$out/grid-layout-$scene-1280x720.json"
done
python3 techniques/irregular/bench_table.py "$out" > "$out/tables.md"
rm -rf "$tmp"
