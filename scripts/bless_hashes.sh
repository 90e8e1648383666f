#!/usr/bin/env bash
# Re-blesses the pinned determinism hashes (tests/data/determinism/hashes.json):
# runs the pinned command with an already built planarbench, hashes every
# dataset of every case x engine with h5py (tests/python/dataset_hashes.py)
# and rewrites the hashes in place. Builds nothing. Review the diff, then commit.
# Usage: bash scripts/bless_hashes.sh [BUILD_DIR]   (default build/release)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${1:-build/release}"
EXE="$BUILD_DIR/apps/planarbench"
PINNED=tests/data/determinism/hashes.json
if [[ ! -x "$EXE" ]]; then
  echo "no planarbench at $EXE: build first (bash scripts/build.sh) or name the build folder" >&2
  exit 2
fi
# the pinned command, word by word, as the test runs it
read -r -a ARGS < <(/usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["args"])' "$PINNED")
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
# the built-in cases folder (the source tree's cases/), as in the test
# exit 3 (a run diverged) still writes the file, and a divergence is as
# deterministic as the rest: it is pinned too
rc=0
env -u PLANARBENCH_CASES_DIR "$EXE" "${ARGS[@]}" --out "$WORK/matrix.h5" || rc=$?
if [[ $rc -ne 0 && $rc -ne 3 ]]; then
  echo "planarbench ${ARGS[*]} failed (exit $rc): nothing blessed" >&2
  exit 1
fi
/usr/bin/python3 tests/python/dataset_hashes.py bless "$PINNED" "$WORK/matrix.h5"
git --no-pager diff --stat -- "$PINNED" 2>/dev/null || true
