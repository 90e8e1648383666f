#!/usr/bin/python3
"""Writes the seed corpus of fuzz_mujoco3_batch (tests/fuzz/corpus/mujoco3_batch):
BATCH messages as adapters/mujoco3/wasm/server.mjs sends them, for a model of
nq = nv = 3 and ngeom = 2 (one planar body, the ground and it): three sizes
bytes, then float64 numbers (fuzz_mujoco3_batch.cpp). Deterministic; run from
the repository's root: /usr/bin/python3 tests/fuzz/make_mujoco3_batch_corpus.py
"""
import os
import struct

NQ, NV, NGEOM = 3, 3, 2
OUT = "tests/fuzz/corpus/mujoco3_batch"


def contact(record, geom1=0, geom2=1):
    # geom1, geom2, dist, pos[3], frame[9], exclude (+ efc_address, force[6])
    c = [geom1, geom2, -1e-4, 0.1, 0.0, 0.0, 0, 0, 1, 1, 0, 0, 0, 1, 0, 0]
    return c + ([0, 9.8, 0, 0, 0, 0, 0] if record else [])


def step(ncon, record, asked=0):
    head = [asked] if record else []
    numbers = head + [0] * 16 + [0.0, 0.1, 0.0] + [0.0, -1.0, 0.0] + [ncon]
    for _ in range(ncon):
        numbers += contact(record)
    return numbers


def message(records, question):
    out = [len(records)]
    for r in records:
        out += r
    if question is None:
        out.append(0)
    else:
        out += [1] + question
    return out


SEEDS = {
    "empty": message([], None),
    "one_step_no_contact": message([step(0, True)], None),
    "one_step_one_contact": message([step(1, True)], None),
    "two_steps_then_a_question": message([step(0, True), step(1, True, asked=1)], step(2, False)),
}


def main():
    os.makedirs(OUT, exist_ok=True)
    for name, numbers in SEEDS.items():
        with open(os.path.join(OUT, name), "wb") as f:
            f.write(bytes([NQ, NV, NGEOM]) + struct.pack(f"<{len(numbers)}d", *numbers))


if __name__ == "__main__":
    main()
