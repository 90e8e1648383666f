#!/usr/bin/python3
"""Reads a planarbench sweep file with h5py and numpy alone.

Usage: /usr/bin/python3 read_sweep.py SWEEP.h5

Checks the layout on the way (the provenance attributes of /parameters, each
case's attributes and digest, each series' attributes, a `unit` attribute on
every dataset, equal lengths, known status words) and prints the file's
numbers as one JSON object on stdout:
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
              "utc_time", "planarbench_version", "command_line", "file_kind"]
CASE_ATTRS = ["case_text", "case_sha256", "case_path", "overrides", "duration_s", "truth",
              "truth_note"]
SERIES_ATTRS = ["engine", "knob", "knob_key", "default_value", "fixed_settings", "truth"]
DATASETS = {  # name: unit (None: depends on the knob)
    "value": None, "wall_time_s": "s", "steps": "1", "position_error_m": "m",
    "status": "", "reason": ""}
STATUS = {"ok", "diverged", "unsupported"}

errors = []


def fail(where, what):
    errors.append(f"{where}: {what}")


def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def number(v):
    v = float(v)
    return None if math.isnan(v) else v


def read_series(g, where):
    out = {}
    for a in SERIES_ATTRS:
        if a not in g.attrs:
            fail(where, f"attribute {a} missing")
    out["knob"] = text(g.attrs.get("knob", ""))
    out["engine"] = text(g.attrs.get("engine", ""))
    out["default_value"] = number(g.attrs.get("default_value", float("nan")))
    json.loads(text(g.attrs.get("fixed_settings", "{}")))
    lengths = set()
    for name, unit in DATASETS.items():
        if name not in g:
            fail(where, f"dataset {name} missing")
            continue
        d = g[name]
        if "unit" not in d.attrs:
            fail(f"{where}/{name}", "no unit attribute")
        want = unit if unit is not None else ("s" if out["knob"] == "dt" else "1")
        if text(d.attrs.get("unit", "?")) != want:
            fail(f"{where}/{name}", f"unit {text(d.attrs.get('unit', '?'))!r}, expected {want!r}")
        if d.ndim != 1:
            fail(f"{where}/{name}", f"shape {d.shape}, expected [n]")
        lengths.add(d.shape[0])
        if d.dtype.kind == "O" or h5py.check_string_dtype(d.dtype) is not None:
            out[name] = [text(x) for x in d.asstr()[()]]
        else:
            out[name] = [number(x) for x in np.asarray(d[()], dtype=float)]
    if len(lengths) > 1:
        fail(where, f"datasets differ in length: {sorted(lengths)}")
    for s in out.get("status", []):
        if s not in STATUS:
            fail(f"{where}/status", f"unknown status {s!r}")
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
        result["parameters"]["repeat"] = int(p.attrs["repeat"])
        result["parameters"]["dt_ladder"] = [float(x) for x in p.attrs["dt_ladder"]]
        result["parameters"]["rtol_ladder"] = [float(x) for x in p.attrs["rtol_ladder"]]
        for case, cg in f["sweep"].items():
            where = f"/sweep/{case}"
            for a in CASE_ATTRS:
                if a not in cg.attrs:
                    fail(where, f"attribute {a} missing")
            digest = hashlib.sha256(text(cg.attrs["case_text"]).encode()).hexdigest()
            if digest != text(cg.attrs["case_sha256"]):
                fail(where, "case_sha256 does not match case_text")
            c = {"truth": text(cg.attrs["truth"]), "truth_note": text(cg.attrs["truth_note"]),
                 "duration_s": float(cg.attrs["duration_s"]), "series": {}}
            for name, sg in cg.items():
                c["series"][name] = read_series(sg, f"{where}/{name}")
            result["cases"][case] = c
    if errors:
        for e in errors:
            print(e, file=sys.stderr)
        return 1
    print(json.dumps(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
