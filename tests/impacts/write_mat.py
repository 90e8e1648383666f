#!/usr/bin/python3
"""Writes a MAT v5 file of made-up impacts with scipy.io.savemat, in the MCube
file's layout and conventions (angles clockwise-positive, y twice the centre's
height): an independent writer for planarbench's reader, and impacts made by
an independent implementation (numpy) of the rigid law the project's
baseline states: Newton restitution at the contact point and Coulomb friction
with a stick check (core/impacts/include/planarbench/impacts/rigid_impact.hpp).

Usage: write_mat.py OUT.mat N SEED E MU [--models]
"""
import sys

import numpy as np
import scipy.io

A, B, M, K = 0.035, 0.025, 0.0364, 0.0192354
I = M * K * K


def lowest_point(th):
    """world offset centre -> lowest point of the ellipse at angle th (CCW)"""
    ux, uy = -np.sin(th), -np.cos(th)
    s = np.sqrt(A * A * ux * ux + B * B * uy * uy)
    px, py = A * A * ux / s, B * B * uy / s
    c, sn = np.cos(th), np.sin(th)
    return np.array([c * px - sn * py, sn * px + c * py])


def rigid(th, v, w, e, mu):
    r = lowest_point(th)
    p = np.array([-r[1], r[0]])
    W = np.eye(2) / M + np.outer(p, p) / I
    u = v + w * p
    P = np.linalg.solve(W, np.array([-u[0], -(1 + e) * u[1]]))
    if abs(P[0]) > mu * P[1]:
        d = np.array([-mu * np.sign(u[0]), 1.0])
        P = -(1 + e) * u[1] / (W @ d)[1] * d
    return v + P / M, w + (r[0] * P[1] - r[1] * P[0]) / I


def main():
    out, n, seed, e, mu = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
    rng = np.random.default_rng(seed)
    pre, post = [], []
    while len(pre) < n:
        th = rng.uniform(-3.1, 3.1)
        v = np.array([rng.uniform(0.1, 1.1), rng.uniform(-2.9, -2.2)])
        w = rng.uniform(-14.0, 25.0)
        r = lowest_point(th)
        if v[1] + w * r[0] > -0.5:
            continue  # the lowest point must approach the ground
        v1, w1 = rigid(th, v, w, e, mu)
        h2 = 2 * np.sqrt(A * A * np.sin(th) ** 2 + B * B * np.cos(th) ** 2)
        pre.append([0.2, h2, -th, v[0], v[1], -w])
        post.append([0.2, h2, -th, v1[0], v1[1], -w1])
    pre, post = np.array(pre), np.array(post)
    data = {
        "states_i": pre,
        "states_f": post,
        "n": np.tile([0.0, 1.0, 0.0], (n, 1)),
        "d": np.tile([1.0, 0.0, 0.0], (n, 1)),
        "drop": np.arange(1, n + 1, dtype=float).reshape(1, n),
    }
    content = {"data": data}
    if "--models" in sys.argv:
        content["v_models"] = np.tile(post[:, 3:6], (1, 6))
    scipy.io.savemat(out, content, format="5", do_compression=True)


if __name__ == "__main__":
    main()
