// The shipped scenes (cases/scenes/, SPEC §11) as the engine and reference
// tests load them, and one reading of a run's contact rows. Every scene test
// loads through scene_case: a scene removed or renamed fails its tests
// (load_case throws, naming the file), never skips them.
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include "planarbench/case_loader.hpp"
#include "planarbench/run_result.hpp"

namespace pb::test {

// cases/scenes/<name>.toml, its duration replaced when one is given (s)
inline Case scene_case(const std::string& name, std::optional<double> duration_s = std::nullopt) {
  Case c = load_case(std::string(PB_CASES_DIR) + "/scenes/" + name + ".toml");
  if (duration_s) c.duration_s = *duration_s;
  return c;
}

// the normal force of bodies a and b (in the rows' order) at the last sample
// at or before t_s, N; NaN when no row of the pair is that early
inline double pair_force_at(const RunResult& r, const Case& c, const std::string& a,
                            const std::string& b, double t_s) {
  const int ia = c.body_index(a);
  const int ib = c.body_index(b);
  double f = std::nan("");
  for (const ContactRow& row : r.contacts) {
    if (row.time_s > t_s + 1e-12) break;  // 1e-12 s: far below a step, above a time's rounding
    if (row.sample.body_a == ia && row.sample.body_b == ib) f = row.sample.force_n;
  }
  return f;
}

}  // namespace pb::test
