// Tests for adapters/box2d/box2d_mapping_notes.cpp
#include "box2d_mapping_notes.hpp"

#include <box2d/b2_common.h>
#include <gtest/gtest.h>

namespace pb::internal::box2d {
namespace {

// the skin and slop reported are Box2D's compiled-in constants (b2_common.h:
// b2_linearSlop = 0.005 m, b2_polygonRadius = 2 b2_linearSlop), exactly
TEST(Box2dMappingNotes, SkinAndSlopAreBox2dsConstants) {
  const nlohmann::json n = mapping_notes(false);
  EXPECT_EQ(n.at("skin_and_slop").at("b2_linearSlop_m").get<double>(),
            static_cast<double>(b2_linearSlop));
  EXPECT_EQ(n.at("skin_and_slop").at("b2_polygonRadius_m").get<double>(),
            static_cast<double>(b2_polygonRadius));
  EXPECT_EQ(static_cast<double>(b2_polygonRadius), 2.0 * static_cast<double>(b2_linearSlop));
}

// engine mode states what the rigid contact cannot express and how forces,
// penetrations and episodes are measured; injection mode states its own limits
TEST(Box2dMappingNotes, EachModeStatesItsLimits) {
  const nlohmann::json engine = mapping_notes(false);
  for (const char* key :
       {"frame", "precision", "forces", "episodes", "penetration", "thread_safety"}) {
    EXPECT_TRUE(engine.contains(key)) << key;
  }
  EXPECT_GE(engine.at("not_expressible").size(), 5u);
  const nlohmann::json inject = mapping_notes(true);
  EXPECT_FALSE(inject.contains("forces"));
  EXPECT_GE(inject.at("not_expressible").size(), 2u);
}

}  // namespace
}  // namespace pb::internal::box2d
