#!/usr/bin/python3
"""Reads a planarbench sweep file with h5py and numpy alone.

Usage: /usr/bin/python3 read_sweep.py SWEEP.h5

The sweep is a results file whose /campaign table (kind "sweep") has a row per
rung (core/include/planarbench/sweep_file.hpp). Checks the layout on the way
(the provenance attributes of /parameters, each case's attributes and digest,
its series, a `unit` attribute on every column, one row per rung in every
column, known status words) and prints the file's numbers, regrouped by
series, as one JSON object on stdout:
  {"parameters": {...}, "cases": {case: {"truth": ..., "series": {name:
   {"knob": ..., "value": [...], "position_error_m": [...], "status": [...], ...}}}}}
NaN becomes null. Exits 1 on any violation (all are listed on stderr), 2 on
bad usage.
"""
import hashlib
import json
import math
import sys

import h5py
import numpy as np

PARAMETERS = ["build_revision", "compiler", "compiler_flags", "build_type", "host",
              "utc_time", "planarbench_version", "command_line"]
CASE_ATTRS = ["case_text", "case_sha256", "case_path", "overrides", "duration_s", "truth",
              "truth_note", "extra"]
SERIES_KEYS = ["name", "engine", "knob", "knob_key", "knob_unit", "default_value",
               "fixed_settings"]
COLUMNS = {  # name: unit
    "id": "1", "case": "", "engine": "", "series": "", "overrides": "", "physics": "", "status": "",
    "reason": "", "steps": "1", "axis/dt": "s", "axis/rtol": "1", "metric/position_error_m": "m"}
STATUS = {"ok", "diverged", "unsupported"}

errors = []


def fail(where, what):
    errors.append(f"{where}: {what}")


def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def number(v):
    v = float(v)
    return None if math.isnan(v) else v


def read_columns(runs):
    cols = {}
    for name, unit in COLUMNS.items():
        where = f"/campaign/runs/{name}"
        if name not in runs:
            fail(where, "dataset missing")
            continue
        d = runs[name]
        if text(d.attrs.get("unit", "?")) != unit:
            fail(where, f"unit {text(d.attrs.get('unit', '?'))!r}, expected {unit!r}")
        if d.ndim != 1:
            fail(where, f"shape {d.shape}, expected [n]")
        if h5py.check_string_dtype(d.dtype) is not None:
            cols[name] = [text(x) for x in d.asstr()[()]]
        else:
            cols[name] = [float(x) for x in np.asarray(d[()], dtype=float)]
    cols["wall_time_s"] = [float(x) for x in runs.attrs.get("wall_time_s", [])]
    if len({len(v) for v in cols.values()}) > 1:
        fail("/campaign/runs", f"columns differ in length: {sorted({len(v) for v in cols.values()})}")
    for s in cols.get("status", []):
        if s not in STATUS:
            fail("/campaign/runs/status", f"unknown status {s!r}")
    return cols


def read_series(case, spec, cols):
    out = {"knob": spec["knob"], "engine": spec["engine"],
           "default_value": number(spec["default_value"])}
    json.loads(spec["fixed_settings"])
    rows = [i for i, (c, s) in enumerate(zip(cols["case"], cols["series"]))
            if c == case and s == spec["name"]]
    axis = "axis/dt" if spec["knob"] == "dt" else "axis/rtol"
    out["value"] = [number(cols[axis][i]) for i in rows]
    out["wall_time_s"] = [number(cols["wall_time_s"][i]) for i in rows]
    out["steps"] = [number(cols["steps"][i]) for i in rows]
    out["position_error_m"] = [number(cols["metric/position_error_m"][i]) for i in rows]
    out["status"] = [cols["status"][i] for i in rows]
    out["reason"] = [cols["reason"][i] for i in rows]
    return out


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    result = {"parameters": {}, "cases": {}}
    with h5py.File(sys.argv[1], "r") as f:
        p = f["parameters"]
        for a in PARAMETERS:
            if a not in p.attrs:
                fail("/parameters", f"attribute {a} missing")
            else:
                result["parameters"][a] = text(p.attrs[a])
        g = f["campaign"]
        if text(g.attrs.get("kind", "")) != "sweep":
            fail("/campaign", "kind is not 'sweep'")
        result["parameters"]["file_kind"] = text(g.attrs.get("kind", ""))
        description = json.loads(text(g.attrs["description"]))
        result["parameters"]["repeat"] = int(description["repeat"])
        result["parameters"]["dt_ladder"] = [float(x) for x in description["dt_ladder"]]
        result["parameters"]["rtol_ladder"] = [float(x) for x in description["rtol_ladder"]]
        cols = read_columns(g["runs"])
        for case, cg in g["cases"].items():
            where = f"/campaign/cases/{case}"
            for a in CASE_ATTRS:
                if a not in cg.attrs:
                    fail(where, f"attribute {a} missing")
            digest = hashlib.sha256(text(cg.attrs["case_text"]).encode()).hexdigest()
            if digest != text(cg.attrs["case_sha256"]):
                fail(where, "case_sha256 does not match case_text")
            c = {"truth": text(cg.attrs["truth"]), "truth_note": text(cg.attrs["truth_note"]),
                 "duration_s": float(cg.attrs["duration_s"]), "series": {}}
            for spec in json.loads(text(cg.attrs["extra"]))["series"]:
                for k in SERIES_KEYS:
                    if k not in spec:
                        fail(f"{where}@extra", f"series without {k}")
                c["series"][spec["name"]] = read_series(case, spec, cols)
            result["cases"][case] = c
    if errors:
        for e in errors:
            print(e, file=sys.stderr)
        return 1
    print(json.dumps(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
