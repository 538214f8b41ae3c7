#!/usr/bin/env bash
# One command: install what is missing, build, run the whole test suite (GPU tests run
# headless on Mesa's llvmpipe through EGL; the window smoke test under Xvfb), then build the
# same suite with AddressSanitizer + UBSan (CMakePresets.json, preset asan, into build-asan/)
# and run it again. SHADOWLAB_SKIP_ASAN=1 skips the sanitizer run locally; CI runs both.
# Arguments go to both ctest runs (e.g. -R Scene). Exits non-zero if either run fails.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh

logs="$(mktemp -d)"
trap 'rm -rf "$logs"' EXIT

# ctest's closing lines: "N% tests passed, M tests failed out of K", the time, failures.
summary() { sed -n '/tests passed, /,$p' "$1"; }

normal=0
(cd build && ctest --output-on-failure -j2 "$@") 2>&1 | tee "$logs/normal.txt" || normal=$?

asan=skipped
if [ "${SHADOWLAB_SKIP_ASAN:-0}" != 1 ]; then
  echo
  echo "== AddressSanitizer + UBSan build (build-asan/) =="
  asan=0
  if cmake --preset asan >/dev/null && cmake --build --preset asan -j"$(nproc)"; then
    ctest --preset asan "$@" 2>&1 | tee "$logs/asan.txt" || asan=$?
  else
    echo "asan: configure or build failed" | tee "$logs/asan.txt"
    asan=1
  fi
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
fi
if [ "$normal" != 0 ] || { [ "$asan" != 0 ] && [ "$asan" != skipped ]; }; then exit 1; fi
