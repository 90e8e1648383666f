// Typed, range-checked reading of the TOML tables of a case file. Every
// failure is one InputError naming where the value came from (the file and
// its line, or `--set KEY`), the field path (e.g. `bodies[1].shape.radius`)
// and what is allowed.
#pragma once

#include <fmt/format.h>

#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <toml++/toml.h>
#include <unordered_map>
#include <utility>
#include <vector>

#include "planarbench/did_you_mean.hpp"
#include "planarbench/case.hpp"
#include "planarbench/errors.hpp"

namespace pb::internal {

// allowed interval of a real number, open or closed at each end
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;

  static Range any() { return {}; }
  static Range positive(double hi = std::numeric_limits<double>::infinity()) {
    return {0.0, hi, true, false};
  }
  static Range non_negative(double hi = std::numeric_limits<double>::infinity()) {
    return {0.0, hi, false, false};
  }
  static Range magnitude(double max_abs) { return {-max_abs, max_abs, false, false}; }

  [[nodiscard]] bool contains(double x) const {
    if (!std::isfinite(x)) return false;
    if (lo_open ? !(x > lo) : !(x >= lo)) return false;
    return hi_open ? x < hi : x <= hi;
  }
  // "", " > 0", " >= 0", " <= 5", " in (0, 1]"
  [[nodiscard]] std::string describe() const {
    const bool has_lo = std::isfinite(lo);
    const bool has_hi = std::isfinite(hi);
    if (!has_lo && !has_hi) return "";
    if (has_lo && !has_hi) return fmt::format(" {} {}", lo_open ? ">" : ">=", lo);
    if (!has_lo) return fmt::format(" {} {}", hi_open ? "<" : "<=", hi);
    return fmt::format(" in {}{}, {}{}", lo_open ? "(" : "[", lo, hi, hi_open ? ")" : "]");
  }
};

// a value as quoted in messages: -1, 0.5, "abc", true, an array, a table; a
// string printable and cut to kEchoChars characters ("1111...", 200 characters)
inline std::string describe_value(const toml::node& n) {
  if (const auto* v = n.as_integer()) return fmt::format("{}", v->get());
  if (const auto* v = n.as_floating_point()) return fmt::format("{}", v->get());
  if (const auto* v = n.as_boolean()) return v->get() ? "true" : "false";
  if (const auto* v = n.as_string()) return echo_value(v->get(), '"');
  if (const auto* v = n.as_array()) return fmt::format("an array of {}", v->size());
  if (n.is_table()) return "a table";
  return "a date/time";
}

// a value of the wrong type, as written and with its type, so that it does not
// look allowed: 100000.0, a float (not "100000", which an integer field takes);
// "abc", a string; true, a boolean; an array of 2; a table
inline std::string describe_typed(const toml::node& n) {
  if (const auto* v = n.as_floating_point()) {
    std::string text = fmt::format("{}", v->get());
    // a float with an integral value prints as one ("100000"): keep its point
    if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
    return text + ", a float";
  }
  if (n.is_integer()) return describe_value(n) + ", an integer";
  if (n.is_string()) return describe_value(n) + ", a string";
  if (n.is_boolean()) return describe_value(n) + ", a boolean";
  return describe_value(n);
}

// Where the nodes of a case tree come from: the file (toml++ source regions
// give the line) or a command-line override (marked when applied).
class Origins {
 public:
  explicit Origins(std::string file) : file_(std::move(file)) {}

  [[nodiscard]] const std::string& file() const { return file_; }

  // marks `node` and everything under it as set by `origin` (e.g. "--set KEY")
  void mark(const toml::node& node, const std::string& origin, int line) {
    marked_[&node] = Where{origin, line};
    if (const auto* t = node.as_table()) {
      for (auto&& [k, v] : *t) mark(v, origin, line);
    } else if (const auto* a = node.as_array()) {
      for (const auto& v : *a) mark(v, origin, line);
    }
  }
  [[nodiscard]] bool is_override(const toml::node* node) const {
    return node != nullptr && marked_.count(node) > 0;
  }

  // throws the InputError for `field`, located at `node` (nullptr: no line)
  [[noreturn]] void fail(const toml::node* node, const std::string& field,
                         const std::string& what) const {
    if (node != nullptr) {
      const auto it = marked_.find(node);
      if (it != marked_.end()) throw InputError(it->second.origin, it->second.line, field, what);
      throw InputError(file_, static_cast<int>(node->source().begin.line), field, what);
    }
    throw InputError(file_, 0, field, what);
  }

 private:
  struct Where {
    std::string origin;
    int line = 0;
  };
  std::string file_;
  std::unordered_map<const toml::node*, Where> marked_;
};

// Reads the fields of one table; `path` is the table's field path ("" for
// the root, "case", "bodies[1]", "bodies[1].shape").
class TableReader {
 public:
  TableReader(const toml::table& table, std::string path, const Origins& origins)
      : table_(&table), path_(std::move(path)), origins_(&origins) {}

  [[nodiscard]] const toml::table& table() const { return *table_; }
  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] const Origins& origins() const { return *origins_; }
  [[nodiscard]] std::string field(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  }
  [[nodiscard]] const toml::node* find(std::string_view key) const { return table_->get(key); }
  [[nodiscard]] bool has(std::string_view key) const { return find(key) != nullptr; }

  // an error at the key's value if present, else at this table
  [[noreturn]] void fail(std::string_view key, const std::string& what) const {
    const toml::node* n = find(key);
    origins_->fail(n != nullptr ? n : table_, field(key), what);
  }
  [[noreturn]] void fail_missing(std::string_view key, const std::string& expected) const {
    origins_->fail(table_, field(key), "missing; give " + expected);
  }

  // rejects keys outside `allowed`, the first in file order; `context` says
  // why a known word is not allowed here (e.g. "of a kelvin_voigt contact")
  void only_keys(const std::vector<std::string>& allowed, const std::string& context = "") const {
    const toml::node* worst = nullptr;
    std::string worst_key;
    for (auto&& [k, v] : *table_) {
      bool ok = false;
      for (const auto& a : allowed) ok = ok || (k.str() == a);
      if (ok) continue;
      if (worst == nullptr || v.source().begin < worst->source().begin) {
        worst = &v;
        worst_key = std::string(k.str());
      }
    }
    if (worst == nullptr) return;
    const std::string what = context.empty() ? "unknown key" : "not a field " + context;
    origins_->fail(worst, field(worst_key),
                   fmt::format("{}{}; allowed: {}", what, did_you_mean(worst_key, allowed),
                               join_words(allowed)));
  }

  // ---- reals ---------------------------------------------------------------
  [[nodiscard]] double real(std::string_view key, const Range& range,
                            std::string_view unit = "") const {
    const toml::node* n = find(key);
    if (n == nullptr) fail_missing(key, real_expectation(range) + in_unit(unit));
    return real_at(*n, field(key), range, unit);
  }
  [[nodiscard]] double real_or(std::string_view key, double fallback, const Range& range,
                               std::string_view unit = "") const {
    const toml::node* n = find(key);
    return n == nullptr ? fallback : real_at(*n, field(key), range, unit);
  }
  [[nodiscard]] double real_at(const toml::node& n, const std::string& f, const Range& range,
                               std::string_view unit = "") const {
    double x = 0.0;
    if (const auto* i = n.as_integer()) {
      x = static_cast<double>(i->get());
    } else if (const auto* d = n.as_floating_point()) {
      x = d->get();
    } else {
      origins_->fail(&n, f, must_be(real_expectation(range), n) + in_unit(unit));
    }
    if (!range.contains(x)) origins_->fail(&n, f, must_be(real_expectation(range), n) + in_unit(unit));
    return x;
  }

  // ---- integers, booleans, strings -------------------------------------------
  [[nodiscard]] int integer_or(std::string_view key, int fallback, int lo, int hi) const {
    const toml::node* n = find(key);
    if (n == nullptr) return fallback;
    const auto* i = n->as_integer();
    if (i == nullptr) {
      origins_->fail(n, field(key),
                     fmt::format("must be an integer in [{}, {}] (got {})", lo, hi, describe_typed(*n)));
    }
    if (i->get() < lo || i->get() > hi) {
      origins_->fail(n, field(key), must_be(fmt::format("an integer in [{}, {}]", lo, hi), *n));
    }
    return static_cast<int>(i->get());
  }
  [[nodiscard]] bool boolean_or(std::string_view key, bool fallback) const {
    const toml::node* n = find(key);
    if (n == nullptr) return fallback;
    const auto* b = n->as_boolean();
    if (b == nullptr) origins_->fail(n, field(key), must_be("true or false", *n));
    return b->get();
  }
  [[nodiscard]] std::string string(std::string_view key) const {
    const toml::node* n = find(key);
    if (n == nullptr) fail_missing(key, "a string");
    return string_at(*n, field(key));
  }
  [[nodiscard]] std::string string_or(std::string_view key, const std::string& fallback) const {
    const toml::node* n = find(key);
    return n == nullptr ? fallback : string_at(*n, field(key));
  }
  [[nodiscard]] std::string string_at(const toml::node& n, const std::string& f) const {
    const auto* s = n.as_string();
    if (s == nullptr) origins_->fail(&n, f, must_be("a string", n));
    return s->get();
  }
  // one of the allowed words
  [[nodiscard]] std::string word(std::string_view key, const std::vector<std::string>& allowed) const {
    const toml::node* n = find(key);
    if (n == nullptr) fail_missing(key, "one of " + quoted_words(allowed));
    return word_at(*n, field(key), allowed);
  }
  [[nodiscard]] std::string word_or(std::string_view key, const std::string& fallback,
                                    const std::vector<std::string>& allowed) const {
    const toml::node* n = find(key);
    return n == nullptr ? fallback : word_at(*n, field(key), allowed);
  }
  [[nodiscard]] std::string word_at(const toml::node& n, const std::string& f,
                                    const std::vector<std::string>& allowed) const {
    const auto* s = n.as_string();
    if (s != nullptr) {
      for (const auto& a : allowed) {
        if (s->get() == a) return a;
      }
    }
    const std::string hint = s != nullptr ? did_you_mean(s->get(), allowed) : "";
    origins_->fail(&n, f, must_be("one of " + quoted_words(allowed), n) + hint);
  }
  // a name: [A-Za-z_][A-Za-z0-9_]*, at most 64 characters
  [[nodiscard]] std::string identifier(std::string_view key) const {
    const std::string s = string(key);
    bool ok = !s.empty() && s.size() <= 64 && (std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_');
    for (const char ch : s) ok = ok && (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_');
    if (!ok) {
      fail(key, must_be("a name of letters, digits and '_' not starting with a digit "
                        "(at most 64 characters)", *find(key)));
    }
    return s;
  }
  // optional array of strings
  [[nodiscard]] std::vector<std::string> strings_or_empty(std::string_view key) const {
    std::vector<std::string> out;
    const toml::node* n = find(key);
    if (n == nullptr) return out;
    const auto* a = n->as_array();
    if (a == nullptr) origins_->fail(n, field(key), must_be("an array of strings", *n));
    for (std::size_t i = 0; i < a->size(); ++i) {
      out.push_back(string_at(*a->get(i), fmt::format("{}[{}]", field(key), i)));
    }
    return out;
  }

  // ---- pairs of reals --------------------------------------------------------
  // [x, y], each element in `range`
  [[nodiscard]] Vec2 vec2(std::string_view key, const Range& range, std::string_view unit = "") const {
    const toml::node* n = find(key);
    if (n == nullptr) fail_missing(key, pair_expectation(range) + in_unit(unit));
    const auto p = pair_at(*n, field(key), range, unit);
    return Vec2(p[0], p[1]);
  }
  [[nodiscard]] Vec2 vec2_or(std::string_view key, const Vec2& fallback, const Range& range,
                             std::string_view unit = "") const {
    return has(key) ? vec2(key, range, unit) : fallback;
  }
  [[nodiscard]] std::array<double, 2> pair(std::string_view key, const Range& range,
                                           std::string_view unit = "") const {
    const toml::node* n = find(key);
    if (n == nullptr) fail_missing(key, pair_expectation(range) + in_unit(unit));
    return pair_at(*n, field(key), range, unit);
  }
  [[nodiscard]] std::array<double, 2> pair_at(const toml::node& n, const std::string& f,
                                              const Range& range, std::string_view unit = "") const {
    const auto* a = n.as_array();
    if (a == nullptr || a->size() != 2) {
      origins_->fail(&n, f, must_be(pair_expectation(range), n) + in_unit(unit));
    }
    return {real_at(*a->get(0), f + "[0]", range, unit), real_at(*a->get(1), f + "[1]", range, unit)};
  }

  // ---- tables ----------------------------------------------------------------
  [[nodiscard]] TableReader subtable(std::string_view key) const {
    const toml::node* n = find(key);
    if (n == nullptr) fail_missing(key, path_.empty() ? "a [" + std::string(key) + "] table" : "a table");
    const auto* t = n->as_table();
    if (t == nullptr) origins_->fail(n, field(key), must_be("a table", *n));
    return TableReader(*t, field(key), *origins_);
  }
  // an array of tables ([[key]] or [{...}, ...]); empty when absent
  [[nodiscard]] std::vector<TableReader> table_array(std::string_view key) const {
    std::vector<TableReader> out;
    const toml::node* n = find(key);
    if (n == nullptr) return out;
    const auto* a = n->as_array();
    if (a == nullptr) origins_->fail(n, field(key), must_be(fmt::format("an array of tables ([[{}]])", key), *n));
    for (std::size_t i = 0; i < a->size(); ++i) {
      const std::string f = fmt::format("{}[{}]", field(key), i);
      const auto* t = a->get(i)->as_table();
      if (t == nullptr) origins_->fail(a->get(i), f, must_be("a table", *a->get(i)));
      out.emplace_back(*t, f, *origins_);
    }
    return out;
  }

  // "must be X (got Y)"
  [[nodiscard]] static std::string must_be(const std::string& expected, const toml::node& got) {
    return fmt::format("must be {} (got {})", expected, describe_value(got));
  }

 private:
  static std::string real_expectation(const Range& range) {
    return "a finite number" + range.describe();
  }
  static std::string pair_expectation(const Range& range) {
    // appended piecewise: GCC 12's -Wstringop-overflow misreads "," + std::string
    // once this is inlined (a false positive, GCC bug 105329)
    std::string out = "an array of 2 finite numbers";
    const std::string bounds = range.describe();
    if (!bounds.empty()) out.append(",").append(bounds);
    return out;
  }
  // ", in kg" or empty
  static std::string in_unit(std::string_view unit) {
    return unit.empty() ? std::string() : ", in " + std::string(unit);
  }
  static std::string quoted_words(const std::vector<std::string>& words) {
    std::string out;
    for (const auto& w : words) out += (out.empty() ? "\"" : ", \"") + w + "\"";
    return out;
  }

  const toml::table* table_;
  std::string path_;
  const Origins* origins_;
};

}  // namespace pb::internal
