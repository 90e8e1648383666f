// pb_convergence: the observed orders of accuracy of the reference solver.
//   pb_convergence [CASES_DIR]
// Prints three tables (see convergence_study.hpp):
//  1. falling_ball, fixed RK4, dt = 2e-3 .. 1.25e-4 s, against rk45 at rtol
//     1e-12, exact geometry, through the first impact (t = 1.0 s): order 4;
//  2. falling_ball with the disk turned by a third of the 45-point spacing
//     (8/3 degrees: no outline point lies on the contact normal for any N of
//     45 .. 1440, so the outline's error is the same fraction of its sag at
//     every N), outline points 45 .. 1440 against geometry=exact: order 2;
//  3. dual_pendulum, rk45 at rtol 1e-8 .. 1e-12, exact geometry, at t = 2.0 s:
//     the differences and the Richardson estimate of each solution's error.
#include <fmt/format.h>

#include <cmath>
#include <exception>
#include <filesystem>
#include <numbers>
#include <string>

#include "planarbench/case_loader.hpp"
#include "planarbench/reference/convergence_study.hpp"

namespace {

// index of the first moving body
int moving_body(const pb::Case& c) {
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    if (!c.bodies[i].fixed) return static_cast<int>(i);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::filesystem::path dir = argc > 1 ? argv[1] : PB_CASES_DIR;
    const pb::Case ball = pb::load_case(dir / "falling_ball.toml");
    const int b = moving_body(ball);

    fmt::print("{}\n", pb::format_table(pb::step_size_convergence(
                           ball, b, 1.0, {2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4})));

    pb::Case turned = ball;
    turned.name = "falling_ball (disk turned 8/3 deg)";
    turned.bodies[static_cast<std::size_t>(b)].angle_rad += 2.0 * std::numbers::pi / (3.0 * 45.0);
    fmt::print("{}\n", pb::format_table(pb::outline_convergence(
                           turned, b, 1.0, {45, 90, 180, 360, 720, 1440})));

    const pb::Case pendulums = pb::load_case(dir / "dual_pendulum.toml");
    fmt::print("{}\n", pb::format_table(pb::tolerance_convergence(
                           pendulums, moving_body(pendulums), 2.0,
                           {1e-8, 1e-9, 1e-10, 1e-11, 1e-12})));
    return 0;
  } catch (const std::exception& e) {
    fmt::print(stderr, "pb_convergence: {}\n", e.what());
    return 2;
  }
}
