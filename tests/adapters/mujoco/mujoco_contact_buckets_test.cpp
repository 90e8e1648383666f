// Tests for adapters/mujoco/mujoco_contact_buckets.cpp
//
// The contacts of a scene grouped by pair: every contact in exactly one
// bucket, each bucket's contacts in d->contact's order, the pairs ascending
// (what makes a pass over the buckets the same as a pass over every pair),
// and a contact group's pairs registered as MuJoCo's broad phase first
// reports them, with the case's conventions (the fixed body first).
#include "mujoco_contact_buckets.hpp"

#include <gtest/gtest.h>

#include <set>

#include "mujoco_test_cases.hpp"
#include "planarbench/case_loader.hpp"

namespace pb::internal::mujoco {
namespace {

TEST(ContactBuckets, StackContactsGroupedByPairInOrder) {
  const Case c = load_case(PB_CASES_DIR "/scenes/stack_10.toml");
  ModelLayout layout;
  const ModelPtr m = test::load_case(c, test::native_options(c), layout, 0.01);
  DataPtr d(mj_makeData(m.get()));
  set_initial_state(m.get(), d.get(), c, layout);
  mj_forward(m.get(), d.get());
  // pressed in at their resting pose: the ground and nine interfaces report
  ASSERT_GT(d->ncon, 0);
  EXPECT_EQ(layout.pairs.size(), 0u);  // no declared pairs, none found yet
  ContactBuckets b;
  b.build(d.get(), layout);
  EXPECT_EQ(layout.pairs.size(), 10u);  // ground-box_1 and box_k-box_k+1
  EXPECT_EQ(b.pairs().size(), 10u);
  std::set<int> seen;
  for (std::size_t k = 0; k < b.pairs().size(); ++k) {
    if (k > 0) {
      EXPECT_LT(b.pairs()[k - 1], b.pairs()[k]);
    }
    int last = -1;
    for (const int i : b.contacts(k)) {
      EXPECT_GT(i, last);  // d->contact's order
      last = i;
      EXPECT_TRUE(seen.insert(i).second) << "contact " << i << " in two buckets";
      EXPECT_EQ(b.pair_of_contact(i), b.pairs()[k]);
      EXPECT_EQ(layout.pair_of(d->contact[i].geom1, d->contact[i].geom2), b.pairs()[k]);
    }
  }
  EXPECT_EQ(seen.size(), static_cast<std::size_t>(d->ncon));
  // each pair's bodies: the ground (fixed) first, else the lower index; one
  // index per pair, kept by the next build
  const int ground = c.body_index("ground");
  for (std::size_t k = 0; k < layout.pairs.size(); ++k) {
    const ContactPair& cp = layout.pair(static_cast<int>(k));
    EXPECT_TRUE(cp.body_a == ground || cp.body_a < cp.body_b) << cp.name;
    EXPECT_EQ(cp.friction, 0.5);
  }
  const int ground_pair = layout.rules->find(ground, c.body_index("box_1"));
  ASSERT_GE(ground_pair, 0);
  EXPECT_EQ(layout.pair(ground_pair).body_a, ground);
  b.build(d.get(), layout);
  EXPECT_EQ(layout.pairs.size(), 10u);
}

TEST(ContactBuckets, DeclaredPairsAreFoundNotAdded) {
  const Case c = test::disk_drop(-0.001);  // pressed 1 mm into the ground
  ModelLayout layout;
  const ModelPtr m = test::load_case(c, test::native_options(c), layout, 0.01);
  DataPtr d(mj_makeData(m.get()));
  set_initial_state(m.get(), d.get(), c, layout);
  mj_forward(m.get(), d.get());
  ContactBuckets b;
  const ModelLayout& fixed = layout;
  b.build(d.get(), fixed);
  ASSERT_EQ(b.pairs().size(), 1u);
  EXPECT_EQ(b.pairs()[0], 0);
  EXPECT_EQ(b.contacts(0).size(), 1u);
  EXPECT_EQ(layout.pairs.size(), 1u);
}

}  // namespace
}  // namespace pb::internal::mujoco
