#!/usr/bin/env bash
# Packs build/shadowlab with every shared library it loads (glibc and its loader included, and
# glvnd's libEGL/libOpenGL that libepoxy opens at run time) into one archive, so the benchmark
# can run on a machine that has a GPU driver but none of the Debian packages (a lent GPU box).
# Run there with scripts/portable-run.sh. Usage: scripts/portable-bundle.sh OUT_DIR
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:?usage: portable-bundle.sh OUT_DIR}"
stage=$(mktemp -d)
cp build/shadowlab "$stage/"
ldd build/shadowlab | awk '/=> \// {print $3} /^\t\/lib64/ {print $1}' | while read -r lib; do
  cp -L "$lib" "$stage/"
done
for lib in libEGL.so.1 libGLdispatch.so.0 libOpenGL.so.0 libGL.so.1 libGLX.so.0; do
  cp -L "/lib/x86_64-linux-gnu/$lib" "$stage/"
done
mkdir -p "$out"
tar -C "$stage" -cJf "$out/shadowlab-portable.tar.xz" .
rm -rf "$stage"
ls -la "$out/shadowlab-portable.tar.xz"
