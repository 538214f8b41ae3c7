#!/usr/bin/env bash
# One command: install what is missing, build, run the whole test suite (GPU tests run
# headless on Mesa's llvmpipe through EGL; the window smoke test under Xvfb), then build the
# same suite with clang, AddressSanitizer + UBSan and the libFuzzer targets (CMakePresets.json,
# preset asan, into build-asan/), run it again, and fuzz the scene, glTF and tour loaders for 30 s
# each on that build (scripts/fuzz.sh).
# SHADOWLAB_SKIP_ASAN=1 / SHADOWLAB_SKIP_FUZZ=1 skip those locally; CI runs all three.
# Arguments go to both ctest runs (e.g. -R Scene). Exits non-zero if either run fails.
# The last lines are the stage breakdown (seconds per build and test stage) and the slowest tests.
#
# scripts/test.sh --fast [ctest args]: the check for every edit. Builds incrementally, then runs
# the unit tier (no GL) and the GL smoke test (labels in tests/labels.cmake), nothing else.
set -euo pipefail
cd "$(dirname "$0")/.."

fast=0
if [ "${1:-}" = --fast ]; then
  fast=1
  shift
fi

logs="$(mktemp -d)"
trap 'rm -rf "$logs"' EXIT

# ctest's closing lines: "N% tests passed, M tests failed out of K", the time, failures.
summary() { sed -n '/tests passed, /,$p' "$1"; }

# Stage timing: "name seconds" lines, printed last.
stage_start=$(date +%s)
stage() {
  local now
  now=$(date +%s)
  printf '%s\t%s\n' "$1" "$((now - stage_start))" >>"$logs/stages.txt"
  stage_start=$now
}
print_stages() {
  echo "== time per stage (s) =="
  awk -F'\t' '{ printf "  %-28s %6d\n", $1, $2; total += $2 } END { printf "  %-28s %6d\n", "total", total }' "$logs/stages.txt"
}
# The slowest tests of a ctest log, and how many ran over the stage's limit (seconds). Never
# fails the script (awk reads all its input: no SIGPIPE under pipefail).
slowest() {
  local log="$1" limit="$2"
  echo "slowest tests:"
  { sed -n 's/^ *[0-9]*\/[0-9]* Test *#[0-9]*: \([^ ]*\) .* \([0-9.]*\) sec$/\2 \1/p' "$log" | sort -rn |
    awk -v l="$limit" 'NR <= 8 { printf "  %8.1f s  %s\n", $1, $2 } $1 > l { n++ } END { printf "tests over %d s: %d\n", l, n }'; } || true
}

scripts/setup.sh
stage build

# Mesa's shader cache in the build folder, not the home directory: a fresh clone starts cold (as
# on CI), and the ASan run below finds the programs the normal run compiled.
export MESA_SHADER_CACHE_DIR="${MESA_SHADER_CACHE_DIR:-$PWD/build/mesa-shader-cache}"

if [ "$fast" = 1 ]; then
  status=0
  (cd build && ctest --output-on-failure -j2 -L 'unit|smoke' "$@") 2>&1 | tee "$logs/fast.txt" || status=$?
  stage "fast tier (unit + smoke)"
  echo
  summary "$logs/fast.txt"
  print_stages
  exit "$status"
fi


normal=0
(cd build && ctest --output-on-failure -j2 "$@") 2>&1 | tee "$logs/normal.txt" || normal=$?
stage "tests (build/)"

asan=skipped
if [ "${SHADOWLAB_SKIP_ASAN:-0}" != 1 ]; then
  echo
  echo "== AddressSanitizer + UBSan build (build-asan/) =="
  asan=0
  if cmake --preset asan >/dev/null && cmake --build --preset asan -j"$(nproc)"; then
    stage "asan build"
    # The preset sets LP_NUM_THREADS=0: llvmpipe rasterizes in the calling thread. With Mesa
    # threads alive at exit, LeakSanitizer's own thread tracer crashes ("Tracer caught signal 11",
    # no leak reported) in some GL tests, a different set each run: with rasterizer threads two
    # tests crashed it in 3 of 3 runs, 0 of 4 without. Mesa's shader cache stays on (its thread
    # too): without it every process compiles its programs with LLVM again, three quarters of a
    # GL test's time (EveryPreset on sponza: 63 s without, 17 s with, normal build), and the
    # programs the normal run above compiled are found in it. The cache thread crashed the tracer
    # in DeepGl.TexelCurveFollowsTheReference in 4 of 4 runs, and
    # ReferenceIndependentReal.EngineAgreesWithTheGridCaster crashes it every time (Embree's
    # threads, it seems). The likely cause, found later: GCC 12's __tls_get_addr interceptor takes
    # a malloc'd dynamic TLS block that lands 16 bytes past a page boundary for a pre-2.25 glibc
    # header and reads garbage bounds (fixed upstream after GCC 13 / LLVM 16); the preset's
    # ASAN_OPTIONS therefore set intercept_tls_get_addr=0. It struck a test whose child process
    # crashed the tracer (Bench.PathMeasuresFlicker: exit code 1), which the check below cannot
    # excuse; scripts/asan-tracer-check.py stays for any crash of another cause.
    ctest --preset asan "$@" 2>&1 | tee "$logs/asan.txt" || asan=$?
    # Where every failure is a test that passed and then crashed LeakSanitizer's tracer (no
    # report of any sanitizer), the run counts as passed and says so for each such test.
    if [ "$asan" != 0 ] && scripts/asan-tracer-check.py build-asan | tee "$logs/asan-tracer.txt"; then asan=0; fi
    stage "tests (build-asan/)"
  else
    echo "asan: configure or build failed" | tee "$logs/asan.txt"
    asan=1
  fi
fi

# The loaders under libFuzzer, 30 s per target, on the ASan build (its fuzz targets were built
# with it). SHADOWLAB_SKIP_FUZZ=1 skips it locally.
fuzz=skipped
if [ "${SHADOWLAB_SKIP_FUZZ:-0}" != 1 ]; then
  echo
  echo "== libFuzzer: scene, glTF and tour loaders (build-asan/) =="
  fuzz=0
  scripts/fuzz.sh 30 2>&1 | tee "$logs/fuzz.txt" || fuzz=$?
  stage "fuzz (3 x 30 s)"
fi

# Both results last, the normal run's first, so neither scrolls away behind the other.
echo
echo "== normal build (build/) =="
summary "$logs/normal.txt"
echo "== AddressSanitizer + UBSan build (build-asan/) =="
if [ "$asan" = skipped ]; then
  echo "skipped (SHADOWLAB_SKIP_ASAN=1)"
else
  summary "$logs/asan.txt"
  grep -q 'tests passed, ' "$logs/asan.txt" || cat "$logs/asan.txt"
  [ ! -s "$logs/asan-tracer.txt" ] || cat "$logs/asan-tracer.txt"
fi
echo "== libFuzzer (build-asan/) =="
if [ "$fuzz" = skipped ]; then echo "skipped (SHADOWLAB_SKIP_FUZZ=1)"; else tail -n 1 "$logs/fuzz.txt"; fi
echo "== normal build: per-test times =="
slowest "$logs/normal.txt" 30
if [ "$asan" != skipped ]; then
  echo "== AddressSanitizer + UBSan build: per-test times =="
  slowest "$logs/asan.txt" 120
fi
print_stages
if [ "$normal" != 0 ] || { [ "$asan" != 0 ] && [ "$asan" != skipped ]; } ||
  { [ "$fuzz" != 0 ] && [ "$fuzz" != skipped ]; }; then exit 1; fi
