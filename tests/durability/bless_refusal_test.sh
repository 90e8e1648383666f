#!/bin/sh
# scripts/bless_hashes.sh refuses to bless (exit 1, the hashes file left as
# it was) a results file on which the gate fails, or one with a diverged run;
# and blesses one the gate passes (the control: the refusal is not
# unconditional). Cheap: one falling_ball x box2d run (0.1 s in Release),
# judged in place of the full matrix (PB_BLESS_RESULTS), a copy of the
# pinned hashes as the file to rewrite (PB_BLESS_PINNED).
# Usage: bless_refusal_test.sh PLANARBENCH_EXE SOURCE_DIR WORK_DIR
set -u
EXE="$1"; SRC="$2"; W="$3"
rm -rf "$W"; mkdir -p "$W"
fail() { echo "FAIL $*"; exit 1; }
"$EXE" run --case falling_ball --engine box2d --quiet --out "$W/fb.h5" || fail "run falling_ball x box2d"
BUILD_DIR="$(dirname "$(dirname "$EXE")")"

# one threshold the run meets: wall time per simulated second below 1e6 s/s
cat > "$W/passing.toml" <<'TOML'
[[threshold]]
case = "falling_ball"
engine = "box2d"
against = "self"
metric = "wall_per_sim_s"
atol = 1e6
why = "test: any finished run is faster than 1e6 wall s per simulated s"
TOML

# bless RESULTS THRESHOLDS: runs the script on a fresh copy of the pinned
# hashes, its pinned command the one run here (dataset_hashes.py blesses
# only a file made by the pinned command)
bless() {
  /usr/bin/python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
d["args"] = "run --case falling_ball --engine box2d --quiet"
json.dump(d, open(sys.argv[2], "w"), indent=2)
' "$SRC/tests/data/determinism/hashes.json" "$W/pinned.json" || fail "cannot copy the pinned hashes"
  cp "$W/pinned.json" "$W/pinned.before.json"
  PB_BLESS_RESULTS="$1" PB_BLESS_PINNED="$W/pinned.json" PB_BLESS_THRESHOLDS="$2" \
    bash "$SRC/scripts/bless_hashes.sh" "$BUILD_DIR" > "$W/out.txt" 2>&1
  rc=$?
  cat "$W/out.txt"
  return $rc
}
unchanged() { cmp -s "$W/pinned.before.json" "$W/pinned.json"; }

# 1. the gate fails (the full thresholds file against one run: every other
#    case's thresholds are not computed)
bless "$W/fb.h5" "$SRC/cases/thresholds.toml"; rc=$?
[ $rc -eq 1 ] || fail "gate failing: exit $rc, want 1"
grep -q "refused: the gate fails" "$W/out.txt" || fail "gate failing: no refusal message"
unchanged || fail "gate failing: the hashes file was rewritten"

# 2. the control: the gate passes, nothing diverged: blessed (the copy rewritten)
bless "$W/fb.h5" "$W/passing.toml"; rc=$?
[ $rc -eq 0 ] || fail "gate passing: exit $rc, want 0"
unchanged && fail "gate passing: the hashes file was not rewritten"

# 3. the same run marked diverged (h5py): refused before the gate, named
/usr/bin/python3 -c '
import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:
    f["runs/falling_ball/box2d"].attrs["status"] = "diverged"
' "$W/fb.h5" || fail "cannot mark the run diverged"
bless "$W/fb.h5" "$W/passing.toml"; rc=$?
[ $rc -eq 1 ] || fail "diverged run: exit $rc, want 1"
grep -q "refused: run(s) diverged: falling_ball.box2d" "$W/out.txt" || fail "diverged run: not named"
unchanged || fail "diverged run: the hashes file was rewritten"
echo "bless refusal test passed"
