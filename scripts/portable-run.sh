#!/usr/bin/env bash
# Runs the shadowlab of a portable bundle (scripts/portable-bundle.sh) through the bundle's own
# loader, with NVIDIA's EGL vendor when the machine has one. Usage:
#   scripts/portable-run.sh BUNDLE.tar.xz shadowlab-args...
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bundle="${1:?usage: portable-run.sh BUNDLE.tar.xz args...}"
shift
dir=/tmp/shadowlab-portable
if [ ! -x "$dir/shadowlab" ]; then
  mkdir -p "$dir"
  tar -C "$dir" -xJf "$bundle"
fi
libs="$dir"
for d in /usr/local/nvidia/lib64 /usr/local/nvidia/lib /usr/lib/x86_64-linux-gnu; do
  [ -d "$d" ] && libs="$libs:$d"
done
for f in /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json /usr/share/glvnd/egl_vendor.d/10_nvidia.json; do
  if [ -f "$f" ]; then export __EGL_VENDOR_LIBRARY_FILENAMES="$f"; break; fi
done
export SHADOWLAB_SHADERS="${SHADOWLAB_SHADERS:-$root/shaders}" SHADOWLAB_ASSETS="${SHADOWLAB_ASSETS:-$root/assets}"
exec "$dir/ld-linux-x86-64.so.2" --library-path "$libs" "$dir/shadowlab" "$@"
