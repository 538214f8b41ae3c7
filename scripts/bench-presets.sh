#!/usr/bin/env bash
# The every-preset cost table of docs/performance.md (issue "Interactive everywhere"): one
# interleaved bench per scene with standard first and then every preset `shadowlab list` names,
# each with its defaults, 1280x720. The timer is the renderer's: cpu-fence (glFinish + steady
# clock) on llvmpipe, GL timer queries on a GPU. Writes docs/bench/performance/<tag>-<scene>.json;
# scripts/performance-table.py turns them into the table. PRESETS=a,b,... replaces the list;
# FRAMES, WARMUP, SIZE and BENCH_OUT change the run.
#   scripts/bench-presets.sh [tag] [scene...]    (tag default: llvmpipe; scenes: basic terrain sponza)
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${SHADOWLAB:-build/shadowlab}"
tag="${1:-llvmpipe}"
shift || true
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(basic terrain sponza)
out="${BENCH_OUT:-docs/bench/performance}"
mkdir -p "$out"
presets=${PRESETS:-}
[ -n "$presets" ] || presets=$("$bin" list | awk '/^techniques/ {on=1; next} /^parameters/ {on=0} on && /^  [a-z]/ {print $1}' |
  grep -vx standard | paste -sd, -)
for scene in "${scenes[@]}"; do
  if [ "$scene" = sponza ] && [ ! -d "${SHADOWLAB_SHARED:-../shared}/scenes-real" ]; then
    echo "bench-presets: scenes-real not found, sponza skipped" >&2
    continue
  fi
  "$bin" bench --scene "$scene" --techniques "standard,$presets" --size "${SIZE:-1280x720}" \
    --frames "${FRAMES:-10}" --warmup "${WARMUP:-3}" --json "$out/$tag-$scene.json" ||
    echo "bench-presets: the $scene bench failed" >&2
done
