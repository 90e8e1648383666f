#!/usr/bin/python3
"""Exits 0 when two results files hold the same groups and bit-identical datasets.

Attributes that record when and how a file was made (/parameters, wall_time_s)
are allowed to differ; everything computed must not.
Usage: same_datasets.py A.h5 B.h5
"""
import sys

import h5py


def datasets(f):
    out = {}
    f.visititems(lambda n, o: out.__setitem__(n, o[()]) if isinstance(o, h5py.Dataset) else None)
    return out


def main(a, b):
    with h5py.File(a, "r") as fa, h5py.File(b, "r") as fb:
        da, db = datasets(fa), datasets(fb)
        if sorted(da) != sorted(db):
            print(f"different datasets: {sorted(set(da) ^ set(db))}")
            return 1
        bad = [n for n in da if da[n].tobytes() != db[n].tobytes()]
        if bad:
            print(f"datasets differ: {bad}")
            return 1
        print(f"{len(da)} datasets identical")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
