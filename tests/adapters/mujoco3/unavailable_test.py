"""Issue 33: without the WebAssembly package, engine mujoco3 is listed as
unavailable with a one-line reason naming the command that installs it, and
`run --engine all` runs every other engine as before (mujoco3's runs are
`unsupported`, with that reason). PB_MUJOCO3_DIR points the engine at an empty
folder: the state of a clone whose node_modules was removed.

Usage: unavailable_test.py PLANARBENCH
"""
import os
import subprocess
import sys
import tempfile
import unittest

import h5py

EXE = sys.argv.pop(1)


class Unavailable(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        open(os.path.join(self.dir.name, "server.mjs"), "w").close()
        self.env = dict(os.environ, PB_MUJOCO3_DIR=self.dir.name)

    def tearDown(self):
        self.dir.cleanup()

    def test_list_says_why_and_how_to_install(self):
        out = subprocess.run([EXE, "list"], env=self.env, capture_output=True, text=True)
        self.assertEqual(out.returncode, 0, out.stderr)
        line = [l for l in out.stdout.splitlines() if l.strip().startswith("mujoco3 ")][0]
        self.assertIn("unavailable: the mujoco-js package is not installed", line)
        self.assertIn("install it with: bash scripts/setup_web.sh", line)

    def test_the_other_engines_run(self):
        target = os.path.join(self.dir.name, "r.h5")
        out = subprocess.run([EXE, "run", "--case", "falling_ball", "--engine", "all", "--quiet",
                              "--set", "duration=0.05", "--out", target],
                             env=self.env, capture_output=True, text=True)
        self.assertEqual(out.returncode, 0, out.stderr)
        with h5py.File(target) as f:
            runs = f["runs/falling_ball"]
            status = {e: runs[e].attrs["status"] for e in runs}
        self.assertEqual(status.pop("mujoco3"), "unsupported")
        self.assertEqual(sorted(status), ["analytic", "box2d", "mujoco", "ode", "reference"])
        self.assertTrue(all(s == "ok" for s in status.values()), status)


if __name__ == "__main__":
    unittest.main(verbosity=2)
