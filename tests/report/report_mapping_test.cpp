// Tests for reports/src/report_mapping.cpp
#include "report_mapping.hpp"

#include <gtest/gtest.h>

namespace pb::internal {
namespace {

// the shapes the adapters write: MuJoCo a top-level and per-pair
// "not_expressed", Box2D "not_expressible", ODE a string "not expressed: ..."
TEST(NotExpressed, CollectsEveryAdapterConvention) {
  const auto mapping = nlohmann::json::parse(R"({
    "engine": "x",
    "not_expressed": ["gravity share"],
    "pairs": [
      {"name": "ground_ball", "not_expressed": ["damping ramp"], "solref": [-1, -2]},
      {"name": "other", "not_expressed": []}
    ],
    "contacts": [{"pair": "p", "threshold": "not expressed: depth >= 0"}],
    "not_expressible": ["stiffness"]
  })");
  const auto lost = not_expressed(mapping);
  ASSERT_EQ(lost.size(), 4u);
  // nlohmann orders object keys alphabetically: contacts, engine, not_expressed, not_expressible,
  // pairs
  EXPECT_EQ(lost[0], "p: not expressed: depth >= 0");
  EXPECT_EQ(lost[1], "gravity share");
  EXPECT_EQ(lost[2], "stiffness");
  EXPECT_EQ(lost[3], "ground_ball: damping ramp");
}

TEST(NotExpressed, NothingForAnEmptyMapping) {
  EXPECT_TRUE(not_expressed(nlohmann::json::object()).empty());
  EXPECT_TRUE(not_expressed(nlohmann::json::parse(R"({"not_expressed": []})")).empty());
}

TEST(FlattenMapping, PathsForObjectsAndListsScalarsArraysAsOneValue) {
  const auto flat = flatten_mapping(nlohmann::json::parse(
      R"({"a": {"b": 1.5, "c": "text"}, "pairs": [{"k": [1, 2]}], "e": {}})"));
  ASSERT_EQ(flat.size(), 4u);
  EXPECT_EQ(flat[0], (std::pair<std::string, std::string>{"a.b", "1.5"}));
  EXPECT_EQ(flat[1], (std::pair<std::string, std::string>{"a.c", "text"}));
  EXPECT_EQ(flat[2], (std::pair<std::string, std::string>{"e", "{}"}));
  EXPECT_EQ(flat[3], (std::pair<std::string, std::string>{"pairs[0].k", "[1, 2]"}));
}

}  // namespace
}  // namespace pb::internal
