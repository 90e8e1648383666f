#!/usr/bin/env bash
# Runs the benchmark suite and compares it with the committed baseline
# (bench/README.md). Builds the release preset, runs every bench_* binary with
# repetitions into results/bench/<binary>.json, then bench/compare.py prints a
# table and writes results/bench/comparison.md.
#
#   scripts/bench.sh [--repetitions N] [--threshold X] [--metric M] [--strict]
#                    [--bless] [--filter REGEX] [--build-dir DIR]
#
#   --repetitions N  repetitions of every benchmark (default 5); the median counts
#   --threshold X    flag SLOWER when now / baseline > 1 + X (default 0.15)
#   --metric M       cpu_time (default) or real_time: the time compared
#   --strict         exit 1 when a benchmark is SLOWER, MISSING or failed
#                    (default: report only and exit 0, for shared CI machines)
#   --bless          copy the new JSON files to bench/baseline/ afterwards
#   --filter REGEX   only the benchmarks matching REGEX (Google Benchmark's
#                    --benchmark_filter); do not --bless a filtered run
#   --build-dir DIR  use the binaries already built in DIR instead of building
#                    the release preset
set -euo pipefail
cd "$(dirname "$0")/.."

REPETITIONS=5
THRESHOLD=0.15
METRIC=cpu_time
STRICT=()
BLESS=0
FILTER=""
BUILD_DIR=""
while [ $# -gt 0 ]; do
  case "$1" in
    --repetitions) REPETITIONS="$2"; shift 2 ;;
    --threshold) THRESHOLD="$2"; shift 2 ;;
    --metric) METRIC="$2"; shift 2 ;;
    --strict) STRICT=(--strict); shift ;;
    --bless) BLESS=1; shift ;;
    --filter) FILTER="$2"; shift 2 ;;
    --build-dir) BUILD_DIR="$2"; shift 2 ;;
    -h|--help) sed -n '2,20p' "$0"; exit 0 ;;
    *) echo "bench.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
done
if ! [[ "$REPETITIONS" =~ ^[1-9][0-9]*$ ]]; then
  echo "bench.sh: --repetitions must be a positive integer, got '$REPETITIONS'" >&2
  exit 2
fi
if [ "$BLESS" -eq 1 ] && [ -n "$FILTER" ]; then
  echo "bench.sh: --bless with --filter would bless a partial baseline" >&2
  exit 2
fi

START_S=$(date +%s)
if [ -z "$BUILD_DIR" ]; then
  bash scripts/build.sh release
  BUILD_DIR=build/release
fi
BINARIES=()
for b in "$BUILD_DIR"/bench/bench_*; do
  [ -x "$b" ] && [ -f "$b" ] && BINARIES+=("$b")
done
if [ "${#BINARIES[@]}" -eq 0 ]; then
  echo "bench.sh: no bench_* binaries in $BUILD_DIR/bench (configure with -DPB_BUILD_BENCH=ON)" >&2
  exit 2
fi

OUT=results/bench
mkdir -p "$OUT"
PAIRS=()
for bin in "${BINARIES[@]}"; do
  name=$(basename "$bin")
  echo "== $name ($REPETITIONS repetitions)"
  # random interleaving spreads each benchmark's repetitions over the whole
  # run, so that a burst of load on a shared machine hits one repetition of
  # several benchmarks rather than every repetition of one (the median then
  # discards it); the console shows aggregates only, the JSON every repetition
  args=(--benchmark_repetitions="$REPETITIONS"
        --benchmark_enable_random_interleaving=true
        --benchmark_display_aggregates_only=true
        --benchmark_out="$OUT/$name.json" --benchmark_out_format=json)
  [ -n "$FILTER" ] && args+=(--benchmark_filter="$FILTER")
  # 48 detection benchmarks: 0.2 s each per repetition instead of the default
  # 0.5 (still >= 35 brute-force detections at N = 1440, 5.6 ms each); the
  # whole script then takes ~4 min instead of ~8
  [ "$name" = bench_detection ] && args+=(--benchmark_min_time=0.2)
  "$bin" "${args[@]}"
  PAIRS+=(--pair "bench/baseline/$name.json" "$OUT/$name.json")
done

rc=0
/usr/bin/python3 bench/compare.py --threshold "$THRESHOLD" --metric "$METRIC" "${STRICT[@]}" \
  --markdown "$OUT/comparison.md" "${PAIRS[@]}" || rc=$?

if [ "$BLESS" -eq 1 ]; then
  mkdir -p bench/baseline
  for bin in "${BINARIES[@]}"; do
    cp "$OUT/$(basename "$bin").json" bench/baseline/
  done
  echo "bench.sh: blessed ${#BINARIES[@]} file(s) into bench/baseline/ (commit them)"
fi
echo "bench.sh: $(( $(date +%s) - START_S )) s; comparison in $OUT/comparison.md"
exit "$rc"
