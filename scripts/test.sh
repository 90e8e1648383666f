#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite (the README's test command;
# .ci/run calls it). Usage: scripts/test.sh [preset]   (release | debug | asan-ubsan)
set -euo pipefail
cd "$(dirname "$0")/.."
PRESET="${1:-release}"
bash scripts/build.sh "$PRESET"
bash scripts/setup_web.sh
ctest --preset "$PRESET" -j "$(nproc)" --timeout 900
