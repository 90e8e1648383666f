#!/usr/bin/python3
"""Checks the truth of cases/concave_corner.toml with an integration of its own.

The case: a rigid polygon (the L) falls onto a fixed line and lands on a
single vertex, its outer corner. Nothing here comes from planarbench's code:
the rigid body's three degrees of freedom (x, y, theta) are integrated with
SciPy's solve_ivp (DOP853, event location), the Kelvin-Voigt law of paper
eq. 1, F = K delta + c delta_dot clamped at F >= 0 (SPEC §1), acts along the
line's normal at the lowest vertex, and every number of the body, the line and
the law is read from the case file with tomllib. The first contact episode of
the `analytic` engine's run of the case (its truth, `truth = "converged"`: the
reference solver at exact geometry, rk45 rtol 1e-10), and the body's state at
the end of the run, are compared with this integration.

What the comparison proves: the case's truth, written by code that shares
nothing with this file (core/reference), agrees with an independent
integration of the same physics, to the tolerances stated below.

Usage: check_concave_corner.py PLANARBENCH CASE.toml WORK_DIR
       check_concave_corner.py --mujoco-model CASE.toml   (the figures of
       MuJoCo's impedance model, ImpedanceCorner, for the thresholds)
"""
import math
import os
import subprocess
import sys
import tomllib

import h5py
import numpy as np
from scipy.integrate import solve_ivp

# solve_ivp's tolerances: DOP853 at rtol 1e-12 keeps its own error near 1e-11
# relative over the run, far below every tolerance below
RTOL = 1e-12
ATOL = 1e-14


def rot(theta):
    c, s = math.cos(theta), math.sin(theta)
    return np.array([[c, -s], [s, c]])


class Corner:
    """The case's one moving polygon over its one half-plane."""

    def __init__(self, case):
        ground = next(b for b in case["bodies"] if b.get("fixed", False))
        body = next(b for b in case["bodies"] if not b.get("fixed", False))
        law = case["contacts"][0]
        assert law["law"] == "kelvin_voigt" and law.get("damping_depth", 0.0) == 0.0
        assert law.get("friction", 0.0) == 0.0
        self.k = float(law["stiffness"])          # N/m
        self.c = float(law["damping"])            # N s/m
        self.m = float(body["mass"])              # kg
        self.g = np.array(case["case"]["gravity"], float)  # m/s^2
        self.points = np.array(body["shape"]["points"], float)  # body frame, m
        # the lamina's polar moment about its centroid (the polygon's area
        # moments, Green's theorem), times m / area
        x, y = self.points[:, 0], self.points[:, 1]
        x1, y1 = np.roll(x, -1), np.roll(y, -1)
        cr = x * y1 - x1 * y
        area = cr.sum() / 2.0
        jz = ((x * x + x * x1 + x1 * x1 + y * y + y * y1 + y1 * y1) * cr).sum() / 12.0
        self.inertia = self.m * jz / area         # kg m^2 (centroid at the origin)
        a = math.radians(ground.get("angle_deg", 0.0))
        self.n = np.array([-math.sin(a), math.cos(a)])  # the line's outward normal
        self.p0 = np.array(ground["position"], float)   # a point of the line, m
        theta0 = math.radians(body["angle_deg"])
        self.state0 = np.array([*body["position"], theta0, *body.get("velocity", [0.0, 0.0]),
                                body.get("angular_velocity", 0.0), 0.0])
        # the lowest vertex at the start: the corner that lands
        heights = [self.height(self.state0, i) for i in range(len(self.points))]
        self.corner = int(np.argmin(heights))

    def height(self, s, i):
        """m, vertex i above the line along its normal."""
        r = rot(s[2]) @ self.points[i]
        return float(self.n @ (s[:2] + r - self.p0))

    def law(self, s):
        """delta (m), delta_dot (m/s), the clamped force (N) and the arm r."""
        r = rot(s[2]) @ self.points[self.corner]
        v = s[3:5] + s[5] * np.array([-r[1], r[0]])
        delta = -float(self.n @ (s[:2] + r - self.p0))
        delta_dot = -float(self.n @ v)
        force = max(0.0, self.k * delta + self.c * delta_dot) if delta > 0.0 else 0.0
        return delta, delta_dot, force, r

    def rhs(self, _t, s):
        _, _, force, r = self.law(s)
        f = force * self.n
        torque = r[0] * f[1] - r[1] * f[0]
        acc = self.g + f / self.m
        return [s[3], s[4], s[5], acc[0], acc[1], torque / self.inertia, force]


class ImpedanceCorner(Corner):
    """The same body under MuJoCo's soft contact at impedance d -> 1 (the
    mujoco adapter's mapping, not_expressed): inside the contact the share d
    of the load of gravity along the normal is removed from the contact's own
    dynamics, i.e. the corner's force is the law plus m_eff g (m_eff the
    corner's effective mass now, g . n the normal load), clamped at 0. The
    thresholds' constants mj_cc_lc_* (cases/thresholds.toml) are this model's
    figures, printed by `check_concave_corner.py --mujoco-model CASE.toml`."""

    def law(self, s):
        delta, delta_dot, force, r = super().law(s)
        if delta > 0.0:
            arm = r[0] * self.n[1] - r[1] * self.n[0]
            m_eff = 1.0 / (1.0 / self.m + arm * arm / self.inertia)
            load = -m_eff * float(self.g @ self.n)  # N, gravity's normal load on the corner
            force = max(0.0, self.k * delta + self.c * delta_dot + load)
        return delta, delta_dot, force, r


def crest(f, t0, t1):
    """The largest value of f on [t0, t1]: a 1e-5 s grid, then a golden section."""
    ts = np.arange(t0, t1, 1e-5)
    values = [f(t) for t in ts]
    k = int(np.argmax(values))
    lo, hi = ts[max(k - 1, 0)], ts[min(k + 1, len(ts) - 1)]
    r = (math.sqrt(5.0) - 1.0) / 2.0
    a, b = hi - r * (hi - lo), lo + r * (hi - lo)
    while hi - lo > 1e-12:
        if f(a) > f(b):
            hi, b = b, a
            a = hi - r * (hi - lo)
        else:
            lo, a = a, b
            b = lo + r * (hi - lo)
    return max(f(0.5 * (lo + hi)), max(values))


def integrate(model, t_end):
    """The first episode and the state at t_end (solve_ivp with events)."""
    corner_height = lambda t, s: model.height(s, model.corner)
    # free flight until the corner reaches the line
    falling = lambda t, s: corner_height(t, s)
    falling.terminal, falling.direction = True, -1
    a = solve_ivp(model.rhs, (0.0, t_end), model.state0, method="DOP853", rtol=RTOL, atol=ATOL,
                  events=falling)
    onset = float(a.t_events[0][0])
    s_on = a.y_events[0][0]
    # in contact until the corner leaves the line
    rising = lambda t, s: corner_height(t, s)
    rising.terminal, rising.direction = True, 1
    # the first step leaves the surface: the event at the onset is not the offset
    b = solve_ivp(model.rhs, (onset, t_end), s_on, method="DOP853", rtol=RTOL, atol=ATOL,
                  events=rising, dense_output=True, first_step=1e-9)
    offset = float(b.t_events[0][0])
    s_off = b.y_events[0][0]
    # the force's and the penetration's crests: a 1e-5 s grid of the dense
    # output brackets each, a golden-section search in the bracket finds it to
    # 1e-12 s (a crest's curvature F omega^2 ~ 2e6 N/s^2 then misses ~1e-18 N)
    force = lambda t: model.law(b.sol(t))[2]
    depth = lambda t: model.law(b.sol(t))[0]
    peak = crest(force, onset, offset)
    max_pen = crest(depth, onset, offset)
    # the other vertices stay off the line through the episode (a 1e-4 s
    # grid: they are centimetres away, moving at ~2 m/s): one vertex on a
    # line is the whole contact
    grid = b.sol(np.arange(onset, offset, 1e-4))
    others = min(model.height(grid[:, j], i) for j in range(grid.shape[1])
                 for i in range(len(model.points)) if i != model.corner)
    c = solve_ivp(model.rhs, (offset, t_end), s_off, method="DOP853", rtol=RTOL, atol=ATOL)
    return {
        "onset_time": onset,
        "offset_time": offset,
        "approach_speed": model.law(s_on)[1],
        "separation_speed": -model.law(s_off)[1],
        "peak_force": peak,
        "impulse": s_off[6] - s_on[6],
        "max_penetration": max_pen,
        "others_min_height": others,
        "end": c.y[:, -1],
    }


def main(exe, case_path, work):
    with open(case_path, "rb") as f:
        case = tomllib.load(f)
    name = os.path.splitext(os.path.basename(case_path))[0]
    t_end = float(case["case"]["duration"])
    model = Corner(case)
    mine = integrate(model, t_end)
    mine["restitution"] = mine["separation_speed"] / mine["approach_speed"]

    os.makedirs(work, exist_ok=True)
    out = os.path.join(work, name + "_truth.h5")
    subprocess.run([exe, "run", "--case", case_path, "--engine", "analytic", "--out", out],
                   check=True, stdout=subprocess.DEVNULL)
    with h5py.File(out, "r") as f:
        run = f[f"runs/{name}/analytic"]
        assert run.attrs["status"] == "ok", run.attrs["reason"]
        events = run["events"][:]
        body = next(b for b in case["bodies"] if not b.get("fixed", False))["name"]
        pos = run[f"bodies/{body}/position"][-1]
        ang = run[f"bodies/{body}/angle"][-1]
        vel = run[f"bodies/{body}/velocity"][-1]
        omg = run[f"bodies/{body}/angular_velocity"][-1]
        t_last = run[f"bodies/{body}/time"][-1]
        steps = int(run.attrs["steps"])

    ok = True

    def near(what, truth, ours, tol, rel):
        nonlocal ok
        err = abs(truth - ours) / (abs(ours) if rel else 1.0)
        good = err <= tol
        ok &= good
        print(f"{what:>18}: truth {truth:.12g}  independent {ours:.12g}  "
              f"{'rel' if rel else 'abs'} err {err:.2e} <= {tol:.1e} {'ok' if good else 'FAIL'}")

    # the case's own premise: a single episode, and no other vertex near the line
    print(f"truth: {steps} steps; episodes: {len(events)}; lowest other vertex during the contact "
          f"{mine['others_min_height']:.4f} m above the line")
    ok &= len(events) == 1 and mine["others_min_height"] > 0.0
    e = events[0]
    # Tolerances. The truth is rk45 at rtol 1e-10 (SPEC §3), onsets, offsets
    # and crests located by root finding and golden sections on its
    # interpolant (core/reference); solve_ivp here runs at rtol 1e-12, its
    # crests found to 1e-12 s. The worst the truth's relative error can grow
    # to is 1e-10 per accepted step, summed without cancellation over its
    # steps (the run's own count, read from its attributes): rel = 1e-10 x
    # steps (2.4e-8 at its 243 steps). Speeds, restitution (a ratio of two
    # speeds: 2 rel, absolute on a figure below 1), impulse, peak force and
    # peak penetration within rel, 2 rel, rel, rel, rel. Times: a state off by
    # rel moves a crossing by rel x 0.34 m (the drop's scale) / 1.98 m/s
    # (the corner's speed) = 0.17 rel s; checked to rel s. End state at t_end:
    # position and angle within rel x their scale (0.35 m, 0.35 rad turned):
    # 0.35 rel; vy within rel x 2 m/s, omega within rel x 15 rad/s.
    rel = 1e-10 * steps
    near("onset_time [s]", e["onset_time"], mine["onset_time"], rel, False)
    near("offset_time [s]", e["offset_time"], mine["offset_time"], rel, False)
    near("approach [m/s]", e["approach_speed"], mine["approach_speed"], rel, True)
    near("separation [m/s]", e["separation_speed"], mine["separation_speed"], rel, True)
    near("restitution", e["restitution"], mine["restitution"], 2.0 * rel, False)
    near("impulse [N s]", e["impulse"], mine["impulse"], rel, True)
    near("peak_force [N]", e["peak_force"], mine["peak_force"], rel, True)
    near("max_pen [m]", e["max_penetration"], mine["max_penetration"], rel, True)
    end = mine["end"]
    ok &= abs(t_last - t_end) < 1e-12
    near("end x [m]", pos[0], end[0], 0.35 * rel, False)
    near("end y [m]", pos[1], end[1], 0.35 * rel, False)
    near("end angle [rad]", ang, end[2], 0.35 * rel, False)
    near("end vy [m/s]", vel[1], end[4], 2.0 * rel, False)
    near("end omega [rad/s]", omg, end[5], 15.0 * rel, False)
    return 0 if ok else 1


def print_model(case_path):
    with open(case_path, "rb") as f:
        case = tomllib.load(f)
    ours = integrate(ImpedanceCorner(case), float(case["case"]["duration"]))
    print(f"impedance model: restitution {ours['separation_speed'] / ours['approach_speed']:.6f}, "
          f"impulse {ours['impulse']:.6f} N s, peak force {ours['peak_force']:.4f} N")
    return 0


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--mujoco-model":
        sys.exit(print_model(sys.argv[2]))
    if len(sys.argv) != 4:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(*sys.argv[1:]))
