#!/usr/bin/env bash
# Reproduces techniques/adaptive/README.md: the paged virtual shadow map against the focused
# 4096² map on columns and terrain (wrong pixels, shadow_texels, cost ratio), cached and not.
set -euo pipefail
cd "$(dirname "$0")/.."
out=docs/bench/adaptive
mkdir -p "$out"
for scene in columns terrain; do
  "${SHADOWLAB:-build/shadowlab}" bench --scene "$scene" --techniques standard,virtual --set shadowmap.size=4096 \
    --sweep virtual.lod_bias=0,-1 --sweep virtual.cache=on,off --size 640x360 --frames 10 --warmup 2 \
    --json "$out/$scene.json"
done
