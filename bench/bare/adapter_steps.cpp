// The adapter side of the bare-loop comparison (issue 22; bench/bare/README.md):
// drives one engine of planarbench through the pb::Engine interface on a
// case file exactly as the runner does per output sample, advance_to the next
// step, then body_states and contacts, for a given number of steps of the
// engine's own dt (1e-4 s, the shipped cases' output grid), and prints the
// final centre of the first moving body like the bare loops do.
//   adapter_steps <mujoco|ode|box2d> <case.toml> <steps>
// The case's duration is set to steps x 1e-4 s (Box2D sizes its ground from it).
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "planarbench/case_loader.hpp"
#include "planarbench/engines.hpp"
#include "planarbench/errors.hpp"

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: adapter_steps <mujoco|ode|box2d> <case.toml> <steps>\n");
    return 2;
  }
  try {
    const std::string engine_name = argv[1];
    pb::Case c = pb::load_case(argv[2]);
    const long steps = std::atol(argv[3]);
    const double dt = 1e-4;  // s, every engine's default step (and the output grid)
    c.duration_s = static_cast<double>(steps) * dt;
    pb::SettingsOverrides o;
    for (const auto& [key, text] : c.settings) o.set(key, text, pb::SettingSource{c.source_path, 0});
    auto engine = pb::make_engine(engine_name);
    engine->build(c, o);
    std::vector<pb::BodyState> states;
    std::vector<pb::ContactSample> contacts;
    for (long k = 1; k <= steps; ++k) {
      engine->advance_to(static_cast<double>(k) * dt);
      engine->body_states(states);
      engine->contacts(contacts);
    }
    for (std::size_t i = 0; i < c.bodies.size(); ++i) {
      if (c.bodies[i].fixed) continue;
      std::printf("%s %s steps=%ld x=%.17g y=%.17g\n", engine_name.c_str(), c.name.c_str(), steps,
                  states[i].position_m.x(), states[i].position_m.y());
      break;
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "adapter_steps: %s\n", e.what());
    return 1;
  }
}
