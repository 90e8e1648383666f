#!/usr/bin/env bash
# Re-blesses the pinned determinism hashes (tests/data/determinism/hashes.json):
# runs the pinned command with an already built planarbench, then REFUSES to
# bless (exit 1, nothing written) when any run of the file it produced has
# status "diverged", or when the gate fails on that file
# (`planarbench check FILE --thresholds cases/thresholds.toml` exits non-zero:
# a breach, invalid data, a diverged run, or runs the thresholds do not cover);
# only then hashes every dataset of every case x engine with h5py
# (tests/python/dataset_hashes.py) and rewrites the hashes in place. A change
# that breaks the gate is fixed (or its thresholds re-derived) first, never
# pinned. Builds nothing. Review the diff, then commit.
# Usage: bash scripts/bless_hashes.sh [BUILD_DIR]   (default build/release)
# For its own test (tests/durability/bless_refusal_test.sh) three variables
# point it elsewhere: PB_BLESS_RESULTS=FILE (judge this results file instead
# of running the pinned command), PB_BLESS_PINNED=FILE (the hashes file to
# rewrite), PB_BLESS_THRESHOLDS=FILE (the gate's thresholds file).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${1:-build/release}"
EXE="$BUILD_DIR/apps/planarbench"
PINNED="${PB_BLESS_PINNED:-tests/data/determinism/hashes.json}"
THRESHOLDS="${PB_BLESS_THRESHOLDS:-cases/thresholds.toml}"
if [[ ! -x "$EXE" ]]; then
  echo "no planarbench at $EXE: build first (bash scripts/build.sh) or name the build folder" >&2
  exit 2
fi
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
if [[ -n "${PB_BLESS_RESULTS:-}" ]]; then
  cp -- "$PB_BLESS_RESULTS" "$WORK/matrix.h5"
else
  # the pinned command, word by word, as the test runs it
  read -r -a ARGS < <(/usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["args"])' "$PINNED")
  # the built-in cases folder (the source tree's cases/), as in the test;
  # exit 3 (a run diverged) still writes the file: the status check below
  # names the runs and refuses
  rc=0
  env -u PLANARBENCH_CASES_DIR "$EXE" "${ARGS[@]}" --out "$WORK/matrix.h5" || rc=$?
  if [[ $rc -ne 0 && $rc -ne 3 ]]; then
    echo "planarbench ${ARGS[*]} failed (exit $rc): nothing blessed" >&2
    exit 1
  fi
fi
# every run's status, read with h5py (not with the code under test)
diverged="$(/usr/bin/python3 -c '
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    for case in sorted(f["runs"]):
        for engine in sorted(f["runs"][case]):
            s = f["runs"][case][engine].attrs.get("status", "")
            s = s.decode() if isinstance(s, bytes) else str(s)
            if s == "diverged":
                print(f"{case}.{engine}")
' "$WORK/matrix.h5")"
if [[ -n "$diverged" ]]; then
  echo "refused: run(s) diverged: $(echo "$diverged" | tr '\n' ' ')- a divergence is fixed, not pinned: nothing blessed" >&2
  exit 1
fi
rc=0
"$EXE" check "$WORK/matrix.h5" --thresholds "$THRESHOLDS" --junit "$WORK/check.junit.xml" \
  --summary "$WORK/check.summary.md" > "$WORK/check.txt" 2>&1 || rc=$?
if [[ $rc -ne 0 ]]; then
  grep -E '^(FAIL|BREACH|DIVERGED|UNEXPECTED|INVALID)' "$WORK/check.txt" | head -n 20 >&2 || true
  tail -n 1 "$WORK/check.txt" >&2 || true
  echo "refused: the gate fails (planarbench check --thresholds $THRESHOLDS exited $rc): nothing blessed" >&2
  exit 1
fi
/usr/bin/python3 tests/python/dataset_hashes.py bless "$PINNED" "$WORK/matrix.h5"
git --no-pager diff --stat -- "$PINNED" 2>/dev/null || true
