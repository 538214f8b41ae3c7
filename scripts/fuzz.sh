#!/usr/bin/env bash
# Fuzzes the scene and tour loaders with libFuzzer: scripts/fuzz.sh [SECONDS per target, default 30].
# Builds the targets of fuzz/ in the ASan build (CMakePresets.json preset asan: clang, ASan and
# UBSan, -DSHADOWLAB_FUZZ=ON; into build-asan/, on the core the ASan suite tests), then runs each
# target for SECONDS from a corpus of the repository's scenes, the real
# glTF files under $SHADOWLAB_SHARED/scenes-real (../shared by default, when present) and
# tests/fuzz-regressions/. A crash, sanitizer report, leak, or an input slower than 10 s fails;
# the input is kept under build-asan/fuzz-artifacts/ (add it to tests/fuzz-regressions/<target>/ and a
# test to tests/scene_fuzz_regression_test.cpp once fixed). Exits non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-30}"
case "$seconds" in '' | *[!0-9]*) echo "usage: scripts/fuzz.sh [SECONDS]" >&2; exit 2 ;; esac

if ! command -v clang++ >/dev/null; then
  echo "fuzz: clang++ not found (scripts/setup.sh installs clang and libclang-rt-dev)" >&2
  exit 1
fi
TARGETS="scene_json_fuzz gltf_fuzz tour_fuzz"
cmake --preset asan >/dev/null
# shellcheck disable=SC2086 # one word per target
cmake --build --preset asan --target $TARGETS

shared="${SHADOWLAB_SHARED:-../shared}/scenes-real"
mkdir -p build-asan/fuzz-artifacts
failed=""
for target in $TARGETS; do
  corpus="build-asan/fuzz-corpus/$target"
  mkdir -p "$corpus"
  seeds=()
  case "$target" in
    scene_json_fuzz) cp assets/scenes/*.json "$corpus"/ ;;
    tour_fuzz) cp tours/*.json "$corpus"/ ;;
    gltf_fuzz)
      if [ -d "$shared" ]; then
        for f in "$shared"/*/*.gltf; do [ -f "$f" ] && cp "$f" "$corpus"/; done
      fi
      ;;
  esac
  regressions="tests/fuzz-regressions/${target%_fuzz}"
  [ -d "$regressions" ] && seeds+=("$regressions")
  echo "== $target: ${seconds}s =="
  # -timeout: one input slower than 10 s is a hang; -rss_limit_mb: a 2 GiB input is a bug too.
  if ! ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1:intercept_tls_get_addr=0 UBSAN_OPTIONS=print_stacktrace=1 \
    "build-asan/$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=262144 \
    -print_final_stats=1 -artifact_prefix="build-asan/fuzz-artifacts/$target-" "$corpus" "${seeds[@]}" \
    2>"build-asan/fuzz-$target.log"; then
    failed="$failed $target"
    tail -n 40 "build-asan/fuzz-$target.log"
  else
    grep -E '^stat::(number_of_executed_units|peak_rss_mb)' "build-asan/fuzz-$target.log" || true
  fi
done
if [ -n "$failed" ]; then
  echo "fuzz: FAILED:$failed (inputs in build-asan/fuzz-artifacts/, logs in build-asan/fuzz-*.log)"
  exit 1
fi
echo "fuzz: no crash, hang or leak in $seconds s per target"
