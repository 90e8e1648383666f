#!/usr/bin/python3
"""Checks the analytic falling_ball events in a results file against SPEC §2.

The figures are SPEC §2's closed-form values for the case (disk R = 0.5 m,
m = 1 kg, from rest at (2, 2) onto the line through the origin declining at
30 deg, Kelvin-Voigt k = 1e4 N/m, c = 10 N s/m, clamped): they are compared
to their printed digits, i.e. to half a unit of the last printed digit.
Only h5py and numpy are used, so this also proves the file opens without
planarbench.  Usage: check_falling_ball.py RESULTS.h5
"""
import sys

import h5py
import numpy as np


def near(name, value, printed, digits_after_point):
    tol = 0.5 * 10.0 ** (-digits_after_point)
    ok = abs(value - printed) <= tol
    print(f"{name:>18}: {value:.10g}  (SPEC {printed}, tol {tol:g}) {'ok' if ok else 'FAIL'}")
    return ok


def main(path):
    with h5py.File(path, "r") as f:
        run = f["runs/falling_ball/analytic"]
        status = run.attrs["status"]
        if status != "ok":
            print(f"status {status}: {run.attrs['reason']}")
            return 1
        ev = run["events"][:]
        if len(ev) < 2:
            print(f"expected two bounces, got {len(ev)} episodes")
            return 1
        first = ev[0]
        ok = all([
            near("onset_time [s]", first["onset_time"], 0.72501, 5),
            near("approach [m/s]", first["approach_speed"], 6.1573, 4),
            near("restitution", first["restitution"], 0.8562, 4),
            near("peak_force [N]", first["peak_force"], 581.2, 1),
            near("impulse [N s]", first["impulse"], 11.70, 2),
            near("max_pen [mm]", 1e3 * first["max_penetration"], 57.8, 1),
            near("duration [ms]", 1e3 * (first["offset_time"] - first["onset_time"]), 31.75, 2),
        ])
        second = ev[1]
        ok &= bool(first["offset_time"] < second["onset_time"] < 2.5)
        print(f"{'second onset [s]':>18}: {second['onset_time']:.10g}")
        # every dataset of the run carries a unit
        units = []
        run.visititems(lambda n, o: units.append(n) if isinstance(o, h5py.Dataset)
                       and "unit" not in o.attrs else None)
        if units:
            print(f"datasets without unit: {units}")
            ok = False
        t = run["bodies/ball/time"][:]
        ok &= bool(np.all(np.diff(t) > 0))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
