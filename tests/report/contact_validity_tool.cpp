// contact_validity_tool RESULTS.h5 ...: per run and contact pair with
// recorded tangential columns, the per-step validity of issue 32
// (planarbench/reports/contact_validity.hpp) as one Markdown row: cone,
// dissipation and stick creep (max and p99), force at a distance (max),
// the dissipation deficit, the normal-law residual and the complementarity. The measurements in the note come from
// it; it is a tool, not a test.
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

#include "planarbench/case_loader.hpp"
#include "planarbench/reports/contact_validity.hpp"
#include "planarbench/results_file.hpp"

namespace {

std::string num(double x) {
  if (std::isnan(x)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2g", x);
  return buf;
}

std::string series(const pb::ValiditySeries& s) {
  return s.samples == 0 ? "-" : num(s.max) + " / " + num(s.p99);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: contact_validity_tool RESULTS.h5 ...\n");
    return 2;
  }
  std::printf("| case | engine | pair | mu | rows | cone max / p99 | dissipation max / p99 | "
              "stick creep m/s max / p99 | force at a distance N max | deficit J | "
              "law residual max / p99 | complementarity W max / p99 |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  try {
    for (int a = 1; a < argc; ++a) {
      const pb::ResultsFile f = pb::read_results_file(argv[a]);
      for (const auto& cr : f.cases) {
        const pb::Case c = pb::case_as_run(cr);
        for (const auto& r : cr.runs) {
          for (const pb::PairValidity& v : pb::contact_validity(c, r)) {
            if (v.samples == v.not_recorded) continue;  // nothing recorded
            std::printf("| %s | %s | %s | %g | %d | %s | %s | %s | %s | %s | %s | %s |\n", c.name.c_str(),
                        r.engine_name.c_str(), v.pair.c_str(), v.mu, v.samples,
                        series(v.mu > 0.0 ? v.cone : v.frictionless_tangent).c_str(),
                        series(v.dissipation).c_str(), series(v.stick_creep_mps).c_str(),
                        v.force_at_distance_n.samples == 0 ? "0" : num(v.force_at_distance_n.max).c_str(),
                        num(v.power_deficit_j).c_str(), series(v.law_residual).c_str(),
                        series(v.complementarity_w).c_str());
          }
        }
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "contact_validity_tool: %s\n", e.what());
    return 2;
  }
  return 0;
}
