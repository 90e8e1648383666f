#!/usr/bin/env bash
# Sets up, builds, runs every case on every engine and writes the accuracy
# report (the README's report command):
#   results/results.h5          the results file (HDF5, SPEC §5)
#   results/report/report.html  the report, self-contained (open it in a browser)
#   results/report/report.md    the same in Markdown, with SVG figures
# and prints the gate's verdict against cases/thresholds.toml.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh release
bash scripts/setup_web.sh
mkdir -p results
PB=./build/release/apps/planarbench
rc=0
"$PB" run --case all --engine all --jobs "$(nproc)" --out results/results.h5 || rc=$?
"$PB" report results/results.h5 --thresholds cases/thresholds.toml --out results/report
"$PB" check --thresholds cases/thresholds.toml results/results.h5 || rc=$((rc > 0 ? rc : $?))
echo "report: results/report/report.html and results/report/report.md"
exit "$rc"
