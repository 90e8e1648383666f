#!/usr/bin/env bash
# Each adapter's cost per step against a bare loop of the same library on the
# same scene (issue 22), in instructions (valgrind --tool=callgrind): stable on
# a shared machine, unlike time. Per step as a differential,
# (Ir(N2) - Ir(N1)) / (N2 - N1), so that start-up (library initialisation,
# model building, the case file) cancels:
#   falling_ball: N1 = 7000, N2 = 8000 (the first impact, t = 0.725 s, inside)
#   disk_roll:    N1 = 2000, N2 = 3000 (rolling in contact throughout)
# The bare loops are bench/bare/<engine>_bare.cpp (the library as its users
# step it, reading each body's state every step); the adapter side is
# bench/bare/adapter_steps.cpp (pb::Engine's advance_to, body_states and
# contacts every step, as the runner calls them).
# Usage: bash bench/bare/compare.sh [BUILD_DIR]   (default build/release; builds the four)
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD="${1:-build/release}"
cmake --build "$BUILD" --target bare_mujoco bare_ode bare_box2d bare_adapter_steps >/dev/null
BIN="$BUILD/bench"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT

# total instructions of one command under callgrind
ir() {
  local out="$WORK/cg.$RANDOM$RANDOM"
  valgrind --tool=callgrind --callgrind-out-file="$out" "$@" >"$out.stdout" 2>"$out.stderr"
  awk '/^(summary|totals):/ {print $2; exit}' "$out"
}

per_step() {  # N1 N2 command... (the step count appended)
  local n1=$1 n2=$2
  shift 2
  local a b
  a=$(ir "$@" "$n1")
  b=$(ir "$@" "$n2")
  awk -v a="$a" -v b="$b" -v n="$((n2 - n1))" 'BEGIN {printf "%.1f", (b - a) / n}'
}

printf '%-8s %-13s %12s %12s %8s\n' engine scene bare_Ir/step adapter_Ir/step ratio
for engine in mujoco ode box2d; do
  for spec in "falling_ball 7000 8000" "disk_roll 2000 3000"; do
    read -r scene n1 n2 <<<"$spec"
    bare=$(per_step "$n1" "$n2" "$BIN/bare_$engine" "$scene")
    adapter=$(per_step "$n1" "$n2" "$BIN/bare_adapter_steps" "$engine" "cases/$scene.toml")
    printf '%-8s %-13s %12s %12s %8s\n' "$engine" "$scene" "$bare" "$adapter" \
      "$(awk -v a="$adapter" -v b="$bare" 'BEGIN {printf "%.3f", a / b}')"
  done
done
