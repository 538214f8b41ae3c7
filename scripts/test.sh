#!/usr/bin/env bash
# One command: install what is missing, build, run the whole test suite (GPU tests run
# headless on Mesa's llvmpipe through EGL; the window smoke test under Xvfb).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cd build
ctest --output-on-failure -j2 "$@"
