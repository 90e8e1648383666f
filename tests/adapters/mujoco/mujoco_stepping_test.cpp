// Tests for adapters/mujoco/mujoco_stepping.cpp
//
// The split step must be MuJoCo's mj_step bit for bit, so that sampling
// between the halves changes nothing: a disk bouncing on active soft contact
// is stepped both ways, with both integrators, and compared exactly.
#include "mujoco_stepping.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "mujoco_mjcf.hpp"
#include "mujoco_model.hpp"
#include "mujoco_test_cases.hpp"

namespace pb::internal::mujoco {
namespace {

ModelPtr bouncing_disk(const std::string& integrator) {
  const Case c = test::disk_drop(0.05);
  MjcfOptions o;
  o.integrator = integrator;
  PairParams p;
  p.solref = {-1e4, -10.0};
  p.solimp = {0.9999, 0.9999, 0.001, 0.5, 2.0};
  o.pairs.push_back(p);
  ModelLayout layout;
  return test::load_case(c, o, layout);
}

class SplitStep : public ::testing::TestWithParam<const char*> {};

TEST_P(SplitStep, IsBitIdenticalToMjStep) {
  const ModelPtr m = bouncing_disk(GetParam());
  DataPtr a(mj_makeData(m.get()));
  DataPtr b(mj_makeData(m.get()));
  // 0.3 s: free fall, one full impact (~31 ms) and the rebound
  for (int i = 0; i < 3000; ++i) {
    mj_step(m.get(), a.get());
    forward_checked(m.get(), b.get());
    integrate(m.get(), b.get());
  }
  // the slide coordinate starts at 0 with the disk 0.05 m above the ground;
  // at 0.3 s it has fallen (0.1 s), bounced (e ~0.86) and is near -0.05 m
  // again: below -0.01 m rules out a run where nothing moved
  ASSERT_LT(a->qpos[1], -0.01);
  EXPECT_EQ(std::memcmp(a->qpos, b->qpos, sizeof(mjtNum) * static_cast<std::size_t>(m->nq)), 0);
  EXPECT_EQ(std::memcmp(a->qvel, b->qvel, sizeof(mjtNum) * static_cast<std::size_t>(m->nv)), 0);
}

INSTANTIATE_TEST_SUITE_P(Integrators, SplitStep, ::testing::Values("Euler", "RK4"));

// With a hook, forward_checked runs mj_forward's stages one by one; a hook
// that changes nothing leaves the step bit-identical to mj_step, so the
// native rule's hook changes the run only through the solref it sets. The
// hook is called once per step, after the contacts are found and before
// their constraint rows are made (mjData keeps the last step's nefc until
// mj_makeConstraint, so the rows cannot be the witness: the contact count is).
struct HookLog {
  int calls = 0;
  int ncon_seen = -1;  // d->ncon when the hook ran last
  int calls_with_contact = 0;
};

void count_and_check(void* log, const mjModel*, mjData* d) {
  auto* l = static_cast<HookLog*>(log);
  ++l->calls;
  l->ncon_seen = d->ncon;
  if (d->ncon > 0) ++l->calls_with_contact;
}

TEST(ForwardHook, NoOpHookIsBitIdenticalToMjStep) {
  const ModelPtr m = bouncing_disk("Euler");
  DataPtr a(mj_makeData(m.get()));
  DataPtr b(mj_makeData(m.get()));
  HookLog log;
  for (int i = 0; i < 3000; ++i) {
    mj_step(m.get(), a.get());
    forward_checked(m.get(), b.get(), &count_and_check, &log);
    // the hook saw this state's contacts: the ones the step goes on with
    ASSERT_EQ(log.ncon_seen, b->ncon) << "step " << i;
    integrate(m.get(), b.get());
  }
  EXPECT_EQ(log.calls, 3000);
  // the impact lasts ~31 ms of the 0.3 s: some 300 steps with a contact
  EXPECT_GT(log.calls_with_contact, 100);
  ASSERT_LT(a->qpos[1], -0.01);  // it moved (see above)
  EXPECT_EQ(std::memcmp(a->qpos, b->qpos, sizeof(mjtNum) * static_cast<std::size_t>(m->nq)), 0);
  EXPECT_EQ(std::memcmp(a->qvel, b->qvel, sizeof(mjtNum) * static_cast<std::size_t>(m->nv)), 0);
}

// integrate() counts every step of this thread: the trace behind
// Engine::steps_before_start
TEST(ForwardHook, IntegrationsAreCounted) {
  const ModelPtr m = bouncing_disk("Euler");
  DataPtr d(mj_makeData(m.get()));
  const long before = integrations_on_this_thread();
  for (int i = 0; i < 7; ++i) {
    forward_checked(m.get(), d.get());
    integrate(m.get(), d.get());
  }
  EXPECT_EQ(integrations_on_this_thread() - before, 7);
}

TEST(WarningWatch, ReportsABadVelocityOnce) {
  install_warning_handler();  // MuJoCo's text goes to a record, not to stdout
  const ModelPtr m = bouncing_disk("Euler");
  DataPtr d(mj_makeData(m.get()));
  WarningWatch watch;
  watch.reset(d.get());
  forward_checked(m.get(), d.get());
  EXPECT_EQ(watch.new_warning(d.get()), nullptr);
  d->qvel[0] = std::numeric_limits<double>::quiet_NaN();
  forward_checked(m.get(), d.get());  // mj_checkVel resets the state and warns
  const char* w = watch.new_warning(d.get());
  ASSERT_NE(w, nullptr);
  EXPECT_NE(std::string(w).find("mjWARN_BADQVEL"), std::string::npos);
  EXPECT_NE(last_warning_text().find("QVEL"), std::string::npos) << last_warning_text();
  EXPECT_EQ(watch.new_warning(d.get()), nullptr);
}

}  // namespace
}  // namespace pb::internal::mujoco
