#!/usr/bin/python3
"""The pinned mujoco-js (adapters/mujoco3/wasm/package-lock.json) as the
mujoco3 engine will use it (issue 33), run in Node by probe.mjs:
  - it is MuJoCo 3.3.8 (mj_versionString);
  - a contact's solref set between mj_collision and the constraint solve
    takes effect: the row's stiffness is MuJoCo's closed form
    k = 1 / (d_max^2 timeconst^2 dampratio^2) with its default solimp
    d_max = 0.95 (MuJoCo's documentation, Modeling > Solver parameters):
    2770.08 1/s^2 (its reference acceleration per unit depth) at 0.02 s,
    four times that at 0.01 s;
  - the ball at rest carries m g = 9.81 N (MuJoCo's default gravity) in
    mj_contactForce's normal;
  - a repeated run is bit-identical (WebAssembly's IEEE-754 doubles, one thread).
Fails, never skips, when node or the package is missing, naming the script
that installs them. Usage: wasm_probe_test.py ADAPTERS_MUJOCO3_WASM_DIR"""
import json
import os
import shutil
import subprocess
import sys


def probe(wasm, *args):
    out = subprocess.run(["node", os.path.join(wasm, "probe.mjs"), *args], cwd=wasm,
                         capture_output=True, text=True, timeout=100)
    if out.returncode != 0:
        sys.exit(f"FAIL probe.mjs {' '.join(args)}: {out.stderr.strip()}")
    return json.loads(out.stdout)


def main(wasm):
    if shutil.which("node") is None:
        sys.exit("FAIL node not found: run scripts/setup_web.sh (installs nodejs and the npm packages)")
    if not os.path.isfile(os.path.join(wasm, "node_modules", "mujoco-js", "package.json")):
        sys.exit(f"FAIL mujoco-js not installed in {wasm}/node_modules: run scripts/setup_web.sh")
    failures = []

    def check(ok, what):
        print(("ok   " if ok else "FAIL ") + what)
        if not ok:
            failures.append(what)

    a, b = probe(wasm), probe(wasm)
    stiff = probe(wasm, "0.01")
    check(a["version"] == "3.3.8", f"mj_versionString() = {a['version']}")
    check(a["qpos_hex"] == b["qpos_hex"], f"a repeated run is bit-identical: {a['qpos_hex']} / {b['qpos_hex']}")
    # 1e-12 relative: k is 1 / (0.95^2 tc^2) formed in a few double operations
    for run, tc in ((a, 0.02), (stiff, 0.01)):
        want = 1.0 / (0.95 ** 2 * tc ** 2)
        check(abs(run["kbip_k"] - want) <= 1e-12 * want,
              f"solref [{tc}, 1] set on the copied contact: row stiffness {run['kbip_k']} = {want}")
    # 1e-12 relative: at rest the soft contact's force balances gravity to rounding
    check(abs(a["normal_n"] - 9.81) <= 1e-12 * 9.81, f"normal force at rest {a['normal_n']} = m g = 9.81 N")
    check(stiff["qpos_hex"] != a["qpos_hex"], "the stiffer contact moves the ball differently")
    if failures:
        sys.exit(f"{len(failures)} check(s) failed")


if __name__ == "__main__":
    main(sys.argv[1])
