#!/usr/bin/env bash
# Installs the Debian packages (scripts/setup.sh) and builds planarbench with
# the given CMake preset (default: release) into build/<preset>.
set -euo pipefail
cd "$(dirname "$0")/.."
PRESET="${1:-release}"
bash scripts/setup.sh
cmake --preset "$PRESET" >/dev/null
cmake --build --preset "$PRESET" -j "$(nproc)"
