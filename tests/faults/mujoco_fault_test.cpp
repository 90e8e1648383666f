// Tests for adapters/mujoco/mujoco_fault.cpp and the warning watch of
// adapters/mujoco/mujoco_stepping.cpp: MuJoCo 2.2.2's warnings become a
// diverged run at the step they first occur in, and MuJoCo's silent reset of
// the state (mj_checkPos/Vel/Acc call mj_resetData on a bad number) never
// reaches the results.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <cmath>

#include "fault_runs.hpp"
#include "mujoco_fault.hpp"
#include "mujoco_plan.hpp"
#include "star_case.hpp"
#include "mujoco_model.hpp"
#include "mujoco_stepping.hpp"

namespace pb {
namespace {

using namespace internal::mujoco;

// the decision of which warnings end a run (mujoco_stepping.cpp says why)
TEST(MujocoWarnings, FaultsAndNotedOnes) {
  for (const int w : {mjWARN_INERTIA, mjWARN_CONTACTFULL, mjWARN_CNSTRFULL, mjWARN_BADQPOS,
                      mjWARN_BADQVEL, mjWARN_BADQACC}) {
    EXPECT_TRUE(warning_info(w).fault) << warning_info(w).name;
  }
  for (const int w : {mjWARN_VGEOMFULL, mjWARN_BADCTRL}) {
    EXPECT_FALSE(warning_info(w).fault) << warning_info(w).name;
  }
  EXPECT_STREQ(warning_info(mjWARN_BADQACC).name, "mjWARN_BADQACC");
}

// A sphere on a vertical slide. A force of 1e30 N on 1 kg gives |qacc| >
// mjMAXVAL = 1e10: mj_checkAcc warns, resets the whole mjData (zeroing every
// warning counter, also the two set here beforehand) and counts the bad qacc
// once more. The watch reports exactly that one warning, once.
TEST(WarningWatch, BadQaccAfterMuJoCosResetIsReportedAlone) {
  install_warning_handler();
  const ModelPtr m =
      load_mjcf(R"(<mujoco><option timestep="1e-3"/><worldbody><geom type="plane" size="1 1 0.1"/>)"
                R"(<body pos="0 0 1"><joint name="z" type="slide" axis="0 0 1"/>)"
                R"(<geom type="sphere" size="0.1" mass="1"/></body></worldbody></mujoco>)");
  DataPtr d(mj_makeData(m.get()));
  d->qpos[0] = 0.3;  // m, off the model's initial qpos0 = 0
  d->warning[mjWARN_BADCTRL].number = 2;
  d->warning[mjWARN_VGEOMFULL].number = 5;
  WarningWatch watch;
  watch.reset(d.get());
  d->qfrc_applied[0] = 1e30;  // N
  forward_checked(m.get(), d.get());
  // MuJoCo's own behaviour, which the adapter must not let through: the state is back at qpos0
  EXPECT_EQ(d->qpos[0], 0.0);
  const auto raised = watch.raised(d.get());
  ASSERT_EQ(raised.size(), 1u);
  EXPECT_EQ(raised[0].warning, mjWARN_BADQACC);
  EXPECT_EQ(raised[0].count, 1);
  EXPECT_EQ(raised[0].lastinfo, 0);  // DOF 0
  EXPECT_NE(last_warning_text().find("QACC"), std::string::npos) << last_warning_text();
  EXPECT_TRUE(watch.raised(d.get()).empty());
  // a warning raised twice between two looks is one entry with its count
  mj_warning(d.get(), mjWARN_BADCTRL, 3);
  mj_warning(d.get(), mjWARN_BADCTRL, 4);
  const auto noted = watch.raised(d.get());
  ASSERT_EQ(noted.size(), 1u);
  EXPECT_EQ(noted[0].warning, mjWARN_BADCTRL);
  EXPECT_EQ(noted[0].count, 2);
  EXPECT_EQ(noted[0].lastinfo, 4);
}

// The reason names the warning, its time, its count, the case body and
// coordinate of its DOF, and what MuJoCo did; counts name what they count.
TEST(MujocoFault, ReasonNamesWarningTimeCountAndCoordinate) {
  Case c;
  c.bodies.resize(2);
  c.bodies[0].name = "ground";
  c.bodies[1].name = "ball";
  ModelLayout layout;
  layout.bodies.resize(2);
  layout.bodies[1].dof_x = 0;
  layout.bodies[1].dof_z = 1;
  layout.bodies[1].dof_hinge = 2;
  const std::string r =
      fault_reason(c, layout, RaisedWarning{mjWARN_BADQVEL, 3, 1}, 0.5, "Nan in QVEL");
  EXPECT_NE(r.find("mjWARN_BADQVEL at t = 0.5 s"), std::string::npos) << r;
  EXPECT_NE(r.find("raised 3 times"), std::string::npos) << r;
  EXPECT_NE(r.find("DOF 1 = slide z of body 'ball' (the case's y)"), std::string::npos) << r;
  EXPECT_NE(r.find("reset the whole state"), std::string::npos) << r;
  EXPECT_NE(r.find("\"Nan in QVEL\""), std::string::npos) << r;
  EXPECT_EQ(describe_dof(c, layout, 2), "hinge of body 'ball' (the case's angle)");
  EXPECT_EQ(describe_dof(c, layout, 9), "DOF 9");
  const std::string full =
      fault_reason(c, layout, RaisedWarning{mjWARN_CONTACTFULL, 1, 100}, 0.1, "");
  EXPECT_NE(full.find("100 contacts"), std::string::npos) << full;
  EXPECT_EQ(full.find("MuJoCo: \""), std::string::npos) << full;  // no text, no quote
}

// falling_ball with contact.stiffness = 1e16 N/m: native mode maps it to
// solref k / m_eff = 1e16 s^-2, so at the first step in contact (penetration
// ~ v h = 7e-4 m) the reference acceleration is ~7e12 m/s^2 > mjMAXVAL:
// mj_checkAcc raises mjWARN_BADQACC and resets the state to the ball's start.
// The run is diverged at the first contact (t = 0.72501 s in closed form, the
// case's header), and its last sample is the ball just above the ground, not
// MuJoCo's reset state back at the start.
TEST(MujocoFault, BadQaccFromAnAbsurdStiffnessIsDivergedAtTheFirstContact) {
  const faults_test::Sets sets = {{"contact.stiffness", "1e16"}, {"duration", "0.8"}};
  const RunResult r = faults_test::run_shipped("falling_ball", "mujoco", sets);
  ASSERT_EQ(r.status, RunStatus::diverged) << r.reason;
  EXPECT_NE(r.reason.find("mjWARN_BADQACC"), std::string::npos) << r.reason;
  EXPECT_NE(r.reason.find("reset the whole state"), std::string::npos) << r.reason;
  EXPECT_NE(r.reason.find("body 'ball'"), std::string::npos) << r.reason;
  // 2e-4 s: two steps of 1e-4 s, one for resolving the onset to a step, one
  // for semi-implicit Euler's lead of g h t / 2 = 3.6e-4 m (5e-5 s at 7.1 m/s)
  EXPECT_NEAR(r.diverged_at_s, 0.72501, 2e-4);
  const BodyTrajectory& ball = r.bodies.at(0);
  ASSERT_FALSE(ball.time_s.empty());
  EXPECT_LT(ball.time_s.back(), r.diverged_at_s);
  // fallen 2.2321 m / cos30 = 2.5774 m along -y by then; the reset state is at the start
  // (0 m fallen). The last sample is before diverged_at_s (within 2e-4 s of
  // the onset, above) by at most one output interval (1e-4 s): within 3e-4 s
  // of the onset, 3e-4 s x g t = 3e-4 x 7.1 m/s = 2.1e-3 m; plus Euler's lead
  // 3.6e-4 m and the 4 printed decimals (5e-5 m): 2.5e-3 m; band 3e-3 m
  EXPECT_NEAR(2.0 - ball.position_m.back().y(), 2.5774, 3e-3);
}

// dual_pendulum at mujoco.dt = 1e-3: the 0.24 ms Lankarani-Nikravesh impact,
// mapped onto MuJoCo's soft contact (solref k / m_eff ~ 2e8 s^-2), spans a
// quarter of a step; the contact's reference acceleration -k r is explicit
// in r, and k h^2 ~ 200 >> 1 makes each step multiply the rebound. MuJoCo
// raises no warning while qacc stays below 1e10, so the runner's energy
// check is what ends the run, right after the first impact (t = 0.4965 s,
// SPEC §2).
TEST(MujocoFault, RunawayWithoutAWarningIsCaughtByTheEnergyCheck) {
  const RunResult r = faults_test::run_shipped("dual_pendulum", "mujoco", {{"dt", "1e-3"}});
  ASSERT_EQ(r.status, RunStatus::diverged) << r.reason;
  EXPECT_NE(r.reason.find("energy runaway"), std::string::npos) << r.reason;
  // within 5 steps of the impact: the growth is exponential
  EXPECT_GT(r.diverged_at_s, 0.4965 - 1e-3);
  EXPECT_LT(r.diverged_at_s, 0.4965 + 5e-3);
}

// Issue 35 item 8: at mujoco.dt = 1e-2 (inside its range) block_stop's slab
// (1 kg, 2 m/s along the ground: 2 J) and disk_throw's disk are thrown up
// with energy from nowhere (386 J and 371 J at t = 0.88-0.9 s) and the runs
// were ok: the check compared with 10 x an a-priori free-fall bound (56 J by
// then), not with the energy the case had. Against the case's own budget
// (energy_budget.hpp) both are runaways.
TEST(MujocoFault, EnergyFromNowhereAtACoarseStepIsARunaway) {
  for (const char* name : {"block_stop", "disk_throw"}) {
    const RunResult r = faults_test::run_shipped(name, "mujoco", {{"dt", "1e-2"}});
    ASSERT_EQ(r.status, RunStatus::diverged) << name << ": " << r.reason;
    EXPECT_NE(r.reason.find("energy runaway"), std::string::npos) << r.reason;
    EXPECT_NE(r.reason.find("the case has made available"), std::string::npos) << r.reason;
  }
}

// Two 2000-point concave stars in contact would need one explicit <pair> per
// two of their ~1400 convex pieces each: ~1.9e6 pairs, ~5.5 GB in MuJoCo's
// compiler (issue 24). The run ends before MuJoCo allocates anything, naming
// the count and the bound; the same star on the ground (pieces x 1) runs.
TEST(MujocoFaults, StarOnStarBeyondThePairBoundIsRefusedNamingTheCount) {
  const RunResult r = run_engine(*make_engine("mujoco"), faults_test::star_case(2000, true), {});
  ASSERT_EQ(r.status, RunStatus::diverged) << r.reason;
  EXPECT_NE(r.reason.find("explicit geom <pair>s"), std::string::npos) << r.reason;
  EXPECT_NE(r.reason.find("at most 100000"), std::string::npos) << r.reason;
  EXPECT_EQ(r.steps, 0);
  const RunResult ground = run_engine(*make_engine("mujoco"), faults_test::star_case(2000, false), {});
  EXPECT_EQ(ground.status, RunStatus::ok) << ground.reason;
}

}  // namespace
}  // namespace pb
