#!/usr/bin/python3
"""Writes an uncompressed MAT v5 file of 10 made-up impacts (scipy.io.savemat)
whose data.states_i header then claims CLAIM rows instead of 10 (its int32
dimensions patched in place), the data left as it is: a header that promises
far more than the file holds (issue 35: a 416-byte file claiming 5e7 x 6
doubles ended in bad_alloc). Usage: write_claiming_mat.py OUT.mat CLAIM"""
import struct
import sys

import numpy as np
import scipy.io

out, claim = sys.argv[1], int(sys.argv[2])
n = 10
rng = np.random.default_rng(3)
data = {"states_i": rng.normal(size=(n, 6)), "states_f": rng.normal(size=(n, 6)),
        "n": rng.normal(size=(n, 3)), "d": rng.normal(size=(n, 3)),
        "drop": np.arange(1, n + 1, dtype=float).reshape(1, n)}
scipy.io.savemat(out, {"data": data}, format="5", do_compression=False)
raw = bytearray(open(out, "rb").read())
dims = struct.pack("<ii", n, 6)
at = raw.find(dims)  # states_i's dimensions, the struct's first (n, 6) field
assert at > 0, "no (10, 6) dimensions found"
raw[at:at + 8] = struct.pack("<ii", claim, 6)
open(out, "wb").write(bytes(raw))
