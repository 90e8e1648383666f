#!/usr/bin/python3
# Tests for bench/compare.py
#
# The inputs are two small hand-written Google Benchmark JSON files,
# tests/data/bench/baseline.json and now.json (format of Google Benchmark
# 1.7.1's JSON reporter, one benchmark entry per line). Their times were chosen
# so that each verdict has a known answer:
#   demo/same             10, 11, 12 ms vs 11, 10, 12 ms: median 11 = 11, ratio 1
#   demo/twice            10 ms vs 20 ms: ratio 2, a 2x slow-down
#   demo/ten_percent      10 ms vs 11 ms: ratio 1.1, inside 1.15, outside 1.05
#   demo/units            2 ms vs 2000 us: the same time in another unit, ratio 1
#   demo/even             1, 2, 3, 4 ms: median (2 + 3) / 2 = 2.5 ms
#   demo/aggregates_only  only a "median" aggregate, 5 ms in both: ratio 1
#   demo/gone             in the baseline only: MISSING
#   demo/added            in the new file only: new
#   demo/broken           the new run has error_occurred: ERROR
#   demo/busy             cpu_time 10 ms in both, real_time 10 ms vs 20 ms
# The contexts differ in planarbench_revision only; the new run started at a
# 1-minute load of 3.0 on 2 CPUs (busy), the baseline at 0.
#
# Usage (CTest): compare_test.py <path of compare.py> <tests/data/bench>

import importlib.util
import os
import re
import subprocess
import sys
import tempfile
import unittest

COMPARE = sys.argv[1] if len(sys.argv) > 1 else ""
DATA = sys.argv[2] if len(sys.argv) > 2 else ""
BASELINE = os.path.join(DATA, "baseline.json")
NOW = os.path.join(DATA, "now.json")


def run(*args):
    """compare.py's exit code and stdout for the given arguments."""
    p = subprocess.run([sys.executable, COMPARE, *args], capture_output=True, text=True,
                       check=False)
    return p.returncode, p.stdout, p.stderr


def verdicts(stdout):
    """benchmark name -> (ratio column, verdict column) of the text table."""
    out = {}
    for line in stdout.splitlines():
        # columns are separated by two spaces or more; a cell has single spaces
        # at most ("10 ms"): name, baseline, now, ratio, reps, spread, verdict
        cols = re.split(r"\s{2,}", line.strip())
        if cols[0].startswith("demo/"):
            out[cols[0]] = (cols[3], cols[6])
    return out


class CompareTest(unittest.TestCase):

    def test_two_fold_slow_down_is_flagged_slower(self):
        rc, out, _ = run("--pair", BASELINE, NOW)
        self.assertEqual(rc, 0, "without --strict the comparison only reports")
        self.assertEqual(verdicts(out)["demo/twice"], ("2.000", "SLOWER"))

    def test_equal_times_are_not_flagged(self):
        _, out, _ = run("--pair", BASELINE, NOW)
        v = verdicts(out)
        self.assertEqual(v["demo/same"], ("1.000", "ok"))
        # the same time written in us instead of ms
        self.assertEqual(v["demo/units"], ("1.000", "ok"))
        # a file with aggregates only falls back on the "median" aggregate
        self.assertEqual(v["demo/aggregates_only"], ("1.000", "ok"))

    def test_missing_new_and_failed_benchmarks_are_reported(self):
        _, out, _ = run("--pair", BASELINE, NOW)
        v = verdicts(out)
        self.assertEqual(v["demo/gone"][1], "MISSING")
        self.assertEqual(v["demo/added"][1], "new")
        self.assertTrue(v["demo/broken"][1].startswith("ERROR"))
        self.assertIn("engine threw", out)

    def test_metric_chooses_cpu_or_real_time(self):
        # the default compares CPU time (unchanged), --metric real_time the wall
        _, out, _ = run("--pair", BASELINE, NOW)
        self.assertEqual(verdicts(out)["demo/busy"], ("1.000", "ok"))
        _, out, _ = run("--metric", "real_time", "--pair", BASELINE, NOW)
        self.assertEqual(verdicts(out)["demo/busy"], ("2.000", "SLOWER"))

    def test_threshold_decides_a_ten_percent_change(self):
        # ratio 1.1: inside the default 1 + 0.15, outside 1 + 0.05
        _, out, _ = run("--pair", BASELINE, NOW)
        self.assertEqual(verdicts(out)["demo/ten_percent"], ("1.100", "ok"))
        _, out, _ = run("--threshold", "0.05", "--pair", BASELINE, NOW)
        self.assertEqual(verdicts(out)["demo/ten_percent"], ("1.100", "SLOWER"))

    def test_strict_fails_on_a_slow_down_and_passes_on_the_baseline_itself(self):
        rc, _, _ = run("--strict", "--pair", BASELINE, NOW)
        self.assertEqual(rc, 1)
        rc, out, _ = run("--strict", "--pair", BASELINE, BASELINE)
        self.assertEqual(rc, 0, out)
        self.assertEqual({v for _, v in verdicts(out).values()}, {"ok"})

    def test_context_difference_is_warned(self):
        _, out, _ = run("--pair", BASELINE, NOW)
        self.assertIn("warning: context differs: planarbench_revision: "
                      "baseline 'aaaaaaaaaaaa', now 'bbbbbbbbbbbb'", out)
        # only the revision differs between the two files
        self.assertEqual(out.count("warning: context differs"), 1)
        _, out, _ = run("--pair", BASELINE, BASELINE)
        self.assertNotIn("warning", out)

    def test_busy_machine_is_warned(self):
        _, out, _ = run("--pair", BASELINE, NOW)
        self.assertIn("warning: now: the machine was busy (1-minute load 3.00 on 2 CPUs)", out)
        self.assertNotIn("warning: baseline: the machine was busy", out)

    def test_markdown_file_holds_the_table(self):
        with tempfile.TemporaryDirectory() as d:
            md = os.path.join(d, "sub", "comparison.md")
            run("--markdown", md, "--pair", BASELINE, NOW)
            with open(md, encoding="utf-8") as f:
                text = f.read()
        row = next(line for line in text.splitlines() if line.startswith("| demo/twice "))
        self.assertIn("| 2.000 |", row)
        self.assertTrue(row.endswith("| SLOWER |"), row)
        self.assertIn("`planarbench_revision`", text)

    def test_missing_baseline_file_reports_new_and_does_not_fail_strict(self):
        # baseline.json as the new results: no errors in it, so only "new" rows
        rc, out, _ = run("--strict", "--pair", os.path.join(DATA, "no_such.json"), BASELINE)
        self.assertEqual(rc, 0, out)
        self.assertIn("no baseline", out)
        self.assertEqual(verdicts(out)["demo/twice"], ("-", "new"))

    def test_unreadable_input_exits_2(self):
        with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
            f.write("{not json")
        try:
            rc, _, err = run("--pair", BASELINE, f.name)
        finally:
            os.unlink(f.name)
        self.assertEqual(rc, 2)
        self.assertIn("compare.py:", err)

    def test_median_of_an_even_number_of_repetitions(self):
        spec = importlib.util.spec_from_file_location("compare", COMPARE)
        compare = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(compare)
        s = compare.summarise(compare.load(BASELINE))
        # (2 + 3) / 2 = 2.5 ms; spread (4 - 1) / 2.5 = 1.2. Tolerances: the ms -> s
        # scaling by 1e-3 rounds each time by half an ulp (~2e-19 s here)
        self.assertAlmostEqual(s["demo/even"]["median_s"], 2.5e-3, delta=1e-18)
        self.assertEqual(s["demo/even"]["reps"], 4)
        self.assertAlmostEqual(s["demo/even"]["spread"], 1.2, delta=1e-14)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
