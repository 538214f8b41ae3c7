#!/usr/bin/env bash
# One command: install what is missing, build, run the whole test suite (GPU tests run
# headless on Mesa's llvmpipe through EGL; the window smoke test under Xvfb), then build the
# same suite with AddressSanitizer + UBSan (CMakePresets.json, preset asan, into build-asan/)
# and run it again; in between, the scene loaders are fuzzed for 30 s each (scripts/fuzz.sh).
# SHADOWLAB_SKIP_ASAN=1 / SHADOWLAB_SKIP_FUZZ=1 skip those locally; CI runs all three.
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

# The scene loaders under libFuzzer, 30 s per target (scripts/fuzz.sh; builds build-fuzz/, a
# few minutes on 2 cores the first time). SHADOWLAB_SKIP_FUZZ=1 skips it locally.
fuzz=skipped
if [ "${SHADOWLAB_SKIP_FUZZ:-0}" != 1 ]; then
  echo
  echo "== libFuzzer: scene loaders (build-fuzz/) =="
  fuzz=0
  scripts/fuzz.sh 30 2>&1 | tee "$logs/fuzz.txt" || fuzz=$?
fi

asan=skipped
if [ "${SHADOWLAB_SKIP_ASAN:-0}" != 1 ]; then
  echo
  echo "== AddressSanitizer + UBSan build (build-asan/) =="
  asan=0
  if cmake --preset asan >/dev/null && cmake --build --preset asan -j"$(nproc)"; then
    # LeakSanitizer's own thread tracer crashes at the exit of these two tests under ctest (it
    # reads a bogus dynamic-TLS range of Mesa's dlopen'ed driver: "Tracer caught signal 11",
    # not a leak; run alone, leak check on, both pass). The preset excludes them; they run here
    # under ASan + UBSan without the leak check. The regex is the preset's exclusion.
    (cd build-asan && ASAN_OPTIONS=detect_leaks=0:halt_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
      ctest --output-on-failure \
        -R '^(PixelCorrect\.ConvergesToTheReferenceWithAStillCamera|DeepGl\.DeepPassesOnlyWithSemiTransparentCasters)$') 2>&1 |
      tee "$logs/asan-no-leaks.txt" || asan=$?
    ctest --preset asan "$@" 2>&1 | tee "$logs/asan.txt" || asan=$?
    # The same tracer crash strikes other GL tests now and then (a different one each run). Where
    # every failure is that crash after the test passed (scripts/lsan-tracer-retry.py), those
    # tests run again, leak check still on: a real leak reproduces, the crash does not. Anything
    # else (a leak, an ASan or UBSan report, an assertion) stays red.
    for try in 1 2; do
      [ "$asan" != 0 ] || break
      names="$(scripts/lsan-tracer-retry.py build-asan)" || break
      echo "asan: LeakSanitizer's tracer crashed after these passed (not a leak); rerun $try:" $names |
        tee -a "$logs/asan-rerun.txt"
      asan=0
      ctest --preset asan --rerun-failed 2>&1 | tee -a "$logs/asan-rerun.txt" || asan=$?
    done
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
  echo "(without the leak check:)"
  summary "$logs/asan-no-leaks.txt"
  summary "$logs/asan.txt"
  grep -q 'tests passed, ' "$logs/asan.txt" || cat "$logs/asan.txt"
  if [ -f "$logs/asan-rerun.txt" ]; then grep '^asan: ' "$logs/asan-rerun.txt"; tail -n 4 "$logs/asan-rerun.txt"; fi
fi
echo "== libFuzzer (build-fuzz/) =="
if [ "$fuzz" = skipped ]; then echo "skipped (SHADOWLAB_SKIP_FUZZ=1)"; else tail -n 1 "$logs/fuzz.txt"; fi
if [ "$normal" != 0 ] || { [ "$asan" != 0 ] && [ "$asan" != skipped ]; } ||
  { [ "$fuzz" != 0 ] && [ "$fuzz" != skipped ]; }; then exit 1; fi
