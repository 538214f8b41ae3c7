#!/usr/bin/env bash
# The every-preset table on a GPU machine that lacks the Debian packages (a lent device box):
# renders each preset once small to find any the driver rejects, then benches the rest with GL
# timer queries (scripts/bench-presets.sh). Expects the portable bundle at .device/ (made here by
# scripts/portable-bundle.sh .device) and Sponza under .device/shared/scenes-real.
#   scripts/bench-presets-gpu.sh OUT_DIR [tag]
set -uo pipefail
cd "$(dirname "$0")/.."
out="${1:?usage: bench-presets-gpu.sh OUT_DIR [tag]}"
tag="${2:-gpu}"
root=$PWD
printf '#!/bin/sh\nexec %s/scripts/portable-run.sh %s/.device/shadowlab-portable.tar.xz "$@"\n' "$root" "$root" >/tmp/sl
chmod +x /tmp/sl
export SHADOWLAB_SHARED=$root/.device/shared
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.mem --format=csv >"$out/machine.txt" 2>&1
nproc >>"$out/machine.txt"
if ! /tmp/sl render --scene basic --technique standard --size 320x180 --out "$out/check.png" --stats "$out/check.json" \
  >"$out/check.log" 2>&1; then
  cat "$out/check.log"
  ls /usr/local/nvidia/lib64 /usr/local/nvidia/share/glvnd/egl_vendor.d /usr/share/glvnd/egl_vendor.d 2>&1 | head -40
  EGL_LOG_LEVEL=debug /tmp/sl render --scene basic --technique standard --size 64x64 --out /tmp/x.png 2>&1 | tail -20
  exit 1
fi
grep -o '"renderer"[^,]*' "$out/check.json"
ok=()
for p in $(/tmp/sl list | awk '/^techniques/ {on=1; next} /^parameters/ {on=0} on && /^  [a-z]/ {print $1}'); do
  if /tmp/sl render --scene basic --technique "$p" --size 160x90 --frames 2 --out /tmp/p.png >/tmp/p.log 2>&1; then
    ok+=("$p")
  else
    echo "preset $p failed:" >>"$out/check.log"
    tail -5 /tmp/p.log >>"$out/check.log"
  fi
done
echo "presets that render: ${#ok[@]}"
grep -A5 failed "$out/check.log" | head -40
list=$(printf '%s\n' "${ok[@]}" | grep -vx standard | paste -sd, -)
# The SM clock while the benches run (the card idles at a low clock between light frames).
(while sleep 5; do nvidia-smi --query-gpu=clocks.sm,utilization.gpu --format=csv,noheader; done) >"$out/clocks.txt" 2>&1 &
clocks=$!
SHADOWLAB=/tmp/sl BENCH_OUT="$out" PRESETS="$list" FRAMES="${FRAMES:-20}" WARMUP="${WARMUP:-5}" \
  scripts/bench-presets.sh "$tag" basic sponza terrain 2>&1 | grep -v '^bench: \[' | tail -30
kill $clocks 2>/dev/null
echo "SM clock during the benches (MHz, utilization):"; sort "$out/clocks.txt" | uniq -c | sort -rn | head -5
