#!/usr/bin/python3
"""Writes a damaged copy of a planarbench results file, with h5py alone.

    damage_results.py GOOD OUT KIND [RUN]

copies GOOD to OUT and damages one dataset of RUN (default
/runs/falling_ball/analytic; its body "ball"), the way a hostile tester or a
broken writer would (issue 24). KIND:

  bad input (the reader refuses the file, exit 2; tests/data/bad/corpus.toml):
    time_int64        bodies/ball/time stored as int64 (milliseconds)
    time_nan          bodies/ball/time row 5 is NaN
    time_decreasing   bodies/ball/time rows 5 and 6 swapped
    position_short    bodies/ball/position keeps its first 1000 rows only
    time_huge         bodies/ball/time claims 10**12 rows (chunked, none written)
    contacts_huge     contacts claims 10**9 rows (chunked, none written)
    force_int64       contacts field force_n stored as int64

  invalid data (check fails the run, exit 1; tests/cli/cli_test.cpp):
    position_nan_all  every row of bodies/ball/position is NaN
    position_nan_rows rows 100 .. 109 of bodies/ball/position are NaN
    velocity_nan      bodies/ball/velocity row 200 is NaN
    force_nan         contacts row 0 has force_n NaN

    events_nan_all    every float field of every events row is NaN (issue 49)

  a known breach's value (check fails it, exit 1; issue 31, tests/cli/cli_test.cpp):
    events_lost       events keeps no rows: every episode lost
    impulse_nan       events row 0 has impulse NaN
    peak_beyond       events row 0 has peak_force x 1000

  another truth (check refuses the run, exit 2; issue 31): RUN is the analytic run
    truth_converged   its mapping's physics.mode says "converged reference"

  a file check refuses (exit 2, naming the object; issue 49): RUN's group
    mode_number       its mapping's physics.mode is the number 7
    engine_renamed    the run's group renamed to its engine's name + "o"

  a broken assumption (check fails the run's bands that assume it, exit 1; issue 31)
    steps_many        the run's `steps` attribute says 10**6 accepted steps

Every other dataset and attribute is left as it is; a replaced dataset keeps
its attributes (`unit`, `fields`).
"""
import json
import shutil
import sys

import h5py
import numpy as np


def replace(group, name, **create):
    """deletes dataset `name` of `group` and makes it again with `create`"""
    attrs = dict(group[name].attrs)
    del group[name]
    d = group.create_dataset(name, **create)
    for k, v in attrs.items():
        d.attrs[k] = v
    return d


def main():
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__)
    good, out, kind = sys.argv[1:4]
    run = sys.argv[4] if len(sys.argv) == 5 else "/runs/falling_ball/analytic"
    shutil.copyfile(good, out)
    with h5py.File(out, "r+") as f:
        r = f[run]
        ball = r["bodies/ball"] if "bodies/ball" in r else None
        if kind == "time_int64":
            t = ball["time"][()]
            replace(ball, "time", data=np.round(t * 1000).astype("<i8"))
        elif kind == "time_nan":
            t = ball["time"][()]
            t[5] = np.nan
            ball["time"][...] = t
        elif kind == "time_decreasing":
            t = ball["time"][()]
            t[5], t[6] = t[6], t[5]
            ball["time"][...] = t
        elif kind == "position_short":
            p = ball["position"][()]
            replace(ball, "position", data=p[:1000])
        elif kind == "time_huge":
            replace(ball, "time", shape=(10**12,), dtype="<f8", chunks=(4096,),
                    compression="gzip", maxshape=(None,))
        elif kind == "contacts_huge":
            dtype = r["contacts"].dtype
            replace(r, "contacts", shape=(10**9,), dtype=dtype, chunks=(4096,),
                    compression="gzip", maxshape=(None,))
        elif kind == "force_int64":
            rows = r["contacts"][()]
            dtype = np.dtype([(n, "<i8" if n == "force_n" else rows.dtype[n])
                              for n in rows.dtype.names])
            replace(r, "contacts", data=rows.astype(dtype))
        elif kind == "position_nan_all":
            p = ball["position"][()]
            p[:] = np.nan
            ball["position"][...] = p
        elif kind == "position_nan_rows":
            p = ball["position"][()]
            p[100:110] = np.nan
            ball["position"][...] = p
        elif kind == "velocity_nan":
            v = ball["velocity"][()]
            v[200, 1] = np.nan
            ball["velocity"][...] = v
        elif kind == "force_nan":
            rows = r["contacts"][()]
            rows["force_n"][0] = np.nan
            r["contacts"][...] = rows
        elif kind == "events_lost":
            rows = r["events"][()]
            replace(r, "events", data=rows[:0], maxshape=(None,), chunks=True)
        elif kind in ("impulse_nan", "peak_beyond"):
            rows = r["events"][()]
            if kind == "impulse_nan":
                rows["impulse"][0] = np.nan
            else:
                rows["peak_force"][0] *= 1000.0
            r["events"][...] = rows
        elif kind == "steps_many":
            r.attrs["steps"] = np.int64(10**6)
        elif kind == "events_nan_all":
            rows = r["events"][()]
            for name in rows.dtype.names:
                if rows.dtype[name].kind == "f":
                    rows[name] = np.nan
            r["events"][...] = rows
        elif kind == "mode_number":
            mapping = json.loads(r.attrs["mapping"])
            mapping["physics"]["mode"] = 7
            r.attrs["mapping"] = json.dumps(mapping)
        elif kind == "engine_renamed":
            f.move(run, run + "o")
        elif kind == "truth_converged":
            mapping = json.loads(r.attrs["mapping"])
            mapping["physics"]["mode"] = "converged reference"
            r.attrs["mapping"] = json.dumps(mapping)
        else:
            sys.exit(f"unknown KIND {kind!r}\n{__doc__}")


if __name__ == "__main__":
    main()
