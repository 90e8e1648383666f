#!/usr/bin/python3
"""Reads a merged planarbench campaign file with h5py and numpy alone.

Usage: /usr/bin/python3 read_campaign.py CAMPAIGN.h5

Checks the layout of /campaign on the way (core/include/planarbench/
campaign_table.hpp): every column has a `unit` and one row per run, ids are
0..n-1 in order, status words are known, wall_time_s has a value per run, the
trace has shape [n, 2 B T], each case's digest matches its text. Prints, as
one JSON object on stdout: runs, planned_runs, axes, status counts, each
engine's "mode: force by ..." attributions (the physics column), the
position errors of the analytic engine and of the others (runs ok), and
whether every ok run's trace starts at its case's initial positions (the case text's, or the
run's overrides where they set a body's position). Exits 1 on any violation
(listed on stderr), 2 on bad usage.
"""
import hashlib
import json
import re
import sys

import h5py
import numpy as np

errors = []


def fail(where, what):
    errors.append(f"{where}: {what}")


def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def initial_positions(case_text):
    """{body: (x, y)} from a case file's [[bodies]] tables (name and position lines)."""
    out, name = {}, None
    for line in case_text.splitlines():
        line = line.split("#", 1)[0].strip()
        m = re.match(r'name\s*=\s*"([^"]+)"', line)
        if m:
            name = m.group(1)
        m = re.match(r"position\s*=\s*\[\s*([-+0-9.eE]+)\s*,\s*([-+0-9.eE]+)\s*\]", line)
        if m and name is not None:
            out[name] = (float(m.group(1)), float(m.group(2)))
    return out


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    out = {}
    with h5py.File(sys.argv[1], "r") as f:
        g = f["campaign"]
        runs = g["runs"]
        n = runs["id"].shape[0]
        out["runs"] = int(n)
        out["planned_runs"] = int(g.attrs["planned_runs"])
        out["axes"] = list(g["axes"].keys())
        cols = {}
        for name in ["id", "case", "engine", "series", "overrides", "physics", "status", "reason", "steps"]:
            d = runs[name]
            if "unit" not in d.attrs:
                fail(f"/campaign/runs/{name}", "no unit attribute")
            if d.shape != (n,):
                fail(f"/campaign/runs/{name}", f"shape {d.shape}, expected ({n},)")
            cols[name] = d.asstr()[()] if h5py.check_string_dtype(d.dtype) else d[()]
        for group in ["axis", "metric"]:
            for name, d in runs[group].items():
                if "unit" not in d.attrs or d.shape != (n,):
                    fail(f"/campaign/runs/{group}/{name}", "no unit or not one row per run")
        if not np.array_equal(cols["id"], np.arange(n)):
            fail("/campaign/runs/id", "ids are not 0..n-1 in order")
        if len(runs.attrs["wall_time_s"]) != n:
            fail("/campaign/runs@wall_time_s", "not one value per run")
        status = {}
        for s in cols["status"]:
            if s not in ("ok", "diverged", "unsupported"):
                fail("/campaign/runs/status", f"unknown status {s!r}")
            status[s] = status.get(s, 0) + 1
        out["status"] = status
        whose = {}
        for engine, physics in zip(cols["engine"], cols["physics"]):
            p = json.loads(physics)
            whose.setdefault(engine, set()).add(f'{p.get("mode")}: force by {p.get("contact_force_by")}')
        out["physics"] = {e: sorted(v) for e, v in whose.items()}
        cases = {}
        for name, cg in g["cases"].items():
            t = text(cg.attrs["case_text"])
            if hashlib.sha256(t.encode()).hexdigest() != text(cg.attrs["case_sha256"]):
                fail(f"/campaign/cases/{name}", "case_sha256 does not match case_text")
            cases[name] = (initial_positions(t), [text(b) for b in cg.attrs["moving_bodies"]])
        err = runs["metric/position_error_m"][()]
        ok = cols["status"] == "ok"
        analytic = cols["engine"] == "analytic"
        out["analytic_position_error_m"] = [float(x) for x in err[analytic & ok]]
        out["engine_position_error_m"] = [float(x) for x in err[~analytic & ok]]
        tp = int(g.attrs["trace_points"])
        nb = int(g.attrs["trace_bodies"])
        trace = runs["trace_position_m"][()]
        if trace.shape != (n, 2 * nb * tp):
            fail("/campaign/runs/trace_position_m", f"shape {trace.shape}, expected ({n}, {2 * nb * tp})")
        trace = trace.reshape(n, nb, tp, 2)
        starts = True
        for i in np.flatnonzero(ok):
            positions, bodies = cases[cols["case"][i]]
            overrides = json.loads(cols["overrides"][i])
            for b, body in enumerate(bodies):
                want = positions[body]
                key = f"bodies.{body}.position"
                if key in overrides:
                    want = tuple(json.loads(overrides[key]))
                if not np.allclose(trace[i, b, 0], want, rtol=0, atol=1e-12):
                    starts = False
                    fail(f"run {i}", f"trace of {body} starts at {trace[i, b, 0]}, not {want}")
        out["trace_starts_at_initial_position"] = starts
    if errors:
        for e in errors:
            print(e, file=sys.stderr)
        return 1
    print(json.dumps(out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
