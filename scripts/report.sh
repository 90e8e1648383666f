#!/usr/bin/env bash
# Sets up, builds, runs every case on every engine, sweeps every engine over
# its step sizes (and the reference over its tolerances), and writes the
# accuracy report (the README's report command):
#   results/results.h5          the results file (HDF5, SPEC §5)
#   results/sweep.h5            the work-precision sweep (HDF5, apps/cmd_sweep.cpp)
#   results/friction_curve.h5   the friction curve (campaigns/friction_curve.toml)
#   results/block_family.h5     the block family (campaigns/block_family.toml)
#   results/scenes.h5           the scenes (cases/scenes/) on every engine: $PB_SCENES,
#                               default stack_2,stack_10,stack_50,cradle_5,pyramid_5,pile_100
#                               (about 20 min on 2 cores, MuJoCo's pile most of it);
#                               PB_SCENES=scenes runs every scene (pyramid_20 and 50,
#                               pile_1000, pile_poly_200: hours on the reference)
#   results/impacts_fit.h5      measured impacts: every engine fitted, cross-validated
#                               (`planarbench impacts fit`), when the data file exists:
#                               $PB_IMPACTS_DATA, default ../shared/data/mcube/ellipse_impacts_train.mat
#   results/report/report.html  the report, self-contained (open it in a browser)
#   results/report/report.md    the same in Markdown, with SVG figures
# and prints the gate's verdict against cases/thresholds.toml and
# cases/scenes/thresholds.toml (a scene that diverges is data, shown in the
# report and by the gate, not an error of this script).
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
scenes="${PB_SCENES:-stack_2,stack_10,stack_50,cradle_5,pyramid_5,pile_100}"
scene_rc=0
"$PB" run --case "$scenes" --engine all --jobs "$(nproc)" --out results/scenes.h5 || scene_rc=$?
# exit 3 is a run that failed or diverged: data; anything else is an error
if [ "$scene_rc" != 0 ] && [ "$scene_rc" != 3 ]; then rc=$scene_rc; fi
"$PB" report results/results.h5 "${sweep_args[@]}" --campaign results/friction_curve.h5 \
  --campaign results/block_family.h5 "${impacts_args[@]}" --scenes results/scenes.h5 \
  --thresholds cases/thresholds.toml --out results/report
"$PB" check --thresholds cases/thresholds.toml results/results.h5 || rc=$((rc > 0 ? rc : $?))
# its exit 3 (an engine's scene diverged: MuJoCo's stack_50, mujoco3's
# pyramid_5 today) is shown, not yet a known breach with a range: no band of
# an engine's scene is derived yet; a breach (1) or bad input (2) fails
scene_check=0
"$PB" check --thresholds cases/scenes/thresholds.toml --cases-in-results-only results/scenes.h5 \
  --junit results/scenes.junit.xml --summary results/scenes.summary.md || scene_check=$?
if [ "$scene_check" != 0 ] && [ "$scene_check" != 3 ]; then rc=$((rc > 0 ? rc : scene_check)); fi
echo "report: results/report/report.html and results/report/report.md"
exit "$rc"
