#!/usr/bin/env bash
# The survey's conclusion slide, measured (docs/conclusion.md): one point per technique at its
# default parameters on columns, terrain and Sponza, error against the ray-traced reference and
# cost as ms_ratio to `standard` from one interleaved bench run per scene; then the table and the
# error-vs-time figure (docs/images/conclusion-<scene>.svg).
#
# TECHNIQUES is the one list; presets that this build does not have (e.g. `virtual`,
# `alias-free` before their branches are merged) are skipped with a message. SCENES likewise:
# a scene that does not load (Sponza without shared/scenes-real) is skipped.
# Needs a built build/shadowlab ($SHADOWLAB overrides). FRAMES / SIZE override the defaults.
set -euo pipefail
cd "$(dirname "$0")/.."
SL="${SHADOWLAB:-build/shadowlab}"
TECHNIQUES="${TECHNIQUES:-standard pcf lispsm tsm psm cascaded sdsm virtual alias-free pixel-correct silhouette}"
SCENES="${SCENES:-columns terrain sponza}"
FRAMES="${FRAMES:-10}"
SIZE="${SIZE:-640x360}"
out=docs/bench/conclusion
mkdir -p "$out" docs/images

# Preset ids this build has: the first word of every "  id  help" line of `shadowlab list`.
available=$("$SL" list | sed -n '/^techniques/,/^parameters/p' | awk '/^  [a-z]/ {print $1}')
list=()
for t in $TECHNIQUES; do
  if grep -qx -- "$t" <<<"$available"; then
    list+=("$t")
  else
    echo "bench-conclusion: preset '$t' does not exist in this build: skipped" >&2
  fi
done
# standard first: ms_ratio is relative to the first entry.
csv=$(IFS=,; echo "${list[*]}")

for scene in $SCENES; do
  if ! "$SL" bench --scene "$scene" --techniques "$csv" --size "$SIZE" --frames "$FRAMES" \
       --json "$out/$scene.json"; then
    echo "bench-conclusion: scene '$scene' failed or is missing (see above): skipped" >&2
    rm -f "$out/$scene.json"
  fi
done
python3 scripts/conclusion-table.py "$out" docs/images > "$out/table.md"
echo "bench-conclusion: $out/table.md, docs/images/conclusion-*.svg" >&2
