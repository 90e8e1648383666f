#!/usr/bin/python3
"""The error of ODE's per-step contact rule on one Lankarani-Nikravesh collision
(issue 25: the `ode_*_rule_*` constants of cases/thresholds.toml).

    ode_step_rule.py                       print the constants
    ode_step_rule.py cases/thresholds.toml check the file's constants are these

ODE's native mapping (adapters/ode, its mapping notes "law_per_step" and
"soft_contact") turns the law into a linear spring-damper once per step: at the
step's start, with depth d, k = K d^(n-1) (the secant) and c = K d^n 3 (1 - e^2)
/ (4 v-) (v- latched at the first step with d > 0); c' = c - h k where c >= h k,
else 0; ERP = h k / (h k + c'), CFM = 1 / (h k + c'), i.e. an implicit spring on
the step's end: F = k (d + h d'_new) + c' d'_new, clamped at F >= 0, and
semi-implicit Euler. This script runs that rule on the 1-D collision of the
case's effective mass at its approach speed (no gravity) for onsets at 32
phases within a step, and compares it with the law integrated to rtol 1e-12
(scipy's DOP853, SPEC §1 eq. 3 with the square root). The worst relative error
of restitution, peak force and impulse over the phases is what the step rule
can cost on that collision; the thresholds add the 2-D terms (gravity,
geometry) in their `why`.

The rule is written here from the adapter's stated mapping, not from its code;
the law from SPEC §1. A self-test first checks that the rule converges to the
law as h -> 0 (first order: a tenth of the step, at most a fifth of the error).
"""

import math
import sys
import tomllib

import numpy
from scipy.integrate import solve_ivp

# onsets at this many phases within a step; the worst of them is the bound
PHASES = 32


def law_collision(K, n, e, m, v):
    """(restitution, peak force N, impulse N s) of the law, integrated closely."""
    a = 3 * (1 - e * e) / 4

    def force(d, dd):
        return max(0.0, K * max(d, 0.0) ** n * (1 + a * dd / v))

    def rhs(_t, y):
        return [y[1], -force(y[0], y[1]) / m]

    def apart(t, y):
        return y[0] if t > 0 else 1.0
    apart.terminal = True
    apart.direction = -1
    # s: 100 times the time to cross the elastic peak depth (m v^2 / K)^(1/(n+1)) at v,
    # far past the contact's end (about 3 of them)
    t_end = 100 * (m * v * v / K) ** (1 / (n + 1)) / v
    s = solve_ivp(rhs, [0.0, t_end], [0.0, v], method="DOP853", rtol=1e-12, atol=1e-18,
                  events=apart, dense_output=True, max_step=t_end / 2000)
    t_off = s.t_events[0][0]
    # the peak on a grid of 2e4 points: the force is smooth there, so the grid's
    # miss is ~ (pi / 2e4)^2 / 2 = 1.2e-8 of it
    d, dd = s.sol(numpy.linspace(0.0, t_off, 20001))
    peak = float(numpy.max(K * numpy.maximum(d, 0.0) ** n * (1 + a * dd / v)))
    v_out = -s.sol(t_off)[1]
    return v_out / v, peak, m * (v + v_out)


def rule_collision(K, n, e, m, v, h, phase):
    """The same collision under ODE's step rule, the surface reached `phase` of a step in."""
    a = 3 * (1 - e * e) / 4
    d, dd = -phase * v * h, v  # m, m/s: depth and its rate
    latched = None
    peak = impulse = 0.0
    touched = False
    while True:
        lam = 0.0  # N
        if d > 0:
            latched = dd if latched is None else latched
            k = K * d ** (n - 1)
            c = K * d ** n * a / latched
            c_used = c - h * k if c >= h * k else 0.0
            lam = max(0.0, (k * d + (h * k + c_used) * dd) / (1 + h * (h * k + c_used) / m))
            touched = True
        elif touched:
            break
        dd -= h * lam / m
        d += h * dd
        peak = max(peak, lam)
        impulse += h * lam
    return -dd / v, peak, impulse


def worst_errors(K, n, e, m, v, h):
    """Largest relative errors (restitution, peak force, impulse) over the onset phases."""
    e0, f0, j0 = law_collision(K, n, e, m, v)
    worst = [0.0, 0.0, 0.0]
    for i in range(PHASES):
        got = rule_collision(K, n, e, m, v, h, (i + 0.5) / PHASES)
        for k, (x, x0) in enumerate(zip(got, (e0, f0, j0))):
            worst[k] = max(worst[k], abs(x / x0 - 1))
    return worst


def dual_pendulum_K():
    """K of dual_pendulum (SPEC §1 eq. 3): E 210 GPa, nu 0.33, R_i = R_j = 0.0085 m."""
    h_l = (1 - 0.33 ** 2) / (math.pi * 210e9)
    return 4 / (3 * math.pi * 2 * h_l) * math.sqrt(0.0085 * 0.0085 / (0.0085 + 0.0085))


# the collisions: (constant prefix, K N/m^n, n, nominal e, m_eff kg, v_n m/s, h s)
COLLISIONS = [
    # pendulum_wall.toml: K 2e6, e 0.8; m_eff = I_p / arm^2 and v_n = omega arm at the touch
    # from the closed-form swing (the thresholds' pw_meff, pw_v1)
    ("ode_pw", 2e6, 1.5, 0.8, 1.414073788, 1.94716, 1e-4),
    # dual_pendulum.toml: e 0.7, h = 1e-5 s; v_n of the closed-form swing (dp_v1), m_eff =
    # J / (v_n (1 + e)) of the truth's first contact (2.0233 N s, e 0.796077)
    ("ode_dp", dual_pendulum_K(), 1.5, 0.7, 2.0233 / (1.78054 * 1.796077), 1.78054, 1e-5),
]


def constants():
    """{name: worst relative error} for every collision: <prefix>_rule_e, _F, _J."""
    out = {}
    for prefix, K, n, e, m, v, h in COLLISIONS:
        for suffix, x in zip(("e", "F", "J"), worst_errors(K, n, e, m, v, h)):
            out[f"{prefix}_rule_{suffix}"] = x
    return out


def self_test():
    """The rule converges to the law: at h / 10 its restitution error is under a fifth."""
    _, K, n, e, m, v, h = COLLISIONS[0]
    coarse = worst_errors(K, n, e, m, v, h)[0]
    fine = worst_errors(K, n, e, m, v, h / 10)[0]
    if not fine < coarse / 5:
        return [f"self-test: the step rule does not converge (error {coarse:.3g} at h, "
                f"{fine:.3g} at h / 10)"]
    return []


def round_up_2(x):
    unit = 10.0 ** (math.floor(math.log10(x)) - 1)
    return math.ceil(x / unit) * unit


def main(argv):
    failures = self_test()
    values = constants()
    if len(argv) == 1:
        for name, x in values.items():
            print(f'{name} = "{round_up_2(x):.2g}"')
        return 1 if failures else 0
    with open(argv[1], "rb") as f:
        table = tomllib.load(f).get("constants", {})
    for name, x in values.items():
        if name not in table:
            failures.append(f"{argv[1]}: constants.{name} missing (computed {x:.6g})")
            continue
        given = float(table[name])
        # the file holds the computed figure rounded up to 2 significant digits
        if not x <= given <= round_up_2(x) * (1 + 1e-12):
            failures.append(f"{argv[1]}: constants.{name} = {given:g}, computed {x:.6g} "
                            f"(expected it rounded up to 2 digits, {round_up_2(x):.2g})")
    print("\n".join(failures) if failures else f"{len(values)} constants match")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
