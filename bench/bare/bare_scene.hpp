// The two scenes of the bare loops (bench/bare/README.md), their numbers as
// the case files state them, and the command line every bare loop takes.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>

namespace bare {

struct Scene {
  const char* name;
  double radius_m, mass_kg, inertia_kgm2;  // m, kg, kg m^2: the disk
  double x0_m, y0_m;                       // m, its centre at t = 0 (at rest)
  double ground_angle_rad;  // the half-plane's surface line, ccw from +x; through the origin
  double extent_m;          // m, the case's surface length of the half-plane
  double stiffness_n_per_m, damping_ns_per_m;  // Kelvin-Voigt K, c
  double friction;                             // Coulomb coefficient, 0 = frictionless
};

// cases/falling_ball.toml, cases/disk_roll.toml
constexpr Scene kFallingBall{"falling_ball", 0.5, 1.0, 0.125, 2.0, 2.0,
                             -30.0 * std::numbers::pi / 180.0, 40.0, 1e4, 10.0, 0.0};
constexpr Scene kDiskRoll{"disk_roll", 0.25, 1.0, 0.03125, 0.12495753617637623,
                          0.21643280144610968, -30.0 * std::numbers::pi / 180.0, 8.0, 1e5, 600.0,
                          0.3};

constexpr double kDt = 1e-4;         // s, every engine's step (the adapters' default)
constexpr double kGravity = 9.8066;  // m/s^2, along -y

// the state read after every step
struct Sample {
  double x, y, angle, vx, vy, omega;
};
// a small ring buffer, visible outside the program's file so that the stores stay
inline Sample g_samples[64];

// `<prog> <falling_ball|disk_roll> <steps>`: the scene (nullptr after a
// message on stderr for anything else) and the step count
inline const Scene* parse_command_line(int argc, char** argv, long& steps) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s <falling_ball|disk_roll> <steps>\n", argv[0]);
    return nullptr;
  }
  const std::string scene = argv[1];
  const Scene* s = scene == "falling_ball" ? &kFallingBall : scene == "disk_roll" ? &kDiskRoll : nullptr;
  steps = std::strtol(argv[2], nullptr, 10);
  if (!s || steps < 0) {
    std::fprintf(stderr, "unknown scene '%s' or bad step count\n", argv[1]);
    return nullptr;
  }
  return s;
}

}  // namespace bare
