// Tests for core/analytic/numerical_truth.cpp: which numerical truth a case
// gets, and the agreement the mapping reports.
#include "numerical_truth.hpp"

#include <gtest/gtest.h>

#include "planarbench/case_loader.hpp"
#include "planarbench/reference/reference_settings.hpp"
#include "planarbench/reference/reference_solver.hpp"

namespace pb::internal {
namespace {

Case load(const char* name) {
  return load_case(std::string(PB_CASES_DIR) + "/" + name + ".toml");
}

// ellipse_incline (truth = converged) is covered: the independent truth,
// with the converged reference's agreement measured beside it. Bound: the
// summed local errors of both solvers over their steps, 3.5e-9 m on this
// case (independent_agreement_test derives it), rounded up to 1e-8 m.
TEST(NumericalTruth, IndependentWhereItCovers) {
  const Case c = load("ellipse_incline");
  EXPECT_EQ(NumericalTruth::independent_unsupported(c), "");
  NumericalTruth t(c);
  EXPECT_TRUE(t.independent());
  const nlohmann::json d = t.description();
  const nlohmann::json& a = d.at("agreement_with_converged_reference");
  EXPECT_LT(a.at("position_max_m").get<double>(), 1e-8);
  EXPECT_EQ(a.at("episodes_independent"), a.at("episodes_reference"));
  EXPECT_TRUE(a.at("reference").contains("convergence"));
  t.advance_to(c.duration_s);
  EXPECT_EQ(t.episodes().size(), a.at("episodes_independent").get<std::size_t>());
}

// with friction the independent truth (frictionless) refuses: the converged
// reference is the truth, and its description is the reference's own
TEST(NumericalTruth, ConvergedReferenceElse) {
  Case c = load("ellipse_incline");
  c.contacts[0].friction = 0.2;
  EXPECT_NE(NumericalTruth::independent_unsupported(c), "");
  NumericalTruth t(c);
  EXPECT_FALSE(t.independent());
  EXPECT_TRUE(t.description().contains("convergence"));
}

// A case of the user's own without a closed form, tried as a new user would
// (issue 25): a triangle tumbling down a 20 deg incline. The independent
// truth hands over to the converged reference when a second vertex reaches
// the line (saying why); that truth is computed at settings tighter than the
// reference's default run (exact geometry, rtol 1e-12 against the outline at
// 1e-10), so the reference is not judged against its own bits, and the
// description says the reference is judged against itself.
TEST(NumericalTruth, UsersTumblingTriangleIsNotTheReferenceAgainstItsOwnBits) {
  const Case c = parse_case(R"(
[case]
description = "a triangle tumbling down a 20 deg incline"
duration = 1.0
output_interval = 1e-3
truth = "converged"
[[bodies]]
name = "ground"
fixed = true
shape = { type = "halfplane", extent = 20.0 }
position = [0.0, 0.0]
angle_deg = -20.0
[[bodies]]
name = "tri"
shape = { type = "polygon", points = [[-0.2, -0.1], [0.2, -0.1], [0.0, 0.2]] }
mass = 1.0
inertia = "shape"
position = [0.0, 0.4]
angle = 0.3
angular_velocity = 2.0
[[contacts]]
name = "ground_tri"
bodies = ["ground", "tri"]
law = "kelvin_voigt"
stiffness = 1e4
damping = 10.0
)",
                                "triangle.toml", "triangle");
  NumericalTruth truth(c);
  EXPECT_FALSE(truth.independent());
  const nlohmann::json d = truth.description();
  EXPECT_NE(d.at("independent_truth_not_used").get<std::string>().find("second vertex"),
            std::string::npos)
      << d.dump();
  EXPECT_NE(d.at("judged_against_itself").get<std::string>().find("tighter"), std::string::npos);
  ReferenceSolver own(c, ReferenceSettings{});  // the reference's default run
  truth.advance_to(c.duration_s);
  own.advance_to(c.duration_s);
  std::vector<BodyState> t;
  truth.body_states(t);
  // not the same bits: the default run differs from the truth (by ~4 cm at
  // 1 s here: the outline's corners; any difference above rounding, 1e-12 m,
  // shows the two are different computations)
  EXPECT_GT((t[1].position_m - own.body_state(1).position_m).norm(), 1e-12);
  EXPECT_NE(truth.steps(), own.stats().steps);
}

}  // namespace
}  // namespace pb::internal
