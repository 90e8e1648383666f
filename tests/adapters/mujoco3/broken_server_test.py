"""Issue 49: engine mujoco3 when its other process misbehaves. Each fixture is
the real wasm/server.mjs with one line changed (the change is asserted to
apply, so an edit of server.mjs that moves the line fails here rather than
testing nothing), run on the real mujoco-js package (node_modules linked):
  - it stops answering after the version query, or at it: the run ends at
    --run-timeout (or PB_MUJOCO3_TIMEOUT_S) and no Node process outlives the
    command, also when the command itself is sent SIGTERM;
  - it sends what MuJoCo never sends: a geom index of 1e6, a force of +inf,
    INFO frames that are not the JSON asked for, a 1 MB or an empty ERROR
    frame: the run ends `diverged` with one line naming what was wrong.
Not a stand-in for MuJoCo in a test of MuJoCo: these test our side of the
pipe (mujoco3_process.cpp, mujoco3_mirror.cpp, the runner's contact check).

Usage: broken_server_test.py PLANARBENCH WASM_DIR
"""
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest

import h5py

EXE = sys.argv.pop(1)
WASM = os.path.abspath(sys.argv.pop(1))
SERVER = open(os.path.join(WASM, "server.mjs"), encoding="utf-8").read()

# blocks this Node for ever without spinning (a hung library call)
HANG = "Atomics.wait(new Int32Array(new SharedArrayBuffer(4)), 0, 0);"

# A command that hangs for ever is what this test guards against: every
# subprocess here is bounded at 90 s, far above the 5 s limits the runs are
# given and the ~2 s a healthy short run takes, so a regression fails (the
# subprocess timeout) rather than hanging ctest.
BOUND_S = 90


def node_processes(marker):
    """pids of live processes whose command line holds `marker`."""
    pids = []
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as f:
                cmd = f.read().decode("utf-8", "replace")
            with open(f"/proc/{pid}/stat") as f:
                state = f.read().rsplit(")", 1)[1].split()[0]
        except OSError:
            continue
        if marker in cmd and state != "Z":
            pids.append(int(pid))
    return pids


class Fixture:
    """A PB_MUJOCO3_DIR holding server.mjs with `old` replaced by `new`."""

    def __init__(self, old, new):
        assert SERVER.count(old) == 1, f"server.mjs no longer holds exactly one {old!r}"
        self.dir = tempfile.TemporaryDirectory(prefix="pb-broken-server-")
        with open(os.path.join(self.dir.name, "server.mjs"), "w", encoding="utf-8") as f:
            f.write(SERVER.replace(old, new))
        os.symlink(os.path.join(WASM, "node_modules"), os.path.join(self.dir.name, "node_modules"))
        self.env = dict(os.environ, PB_MUJOCO3_DIR=self.dir.name)

    def close(self):
        for pid in node_processes(self.dir.name):
            os.kill(pid, signal.SIGKILL)
        self.dir.cleanup()

    def run(self, *extra, env=None, case="block_hold"):
        out = os.path.join(self.dir.name, "r.h5")
        cmd = [EXE, "run", "--case", case, "--engine", "mujoco3", "--quiet",
               "--set", "duration=0.05", "--out", out, *extra]
        p = subprocess.run(cmd, env=dict(self.env, **(env or {})), capture_output=True, text=True,
                           timeout=BOUND_S)
        status = reason = None
        if os.path.exists(out):
            with h5py.File(out) as f:
                run = f[f"runs/{case}/mujoco3"]
                status, reason = run.attrs["status"], run.attrs.get("reason", "")
        return p, status, reason


class Hangs(unittest.TestCase):
    def test_a_run_that_hangs_ends_at_its_timeout_and_takes_node_with_it(self):
        fx = Fixture("load(payload.toString('utf8'));", HANG)
        try:
            p, status, reason = fx.run("--run-timeout", "5")
            self.assertEqual(p.returncode, 3, p.stderr)  # 3: a run diverged
            self.assertEqual(status, "diverged")
            self.assertIn("run-timeout", reason)
            self.assertEqual(node_processes(fx.dir.name), [])
        finally:
            fx.close()

    def test_the_answer_timeout_ends_a_hang_in_process(self):
        fx = Fixture("load(payload.toString('utf8'));", HANG)
        try:
            p, status, reason = fx.run("--isolation", "none", env={"PB_MUJOCO3_TIMEOUT_S": "3"})
            self.assertEqual(p.returncode, 3, p.stderr)
            self.assertEqual(status, "diverged")
            self.assertIn("no answer within 3 s (a hang)", reason)
            self.assertEqual(node_processes(fx.dir.name), [])
        finally:
            fx.close()

    def test_list_honours_the_answer_timeout(self):
        fx = Fixture("const pkg = JSON.parse(fs.readFileSync(", HANG + "\n    const pkg = JSON.parse(fs.readFileSync(")
        try:
            p = subprocess.run([EXE, "list"], env=dict(fx.env, PB_MUJOCO3_TIMEOUT_S="3"),
                               capture_output=True, text=True, timeout=BOUND_S)
            self.assertEqual(p.returncode, 0, p.stderr)
            line = [l for l in p.stdout.splitlines() if l.strip().startswith("mujoco3 ")][0]
            self.assertIn("unavailable", line)
            self.assertIn("no answer within 3 s", line)
            self.assertEqual(node_processes(fx.dir.name), [])
        finally:
            fx.close()

    def test_sigterm_to_the_command_leaves_no_node(self):
        for isolation in ("process", "none"):
            with self.subTest(isolation=isolation):
                fx = Fixture("load(payload.toString('utf8'));", HANG)
                try:
                    out = os.path.join(fx.dir.name, "r.h5")
                    p = subprocess.Popen([EXE, "run", "--case", "block_hold", "--engine", "mujoco3",
                                          "--quiet", "--isolation", isolation, "--out", out],
                                         env=fx.env, stdout=subprocess.DEVNULL,
                                         stderr=subprocess.DEVNULL)
                    # wait for the hung Node to exist (it answers VERSION first)
                    deadline = time.monotonic() + BOUND_S
                    while not node_processes(fx.dir.name) and time.monotonic() < deadline:
                        time.sleep(0.1)
                    self.assertTrue(node_processes(fx.dir.name), "Node never started")
                    time.sleep(0.5)  # past the version query: the run's own Node hangs
                    p.send_signal(signal.SIGTERM)
                    p.wait(timeout=BOUND_S)
                    # SIGKILL on the parent's death is delivered at once; a
                    # few hundred ms for the kernel to reap
                    deadline = time.monotonic() + 10
                    while node_processes(fx.dir.name) and time.monotonic() < deadline:
                        time.sleep(0.1)
                    self.assertEqual(node_processes(fx.dir.name), [])
                    self.assertFalse(os.path.exists(out))  # never a half-written result
                finally:
                    fx.close()


class AddressSpaceCap(unittest.TestCase):
    """Under `ulimit -v` Node's WebAssembly cannot reserve its guard regions
    (V8's trap handler, ~10 GB a memory): every mujoco3 run failed with a Node
    stack. The adapter starts Node with --disable-wasm-trap-handler when the
    address space is capped (bounds checked in code, the same results)."""

    def test_node_runs_the_module_capped_with_the_flag(self):
        # the mechanism, on the real package: 3 GB of address space
        import resource
        cap = 3_000_000 * 1024

        def limit():
            resource.setrlimit(resource.RLIMIT_AS, (cap, cap))

        frame = (0).to_bytes(4, "little") + (0).to_bytes(4, "little")  # VERSION
        quit_ = (5).to_bytes(4, "little") + (0).to_bytes(4, "little")
        p = subprocess.run(["node", "--disable-wasm-trap-handler", os.path.join(WASM, "server.mjs")],
                           input=frame + quit_, capture_output=True, preexec_fn=limit,
                           timeout=BOUND_S)
        self.assertEqual(p.returncode, 0, p.stderr.decode("utf-8", "replace")[-400:])
        self.assertIn(b'"version":"3.', p.stdout)

    def test_the_adapter_passes_the_flag_when_capped(self):
        # what the adapter starts, recorded by a PB_NODE that runs node; the
        # cap is 2**46 bytes (64 TB): any finite cap, high enough for the
        # sanitizer builds' shadow memory
        import resource
        with tempfile.TemporaryDirectory() as d:
            log = os.path.join(d, "args")
            wrapper = os.path.join(d, "node")
            with open(wrapper, "w") as f:
                f.write(f'#!/bin/sh\necho "$@" >> {log}\nexec node "$@"\n')
            os.chmod(wrapper, 0o755)
            env = dict(os.environ, PB_NODE=wrapper)
            for capped in (False, True):
                if os.path.exists(log):
                    os.remove(log)

                def limit():
                    if capped:
                        resource.setrlimit(resource.RLIMIT_AS, (2**46, 2**46))

                p = subprocess.run([EXE, "list"], env=env, capture_output=True, text=True,
                                   preexec_fn=limit, timeout=BOUND_S)
                self.assertEqual(p.returncode, 0, p.stderr)
                with open(log) as f:
                    args = f.read()
                self.assertEqual("--disable-wasm-trap-handler" in args, capped, args)
                line = [l for l in p.stdout.splitlines() if l.strip().startswith("mujoco3 ")][0]
                self.assertNotIn("unavailable", line)


class Trust(unittest.TestCase):
    def diverged(self, old, new, *expected):
        fx = Fixture(old, new)
        try:
            p, status, reason = fx.run()
            self.assertEqual(p.returncode, 3, p.stderr)
            self.assertEqual(status, "diverged", reason)
            for e in expected:
                self.assertIn(e, reason)
            self.assertNotIn("json.exception", reason)
            self.assertNotIn("\n", reason)
            # one line: what is wrong, not the frame (a 1 MB ERROR frame
            # gives 600 characters of it and its size)
            self.assertLess(len(reason), 1200, reason[:200])
            return reason
        finally:
            fx.close()

    def test_a_geom_index_out_of_range(self):
        self.diverged("out.push(c.geom1, c.geom2,", "out.push(1e6, c.geom2,", "geom1 = 1000000",
                      "allowed")

    def test_an_infinite_contact_force(self):
        # a number MuJoCo computes: a fault of the run when its step is
        # reached (the runner's contact check), not an error of the message
        self.diverged("rec.push(...force.GetView());", "rec.push(Infinity, 0, 0, 0, 0, 0);",
                      "non-finite contact between", "force inf N")

    def test_info_frames_that_are_not_the_json_asked_for(self):
        load_info = "writeFrame(1, Buffer.from(JSON.stringify({\n    version: mj.mj_versionString(), nq"
        cases = {
            "not json": ("writeFrame(1, Buffer.from('not json')); if (0) ((JSON.stringify({\n"
                         "    version: mj.mj_versionString(), nq", "not a JSON object"),
            "an array": ("writeFrame(1, Buffer.from('[1, 2]')); if (0) ((JSON.stringify({\n"
                         "    version: mj.mj_versionString(), nq", "not a JSON object"),
            "empty": ("writeFrame(1, Buffer.from('')); if (0) ((JSON.stringify({\n"
                      "    version: mj.mj_versionString(), nq", "not a JSON object"),
            "missing key": ("writeFrame(1, Buffer.from(JSON.stringify({\n"
                            "    version: mj.mj_versionString(), nqq", "\"nq\" is missing"),
            "wrong type": ("writeFrame(1, Buffer.from(JSON.stringify({\n"
                           "    version: 7, nq", "\"version\" is a JSON number (it must be a string)"),
        }
        for name, (new, expected) in cases.items():
            with self.subTest(name):
                self.diverged(load_info, new, "answered LOAD with an INFO frame", expected)

    def test_error_frames_huge_and_empty(self):
        load = "load(payload.toString('utf8'));"
        huge = self.diverged(load, "writeFrame(9, Buffer.alloc(1 << 20, 'x'));",
                             "(1048576 bytes in all)")
        self.assertIn("x" * 100, huge)
        self.diverged(load, "writeFrame(9, Buffer.alloc(0));", "empty ERROR frame")
        # control characters in a reason become spaces (the JUnit and HTML
        # outputs carry reasons)
        bell = self.diverged(load, "writeFrame(9, Buffer.from('bad\\u0007\\nmodel'));",
                             "bad  model")
        self.assertNotIn("\x07", bell)


if __name__ == "__main__":
    unittest.main(verbosity=2)
