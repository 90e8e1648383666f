#!/usr/bin/python3
"""Reads a planarbench results file with h5py and numpy alone (SPEC §5).

Usage: /usr/bin/python3 read_results.py RESULTS.h5

Prints, for each case and engine, the run's status and the first rows of its
contact-episode table, and checks the layout on the way: the H5MD version,
the provenance attributes, every run's attributes, a `unit` attribute on every
dataset, the shapes of the trajectories and the `unit`/`fields` arrays of the
tables. Exits 1 on any violation (all are listed), 2 on bad usage.
"""
import hashlib
import json
import sys

import h5py
import numpy as np

PARAMETERS = ["build_revision", "compiler", "compiler_flags", "build_type", "host",
              "utc_time", "planarbench_version", "command_line"]
CASE_ATTRS = ["case_text", "case_sha256", "case_path", "overrides"]
RUN_STRINGS = ["engine_version", "status", "reason", "settings", "mapping", "extra"]
RUN_JSON = ["settings", "mapping", "extra"]
BODY_DATASETS = {  # name: (unit, columns or None for [n])
    "time": ("s", None), "position": ("m", 2), "angle": ("rad", None),
    "velocity": ("m/s", 2), "angular_velocity": ("rad/s", None)}
TABLES = {
    "contacts": [("time", "s"), ("body_a", ""), ("body_b", ""), ("force_n", "N"),
                 ("penetration", "m"), ("normal", "1"), ("point", "m"),
                 ("tangential_force_n", "N"), ("slip_mps", "m/s")],
    "events": [("body_a", ""), ("body_b", ""), ("onset_time", "s"), ("offset_time", "s"),
               ("approach_speed", "m/s"), ("separation_speed", "m/s"), ("restitution", "1"),
               ("peak_force", "N"), ("impulse", "N s"), ("max_penetration", "m")],
}
EVENT_ROWS_SHOWN = 3

errors = []


def fail(where, what):
    errors.append(f"{where}: {what}")


def string_attr(obj, name):
    """A scalar string attribute as str (vlen UTF-8 reads as str in h5py >= 3)."""
    if name not in obj.attrs:
        fail(obj.name, f"attribute '{name}' is missing")
        return None
    value = obj.attrs[name]
    if not isinstance(value, str):
        fail(obj.name, f"attribute '{name}' is {type(value).__name__}, not str")
        return None
    return value


def string_list(obj, name):
    """A 1-D string array attribute as a list of str (may be empty)."""
    if name not in obj.attrs:
        fail(obj.name, f"attribute '{name}' is missing")
        return []
    value = obj.attrs[name]
    if isinstance(value, h5py.Empty):
        return []
    return [v.decode("utf-8") if isinstance(v, bytes) else str(v) for v in np.atleast_1d(value)]


def check_units(f):
    """Every dataset in the file carries a `unit` attribute."""
    def visit(name, obj):
        if isinstance(obj, h5py.Dataset) and "unit" not in obj.attrs:
            fail(obj.name, "dataset has no 'unit' attribute")
    f.visititems(visit)


def check_h5md(f):
    if "h5md" not in f:
        fail("/h5md", "group is missing")
        return
    version = f["h5md"].attrs.get("version")
    if version is None or list(np.asarray(version)) != [1, 1]:
        fail("/h5md", f"version is {version!r}, expected [1, 1]")
    for sub in ("author", "creator"):
        if sub not in f["h5md"]:
            fail(f"/h5md/{sub}", "group is missing")
        else:
            string_attr(f["h5md"][sub], "name")
    if "creator" in f["h5md"]:
        string_attr(f["h5md/creator"], "version")


def check_table(run, name, body_names):
    """A compound table with its unit/fields arrays; returns it (or None)."""
    if name not in run:
        fail(f"{run.name}/{name}", "table is missing")
        return None
    table = run[name]
    expected = TABLES[name]
    if table.dtype.names != tuple(n for n, _ in expected):
        fail(table.name, f"fields {table.dtype.names}, expected {[n for n, _ in expected]}")
    if string_list(table, "fields") != [n for n, _ in expected]:
        fail(table.name, "attribute 'fields' does not list the fields in order")
    if string_list(table, "unit") != [u for _, u in expected]:
        fail(table.name, f"attribute 'unit' is {string_list(table, 'unit')}")
    rows = table[()]
    for col in ("body_a", "body_b"):
        for cell in rows[col] if len(rows) else []:
            if cell.decode("utf-8") not in body_names:
                fail(table.name, f"{col} '{cell!r}' is not in body_names")
                break
    return rows


def check_bodies(run):
    if "bodies" not in run:
        if run.attrs.get("status") != "unsupported":
            fail(run.name, "bodies group is missing for a run that is not unsupported")
        return
    for body in run["bodies"].values():
        n = None
        for name, (unit, cols) in BODY_DATASETS.items():
            if name not in body:
                fail(f"{body.name}/{name}", "dataset is missing")
                continue
            d = body[name]
            n = d.shape[0] if n is None else n
            shape = (n,) if cols is None else (n, cols)
            if d.shape != shape or d.dtype != np.float64:
                fail(d.name, f"shape {d.shape} dtype {d.dtype}, expected {shape} float64")
            if d.attrs.get("unit") != unit:
                fail(d.name, f"unit {d.attrs.get('unit')!r}, expected {unit!r}")


def show_run(case_name, run):
    status = string_attr(run, "status")
    if status not in ("ok", "diverged", "unsupported"):
        fail(run.name, f"status {status!r} is not ok, diverged or unsupported")
    for name in RUN_STRINGS:
        string_attr(run, name)
    for name in RUN_JSON:
        try:
            json.loads(run.attrs.get(name, ""))
        except (TypeError, ValueError):
            fail(run.name, f"attribute '{name}' is not JSON")
    for name, kind in (("diverged_at_s", np.floating), ("wall_time_s", np.floating),
                       ("steps", np.integer)):
        if not isinstance(run.attrs.get(name), kind):
            fail(run.name, f"attribute '{name}' is missing or not {kind.__name__}")
    body_names = string_list(run, "body_names")
    reason = run.attrs.get("reason", "")
    print(f"{case_name}/{run.name.split('/')[-1]}: {status}" + (f" ({reason})" if reason else ""))

    check_bodies(run)
    check_table(run, "contacts", body_names)
    events = check_table(run, "events", body_names)
    if events is None:
        return
    print(f"  events: {len(events)} rows")
    for row in events[:EVENT_ROWS_SHOWN]:
        a, b = row["body_a"].decode("utf-8"), row["body_b"].decode("utf-8")
        print(f"    {a}-{b}: onset {row['onset_time']:.6g} s, offset {row['offset_time']:.6g} s, "
              f"approach {row['approach_speed']:.6g} m/s, e = {row['restitution']:.6g}, "
              f"peak {row['peak_force']:.6g} N")


def main(argv):
    if len(argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    with h5py.File(argv[1], "r") as f:
        check_h5md(f)
        if "parameters" not in f:
            fail("/parameters", "group is missing")
        else:
            for name in PARAMETERS:
                string_attr(f["parameters"], name)
        check_units(f)
        if "runs" not in f:
            fail("/runs", "group is missing")
        for case_name, case in (f["runs"].items() if "runs" in f else []):
            for name in CASE_ATTRS:
                string_attr(case, name)
            text = str(case.attrs.get("case_text", ""))
            if hashlib.sha256(text.encode("utf-8")).hexdigest() != case.attrs.get("case_sha256"):
                fail(case.name, "case_sha256 is not the SHA-256 of case_text")
            try:
                if not isinstance(json.loads(case.attrs.get("overrides", "")), dict):
                    raise ValueError
            except (TypeError, ValueError):
                fail(case.name, "overrides is not a JSON object")
            for run in case.values():
                show_run(case_name, run)
    for e in errors:
        print("VIOLATION " + e, file=sys.stderr)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
