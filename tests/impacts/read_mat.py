#!/usr/bin/python3
"""Reads a MAT v5 file of impacts with scipy alone and prints its arrays as JSON
(tests/impacts/impact_data_test.cpp compares them with what planarbench reads).
Floats are printed with repr: they round-trip exactly."""
import hashlib
import json
import sys

import scipy.io


def main(path):
    m = scipy.io.loadmat(path, squeeze_me=False, struct_as_record=False)
    data = m["data"][0, 0]
    out = {
        "states_i": data.states_i.tolist(),
        "states_f": data.states_f.tolist(),
        "drop": data.drop.reshape(-1).tolist(),
        "has_v_models": "v_models" in m,
        "sha256": hashlib.sha256(open(path, "rb").read()).hexdigest(),
    }
    if "v_models" in m:
        out["v_models"] = m["v_models"].tolist()
    json.dump(out, sys.stdout)


if __name__ == "__main__":
    main(sys.argv[1])
