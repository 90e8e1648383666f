#!/usr/bin/python3
"""Writes MAT v7.3 files (HDF5 with MATLAB's 512-byte header, h5py) that
libmatio opens but planarbench does not read: KIND "struct" is a `data`
group of double datasets as MATLAB writes a struct, "int32" the same with an
int32 field, "garbage" the header followed by zeros (not HDF5). Issue 35 item
15: such a file printed HDF5's 26-line error stack before the refusal.
Usage: write_v73_mat.py OUT.mat KIND"""
import sys

import h5py
import numpy as np

out, kind = sys.argv[1], sys.argv[2]
text = b"MATLAB 7.3 MAT-file, Platform: GLNXA64, Created on: Mon Jan  1 00:00:00 2024 HDF5 schema 1.00 ."
# 116 bytes of text, 8 of subsystem offset, version 0x0200, endian "IM"
header = text.ljust(116, b" ") + b"\0" * 8 + b"\x00\x02" + b"IM"
if kind == "garbage":
    open(out, "wb").write(header.ljust(512, b"\0") + b"\0" * 4096)
    sys.exit(0)
with h5py.File(out, "w", userblock_size=512) as f:
    g = f.create_group("data")
    g.attrs["MATLAB_class"] = np.bytes_("struct")
    for name, cols in (("states_i", 6), ("states_f", 6), ("n", 3), ("d", 3)):
        dtype = np.int32 if kind == "int32" and name == "states_i" else np.float64
        ds = g.create_dataset(name, data=np.zeros((cols, 20), dtype=dtype))  # MATLAB stores transposed
        ds.attrs["MATLAB_class"] = np.bytes_("int32" if dtype == np.int32 else "double")
with open(out, "r+b") as f:
    f.write(header)
