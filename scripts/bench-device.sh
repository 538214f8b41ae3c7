#!/usr/bin/env bash
# One round of GPU measurements on a lent device box (no Debian packages there): the every-preset
# table (scripts/bench-presets-gpu.sh), then the benches whose llvmpipe numbers the docs quote
# beside a GPU column: the pre-filtered blur over the receivers' texels on and off, the point
# layouts under street's lamp (faces kept by a still camera, and every face drawn each frame),
# the paraboloid's tessellation budget, and the cost per shadowed lamp. Each bench is one
# interleaved run timed by GL timer queries (`gpu-query`), written as it finishes so a cut-off
# round keeps the ones done. Expects the portable bundle at .device/ (scripts/portable-bundle.sh
# .device) and Sponza under .device/shared/scenes-real. BENCHES="name ..." runs only those
# (presets: the every-preset table).
#   scripts/bench-device.sh OUT_DIR [tag]
set -uo pipefail
cd "$(dirname "$0")/.."
out="${1:?usage: bench-device.sh OUT_DIR [tag]}"
tag="${2:-gpu}"
benches="${BENCHES:-presets skip-unread-basic point-street lights-shadowed skip-unread-terrain skip-unread-sponza
  point-street-redraw paraboloid-error point-away optimized-pcf logpsm-tessellate
  pixel-correct-cost-basic pixel-correct-cost-columns pixel-correct-cost-sponza}"
start=$(date +%s)
wanted() { [[ " $(echo $benches) " == *" $1 "* ]]; }
if wanted presets; then
  FRAMES=${FRAMES:-20} WARMUP=${WARMUP:-5} scripts/bench-presets-gpu.sh "$out" "$tag" || exit 1
  echo "presets table: $(($(date +%s) - start)) s"
fi
printf '#!/bin/sh\nexec %s/scripts/portable-run.sh %s/.device/shadowlab-portable.tar.xz "$@"\n' "$PWD" "$PWD" >/tmp/sl
chmod +x /tmp/sl
export SHADOWLAB_SHARED=$PWD/.device/shared
bench() { # name, then bench arguments
  local name=$1
  shift
  wanted "$name" || return 0
  local t0=$(date +%s)
  timeout 150 /tmp/sl bench "$@" --json "$out/$tag-$name.json" >"$out/$tag-$name.log" 2>&1 ||
    { echo "bench $name failed:"; tail -5 "$out/$tag-$name.log"; }
  echo "$name: $(($(date +%s) - t0)) s"
}
prefiltered=standard,vsm,esm,evsm2,evsm4,convolution,gaussian,ewgf,msm,lvsm,msm16
point=standard,cube,tetrahedron,dual-paraboloid,cube-pcf,tetrahedron-pcf,dual-paraboloid-pcf
bench skip-unread-basic --scene basic --techniques $prefiltered --sweep filter.skip_unread=on,off \
  --size 1280x720 --frames 20 --warmup 5
bench point-street --scene street --techniques $point --size 1280x720 --frames 20 --warmup 5 --samples 1
bench lights-shadowed --scene docs/bench/many-lights/street-16-lamps.json --techniques cube,tetrahedron \
  --set point.keep_faces=0 --set lights.texel_budget=0 --sweep lights.shadowed=1,2,4,8,16 \
  --size 1280x720 --frames 10 --warmup 3 --samples 1
bench skip-unread-terrain --scene terrain --techniques $prefiltered --sweep filter.skip_unread=on,off \
  --size 1280x720 --frames 20 --warmup 5
bench skip-unread-sponza --scene sponza --techniques $prefiltered --sweep filter.skip_unread=on,off \
  --size 1280x720 --frames 20 --warmup 5
bench point-street-redraw --scene street --techniques $point --set point.keep_faces=0 \
  --size 1280x720 --frames 20 --warmup 5 --samples 1
bench paraboloid-error --scene street --techniques standard,cube,dual-paraboloid --set point.keep_faces=0 \
  --sweep paraboloid.max_error=0.25,0.5,2,16 --size 1280x720 --frames 20 --warmup 5 --samples 1
bench point-away --scene street --camera away --techniques standard,cube,tetrahedron,dual-paraboloid \
  --set point.keep_faces=0 --size 1280x720 --frames 20 --warmup 5 --samples 1
# The GPU columns of techniques/optimized_pcf, layouts (logpsm's tessellation) and accumulation
# (pixel-correct's overhead at the paper's 1024²).
bench optimized-pcf --scene basic --techniques standard,pcf,optimized-pcf --sweep pcf.kernel=3,5,7 \
  --size 1280x720 --frames 20 --warmup 5
bench logpsm-tessellate --scene columns --techniques standard,logpsm --sweep logpsm.tessellate=on,off \
  --size 1280x720 --frames 20 --warmup 5
for scene in basic columns sponza; do
  bench pixel-correct-cost-$scene --scene $scene --techniques standard,pixel-correct --set shadowmap.size=1024 \
    --size 1280x720 --frames 30 --warmup 5
done
echo "round: $(($(date +%s) - start)) s"
