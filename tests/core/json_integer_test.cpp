// json_integer<T> (planarbench/json_integer.hpp): integers read from the files
// we write and read back (task files, descriptions) as written, never
// converted. The refused values are the ones nlohmann's get<T>() would have
// converted: a float out of T's range (undefined behaviour, found by
// fuzz_impact_work), a negative number into an unsigned type (wraps), a
// fraction (truncates), an integer past T's range (wraps).
#include "planarbench/json_integer.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using nlohmann::json;

std::string refusal(const json& v) {
  try {
    (void)pb::json_integer<int>(v, "fold");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(JsonInteger, TakesEveryIntegerOfTheTypeAsWritten) {
  EXPECT_EQ(pb::json_integer<int>(json::parse("-2147483648"), "x"), std::numeric_limits<int>::min());
  EXPECT_EQ(pb::json_integer<int>(json::parse("2147483647"), "x"), std::numeric_limits<int>::max());
  EXPECT_EQ(pb::json_integer<std::uint64_t>(json::parse("18446744073709551615"), "x"),
            std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(pb::json_integer<std::size_t>(json::parse("0"), "x"), 0U);
  EXPECT_EQ(pb::json_integer<long>(json::parse("-9223372036854775808"), "x"),
            std::numeric_limits<long>::min());
}

TEST(JsonInteger, RefusesWhatAConversionWouldChangeNamingTheFieldAndTheRange) {
  EXPECT_EQ(refusal(json::parse("5.55556e+102")),
            "fold is 5.55556e+102: must be an integer in [-2147483648, 2147483647]");
  EXPECT_NE(refusal(json::parse("2.5")), "");
  EXPECT_NE(refusal(json::parse("2.0")), "");  // a float, even a whole one: not as written
  EXPECT_NE(refusal(json::parse("2147483648")), "");
  EXPECT_NE(refusal(json::parse("-2147483649")), "");
  EXPECT_NE(refusal(json::parse("\"1\"")), "");
  EXPECT_NE(refusal(json::parse("true")), "");
  EXPECT_NE(refusal(json::parse("null")), "");
  EXPECT_THROW((void)pb::json_integer<std::size_t>(json::parse("-1"), "predicted[3]"),
               std::runtime_error);
  EXPECT_THROW((void)pb::json_integer<std::int64_t>(json::parse("9223372036854775808"), "x"),
               std::runtime_error);
}

TEST(JsonInteger, AnArrayNamesTheElementRefused) {
  EXPECT_EQ(pb::json_integers<std::size_t>(json::parse("[0, 3, 39]"), "predicted"),
            (std::vector<std::size_t>{0, 3, 39}));
  try {
    (void)pb::json_integers<std::size_t>(json::parse("[0, 3, 39.5]"), "predicted");
    ADD_FAILURE() << "39.5 taken";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("predicted[2] is 39.5:", 0), 0U) << e.what();
  }
  EXPECT_THROW((void)pb::json_integers<int>(json::parse("{\"a\": 1}"), "predicted"),
               std::runtime_error);
}

}  // namespace
