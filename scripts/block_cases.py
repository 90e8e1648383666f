#!/usr/bin/python3
"""Writes the friction-on-a-face cases (issue 30): cases/square_{hold,slide,stop}.toml
and the block family cases/family/*.toml that campaigns/block_family.toml runs.

    /usr/bin/python3 scripts/block_cases.py            # rewrite them (deterministic)
    /usr/bin/python3 scripts/block_cases.py --check    # exit 1 if a file differs

Every block is a uniform rectangle w x hh on a Kelvin-Voigt line (K, c = 2 zeta
sqrt(K m)) with a Coulomb coefficient mu; its closed form is SPEC §7's (hold:
drift 0; slide: a = g (sin - mu cos); stop: v0 / (mu g), v0^2 / (2 mu g)).

Where it starts: at rest in the static pose of its first phase under the
one-force law (SPEC §1) with the block's corners as its points (the
reference's rule for a body on a half-plane with friction, pair_geometry.cpp):
the deeper corner pressed in by the static penetration delta_0 = m g cos / K
(so the law's force is m g cos), the face tilted by phi so that the corners'
depth-weighted centroid carries the normal force where it balances the
friction's moment about the centre (the load m g sin while held, mu m g cos
while sliding). Found by bisection on phi. A block started flat is not at
rest in any compliant model: the moment is unbalanced at t = 0, the face rocks
to its static tilt, and the rocking's tangential demand may leave the cone
(reference README, "Friction on a face"); the hold is a question about a body
at rest, the slide's and the stop's about their steady phases. The tilt
(at most delta_0 / w) vanishes as K grows: the closed form is its rigid limit
(core/analytic/body_on_line.hpp, static_level_m).
"""
import math
import pathlib
import sys

G = 9.8066  # m/s^2, SPEC §2
ROOT = pathlib.Path(__file__).resolve().parent.parent


def static_pose(w, hh, m, k, theta, friction_n):
    """(centre height above the line along n, tilt phi) of a block held at
    rest on a line inclined at theta by a friction force friction_n (N, up the
    slope): the deeper (downhill) corner pressed in by delta_0 = m g cos / K,
    so that the law's force is m g cos, and phi found by bisection where the
    moment about the centre vanishes. Incline frame: x down the slope, y the
    outward normal; the block's corners (+-w/2, -h) turned by phi (< 0: the
    downhill corner lower), the uphill corner between delta_0 and the surface."""
    h = hh / 2.0
    fn = m * G * math.cos(theta)     # N, the normal force at rest
    d0 = fn / k                      # m, the deeper corner's depth

    def pose(phi):
        c, s = math.cos(phi), math.sin(phi)
        local = [(c * x + s * h, s * x - c * h) for x in (-w / 2.0, w / 2.0)]
        yc = -d0 - local[1][1]       # the downhill corner at depth d0
        corners = [(x, y + yc) for x, y in local]
        depths = [max(0.0, -y) for _, y in corners]
        total = sum(depths)
        px = sum(d * x for d, (x, _) in zip(depths, corners)) / total
        py = sum(d * y for d, (_, y) in zip(depths, corners)) / total
        # the normal force fn along +y and the friction -friction_n along x at (px, py)
        torque = px * fn - (py - yc) * (-friction_n)
        return yc, torque

    lo = -math.asin(d0 / w)          # the uphill corner at the surface
    hi = 0.0                         # flat: the friction's moment unbalanced
    if pose(lo)[1] < 0.0:
        raise ValueError("the block tips: friction's moment exceeds what its face can carry")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if pose(mid)[1] > 0.0:
            lo = mid
        else:
            hi = mid
    phi = 0.5 * (lo + hi)
    return pose(phi)[0], phi


def block_case(name, description, w, hh, m, k, zeta, theta_deg, mu, v0, duration, notes):
    th = math.radians(theta_deg)
    c = 2.0 * zeta * math.sqrt(k * m)
    d0 = m * G * math.cos(th) / k
    h = hh / 2.0
    n = (math.sin(th), math.cos(th))
    t = (math.cos(th), -math.sin(th))
    # the friction force of the first phase: the load while it holds, mu N
    # while it slides (down the slope, or thrown along the line)
    sliding = v0 > 0.0 or math.tan(th) > mu
    friction_n = mu * m * G * math.cos(th) if sliding else m * G * math.sin(th)
    yc, phi = static_pose(w, hh, m, k, th, friction_n)
    start_text = (f"in the static pose of its first phase ({'sliding' if sliding else 'held'}, "
                  f"friction {friction_n:.6g} N): the deeper corner pressed in by delta_0 = "
                  f"m g cos / K = {d0:.6g} m, the face tilted by {phi:.6g} rad")
    angle = -th + phi
    px, py = yc * n[0], yc * n[1]
    vel = (v0 * t[0], v0 * t[1])
    inertia = m * (w * w + hh * hh) / 12.0
    comment = "\n".join("# " + line for line in notes)
    return f'''# {name}: {description}
{comment}
#
# Written by scripts/block_cases.py (issue 30); edit that script, not this file.
# Block {w} m x {hh} m, {m} kg, on a line declining toward +x at {theta_deg} deg;
# Kelvin-Voigt K = {k:g} N/m, c = 2 zeta sqrt(K m) = {c:.6g} N s/m (zeta = {zeta:.4g});
# Coulomb mu = {mu:.6g} (tan(theta) / mu = {math.tan(th) / mu if mu > 0 else float("inf"):.4g});
# starts {start_text}.

[case]
description = "{description}"
duration = {duration}              # s
output_interval = 1e-4      # s
gravity = [0.0, -9.8066]    # m/s^2
truth = "analytic"          # a rigid block on a line with Coulomb friction (SPEC §7)
assumptions = [
  "block {w} m x {hh} m, mass {m} kg, uniform lamina (I = m (w^2 + h^2) / 12)",
  "line inclined at {theta_deg} deg, Coulomb mu = {mu:.6g}",
  "starts {start_text}",
  "Kelvin-Voigt K = {k:g} N/m, c = {c:.6g} N s/m (damping ratio {zeta:.4g})",
]

[[bodies]]
name = "ground"
fixed = true
shape = {{ type = "halfplane", extent = 40.0 }}    # m
position = [0.0, 0.0]       # m
angle = {-th!r} # rad

[[bodies]]
name = "block"
shape = {{ type = "polygon", points = [[{-w / 2!r}, {-h!r}], [{w / 2!r}, {-h!r}], [{w / 2!r}, {h!r}], [{-w / 2!r}, {h!r}]] }}  # m
mass = {m}                  # kg
inertia = "shape"           # {inertia:.6g} kg m^2
angle = {angle!r} # rad
position = [{px!r}, {py!r}]  # m
velocity = [{vel[0]!r}, {vel[1]!r}]  # m/s

[[contacts]]
name = "ground_block"
bodies = ["ground", "block"]
law = "kelvin_voigt"
stiffness = {k:g}           # N/m
damping = {c!r}   # N s/m
friction = {mu!r}   # Coulomb coefficient (SPEC §7)
'''


def square_cases():
    """The issue's square: 0.2 m x 0.2 m, 2 kg, K 2e5, c 1100 (zeta 0.87)."""
    zeta = 1100.0 / (2.0 * math.sqrt(2e5 * 2.0))
    th = math.radians(25.0)
    slide_a = G * (math.sin(th) - 0.42 * math.cos(th))
    yield "square_hold", block_case(
        "square_hold", "A 0.2 m square at rest on a 25 deg incline, tan(theta) / mu = 0.933: "
        "Coulomb friction must hold it still", 0.2, 0.2, 2.0, 2e5, zeta, 25.0, 0.5, 0.0, 2.0,
        ["The first friction case a new user tries (issue 30): a box on a ramp.",
                   "The truth holds it exactly: hold_drift_m and creep_speed_mps measure the",
                   "drift of the material point under the face's middle."])
    yield "square_slide", block_case(
        "square_slide", "The same square at mu = 0.42 (tan(theta) / mu = 1.11): slides at "
        "g (sin - mu cos)", 0.2, 0.2, 2.0, 2e5, zeta, 25.0, 0.42, 0.0, 1.0,
        [f"Slides at a = g (sin(theta) - mu cos(theta)) = {slide_a:.6f} m/s^2"
         " (slide_acceleration_mps2)."])
    yield "square_stop", block_case(
        "square_stop", "The same square thrown at 3 m/s along flat ground, mu = 0.5: stops "
        "after v0 / (mu g)", 0.2, 0.2, 2.0, 2e5, zeta, 0.0, 0.5, 3.0, 1.0,
        [f"Stops at t = v0 / (mu g) = {3.0 / (0.5 * G):.6f} s after "
         f"v0^2 / (2 mu g) = {9.0 / (2 * 0.5 * G):.6f} m (stop_time_s, stop_distance_m)."])


def family_cases():
    """The block family of issue 30: aspect ratio hh / w from 1:10 to 1:1, mass
    0.5-5 kg, stiffness 5e4-5e5 N/m, slope 10-40 deg, tan(theta) / mu 0.5-0.98
    (hold) and 1.02-2 (slide), stops from 0.5-5 m/s; mass and stiffness cycle
    through their three values so that every pair of levels meets."""
    w = 0.2
    masses = (0.5, 2.0, 5.0)
    stiffnesses = (5e4, 2e5, 5e5)
    i = 0
    # on an incline: held (tan / mu < 1) and sliding (> 1)
    for kind, aspects, ratios in (("hold", (0.1, 0.3, 1.0), (0.5, 0.98)),
                                  ("slide", (0.1, 1.0), (1.02, 2.0))):
        for aspect in aspects:
            for slope in (10.0, 25.0, 40.0):
                for ratio in ratios:
                    m, k = masses[i % 3], stiffnesses[(i // 3) % 3]
                    i += 1
                    mu = math.tan(math.radians(slope)) / ratio
                    name = f"{kind}_a{aspect:g}_s{slope:g}_r{ratio:g}"
                    yield name, block_case(
                        name, f"family: {kind}, aspect {aspect:g}, {slope:g} deg, "
                        f"tan/mu {ratio:g}", w, w * aspect, m, k, 0.9, slope, mu, 0.0, 1.0,
                        [f"Block family (issue 30, campaigns/block_family.toml): {kind}."])
    for aspect in (0.1, 1.0):
        for v0 in (0.5, 5.0):
            for mu in (0.3, 0.6):
                m, k = masses[i % 3], stiffnesses[(i // 3) % 3]
                i += 1
                stop = v0 / (mu * G)
                name = f"stop_a{aspect:g}_v{v0:g}_mu{mu:g}"
                yield name, block_case(
                    name, f"family: stop, aspect {aspect:g}, {v0:g} m/s, mu {mu:g}", w,
                    w * aspect, m, k, 0.9, 0.0, mu, v0, round(stop + 0.3, 3),
                    ["Block family (issue 30, campaigns/block_family.toml): stop."])


def main():
    check = "--check" in sys.argv[1:]
    outputs = [(ROOT / "cases" / f"{n}.toml", text) for n, text in square_cases()]
    outputs += [(ROOT / "cases" / "family" / f"{n}.toml", text) for n, text in family_cases()]
    differs = []
    for path, text in outputs:
        if check:
            if not path.is_file() or path.read_text() != text:
                differs.append(str(path))
            continue
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    if differs:
        print("block_cases.py: differs from the script's output: " + ", ".join(differs))
        return 1
    print(f"block_cases.py: {len(outputs)} case files {'match' if check else 'written'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
