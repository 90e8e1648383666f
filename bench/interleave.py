#!/usr/bin/python3
"""Wall-time medians of whole commands, measured in interleaved rounds.

On a shared 2-vCPU machine the load drifts over minutes; running every
command once per round, round after round, exposes each to the same drift,
so their ratios hold where separate hyperfine runs would not.

Usage: bench/interleave.py ROUNDS LABEL 'COMMAND' [LABEL 'COMMAND' ...]
A command runs under `sh -c` (so `a & b; wait` times two at once); exit codes
0 and 3 (an engine diverged) count, any other stops the measurement.
Prints, per label, the median, min and max wall time over the rounds.

Example (issue 12: how far two threads can go on this machine):
  P=build/release/apps/planarbench
  bench/interleave.py 15 solo "$P run --case all --engine all -j 1 --out s.h5 -q" \
      pair "$P run --case all --engine all -j 1 --out p1.h5 -q & $P run --case all --engine all -j 1 --out p2.h5 -q; wait" \
      j2 "$P run --case all --engine all -j 2 --out j2.h5 -q"
"""
import statistics
import subprocess
import sys
import time


def main(argv):
    if len(argv) < 4 or len(argv) % 2 != 0 or not argv[1].isdigit() or int(argv[1]) < 1:
        print(__doc__, file=sys.stderr)
        return 2
    rounds = int(argv[1])
    pairs = list(zip(argv[2::2], argv[3::2]))
    times = {label: [] for label, _ in pairs}
    for _ in range(rounds):
        for label, command in pairs:
            start = time.perf_counter()
            r = subprocess.run(command, shell=True, stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL, check=False)
            elapsed = time.perf_counter() - start
            if r.returncode not in (0, 3):
                print(f"{label}: exit {r.returncode}: {command}", file=sys.stderr)
                return 1
            times[label].append(elapsed)
    for label, _ in pairs:
        t = times[label]
        print(f"{label}: median {statistics.median(t):.3f} s  min {min(t):.3f} max {max(t):.3f}"
              f"  ({rounds} rounds)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
