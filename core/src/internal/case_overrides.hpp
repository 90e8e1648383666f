// Applies the case keys of `--set KEY=VALUE` to the parsed TOML tree of a case
// file before validation, so that an overridden value is checked exactly like
// the file's own and its errors name `--set KEY`.
//
//   duration, output_interval, gravity,   -> [case].<key>
//   outline_points, truth
//   contact.<field...>                     -> <field...> of every [[contacts]] and
//                                             every [[contact_groups]]
//   contacts.<name>.<field...>             -> <field...> of the contact named <name>
//   groups.<name>.<field...>               -> <field...> of the contact group <name>
//   bodies.<name>.<field...>               -> <field...> of the body named <name>
//   generate.<name>.<field...>             -> <field...> of the [[generate]] <name>
//
// Keys apply in sorted order, so contacts.<name>.x is applied after (and wins
// over) contact.x. Giving one of two alternative ways of stating a quantity
// (mass | density, angle | angle_deg, stiffness | young_modulus +
// poisson_ratio + radius) removes the file's other way.
#pragma once

#include <fmt/format.h>

#include <string>
#include <string_view>
#include <toml++/toml.h>
#include <utility>
#include <vector>

#include "planarbench/did_you_mean.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/settings.hpp"
#include "toml_reader.hpp"

namespace pb::internal {

// the value text of an override as a TOML value (a table holding it as "v"):
// parsed as `v = TEXT`, or taken as a plain string when that is not exactly
// one TOML value (so `truth=none` needs no quotes)
inline toml::table parse_override_value(const std::string& text) {
  const std::string doc = "v = " + text;
  try {
    toml::table t = toml::parse(std::string_view(doc), std::string_view("--set"));
    if (t.size() == 1 && t.contains("v")) return t;
  } catch (const toml::parse_error&) {
    // not a TOML value: a string
  }
  toml::table t;
  t.insert("v", text);
  return t;
}

// "a.b.c" -> {"a", "b", "c"}
inline std::vector<std::string> split_dotted(const std::string& key) {
  std::vector<std::string> out(1);
  for (const char ch : key) {
    if (ch == '.') {
      out.emplace_back();
    } else {
      out.back() += ch;
    }
  }
  return out;
}

class CaseOverrideApplier {
 public:
  CaseOverrideApplier(toml::table& root, Origins& origins) : root_(&root), origins_(&origins) {}

  void apply(const std::string& key, const SettingValue& value) {
    origin_ = value.source.origin.empty() || value.source.origin == "--set"
                  ? "--set " + key
                  : value.source.origin;
    line_ = value.source.line;
    const toml::table parsed = parse_override_value(value.text);
    const toml::node& v = *parsed.get("v");
    const std::vector<std::string> segs = split_dotted(key);

    // [case] fields
    if (segs.size() == 1) {
      set_path(*root_, {"case", segs[0]}, 0, v);
      return;
    }
    // every contact pair and group
    if (segs[0] == "contact") {
      auto entries = named_entries("contacts");
      const auto groups = named_entries("contact_groups");
      entries.insert(entries.end(), groups.begin(), groups.end());
      if (entries.empty()) fail("the case has no [[contacts]] or [[contact_groups]] to apply it to");
      for (const auto& e : entries) set_path(*e.second, segs, 1, v);
      return;
    }
    // one named contact, group, body or generator
    if ((segs[0] == "contacts" || segs[0] == "bodies" || segs[0] == "groups" ||
         segs[0] == "generate") &&
        segs.size() >= 3) {
      const std::string array = segs[0] == "groups" ? "contact_groups" : segs[0];
      const auto entries = named_entries(array);
      std::vector<std::string> names;
      bool found = false;
      for (const auto& e : entries) {
        names.push_back(e.first);
        if (e.first == segs[1]) {
          set_path(*e.second, segs, 2, v);
          found = true;
        }
      }
      if (!found) {
        const char* what = segs[0] == "bodies"     ? "body"
                           : segs[0] == "groups"   ? "contact group"
                           : segs[0] == "generate" ? "[[generate]] table"
                                                   : "contact";
        const std::string hint =
            segs[0] == "bodies" && !named_entries("generate").empty()
                ? " (a generated body is set through its generator: generate.<name>.<field>)"
                : "";
        fail(fmt::format("the case has no {} named '{}'{}; {}: {}{}", what, segs[1],
                         did_you_mean(segs[1], names), segs[0],
                         names.empty() ? "none" : join_words(names), hint));
      }
      return;
    }
    fail("not a case key (duration, output_interval, gravity, outline_points, truth, "
         "contact.<field>, contacts.<name>.<field>, groups.<name>.<field>, "
         "bodies.<name>.<field>, generate.<name>.<field>)");
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(origin_, line_, "", what); }

  // (name, table) of each entry of the array of tables root[array_key]
  std::vector<std::pair<std::string, toml::table*>> named_entries(const std::string& array_key) {
    std::vector<std::pair<std::string, toml::table*>> out;
    auto* a = root_->get_as<toml::array>(array_key);
    if (a == nullptr) return out;
    for (auto& n : *a) {
      auto* t = n.as_table();
      if (t == nullptr) continue;
      const auto* name = t->get_as<std::string>("name");
      out.emplace_back(name != nullptr ? name->get() : std::string(), t);
    }
    return out;
  }

  // sets segs[first..] under `table` to `value`, creating missing tables
  void set_path(toml::table& table, const std::vector<std::string>& segs, std::size_t first,
                const toml::node& value) {
    toml::table* t = &table;
    for (std::size_t i = first; i + 1 < segs.size(); ++i) {
      toml::node* child = t->get(segs[i]);
      if (child == nullptr) {
        t->insert_or_assign(segs[i], toml::table{});
        child = t->get(segs[i]);
        origins_->mark(*child, origin_, line_);
      }
      if (!child->is_table()) {
        fail(fmt::format("'{}' is {}, not a table", segs[i], describe_value(*child)));
      }
      t = child->as_table();
    }
    const std::string& leaf = segs.back();
    if (segs.size() - first == 1) drop_alternatives(*t, leaf);
    value.visit([&](const auto& v) { t->insert_or_assign(leaf, v); });
    origins_->mark(*t->get(leaf), origin_, line_);
  }

  // removes the file's other way of stating the quantity `leaf` states
  void drop_alternatives(toml::table& t, const std::string& leaf) {
    using Ways = std::vector<std::vector<std::string>>;
    static const std::vector<Ways> kAlternatives = {
        {{"mass"}, {"density"}},
        {{"angle"}, {"angle_deg"}},
        {{"stiffness"}, {"young_modulus", "poisson_ratio", "radius"}},
    };
    for (const Ways& ways : kAlternatives) {
      for (std::size_t w = 0; w < ways.size(); ++w) {
        bool mine = false;
        for (const auto& k : ways[w]) mine = mine || k == leaf;
        if (!mine) continue;
        for (std::size_t other = 0; other < ways.size(); ++other) {
          if (other == w) continue;
          for (const auto& k : ways[other]) {
            if (!origins_->is_override(t.get(k))) t.erase(k);
          }
        }
      }
    }
  }

  toml::table* root_;
  Origins* origins_;
  std::string origin_;
  int line_ = 0;
};

// applies every override, in key order
inline void apply_case_overrides(toml::table& root, const SettingsOverrides& overrides,
                                 Origins& origins) {
  CaseOverrideApplier applier(root, origins);
  for (const auto& [key, value] : overrides.all()) applier.apply(key, value);
}

}  // namespace pb::internal
