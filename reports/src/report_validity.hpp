// The physical-validity section of a report (SPEC §9, issue 32): the
// per-step violations of contact_validity.hpp for every run and pair that has
// rows, as
//  - a table: per case, engine and pair the Coulomb cone, the dissipation
//    deficit while sliding, the stick creep, the force at a distance, the
//    normal-law residual (smooth pairs) and the complementarity power, each
//    max (p99);
//  - one reading per engine over every case: the worst of each violation and
//    where ("mujoco: cone respected to 1.2e-15 (disk_slip); ...");
//  - per case with a friction pair, the friction's distance from Coulomb per
//    sample (the cone violation while it holds, |dissipation deficit| while it
//    slides) and its slip while the load is inside the cone, and per case with a frictionless smooth pair (the impacts), the
//    normal-law residual per sample: one line per engine, log scale, each
//    line the largest value per time bucket so spikes survive.
#pragma once

#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/run_result.hpp"
#include "report_model.hpp"

namespace pb::internal {

// cases and results: the report's (index-aligned). Empty (no table row) when
// no run has a contact row.
[[nodiscard]] ValiditySection validity_section(const std::vector<Case>& cases,
                                               const ResultsFile& results);

}  // namespace pb::internal
