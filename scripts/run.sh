#!/usr/bin/env bash
# One command: install what is missing, build, open the explorer (arguments pass through).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
exec build/shadowlab "$@"
