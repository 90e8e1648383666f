// Engine settings: plain structs with defaulted members, bound to string keys
// so that a case's [settings] table and `--set KEY=VALUE` can override them.
//
// Key resolution for an engine named E and a bound key K:
//   "E.K" (e.g. "mujoco.timestep") wins over "K" (e.g. "dt", "geometry").
// Unprefixed keys are shared: "dt" reaches every engine that binds "dt".
#pragma once

#include <functional>
#include <map>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace pb {

// Where a setting's value came from, for error messages.
struct SettingSource {
  std::string origin;  // "--set" or the case file path
  int line = 0;        // line in the case file (0 = command line)
};

struct SettingValue {
  std::string text;  // as written: "1e-4", "exact", "[0.9, 0.95, 0.001, 0.5, 2]"
  SettingSource source;
};

// The settings given for one run: key -> value, before any engine reads them.
class SettingsOverrides {
 public:
  void set(const std::string& key, const std::string& text, SettingSource source);
  [[nodiscard]] const SettingValue* find(const std::string& key) const;
  [[nodiscard]] const std::map<std::string, SettingValue>& all() const { return values_; }
  [[nodiscard]] bool empty() const { return values_.empty(); }

 private:
  std::map<std::string, SettingValue> values_;
};

// One bound setting of an engine: name, doc, and how to parse and print it.
struct SettingSpec {
  std::string key;      // unprefixed key, e.g. "timestep"
  std::string doc;      // one line, with unit and allowed range
  std::function<void(const SettingValue&, const std::string& full_key)> parse;
  std::function<nlohmann::json()> to_json;
};

// Binds an engine's settings struct members to keys. Parsers validate type and
// range and throw InputError naming the origin, the key and what is allowed.
class SettingsBinder {
 public:
  explicit SettingsBinder(std::string engine_name) : engine_(std::move(engine_name)) {}

  // real number in [lo, hi]
  SettingsBinder& real(const std::string& key, double* member, double lo, double hi,
                       const std::string& doc);
  // integer in [lo, hi]
  SettingsBinder& integer(const std::string& key, int* member, int lo, int hi,
                          const std::string& doc);
  SettingsBinder& boolean(const std::string& key, bool* member, const std::string& doc);
  // one of the allowed words
  SettingsBinder& choice(const std::string& key, std::string* member,
                         std::vector<std::string> allowed, const std::string& doc);
  // list of reals of a fixed length (0 = any length)
  SettingsBinder& reals(const std::string& key, std::vector<double>* member,
                        std::size_t length, const std::string& doc);

  // Applies every override that concerns this engine ("engine.key" or "key").
  void apply(const SettingsOverrides& overrides) const;
  // The effective settings as a JSON object, key -> value.
  [[nodiscard]] nlohmann::json to_json() const;
  [[nodiscard]] const std::vector<SettingSpec>& specs() const { return specs_; }
  [[nodiscard]] const std::string& engine() const { return engine_; }
  // true when "key" or "engine.key" names one of these settings
  [[nodiscard]] bool knows(const std::string& key) const;

 private:
  std::string engine_;
  std::vector<SettingSpec> specs_;
};

}  // namespace pb
