#!/usr/bin/env bash
# Sets up, builds, runs every case on every engine, sweeps every engine over
# its step sizes (and the reference over its tolerances), and writes the
# accuracy report (the README's report command):
#   results/results.h5          the results file (HDF5, SPEC §5)
#   results/sweep.h5            the work-precision sweep (HDF5, apps/cmd_sweep.cpp)
#   results/friction_curve.h5   the friction curve (campaigns/friction_curve.toml)
#   results/block_family.h5     the block family (campaigns/block_family.toml)
#   results/impacts_fit.h5      measured impacts: every engine fitted, cross-validated
#                               (`planarbench impacts fit`), when the data file exists:
#                               $PB_IMPACTS_DATA, default ../shared/data/mcube/ellipse_impacts_train.mat
#   results/report/report.html  the report, self-contained (open it in a browser)
#   results/report/report.md    the same in Markdown, with SVG figures
# and prints the gate's verdict against cases/thresholds.toml.
# Set PB_SKIP_SWEEP=1 to leave the sweep out (about 16 s on 2 cores), PB_SKIP_IMPACTS=1
# to leave the measured impacts out (about 7 min on 2 cores).
# Builds the command line only, not the tests (scripts/test.sh builds those).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh release planarbench
bash scripts/setup_web.sh
mkdir -p results
PB=./build/release/apps/planarbench
rc=0
# one worker and 5 repeats: every run's cost is the median of 5 uncontended
# wall times (the report shows the median and the range), ~20 s, and about
# 3 min more for mujoco3 (MuJoCo 3.3.8's WebAssembly build over a pipe)
"$PB" run --case all --engine all --jobs 1 --repeat 5 --out results/results.h5 || rc=$?
sweep_args=()
if [ "${PB_SKIP_SWEEP:-0}" != 1 ]; then
  # work-precision: the native engines; mujoco3's wall time is its pipe's
  # exchange (adapters/mujoco3/README.md, Cost), no measure of MuJoCo's work
  "$PB" sweep --case all --engine reference,mujoco,box2d,ode --jobs "$(nproc)" --out results/sweep.h5
  sweep_args=(--sweep results/sweep.h5)
fi
# the friction curve (issue 22): 11 friction coefficients x 5 engines, ~1 s
rm -rf results/friction_curve
"$PB" campaign run campaigns/friction_curve.toml --out results/friction_curve --jobs "$(nproc)" --quiet
"$PB" campaign merge results/friction_curve --out results/friction_curve.h5 --quiet
# the block family (issue 30): 38 blocks x 4 engines, ~5 s
rm -rf results/block_family
"$PB" campaign run campaigns/block_family.toml --out results/block_family --jobs "$(nproc)" --quiet
"$PB" campaign merge results/block_family --out results/block_family.h5 --quiet
# measured impacts (issue 23): the dataset is never committed (no licence);
# the report reads it where the user has it
impacts_args=()
impacts_data="${PB_IMPACTS_DATA:-../shared/data/mcube/ellipse_impacts_train.mat}"
if [ "${PB_SKIP_IMPACTS:-0}" != 1 ]; then
  if [ -f "$impacts_data" ]; then
    "$PB" impacts fit --data "$impacts_data" --engine all --jobs "$(nproc)" --out results/impacts_fit.h5
    impacts_args=(--impacts results/impacts_fit.h5)
  else
    echo "report: no measured impacts ($impacts_data not found: see README.md, Measured impacts)"
  fi
fi
"$PB" report results/results.h5 "${sweep_args[@]}" --campaign results/friction_curve.h5 \
  --campaign results/block_family.h5 "${impacts_args[@]}" --thresholds cases/thresholds.toml --out results/report
"$PB" check --thresholds cases/thresholds.toml results/results.h5 || rc=$((rc > 0 ? rc : $?))
echo "report: results/report/report.html and results/report/report.md"
exit "$rc"
