#!/usr/bin/python3
"""Reads a file of `planarbench impacts fit` or `impacts score` with h5py alone
and prints what the tests check as JSON: the table's kind, its description,
the models of its rows and their series, the eps column, and the e_f and
spin_eps columns beside their recomputation with numpy from the rows' own
velocity columns and the object of the description (issue 34: an independent
computation of the published metric e_F = ||v_pred - v_meas||_M / ||v_meas||_M,
M = diag(m, m, m k^2), and of the spin's |w_pred - w_meas| / |w_meas - w_pre|),
with the median of each per model."""
import json
import sys

import h5py
import numpy as np


def main(path):
    with h5py.File(path, "r") as f:
        c = f["campaign"]
        runs = c["runs"]
        out = {
            "kind": c.attrs["kind"].decode() if isinstance(c.attrs["kind"], bytes) else str(c.attrs["kind"]),
            "description": json.loads(c.attrs["description"]),
            "engine": [e.decode() if isinstance(e, bytes) else str(e) for e in runs["engine"][()]],
            "series": [e.decode() if isinstance(e, bytes) else str(e) for e in runs["series"][()]],
            # a failed prediction's eps is NaN: null in JSON
            "eps": [float(x) if np.isfinite(x) else None for x in runs["metric"]["eps"][()]],
        }
        metric = runs["metric"]
        if "e_f" in metric:  # a group of one dataset per metric; files before issue 34 lack it
            col = {k: np.asarray(metric[k][()], dtype=float) for k in (
                "e_f", "spin_eps", "pre_w_radps", "meas_vx_mps", "meas_vy_mps", "meas_w_radps",
                "pred_vx_mps", "pred_vy_mps", "pred_w_radps")}
            obj = out["description"]["object"]
            m, k = obj["mass_kg"], obj["gyration_radius_m"]
            miss = np.sqrt(m * (col["pred_vx_mps"] - col["meas_vx_mps"]) ** 2
                           + m * (col["pred_vy_mps"] - col["meas_vy_mps"]) ** 2
                           + m * k * k * (col["pred_w_radps"] - col["meas_w_radps"]) ** 2)
            post = np.sqrt(m * col["meas_vx_mps"] ** 2 + m * col["meas_vy_mps"] ** 2
                           + m * k * k * col["meas_w_radps"] ** 2)
            spin = np.abs(col["pred_w_radps"] - col["meas_w_radps"]) / np.abs(
                col["meas_w_radps"] - col["pre_w_radps"])
            finite = lambda a: [float(x) if np.isfinite(x) else None for x in a]
            out["e_f"] = finite(col["e_f"])
            out["e_f_numpy"] = finite(miss / post)
            out["spin_eps"] = finite(col["spin_eps"])
            out["spin_eps_numpy"] = finite(spin)
            engines = np.array(out["engine"])
            out["e_f_median_numpy"] = {
                e: float(np.median(col["e_f"][engines == e])) for e in sorted(set(out["engine"]))
                if np.all(np.isfinite(col["e_f"][engines == e]))}
    json.dump(out, sys.stdout)


if __name__ == "__main__":
    main(sys.argv[1])
