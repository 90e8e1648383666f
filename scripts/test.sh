#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite (the README's test command;
# .ci/run calls it). Usage: scripts/test.sh [preset] [fuzz-seconds]
#   preset         asan-ubsan (default: Clang -O1, AddressSanitizer + UBSan,
#                  every test and benchmark-once test) | release | debug
#   fuzz-seconds   how long each libFuzzer target runs afterwards (default 15;
#                  0 skips fuzzing). scripts/fuzz.sh builds them with Clang.
# The default is the sanitizer build because one build of the tree fits the
# CI budget on 2 cores and a second does not: Clang's ASan build takes ~9.5
# min, GCC's Release ~7 (scripts/report.sh builds and exercises that one).
# Sanitizer reports fail the test that triggers them (-fno-sanitize-recover).
set -euo pipefail
cd "$(dirname "$0")/.."
PRESET="${1:-asan-ubsan}"
FUZZ_SECONDS="${2:-15}"
start=$(date +%s)
bash scripts/build.sh "$PRESET"
bash scripts/setup_web.sh
echo "test: build took $(( $(date +%s) - start )) s"
# one job more than cores: the suite waits on child processes, Node and
# Chromium at times (~8 % of its wall time idle at -j nproc on 2 cores)
ctest --preset "$PRESET" -j "$(( $(nproc) + 1 ))" --timeout 900
echo "test: build and tests took $(( $(date +%s) - start )) s"
if [ "$FUZZ_SECONDS" != 0 ]; then
  bash scripts/fuzz.sh "$FUZZ_SECONDS"
fi
echo "test: everything took $(( $(date +%s) - start )) s"
