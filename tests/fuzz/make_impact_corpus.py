#!/usr/bin/python3
"""Writes the seed corpora of fuzz_impact_data (corpus/impact_data: MAT files)
and fuzz_impact_work (corpus/impact_work: a first byte '0' for study.json or
'1' for the task file mujoco.1.json, then the file's text). Made-up impacts
only (the MCube dataset states no licence and is never committed). scipy
writes its creation date into a MAT v5 header, so the MAT files differ in
those bytes from run to run; the rest is deterministic. The `found_*` inputs
are the fuzzer's (this script leaves them alone). Run from anywhere:
    /usr/bin/python3 tests/fuzz/make_impact_corpus.py"""
import io
import json
import os
import struct
import subprocess
import sys

import numpy as np
import scipy.io

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "corpus", "impact_data")
WORK = os.path.join(HERE, "corpus", "impact_work")
TESTS = os.path.join(HERE, "..", "impacts")


def mat_bytes(fields, compress=True, models=None):
    buf = io.BytesIO()
    d = {"data": fields}
    if models is not None:
        d["v_models"] = models
    scipy.io.savemat(buf, d, format="5", do_compression=compress)
    return buf.getvalue()


def impacts(n, seed):
    """n made-up drops: falling at 2-3 m/s, bouncing at half the speed"""
    rng = np.random.default_rng(seed)
    pre = np.column_stack([rng.uniform(0.1, 0.5, n), rng.uniform(0.05, 0.07, n),
                           rng.uniform(-3, 3, n), rng.uniform(0.1, 1, n),
                           rng.uniform(-2.9, -2.2, n), rng.uniform(-10, 10, n)])
    post = pre.copy()
    post[:, 4] = -0.5 * pre[:, 4]
    post[:, 5] = 0.8 * pre[:, 5]
    return {"states_i": pre, "states_f": post, "n": np.zeros((n, 3)), "d": np.zeros((n, 3)),
            "drop": np.arange(1, n + 1, dtype=float).reshape(1, n)}


def write(folder, name, data):
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


def data_corpus():
    os.makedirs(DATA, exist_ok=True)
    good = impacts(12, 1)
    write(DATA, "valid_12.mat", mat_bytes(good))
    write(DATA, "valid_12_uncompressed.mat", mat_bytes(good, compress=False))
    write(DATA, "valid_12_models.mat", mat_bytes(good, models=np.zeros((12, 18)) + 0.5))
    write(DATA, "too_few_3.mat", mat_bytes(impacts(3, 2), compress=False))
    t = dict(good)
    t["states_i"] = good["states_i"].T.copy()
    write(DATA, "transposed.mat", mat_bytes(t, compress=False))
    t = dict(good)
    t["states_i"] = (good["states_i"] * 1000).astype(np.int32)
    write(DATA, "int32.mat", mat_bytes(t, compress=False))
    t = dict(good)
    t["states_f"] = good["states_i"].copy()
    write(DATA, "no_change.mat", mat_bytes(t, compress=False))
    t = {k: v.copy() for k, v in good.items()}
    t["states_i"][3, 4] = 1e308
    write(DATA, "huge_speed.mat", mat_bytes(t, compress=False))
    raw = mat_bytes(good, compress=False)
    write(DATA, "cut_short.mat", raw[: len(raw) - 127])
    comp = mat_bytes(good)
    write(DATA, "cut_short_compressed.mat", comp[: len(comp) - 40])
    # states_i's header claiming 5e7 rows (the data left as it is)
    at = raw.find(struct.pack("<ii", 12, 6))
    claim = bytearray(raw)
    claim[at:at + 8] = struct.pack("<ii", 50000000, 6)
    write(DATA, "claims_5e7_rows.mat", bytes(claim))
    write(DATA, "not_mat.mat", b"hello\n")
    write(DATA, "empty.mat", b"")
    # impacts of the rigid law, whose convention is decided (the whole path)
    subprocess.run([sys.executable, os.path.join(TESTS, "write_mat.py"),
                    os.path.join(DATA, "rigid_law_12.mat"), "12", "1", "0.6", "0.2", "--models"],
                   check=True)
    for kind in ("struct", "garbage"):
        out = os.path.join(DATA, "v73_%s.mat" % kind)
        subprocess.run([sys.executable, os.path.join(TESTS, "write_v73_mat.py"), out, kind],
                       check=True)


def task(**edits):
    t = {"model": "mujoco", "fold": 1, "parameters": [1e5, 0.1, 0.2], "objective": 0.05,
         "evaluations": 4, "stop": "maxeval reached", "wall_time_s": 0.01,
         "predicted": [0, 3, 7, 39],
         "outcomes": [[0.1, 0.2, 1.3, -4.0, 0.003, 0.002, 1, 30, ""] for _ in range(4)]}
    t.update(edits)
    return b"1" + json.dumps(t).encode()


def study(**edits):
    s = {"data_sha256": "98cfffb49b43ca2fd0ae4d58be50866a353c23eecbb39f53fe0938cd1c9f7b09",
         "impacts": 40, "folds": 2, "seed": 23, "max_evaluations": 2,
         "models": ["mujoco", "rigid", "naive_bounce"],
         # kFitObjective (core/impacts/include/planarbench/impacts/impact_fit.hpp)
         "objective": "the median eps plus the mean of min(eps, 1) (a failed impact: +inf and 1)"}
    s.update(edits)
    return b"0" + json.dumps(s).encode()


def work_corpus():
    os.makedirs(WORK, exist_ok=True)
    write(WORK, "task_valid.json", task())
    write(WORK, "task_predicted_999999.json", task(predicted=[0, 3, 7, 999999]))
    write(WORK, "task_predicted_minus_1.json", task(predicted=[0, 3, 7, -1]))
    write(WORK, "task_predicted_twice.json", task(predicted=[0, 3, 3, 39]))
    write(WORK, "task_other_model.json", task(model="ode"))
    write(WORK, "task_other_fold.json", task(fold=0))
    write(WORK, "task_fold_2_pow_32_plus_1.json", task(fold=2**32 + 1))
    write(WORK, "task_two_parameters.json", task(parameters=[1.0, 2.0]))
    write(WORK, "task_outcomes_short.json", task(outcomes=[]))
    write(WORK, "task_outcome_strings.json", task(outcomes=[["a"] * 9] * 4))
    write(WORK, "task_null_objective.json", task(objective=None))
    write(WORK, "study_valid.json", study())
    write(WORK, "study_folds_2e9.json", study(folds=2000000000))
    write(WORK, "study_folds_minus_5.json", study(folds=-5))
    write(WORK, "study_model_path.json", study(models=["../../x"]))
    write(WORK, "study_models_twice.json", study(models=["rigid", "rigid"]))
    write(WORK, "study_seed_negative.json", study(seed=-1))
    write(WORK, "study_sha_short.json", study(data_sha256="abc"))
    write(WORK, "study_folds_2_pow_32_plus_2.json", study(folds=2**32 + 2))
    write(WORK, "study_folds_fraction.json", study(folds=2.5))
    write(WORK, "deep_nesting.json", b"0" + b"[" * 5000 + b"]" * 5000)
    write(WORK, "not_json.json", b"1{\"model\": ")


data_corpus()
work_corpus()
