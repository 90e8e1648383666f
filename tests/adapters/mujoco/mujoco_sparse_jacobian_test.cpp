// Tests for adapters/mujoco/mujoco_sparse_jacobian.cpp
//
// The rows on a pair's DOFs against MuJoCo's own dense mj_jac and mj_solveM,
// bit for bit: the sparse path is only an optimisation, so every number it
// gives must be the dense computation's (the determinism hashes of every
// case depend on it), and every entry it leaves out must be an exact zero of
// the dense one. On a scene of boxes turned and moving (the hinge and slides
// of each body coupled in M), and on a pendulum (its hinge away from its
// centre of mass).
#include "mujoco_sparse_jacobian.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "mujoco_pair_state.hpp"
#include "mujoco_test_cases.hpp"
#include "planarbench/case_loader.hpp"

namespace pb::internal::mujoco {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

struct Scene {
  explicit Scene(const Case& c) : case_(c) {
    model = test::load_case(case_, test::native_options(case_), layout, 0.01);
    data.reset(mj_makeData(model.get()));
    set_initial_state(model.get(), data.get(), case_, layout);
    // every body turned and moving, so that no Jacobian entry is trivially 0
    for (int j = 0; j < model->nq; ++j) data->qpos[j] += 0.01 * (j % 7) - 0.02;
    for (int j = 0; j < model->nv; ++j) data->qvel[j] = 0.1 * (j % 5) - 0.2;
    mj_forward(model.get(), data.get());
  }
  Case case_;
  ModelLayout layout;
  ModelPtr model;
  DataPtr data;
};

// the dense row and its M^-1, and the sparse ones, of a contact of bodies
// a and b at p along n, compared entry by entry
void expect_rows_match(const Scene& s, int body_a, int body_b, const double p[3],
                       const double n[3]) {
  const mjModel* m = s.model.get();
  mjData* d = s.data.get();
  Scratch dense(m);
  Scratch sparse(m);
  ASSERT_TRUE(sparse.sparse);
  const auto nv = static_cast<std::size_t>(m->nv);
  std::vector<double> row(nv);
  std::vector<double> minv(nv);
  normal_row(m, d, body_a, body_b, p, n, dense, row.data());
  mj_solveM(m, d, minv.data(), row.data(), 1);
  pair_dofs(m, body_a, body_b, sparse.dofs);
  const std::size_t w = sparse.dofs.size();
  std::vector<double> srow(w);
  std::vector<double> sminv(w);
  normal_row_on_dofs(m, d, body_a, body_b, p, n, sparse, srow.data());
  solve_m_on(m, d, sparse.dofs, sminv.data(), srow.data(), 1);
  std::vector<bool> on(nv, false);
  for (std::size_t c = 0; c < w; ++c) {
    const auto q = static_cast<std::size_t>(sparse.dofs[c]);
    on[q] = true;
    EXPECT_TRUE(same_bits(srow[c], row[q])) << "row, DOF " << q;
    EXPECT_TRUE(same_bits(sminv[c], minv[q])) << "M^-1 row, DOF " << q;
  }
  for (std::size_t q = 0; q < nv; ++q) {
    if (on[q]) continue;
    EXPECT_EQ(row[q], 0.0) << q;
    EXPECT_EQ(minv[q], 0.0) << q;
  }
  // the multiple-vector branch of mj_solveLD: three rows at once
  std::vector<double> rows3(3 * nv);
  std::vector<double> minv3(3 * nv);
  std::vector<double> srows3(3 * w);
  std::vector<double> sminv3(3 * w);
  for (int r = 0; r < 3; ++r) {
    const double pr[3] = {p[0] + 0.03 * r, p[1], p[2] - 0.01 * r};
    normal_row(m, d, body_a, body_b, pr, n, dense, &rows3[static_cast<std::size_t>(r) * nv]);
    normal_row_on_dofs(m, d, body_a, body_b, pr, n, sparse, &srows3[static_cast<std::size_t>(r) * w]);
  }
  mj_solveM(m, d, minv3.data(), rows3.data(), 3);
  solve_m_on(m, d, sparse.dofs, sminv3.data(), srows3.data(), 3);
  for (std::size_t r = 0; r < 3; ++r) {
    for (std::size_t c = 0; c < w; ++c) {
      const auto q = static_cast<std::size_t>(sparse.dofs[c]);
      EXPECT_TRUE(same_bits(sminv3[r * w + c], minv3[r * nv + q])) << r << " " << q;
    }
  }
  // point velocities (the approach speed) through both paths
  dense.sparse = false;
  EXPECT_TRUE(same_bits(approach_speed_mps(m, d, body_a, body_b, p, n, dense),
                        approach_speed_mps(m, d, body_a, body_b, p, n, sparse)));
}

TEST(SparseJacobian, StackRowsAreMujocosDenseRowsToTheBit) {
  const Scene s(load_case(PB_CASES_DIR "/scenes/stack_10.toml"));
  const double n[3] = {0.06, 0.0, 0.998};  // a tilted normal: both slides and the hinge
  const double p[3] = {0.13, 0.0, 0.31};
  const int b3 = s.layout.bodies[static_cast<std::size_t>(s.case_.body_index("box_3"))].mj_body;
  const int b4 = s.layout.bodies[static_cast<std::size_t>(s.case_.body_index("box_4"))].mj_body;
  const int b9 = s.layout.bodies[static_cast<std::size_t>(s.case_.body_index("box_9"))].mj_body;
  expect_rows_match(s, b3, b4, p, n);
  expect_rows_match(s, b9, b3, p, n);  // the higher body first
  expect_rows_match(s, 0, b4, p, n);   // the ground (world body) and a box
}

TEST(SparseJacobian, PendulumRowIsMujocosDenseRowToTheBit) {
  const Scene s(test::dual_pendulum(0.1));
  const double n[3] = {0.8, 0.0, 0.6};
  const double p[3] = {0.2, 0.0, -0.6};
  expect_rows_match(s, s.layout.bodies[0].mj_body, s.layout.bodies[1].mj_body, p, n);
}

TEST(SparseJacobian, OnlyModelsOfBodiesHangingFromTheWorld) {
  // the adapter's models: every moving body a child of the world body
  const Scene s(load_case(PB_CASES_DIR "/scenes/stack_2.toml"));
  EXPECT_TRUE(bodies_hang_from_world(s.model.get()));
  // a body hanging from another: its DOFs' M^-1 reaches the parent's, so the
  // sparse path must not be taken
  const char* xml = R"(<mujoco><worldbody><body><joint type="slide" axis="1 0 0"/>
    <geom size="0.1"/><body pos="0 0 0.5"><joint type="hinge" axis="0 1 0"/>
    <geom size="0.1"/></body></body></worldbody></mujoco>)";
  const ModelPtr chain = load_mjcf(xml);
  EXPECT_FALSE(bodies_hang_from_world(chain.get()));
}

}  // namespace
}  // namespace pb::internal::mujoco
