// Tests for adapters/box2d/box2d_pair_book.cpp
#include "box2d_pair_book.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include "box2d_test_cases.hpp"

namespace pb::internal::box2d {
namespace {

// The pair book: a declared pair by either order of its bodies; a group's
// pair added with the group's state at its first find_or_add and found
// after; a pair no rule covers, or a fixture without a body index, none.
TEST(Box2dPairBook, FindsDeclaredAndAddsGroupPairs) {
  Case c = box2d_test::make_case("book", 1.0);
  c.bodies = {box2d_test::ground_body(), box2d_test::disk_body("d1", 0.1, 1.0, Vec2(0.0, 1.0)),
              box2d_test::disk_body("d2", 0.1, 1.0, Vec2(1.0, 1.0)),
              box2d_test::disk_body("d3", 0.1, 1.0, Vec2(2.0, 1.0))};
  c.contacts = {box2d_test::kv_pair(0, 2)};
  ContactGroup g;
  g.name = "disks";
  g.bodies = {1, 2, 3};
  g.law = KelvinVoigt{1e4, 10.0, 0.0};
  g.friction = 0.25;
  c.contact_groups = {g};
  PairState declared;
  declared.friction = 0.5f;
  PairState group;
  group.friction = 0.25f;
  PairBook book;
  book.reset(c, {declared}, {group});
  EXPECT_EQ(book.size(), 1);
  EXPECT_EQ(book.find(2, 0), 0);
  EXPECT_TRUE(book.may_touch(0, 2));
  EXPECT_TRUE(book.may_touch(3, 1));
  EXPECT_FALSE(book.may_touch(0, 1));   // ground and d1: no rule
  EXPECT_FALSE(book.may_touch(-1, 0));  // fixtures without a body index
  EXPECT_FALSE(book.may_touch(0, 7));
  EXPECT_EQ(book.find(3, 1), -1);  // not added yet
  EXPECT_EQ(book.find_or_add(3, 1), 1);
  EXPECT_EQ(book.find_or_add(1, 3), 1);
  EXPECT_EQ(book.size(), 2);
  EXPECT_EQ(book.state(1).friction, 0.25f);
  EXPECT_EQ(book.state(0).friction, 0.5f);
  EXPECT_EQ(book.pair(1).body_a, 1);  // the lower index first: neither is fixed
  EXPECT_EQ(book.find_or_add(0, 1), -1);
  EXPECT_EQ(book.size(), 2);
  // the stamp: a pair's impulses count for the step that summed them only
  book.state(1).impulse_step = 7;
  book.state(1).step_impulse_ns = 0.25;
  EXPECT_EQ(book.state(1).impulse_ns(7), 0.25);
  EXPECT_EQ(book.state(1).impulse_ns(8), 0.0);
}

// A ground pairs with many disks, each disk with few: a lookup scans the
// shorter list, either order, and the pairs keep their indices.
TEST(Box2dPairBook, ManyPairsOfOneBodyKeepTheirIndices) {
  Case c = box2d_test::make_case("fan", 1.0);
  c.bodies = {box2d_test::ground_body()};
  ContactGroup g;
  g.name = "all";
  g.bodies = {0};
  for (int i = 1; i <= 50; ++i) {
    c.bodies.push_back(box2d_test::disk_body(fmt::format("d{}", i), 0.1, 1.0, Vec2(i, 1.0)));
    g.bodies.push_back(i);
  }
  c.contact_groups = {g};
  PairBook book;
  book.reset(c, {}, {PairState{}});
  for (int i = 50; i >= 1; --i) EXPECT_EQ(book.find_or_add(0, i), 50 - i);
  for (int i = 1; i < 50; ++i) EXPECT_EQ(book.find_or_add(i + 1, i), 49 + i);
  for (int i = 1; i <= 50; ++i) {
    EXPECT_EQ(book.find(i, 0), 50 - i);
    EXPECT_EQ(book.pair(50 - i).body_a, 0);  // the fixed body first
  }
  EXPECT_EQ(book.find(1, 3), -1);
  EXPECT_EQ(book.size(), 99);
}

}  // namespace
}  // namespace pb::internal::box2d
