// Tests for adapters/mujoco/mujoco_capacity.cpp
//
// The contact capacity's rule on the scenes, its settings, and the size of
// MuJoCo 2.2.2's mjData it states against MuJoCo's own (mj_makeData's
// buffer of two models that differ only in <size>).
#include "mujoco_capacity.hpp"

#include <gtest/gtest.h>

#include "mujoco_test_cases.hpp"
#include "planarbench/case_loader.hpp"

namespace pb::internal::mujoco {
namespace {

TEST(ContactCapacity, ScenesAreSizedPerGroupBody) {
  const Case c = load_case(PB_CASES_DIR "/scenes/stack_10.toml");
  const MujocoPlan plan = plan_mujoco(c, 0.01);
  EXPECT_EQ(model_dofs(c, plan), 30);
  // each box: 3 pairs with boxes of up to 5 contacts (multiccd), the ground
  // plane's 3; friction and the pyramidal cone: 4 rows a contact
  const ContactCapacity cap = contact_capacity(c, plan, MujocoSettings{}, 30, true);
  EXPECT_EQ(cap.nconmax, kDefaultNconmax + 10 * (kPairsPerBody * 5 + 3));
  EXPECT_EQ(cap.njmax, kDefaultNjmax + 4 * 10 * (kPairsPerBody * 5 + 3));
  // one MPR contact a pair without multiccd; 3 rows a contact elliptic
  MujocoSettings elliptic;
  elliptic.cone = "elliptic";
  const ContactCapacity one = contact_capacity(c, plan, elliptic, 30, false);
  EXPECT_EQ(one.nconmax, kDefaultNconmax + 10 * (kPairsPerBody + 3));
  EXPECT_EQ(one.njmax, kDefaultNjmax + 3 * 10 * (kPairsPerBody + 3));
  MujocoSettings set;
  set.nconmax = 5000;
  const ContactCapacity given = contact_capacity(c, plan, set, 30, true);
  EXPECT_EQ(given.nconmax, 5000);
  EXPECT_EQ(given.njmax, cap.njmax);
}

TEST(ContactCapacity, RowsStayWithinTheStatedBytes) {
  // 1000 disks (nv = 3000): every contact pressed would be ~2.8 GB of
  // mjData; the rule lowers njmax to what kMaxCapacityBytes holds
  const Case c = load_case(PB_CASES_DIR "/scenes/pile_1000.toml");
  const MujocoPlan plan = plan_mujoco(c, 0.01);
  const ContactCapacity cap = contact_capacity(c, plan, MujocoSettings{}, 3000, false);
  EXPECT_EQ(cap.nconmax, kDefaultNconmax + 1000 * (kPairsPerBody + 3));
  EXPECT_LE(cap.data_bytes, kMaxCapacityBytes);
  EXPECT_GT(capacity_bytes(cap.nconmax, cap.njmax + 1, 3000), kMaxCapacityBytes);
  EXPECT_NE(cap.rule.find("lowered"), std::string::npos) << cap.rule;
}

TEST(ContactCapacity, CasesWithoutGroupsKeepMujocosDefaults) {
  const Case c = test::disk_drop(0.1);
  const MujocoPlan plan = plan_mujoco(c, 0.01);
  const ContactCapacity cap = contact_capacity(c, plan, MujocoSettings{}, 3, false);
  EXPECT_EQ(cap.nconmax, 0);
  EXPECT_EQ(cap.njmax, 0);
  EXPECT_EQ(write_mjcf(c, plan, test::native_options(c)).find("<size"), std::string::npos);
}

TEST(ContactCapacity, StatedBytesAreMujocosOwn) {
  // the same scene compiled with two capacities: mjData's buffer grows by
  // what capacity_bytes says, to MuJoCo's padding of each array to 64 bytes
  // (engine_io.c SKIP)
  const Case c = load_case(PB_CASES_DIR "/scenes/stack_10.toml");
  const MujocoPlan plan = plan_mujoco(c, 0.01);
  auto buffer = [&](int nconmax, int njmax) {
    MjcfOptions o = test::native_options(c);
    o.nconmax = nconmax;
    o.njmax = njmax;
    const ModelPtr m = load_mjcf(write_mjcf(c, plan, o));
    const DataPtr d(mj_makeData(m.get()));
    return static_cast<double>(d->nbuffer);
  };
  const double grown = buffer(400, 2000) - buffer(100, 500);
  const double stated = capacity_bytes(400, 2000, 30) - capacity_bytes(100, 500, 30);
  // 26 arrays sized by nconmax or njmax, each padded by < 64 bytes: < 1664
  // bytes (a row's array missed would be 2000 bytes and more)
  EXPECT_NEAR(grown, stated, 26.0 * 64.0);
}

}  // namespace
}  // namespace pb::internal::mujoco
