#!/usr/bin/env bash
# Installs the Debian packages (scripts/setup.sh) and builds planarbench with
# the given CMake preset (default: release) into build/<preset>: every target,
# or only the targets named after the preset.
#   scripts/build.sh [preset] [target ...]
set -euo pipefail
cd "$(dirname "$0")/.."
PRESET="${1:-release}"
shift || true
bash scripts/setup.sh
cmake --preset "$PRESET" >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build --preset "$PRESET" -j "$(nproc)" "${targets[@]}"
