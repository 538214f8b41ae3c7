#!/usr/bin/env bash
# Reproduces the soft-shadow numbers of techniques/soft/README.md: every technique against the
# area-light reference (64 light samples) on soft, contact and Sponza under a sun disk, 60 still
# frames (so pixel-correct-soft's figure is after 60 frames), ms_ratio against `standard`.
set -euo pipefail
cd "$(dirname "$0")/.."
bench() { "${SHADOWLAB:-build/shadowlab}" bench "$@"; }
out=docs/bench/soft
mkdir -p "$out"
for scene in contact soft sponza-sun-disk; do
  bench --scene "$scene" --techniques standard,pcf,poisson,pcss,pcss-cascaded,pixel-correct-soft,vssm,convolution-soft --camera default \
    --size 320x180 --frames 60 --warmup 0 --json "$out/$scene.json"
  # pixel-correct-soft after 1 and 20 still frames (error of the last measured frame).
  for n in 1 20; do
    bench --scene "$scene" --techniques pixel-correct-soft --camera default --size 320x180 --frames "$n" --warmup 0 \
      --json "$out/$scene-pcsoft-$n.json"
  done
done
python3 scripts/soft-table.py "$out" > "$out/table.md"
