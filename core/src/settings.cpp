#include "planarbench/settings.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <optional>

#include "planarbench/errors.hpp"

namespace pb {

namespace {

[[noreturn]] void bad_value(const SettingValue& v, const std::string& key, const std::string& what) {
  // the value as given, cut when long (a 100000-digit value is not echoed whole)
  throw InputError(v.source.origin, v.source.line, key,
                   fmt::format("{} (got {})", what, echo_value(v.text)));
}

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\"'");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\"'");
  return s.substr(b, e - b + 1);
}

// a whole-string finite number, or nullopt
std::optional<double> parse_real(const std::string& text) {
  const std::string s = trimmed(text);
  if (s.empty()) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || errno == ERANGE || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace

void SettingsOverrides::set(const std::string& key, const std::string& text, SettingSource source) {
  values_[key] = SettingValue{text, std::move(source)};
}

const SettingValue* SettingsOverrides::find(const std::string& key) const {
  const auto it = values_.find(key);
  return it == values_.end() ? nullptr : &it->second;
}

SettingsBinder& SettingsBinder::real(const std::string& key, double* member, double lo, double hi,
                                     const std::string& doc) {
  specs_.push_back(SettingSpec{
      key, doc,
      [=](const SettingValue& v, const std::string& full) {
        const auto x = parse_real(v.text);
        if (!x || *x < lo || *x > hi) {
          bad_value(v, full, fmt::format("must be a finite number in [{:g}, {:g}]", lo, hi));
        }
        *member = *x;
      },
      [=] { return nlohmann::json(*member); }});
  return *this;
}

SettingsBinder& SettingsBinder::integer(const std::string& key, int* member, int lo, int hi,
                                        const std::string& doc) {
  specs_.push_back(SettingSpec{
      key, doc,
      [=](const SettingValue& v, const std::string& full) {
        const auto x = parse_real(v.text);
        if (!x || *x != std::floor(*x) || *x < lo || *x > hi) {
          bad_value(v, full, fmt::format("must be an integer in [{}, {}]", lo, hi));
        }
        *member = static_cast<int>(*x);
      },
      [=] { return nlohmann::json(*member); }});
  return *this;
}

SettingsBinder& SettingsBinder::boolean(const std::string& key, bool* member,
                                        const std::string& doc) {
  specs_.push_back(SettingSpec{
      key, doc,
      [=](const SettingValue& v, const std::string& full) {
        const std::string s = trimmed(v.text);
        if (s == "true" || s == "1" || s == "on") {
          *member = true;
        } else if (s == "false" || s == "0" || s == "off") {
          *member = false;
        } else {
          bad_value(v, full, "must be true or false");
        }
      },
      [=] { return nlohmann::json(*member); }});
  return *this;
}

SettingsBinder& SettingsBinder::choice(const std::string& key, std::string* member,
                                       std::vector<std::string> allowed, const std::string& doc) {
  specs_.push_back(SettingSpec{
      key, doc,
      [=](const SettingValue& v, const std::string& full) {
        const std::string s = trimmed(v.text);
        for (const auto& a : allowed) {
          if (s == a) {
            *member = s;
            return;
          }
        }
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        bad_value(v, full, fmt::format("must be one of: {}", list));
      },
      [=] { return nlohmann::json(*member); }});
  return *this;
}

SettingsBinder& SettingsBinder::reals(const std::string& key, std::vector<double>* member,
                                      std::size_t length, const std::string& doc) {
  specs_.push_back(SettingSpec{
      key, doc,
      [=](const SettingValue& v, const std::string& full) {
        // accepts "[a, b, c]", "a,b,c" and "a b c"
        std::string s = v.text;
        for (char& ch : s) {
          if (ch == '[' || ch == ']' || ch == ',') ch = ' ';
        }
        std::vector<double> out;
        std::size_t pos = 0;
        while (pos < s.size()) {
          const auto b = s.find_first_not_of(' ', pos);
          if (b == std::string::npos) break;
          const auto e = s.find(' ', b);
          const auto item = s.substr(b, e == std::string::npos ? std::string::npos : e - b);
          const auto x = parse_real(item);
          if (!x) bad_value(v, full, "must be a list of finite numbers");
          out.push_back(*x);
          pos = e == std::string::npos ? s.size() : e;
        }
        if (out.empty() || (length != 0 && out.size() != length)) {
          bad_value(v, full,
                    length ? fmt::format("must be a list of {} finite numbers", length)
                           : std::string("must be a non-empty list of finite numbers"));
        }
        *member = std::move(out);
      },
      [=] { return nlohmann::json(*member); }});
  return *this;
}

void SettingsBinder::apply(const SettingsOverrides& overrides) const {
  // shared "key" first, then "engine.key", so the prefixed one wins; a shared
  // key's refusal names the engine whose range it broke (--engine all applies
  // it to every engine, each with its own range)
  for (const auto& spec : specs_) {
    if (const auto* v = overrides.find(spec.key)) {
      spec.parse(*v, fmt::format("{} (for {}; {}.{} sets {}'s alone)", spec.key, engine_, engine_,
                                 spec.key, engine_));
    }
    const std::string full = engine_ + "." + spec.key;
    if (const auto* v = overrides.find(full)) spec.parse(*v, full);
  }
}

nlohmann::json SettingsBinder::to_json() const {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& spec : specs_) j[spec.key] = spec.to_json();
  return j;
}

bool SettingsBinder::knows(const std::string& key) const {
  for (const auto& spec : specs_) {
    if (key == spec.key || key == engine_ + "." + spec.key) return true;
  }
  return false;
}

}  // namespace pb
