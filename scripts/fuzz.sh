#!/usr/bin/env bash
# Builds the libFuzzer targets (CMake preset "fuzz": Clang, ASan + UBSan) and
# runs each for a bounded time on a copy of its seed corpus (tests/fuzz/corpus;
# the repository is never written). Crash, timeout and out-of-memory inputs are
# kept under results/fuzz/<target>/. Exits non-zero if any target failed.
#
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET]   (default 60)
#   PB_FUZZ_SEED   libFuzzer's random seed (default 1; the run is still
#                  time-bounded, so the number of executions varies)
#   PB_FUZZ_JOBS   build parallelism (default: nproc)
set -euo pipefail
cd "$(dirname "$0")/.."

SECONDS_PER_TARGET="${1:-60}"
SEED="${PB_FUZZ_SEED:-1}"
JOBS="${PB_FUZZ_JOBS:-$(nproc)}"
if ! [[ "$SECONDS_PER_TARGET" =~ ^[1-9][0-9]*$ ]]; then
  echo "fuzz: SECONDS_PER_TARGET must be a positive integer (got '$SECONDS_PER_TARGET')" >&2
  exit 2
fi

# build: the fuzz targets and the libraries they link, nothing else
bash scripts/setup.sh
build_start=$(date +%s)
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$JOBS"
echo "fuzz: build took $(( $(date +%s) - build_start )) s"

BIN=build/fuzz/tests/fuzz
OUT=results/fuzz
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
mkdir -p "$OUT"

# target, corpus folder, extra libFuzzer options
TARGETS=(
  "fuzz_case_parser|case_parser|-dict=tests/fuzz/fuzz_case_parser.dict -max_len=8192"
  "fuzz_outline|outline|"
  "fuzz_impact_data|impact_data|-max_len=16384"
  "fuzz_impact_work|impact_work|-max_len=16384"
  "fuzz_mujoco3_batch|mujoco3_batch|-max_len=4096"
)

failed=0
summary=()
for entry in "${TARGETS[@]}"; do
  IFS='|' read -r target corpus extra <<<"$entry"
  # a scratch copy: libFuzzer adds every new input to its first corpus folder
  cp -r "tests/fuzz/corpus/$corpus" "$WORK/$corpus"
  mkdir -p "$OUT/$target"
  log="$OUT/$target/fuzz.log"
  echo "fuzz: $target for $SECONDS_PER_TARGET s (log $log)"
  touch "$WORK/$target.start"
  run_start=$(date +%s)
  rc=0
  # shellcheck disable=SC2086  # $extra holds several options
  "$BIN/$target" "$WORK/$corpus" $extra \
    -max_total_time="$SECONDS_PER_TARGET" -timeout=10 -rss_limit_mb=2048 \
    -seed="$SEED" -print_final_stats=1 -artifact_prefix="$OUT/$target/" \
    >"$log" 2>&1 || rc=$?
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  secs=$(( $(date +%s) - run_start ))
  new=$(find "$WORK/$corpus" -type f | wc -l)
  line="$target: ${runs:-?} executions in $secs s (${rate:-?} exec/s), corpus $(find "tests/fuzz/corpus/$corpus" -type f | wc -l) -> $new inputs"
  if [ "$rc" -ne 0 ]; then
    failed=1
    line="$line: FAILED (exit $rc)"
    grep -E "^(SUMMARY|fuzz invariant broken|unexpected exception)|runtime error" "$log" | head -5 || true
    # the inputs this run kept (older ones stay, untouched)
    find "$OUT/$target" -maxdepth 1 -type f -newer "$WORK/$target.start" \
      \( -name 'crash-*' -o -name 'timeout-*' -o -name 'oom-*' -o -name 'leak-*' \) |
      while read -r f; do echo "fuzz: input kept: $f (replay: $BIN/$target $f)"; done
  fi
  echo "$line"
  summary+=("$line")
done

echo "fuzz: summary"
printf '  %s\n' "${summary[@]}"
exit "$failed"
