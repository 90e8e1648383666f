#!/usr/bin/python3
# Tests for bench/bench_context.cpp, bench/engines_bench.cpp and
# bench/force_laws_bench.cpp: what the benchmark binaries register and record.
#
# Nothing here is timed. The expected names come from outside the code under
# test: the case files are found by listing cases/*.toml and keeping those
# with a [[bodies]] table (thresholds.toml has none), the engine names are
# SPEC §5's, and the reference solver runs every case (SPEC §3). The library's
# build type is known twice: Google Benchmark writes "library_build_type"
# itself and bench_context.cpp records "benchmark_library_build_type"; they
# must agree.
#
# Usage (CTest): bench_output_test.py <bench_engines> <bench_force_laws>
#                <cases dir> <CMAKE_BUILD_TYPE>

import glob
import json
import os
import subprocess
import sys
import tempfile
import unittest

ENGINES_BIN, FORCE_LAWS_BIN, CASES_DIR, BUILD_TYPE = (sys.argv[1:5] + [""] * 4)[:4]

# SPEC §5 engine names
ENGINE_NAMES = ["analytic", "reference", "mujoco", "mujoco3", "box2d", "ode"]


def case_names():
    names = []
    for path in sorted(glob.glob(os.path.join(CASES_DIR, "*.toml"))):
        with open(path, encoding="utf-8") as f:
            if "[[bodies]]" in f.read():
                names.append(os.path.splitext(os.path.basename(path))[0])
    return names


def listed(binary):
    """The benchmark names a binary registers (--benchmark_list_tests)."""
    p = subprocess.run([binary, "--benchmark_list_tests=true"], capture_output=True,
                       text=True, check=True)
    return p.stdout.split()


def run_json(binary, *args):
    """The JSON output of one quick run (one iteration per benchmark)."""
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "out.json")
        subprocess.run([binary, "--benchmark_min_time=0", "--benchmark_repetitions=1",
                        f"--benchmark_out={out}", "--benchmark_out_format=json", *args],
                       capture_output=True, text=True, check=True)
        with open(out, encoding="utf-8") as f:
            return json.load(f)


class EnginesBenchTest(unittest.TestCase):

    def test_every_case_is_registered_with_the_reference_solver(self):
        names = listed(ENGINES_BIN)
        cases = case_names()
        # the five cases of cases/ at the time of writing, at least
        self.assertGreaterEqual(len(cases), 5)
        for c in cases:
            # UseRealTime appends "/real_time" to the name
            self.assertIn(f"engines/{c}/reference/real_time", names)

    def test_every_name_is_a_known_case_and_engine(self):
        cases = set(case_names())
        for name in listed(ENGINES_BIN):
            parts = name.split("/")
            self.assertEqual(len(parts), 4, name)
            self.assertEqual(parts[0], "engines")
            self.assertIn(parts[1], cases)
            self.assertIn(parts[2], ENGINE_NAMES)

    def test_one_quick_run_simulates_one_second(self):
        # the analytic falling ball is the cheapest benchmark: one iteration
        data = run_json(ENGINES_BIN, "--benchmark_filter=^engines/falling_ball/analytic/")
        (run,) = data["benchmarks"]
        self.assertEqual(run["iterations"], 1)
        # the window is 1 s (falling_ball lasts 2.5 s), on the 1e-4 s grid
        self.assertEqual(run["window_s"], 1.0)
        # sim_s_per_wall_s is the simulated time over the real time (UseRealTime):
        # 1 s / real_time (ms); relative 1e-6 for the printing of both numbers
        self.assertAlmostEqual(run["sim_s_per_wall_s"] * run["real_time"] * 1e-3, 1.0, delta=1e-6)


class ContextTest(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        cls.data = run_json(FORCE_LAWS_BIN)

    def test_planarbench_build_is_recorded(self):
        ctx = self.data["context"]
        self.assertEqual(ctx["planarbench_build_type"], BUILD_TYPE)
        for key in ("planarbench_version", "planarbench_revision", "planarbench_compiler",
                    "planarbench_flags", "planarbench_sanitize", "machine_cpu_model",
                    "machine_os"):
            self.assertIn(key, ctx)
            self.assertNotEqual(ctx[key], "", key)

    def test_every_engine_version_is_recorded(self):
        ctx = self.data["context"]
        for name in ENGINE_NAMES:
            self.assertIn(f"engine.{name}", ctx)
            self.assertNotEqual(ctx[f"engine.{name}"], "")

    def test_library_build_type_agrees_with_the_library(self):
        ctx = self.data["context"]
        self.assertIn(ctx["library_build_type"], ("debug", "release"))
        self.assertEqual(ctx["benchmark_library_build_type"], ctx["library_build_type"])


class ForceLawsBenchTest(unittest.TestCase):

    def test_each_law_is_evaluated_64_by_64_times_per_iteration(self):
        data = run_json(FORCE_LAWS_BIN)
        runs = {b["name"]: b for b in data["benchmarks"]}
        self.assertEqual(sorted(runs), ["force_laws/hertz", "force_laws/kelvin_voigt",
                                        "force_laws/kelvin_voigt_ramp",
                                        "force_laws/lankarani_nikravesh"])
        for name, run in runs.items():
            # evaluations_per_s = 4096 x iterations / total CPU time, and the
            # JSON's cpu_time is the time per iteration (us): 4096 / cpu_time;
            # relative 1e-6 for the printing of both numbers
            expected = 4096.0 / (run["cpu_time"] * 1e-6)
            self.assertAlmostEqual(run["evaluations_per_s"] / expected, 1.0, delta=1e-6, msg=name)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
