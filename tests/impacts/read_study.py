#!/usr/bin/python3
"""Reads a file of `planarbench impacts fit` or `impacts score` with h5py alone
and prints what the tests check as JSON: the table's kind, its description,
the models of its rows and their series, and the eps column."""
import json
import sys

import h5py


def main(path):
    with h5py.File(path, "r") as f:
        c = f["campaign"]
        runs = c["runs"]
        out = {
            "kind": c.attrs["kind"].decode() if isinstance(c.attrs["kind"], bytes) else str(c.attrs["kind"]),
            "description": json.loads(c.attrs["description"]),
            "engine": [e.decode() if isinstance(e, bytes) else str(e) for e in runs["engine"][()]],
            "series": [e.decode() if isinstance(e, bytes) else str(e) for e in runs["series"][()]],
            "eps": [float(x) for x in runs["metric"]["eps"][()]],
        }
    json.dump(out, sys.stdout)


if __name__ == "__main__":
    main(sys.argv[1])
