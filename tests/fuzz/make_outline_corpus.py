#!/usr/bin/env python3
"""Writes the seed corpus of fuzz_outline (tests/fuzz/corpus/outline/*.bin).

Each seed is a pair of shapes with poses, encoded in the byte format that
outline_fuzz_input.hpp decodes (written out in tests/fuzz/README.md). The
seeds are the geometries planarbench meets: the paper's cases, touching and
overlapping pairs, concave and coarse polygons, and scale extremes.
Deterministic: running it again rewrites the same bytes.

Usage: tests/fuzz/make_outline_corpus.py [OUT_DIR]   (default: next to this file)
"""
import math
import os
import struct
import sys

SIZE_EXP = 13        # kSizeExponent: sizes < 2^13 m
COORD_EXP = 19       # kCoordinateExponent: coordinates < 2^19 m
ANGLE_EXP = 4        # kAngleExponent: angles < 2^4 rad
MAX_POINTS = 128     # kMaxOutlinePoints: circle, ellipse, half-plane outlines

CIRCLE, ELLIPSE, STAR, HALFPLANE, POLYGON = range(5)


def scalar(v, max_exp):
    """3 bytes: int16 m, u8 e with value m / 32768 * 2^(e - 32)."""
    if v == 0.0:
        return struct.pack("<hB", 0, 32)
    e = max(-32, min(max_exp, math.frexp(v)[1]))   # |v| / 2^e in [0.5, 1)
    m = max(-32768, min(32767, round(v / 2.0**e * 32768.0)))
    return struct.pack("<hB", m, e + 32)


def u8(x):
    return struct.pack("<B", x)


def circle(r, n):
    assert 3 <= n <= MAX_POINTS
    return u8(CIRCLE) + u8(n - 3) + scalar(r, SIZE_EXP)


def ellipse(a, b, n):
    assert 3 <= n <= MAX_POINTS
    return u8(ELLIPSE) + u8(n - 3) + scalar(a, SIZE_EXP) + scalar(b, SIZE_EXP)


def halfplane(extent, n):
    assert 2 <= n <= MAX_POINTS
    return u8(HALFPLANE) + u8(n - 2) + scalar(extent, SIZE_EXP)


def star(steps_radii):
    """(angle step 0..255, radius) per point; angles in proportion to step + 1."""
    assert 3 <= len(steps_radii) <= 64
    out = u8(STAR) + u8(len(steps_radii) - 3)
    for step, r in steps_radii:
        out += u8(step) + scalar(r, SIZE_EXP)
    return out


def polygon(points):
    assert 3 <= len(points) <= 64
    out = u8(POLYGON) + u8(len(points) - 3)
    for x, y in points:
        out += scalar(x, COORD_EXP) + scalar(y, COORD_EXP)
    return out


def pose(x, y, angle, exp):
    return scalar(x, exp) + scalar(y, exp) + scalar(angle, ANGLE_EXP)


def seed(shape_a, pose_a, shape_b, offset_b, angle_b, shift=(0.0, 0.0), turn=0.0,
         probe=(0.0, 0.0)):
    """body a at pose_a (x, y, angle), body b at pose_a + offset_b."""
    return (shape_a + pose(*pose_a, COORD_EXP) + shape_b + pose(*offset_b, angle_b, SIZE_EXP) +
            scalar(shift[0], COORD_EXP) + scalar(shift[1], COORD_EXP) + scalar(turn, ANGLE_EXP) +
            scalar(probe[0], SIZE_EXP) + scalar(probe[1], SIZE_EXP))


def seeds():
    d30 = math.radians(30.0)
    d45 = math.radians(45.0)
    s = {}
    # falling_ball: 40 m ground declined 30 deg, ball R 0.5 at (2, 2) (the paper's 180
    # points per outline, cut to the decoder's 128)
    s["falling_ball"] = seed(halfplane(40.0, 128), (0.0, 0.0, -d30), circle(0.5, 128),
                             (2.0, 2.0), 0.0, shift=(3.0, -1.0), turn=0.5, probe=(1.0, 0.5))
    # sliding: the disk touches the 45 deg incline with zero penetration
    r = 0.25
    s["sliding_touching"] = seed(halfplane(20.0, 128), (0.0, 0.0, -d45), circle(r, 128),
                                 (r * math.sin(d45), r * math.cos(d45)), 0.0, probe=(0.1, 0.0))
    # dual_pendulum just before the impact: ellipse pendulum vertical, disk beside it
    s["dual_pendulum"] = seed(ellipse(0.7071, 0.25, 128), (0.0, -0.7071, math.pi / 2),
                              circle(0.5, 128), (0.7501, 0.0), 0.0, turn=1.0, probe=(0.25, 0.0))
    # two disks overlapping by 0.1 m, coarse outlines
    s["disks_overlap"] = seed(circle(0.5, 12), (1.0, 1.0, 0.0), circle(0.5, 7), (0.9, 0.0), 0.3,
                              shift=(-5.0, 2.0), turn=-2.0, probe=(0.45, 0.1))
    # coarse square against a disk, apart: the paper's two stages overestimate
    sq = [(0, math.sqrt(0.5))] * 4
    s["square_disk_apart"] = seed(star(sq), (0.0, 0.0, d45), circle(0.3, 64), (0.5, 0.9), 0.0,
                                  probe=(0.0, 2.0))
    # concave stars overlapping (several overlap regions)
    spiky = [(0, 1.0 if i % 2 == 0 else 0.4) for i in range(10)]
    uneven = [(i * 37 % 200, 0.5 + 0.05 * i) for i in range(9)]
    s["stars_overlap"] = seed(star(spiky), (0.0, 0.0, 0.1), star(uneven), (1.1, 0.2), 2.0,
                              turn=3.0, probe=(0.3, 0.3))
    # a triangle pressed deep into the ground
    tri = [(-1.0, -0.5773502691896258), (1.0, -0.5773502691896258), (0.0, 1.1547005383792517)]
    s["triangle_in_ground"] = seed(halfplane(8.0, 40), (0.0, 0.0, 0.0), polygon(tri), (0.2, 0.3),
                                   math.pi, probe=(0.0, -0.2))
    # two unit squares edge to edge, zero gap (every contact decision on the boundary)
    unit = [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)]
    s["squares_touching"] = seed(polygon(unit), (0.0, 0.0, 0.0), polygon(unit), (1.0, 0.0), 0.0,
                                 probe=(0.5, 0.0))
    # two thin bars crossed like "+": overlap without an outline point inside
    bar = [(-1.0, -0.05), (1.0, -0.05), (1.0, 0.05), (-1.0, 0.05)]
    s["bars_crossed"] = seed(polygon(bar), (0.0, 0.0, 0.0), polygon(bar), (0.0, 0.0), math.pi / 2,
                             probe=(0.0, 0.0))
    # a small disk 0.5 mm from a large one, far from the origin (rounding at scale
    # 5e5 m; edges kept above the 1e-6 x scale the fuzz target resolves)
    s["small_far"] = seed(circle(2000.0, 128), (5e5, -3e5, 0.7), circle(5.0, 16),
                          (2005.0005, 0.0), 0.0, shift=(-4e5, 2e5), turn=1.3,
                          probe=(2000.0, 0.0))
    # ellipse against ellipse, crossing, many points
    s["ellipses_cross"] = seed(ellipse(1.0, 0.1, 128), (0.0, 0.0, 0.0), ellipse(1.0, 0.1, 100),
                               (0.2, 0.05), 1.2, probe=(0.9, 0.0))
    # minimal outlines: triangles of a circle and a 2-point half-plane
    s["minimal"] = seed(halfplane(1.0, 2), (0.0, 0.0, 0.0), circle(0.2, 3), (0.0, 0.19), 0.0)
    return s


def main():
    out_dir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "corpus", "outline")
    os.makedirs(out_dir, exist_ok=True)
    for name, data in sorted(seeds().items()):
        with open(os.path.join(out_dir, name + ".bin"), "wb") as f:
            f.write(data)
        print(f"{name}.bin: {len(data)} bytes")


if __name__ == "__main__":
    main()
