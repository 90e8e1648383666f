// Tests for core/reference/src/reference_settings.cpp
#include "planarbench/reference/reference_settings.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "planarbench/errors.hpp"

namespace pb {
namespace {

SettingsOverrides with(const std::string& key, const std::string& value) {
  SettingsOverrides o;
  o.set(key, value, SettingSource{"--set", 0});
  return o;
}

TEST(ReferenceSettings, DefaultsAndDocs) {
  ReferenceSettings s;
  SettingsBinder b("reference");
  bind_reference_settings(b, s);
  const nlohmann::json j = b.to_json();
  EXPECT_EQ(j.at("geometry"), "outline");
  EXPECT_EQ(j.at("detection"), "fast");
  EXPECT_EQ(j.at("integrator"), "rk45");
  EXPECT_EQ(j.at("rtol").get<double>(), 1e-10);
  for (const char* key : {"geometry", "detection", "integrator", "dt", "rtol", "atol", "h_max", "h_min",
                          "contact_dt", "gap_safety"}) {
    EXPECT_TRUE(b.knows(key)) << key;
    EXPECT_TRUE(b.knows(std::string("reference.") + key)) << key;
  }
  for (const auto& spec : b.specs()) EXPECT_FALSE(spec.doc.empty()) << spec.key;
}

TEST(ReferenceSettings, PrefixedKeyWins) {
  ReferenceSettings s;
  SettingsBinder b("reference");
  bind_reference_settings(b, s);
  SettingsOverrides o;
  o.set("dt", "1e-4", SettingSource{"--set", 0});
  o.set("reference.dt", "2e-4", SettingSource{"--set", 0});
  o.set("geometry", "exact", SettingSource{"--set", 0});
  b.apply(o);
  EXPECT_EQ(s.dt, 2e-4);
  EXPECT_EQ(s.geometry, "exact");
}

TEST(ReferenceSettings, BadValuesAreInputErrors) {
  ReferenceSettings s;
  SettingsBinder b("reference");
  bind_reference_settings(b, s);
  EXPECT_THROW(b.apply(with("integrator", "euler")), InputError);
  EXPECT_THROW(b.apply(with("rtol", "0")), InputError);
  EXPECT_THROW(b.apply(with("reference.dt", "-1")), InputError);
  EXPECT_THROW(b.apply(with("geometry", "polygon")), InputError);
}

TEST(ReferenceSettings, DetectionChoosesTheSearchAndNamesTheAllowedValues) {
  ReferenceSettings s;
  SettingsBinder b("reference");
  bind_reference_settings(b, s);
  b.apply(with("reference.detection", "brute"));
  EXPECT_EQ(s.detection, "brute");
  b.apply(with("detection", "fast"));
  EXPECT_EQ(s.detection, "fast");
  try {
    b.apply(with("detection", "quick"));
    FAIL() << "detection=quick was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("detection"), std::string::npos) << what;
    EXPECT_NE(what.find("fast"), std::string::npos) << what;
    EXPECT_NE(what.find("brute"), std::string::npos) << what;
  }
  EXPECT_EQ(s.detection, "fast");  // a refused value leaves the setting alone
}

}  // namespace
}  // namespace pb
