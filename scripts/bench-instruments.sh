#!/usr/bin/env bash
# Reproduces the numbers of docs/benchmarks.md and docs/reference.md that depend on the reference
# and the metrics: the size sweep on basic, flicker along basic/orbit, the soft-light check, and
# every technique on the scenes whose numbers the reference's ray origin changed (terrain,
# dueling-frusta, the grazing-sun scene). Needs a built build/shadowlab ($SHADOWLAB overrides).
set -euo pipefail
cd "$(dirname "$0")/.."
bench() { "${SHADOWLAB:-build/shadowlab}" bench "$@"; }
out=docs/bench

bench --scene basic --techniques standard,pcf,poisson,uniform --sweep shadowmap.size=256,1024,4096 \
  --size 640x360 --frames 10 --json "$out/basic/bench.json" --report "$out/basic"
bench --scene basic --techniques standard,pcf --path orbit --size 640x360 --frames 10 --json "$out/basic-orbit.json"
bench --scene soft --techniques standard,pcf,poisson --size 320x180 --frames 5 --json "$out/soft.json"

mkdir -p "$out/instruments"
for scene in terrain dueling-frusta basic columns thin-casters grazing; do
  bench --scene "$scene" --techniques standard,uniform,pcf,lispsm,pixel-correct,pixel-correct-lispsm \
    --set shadowmap.size=2048 --size 320x180 --frames 60 --json "$out/instruments/$scene.json"
done
python3 scripts/bench-table.py "$out/basic/bench.json" > "$out/basic/table.md"
python3 scripts/instrument-tables.py "$out/instruments" > "$out/instruments/tables.md"
