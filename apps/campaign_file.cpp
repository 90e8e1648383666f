// A campaign file (TOML) read into its plan (campaign_plan.hpp): every
// error an InputError naming the file, the line, the field and what is
// allowed; the cases loaded, the axes expanded, their points checked
// (campaign_points.hpp).
#include "campaign_plan.hpp"

#include <fmt/format.h>
#include <glob.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <set>
#include <toml++/toml.h>

#include "campaign_points.hpp"
#include "campaign_size.hpp"
#include "cli_common.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/did_you_mean.hpp"
#include "planarbench/engines.hpp"
#include "planarbench/errors.hpp"
#include "sweep_plan.hpp"
#include "task_scheduler.hpp"

namespace pb::cli {

namespace fs = std::filesystem;

namespace {

// the largest campaign is kMaxPlannedRuns (campaign_size.hpp): what its plan
// takes in memory, not its arithmetic, which stays exact far beyond
constexpr std::int64_t kMaxAxisPoints = 1000000;

class Reader {
 public:
  Reader(std::string file) : file_(std::move(file)) {}
  [[noreturn]] void fail(const toml::node* n, const std::string& field,
                         const std::string& what) const {
    const int line = n != nullptr ? static_cast<int>(n->source().begin.line) : 0;
    throw InputError(file_, line, field, what);
  }
  [[noreturn]] void fail(const toml::table& t, const std::string& field,
                         const std::string& what) const {
    fail(static_cast<const toml::node*>(&t), field, what);
  }
  void only_keys(const toml::table& t, const std::string& where,
                 const std::vector<std::string>& allowed) const {
    for (const auto& [k, v] : t) {
      const std::string key(k.str());
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
        fail(&v, where.empty() ? key : where + "." + key,
             fmt::format("unknown key{}; allowed: {}", did_you_mean(key, allowed),
                         join_words(allowed)));
      }
    }
  }
  double real(const toml::table& t, const std::string& key, const std::string& where) const {
    const toml::node* n = t.get(key);
    if (n == nullptr) fail(t, where + "." + key, "is missing (a number)");
    if (const auto v = n->value<double>()) {
      if (std::isfinite(*v)) return *v;
    }
    fail(n, where + "." + key, "must be a finite number");
  }
  std::int64_t integer(const toml::table& t, const std::string& key, const std::string& where,
                       std::int64_t lo, std::int64_t hi) const {
    const toml::node* n = t.get(key);
    if (n == nullptr) fail(t, where + "." + key, fmt::format("is missing (an integer in [{}, {}])", lo, hi));
    const auto* v = n->as_integer();
    if (v == nullptr || v->get() < lo || v->get() > hi) {
      fail(n, where + "." + key, fmt::format("must be an integer in [{}, {}]", lo, hi));
    }
    return v->get();
  }
  // a string or an array of strings
  std::vector<std::pair<std::string, const toml::node*>> strings(const toml::node* n,
                                                                  const std::string& field) const {
    std::vector<std::pair<std::string, const toml::node*>> out;
    if (const auto* s = n->as_string()) {
      out.emplace_back(s->get(), n);
      return out;
    }
    const auto* a = n->as_array();
    if (a == nullptr || a->empty()) fail(n, field, "must be a string or a non-empty array of strings");
    for (const auto& e : *a) {
      const auto* s = e.as_string();
      if (s == nullptr) fail(&e, field, "must be an array of strings");
      out.emplace_back(s->get(), &e);
    }
    return out;
  }
  // a value of `set` as --set text
  std::string setting_text(const toml::node& n, const std::string& field) const {
    if (const auto* s = n.as_string()) return s->get();
    if (const auto* i = n.as_integer()) return fmt::format("{}", i->get());
    if (const auto* f = n.as_floating_point()) return number_text(f->get());
    if (const auto* b = n.as_boolean()) return b->get() ? "true" : "false";
    if (const auto* a = n.as_array()) {
      std::string out = "[";
      for (std::size_t i = 0; i < a->size(); ++i) {
        const auto v = (*a)[i].value<double>();
        if (!v) fail(&(*a)[i], field, "an array value must hold numbers");
        out += (i ? "," : "") + number_text(*v);
      }
      return out + "]";
    }
    fail(&n, field, "must be a string, a number, a boolean or an array of numbers");
  }
  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

std::vector<fs::path> glob_paths(const std::string& pattern) {
  glob_t g{};
  std::vector<fs::path> out;
  if (::glob(pattern.c_str(), 0, nullptr, &g) == 0) {
    for (std::size_t i = 0; i < g.gl_pathc; ++i) out.emplace_back(g.gl_pathv[i]);
  }
  globfree(&g);
  std::sort(out.begin(), out.end());
  return out;
}


std::vector<double> spaced(double from, double to, std::int64_t points, bool log) {
  std::vector<double> out;
  for (std::int64_t i = 0; i < points; ++i) {
    const double f = static_cast<double>(i) / static_cast<double>(points - 1);
    out.push_back(log ? std::exp(std::log(from) + f * (std::log(to) - std::log(from)))
                      : from + f * (to - from));
  }
  // the ends exactly as written
  out.front() = from;
  out.back() = to;
  return out;
}


const std::vector<std::string> kPerturbFields = {"position", "velocity", "angle",
                                                 "angular_velocity"};

std::string axis_unit(const std::string& key) {
  const std::string last = key.substr(key.rfind('.') == std::string::npos ? 0 : key.rfind('.') + 1);
  if (last == "dt" || last == "duration" || last == "output_interval") return "s";
  if (last == "stiffness") return "N/m";
  return "";
}

}  // namespace

CampaignPlan load_campaign(const fs::path& file, const std::string& cases_dir_option, bool quiet) {
  CampaignPlan plan;
  plan.file = file.string();
  const Reader in(plan.file);
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) {
    throw InputError(plan.file, 0, "", "does not exist or is not a file; give a campaign file (TOML)");
  }
  toml::table root;
  try {
    root = toml::parse_file(plan.file);
  } catch (const toml::parse_error& e) {
    throw InputError(plan.file, static_cast<int>(e.source().begin.line), "",
                     fmt::format("is not valid TOML: {}", e.description()));
  }
  {
    std::ifstream f(file);
    plan.text.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
  }
  in.only_keys(root, "", {"campaign", "axis"});
  const toml::table* c = root["campaign"].as_table();
  if (c == nullptr) in.fail(root, "campaign", "the [campaign] table is missing");
  in.only_keys(*c, "campaign", {"cases", "engines", "metrics", "trace_points", "set"});

  // ---- set: the --set of every run ----
  if (const toml::node* s = c->get("set")) {
    const auto* t = s->as_table();
    if (t == nullptr) in.fail(s, "campaign.set", "must be a table of KEY = VALUE");
    for (const auto& [k, v] : *t) {
      plan.set.emplace_back(std::string(k.str()),
                            in.setting_text(v, "campaign.set." + std::string(k.str())));
    }
  }
  std::vector<std::string> set_assignments;
  for (const auto& [k, v] : plan.set) set_assignments.push_back(k + "=" + v);
  Overrides fixed;
  try {
    fixed = parse_overrides(set_assignments);
  } catch (const InputError& e) {
    in.fail(c->get("set"), "campaign.set", e.what());
  }

  // ---- engines ----
  {
    const toml::node* n = c->get("engines");
    if (n == nullptr) in.fail(*c, "campaign.engines", "is missing (engine names or \"all\")");
    for (const auto& [name, node] : in.strings(n, "campaign.engines")) {
      try {
        for (auto& e : resolve_engines(name)) {
          if (std::find(plan.engines.begin(), plan.engines.end(), e) == plan.engines.end()) {
            plan.engines.push_back(std::move(e));
          }
        }
      } catch (const InputError& e) {
        in.fail(node, "campaign.engines", e.what());
      }
    }
    try {
      check_engine_settings(fixed.engine_keys, plan.engines);
    } catch (const InputError& e) {
      in.fail(c->get("set"), "campaign.set", e.what());
    }
  }

  // ---- metrics ----
  {
    std::vector<std::string> names;
    for (const auto& m : campaign_metrics()) names.push_back(m.name);
    const toml::node* n = c->get("metrics");
    std::vector<std::pair<std::string, const toml::node*>> given;
    if (n != nullptr) {
      given = in.strings(n, "campaign.metrics");
    } else {
      for (const char* d : {"position_error_m", "first_restitution", "first_peak_force_n"}) {
        given.emplace_back(d, nullptr);
      }
    }
    for (const auto& given_metric : given) {
      const std::string& name = given_metric.first;
      const toml::node* node = given_metric.second;
      const auto it = std::find(names.begin(), names.end(), name);
      if (it == names.end()) {
        in.fail(node, "campaign.metrics",
                fmt::format("unknown metric '{}'{}; allowed: {}", name, did_you_mean(name, names),
                            join_words(names)));
      }
      if (name == "trace") {
        plan.trace_points = 50;
        continue;
      }
      const auto& m = campaign_metrics()[static_cast<std::size_t>(it - names.begin())];
      if (std::none_of(plan.metrics.begin(), plan.metrics.end(),
                       [&](const CampaignMetric& x) { return x.name == name; })) {
        plan.metrics.push_back(m);
      }
    }
    if (c->get("trace_points") != nullptr) {
      const auto tp = in.integer(*c, "trace_points", "campaign", 2, 10000);
      if (plan.trace_points == 0) {
        in.fail(c->get("trace_points"), "campaign.trace_points",
                "is given but metrics has no \"trace\"");
      }
      plan.trace_points = static_cast<int>(tp);
    }
  }

  // ---- cases ----
  {
    const toml::node* n = c->get("cases");
    if (n == nullptr) in.fail(*c, "campaign.cases", "is missing (case names, paths or globs)");
    const fs::path here = file.parent_path();
    std::vector<fs::path> paths;
    for (const auto& [spec, node] : in.strings(n, "campaign.cases")) {
      const bool is_path =
          spec.find('/') != std::string::npos || (spec.size() > 5 && spec.ends_with(".toml"));
      const fs::path rel = fs::path(spec).is_absolute() ? fs::path(spec) : here / spec;
      std::vector<fs::path> found;
      const bool is_glob = spec.find_first_of("*?[") != std::string::npos;
      if (is_glob) {
        found = glob_paths(rel.string());
        if (found.empty()) {
          in.fail(node, "campaign.cases",
                  fmt::format("'{}' matches no file (globs are relative to the campaign file's "
                              "folder)",
                              spec));
        }
      }
      try {
        if (is_glob) {
          // found above
        } else if (is_path) {
          found = resolve_cases(rel.string(), cases_dir(cases_dir_option));
        } else {
          found = resolve_cases(spec, cases_dir(cases_dir_option));
        }
      } catch (const InputError& e) {
        in.fail(node, "campaign.cases", e.what());
      }
      for (auto& p : found) paths.push_back(std::move(p));
    }
    std::set<std::string> names;
    for (const auto& p : paths) {
      CampaignCasePlan cp;
      cp.path = p;
      cp.c = load_case(p, fixed.case_keys);
      if (!names.insert(cp.c.name).second) {
        in.fail(n, "campaign.cases",
                fmt::format("two case files are named '{}' ({}): case names must be unique",
                            cp.c.name, p.string()));
      }
      for (const Body& b : cp.c.bodies) {
        if (!b.fixed) cp.moving_bodies.push_back(b.name);
      }
      const SettingsOverrides base = engine_settings_for(cp.c, fixed.engine_keys);
      for (const auto& e : plan.engines) {
        auto engine = make_engine(e);
        engine->settings().apply(base);
        const auto j = engine->settings().to_json();
        cp.default_dt.push_back(j.contains("dt") && j.at("dt").is_number()
                                    ? j.at("dt").get<double>()
                                    : std::numeric_limits<double>::quiet_NaN());
      }
      plan.cases.push_back(std::move(cp));
    }
  }

  // ---- axes ----
  if (const toml::node* n = root.get("axis")) {
    const auto* arr = n->as_array();
    if (arr == nullptr || !arr->is_array_of_tables()) {
      in.fail(n, "axis", "must be an array of tables: [[axis]]");
    }
    std::set<std::string> names;
    std::set<std::string> keys;
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const toml::table& t = *(*arr)[i].as_table();
      const std::string where = fmt::format("axis[{}]", i);
      in.only_keys(t, where, {"name", "key", "values", "linear", "log", "perturb"});
      CampaignAxisPlan a;
      const toml::node* key = t.get("key");
      if (key == nullptr || !key->is_string()) {
        in.fail(t, where + ".key", "is missing (a --set key, e.g. \"dt\" or \"bodies.*.velocity\")");
      }
      a.axis.key = key->as_string()->get();
      a.axis.name = a.axis.key;
      if (const toml::node* nm = t.get("name")) {
        if (!nm->is_string()) in.fail(nm, where + ".name", "must be a string");
        a.axis.name = nm->as_string()->get();
      }
      // a name becomes a dataset name: no '/', not empty
      if (a.axis.name.empty() || a.axis.name.find('/') != std::string::npos ||
          a.axis.name == "." || a.axis.name == "..") {
        in.fail(t.get("name") ? t.get("name") : key, where + ".name",
                "must be a non-empty name without '/' (give name = \"...\")");
      }
      if (!names.insert(a.axis.name).second) {
        in.fail(&t, where + ".name", fmt::format("axis '{}' is given twice", a.axis.name));
      }
      if (!keys.insert(a.axis.key).second) {
        in.fail(key, where + ".key", fmt::format("key '{}' has an axis already", a.axis.key));
      }
      if (std::any_of(plan.set.begin(), plan.set.end(),
                      [&](const auto& kv) { return kv.first == a.axis.key; })) {
        in.fail(key, where + ".key",
                fmt::format("'{}' is in campaign.set too: give it one place", a.axis.key));
      }
      int kinds = 0;
      for (const char* k : {"values", "linear", "log", "perturb"}) kinds += t.contains(k) ? 1 : 0;
      if (kinds != 1) {
        in.fail(t, where, "give exactly one of values, linear, log, perturb");
      }
      a.axis.unit = axis_unit(a.axis.key);
      if (const toml::node* v = t.get("values")) {
        a.axis.kind = "values";
        const auto* va = v->as_array();
        if (va == nullptr || va->empty()) in.fail(v, where + ".values", "must be a non-empty array of numbers");
        for (const auto& e : *va) {
          const auto x = e.value<double>();
          if (!x || !std::isfinite(*x)) in.fail(&e, where + ".values", "must hold finite numbers");
          a.axis.values.push_back(*x);
        }
        a.axis.spec["values"] = a.axis.values;
      } else if (t.contains("linear") || t.contains("log")) {
        const bool log = t.contains("log");
        const std::string kind = log ? "log" : "linear";
        const toml::node* r = t.get(kind);
        const auto* rt = r->as_table();
        if (rt == nullptr) in.fail(r, where + "." + kind, "must be a table { from, to, points }");
        in.only_keys(*rt, where + "." + kind, {"from", "to", "points"});
        const double from = in.real(*rt, "from", where + "." + kind);
        const double to = in.real(*rt, "to", where + "." + kind);
        const auto points = in.integer(*rt, "points", where + "." + kind, 2, kMaxAxisPoints);
        if (log && (from <= 0.0 || to <= 0.0)) {
          in.fail(r, where + ".log", "from and to must be > 0 on a log range");
        }
        if (from == to) in.fail(r, where + "." + kind, "from and to must differ");
        a.axis.kind = kind;
        a.axis.values = spaced(from, to, points, log);
        a.axis.spec = {{"from", from}, {"to", to}, {"points", points}};
      } else {
        const toml::node* p = t.get("perturb");
        const auto* pt = p->as_table();
        if (pt == nullptr) in.fail(p, where + ".perturb", "must be a table { sigma, samples, seed }");
        in.only_keys(*pt, where + ".perturb", {"sigma", "samples", "seed"});
        a.sigma = in.real(*pt, "sigma", where + ".perturb");
        if (a.sigma < 0.0) in.fail(p, where + ".perturb.sigma", "must be >= 0");
        const auto samples = in.integer(*pt, "samples", where + ".perturb", 1, kMaxAxisPoints);
        a.seed = static_cast<std::uint64_t>(
            in.integer(*pt, "seed", where + ".perturb", 0, std::numeric_limits<std::int64_t>::max()));
        // bodies.<name|*>.<field>
        const std::string& k = a.axis.key;
        const auto dot1 = k.find('.');
        const auto dot2 = k.rfind('.');
        a.field = dot2 == std::string::npos ? "" : k.substr(dot2 + 1);
        a.body = dot1 == std::string::npos || dot2 <= dot1 ? "" : k.substr(dot1 + 1, dot2 - dot1 - 1);
        if (k.rfind("bodies.", 0) != 0 || a.body.empty() ||
            std::find(kPerturbFields.begin(), kPerturbFields.end(), a.field) ==
                kPerturbFields.end()) {
          in.fail(key, where + ".key",
                  fmt::format("a perturbation perturbs a body's initial state: "
                              "bodies.<name or *>.<{}>",
                              join_words(kPerturbFields)));
        }
        a.axis.kind = "perturb";
        a.axis.unit = "1";
        for (std::int64_t s = 0; s < samples; ++s) a.axis.values.push_back(static_cast<double>(s));
        a.axis.spec = {{"sigma", a.sigma}, {"samples", samples}, {"seed", a.seed},
                       {"unit_of_sigma", a.field == "position" ? "m"
                                         : a.field == "velocity" ? "m/s"
                                         : a.field == "angle"    ? "rad"
                                                                 : "rad/s"}};
      }
      a.case_key = a.axis.kind == "perturb" || is_case_key(a.axis.key);
      plan.axes.push_back(std::move(a));
      if (const std::string problem = plan_size_problem(plan.size()); !problem.empty()) {
        in.fail(&t, where, problem);
      }
    }
  }

  // ---- every axis point against every case and engine, before anything runs ----
  for (std::size_t k = 0; k < plan.axes.size(); ++k) {
    plan.axis_lines.push_back(
        static_cast<int>((*root.get("axis")->as_array())[k].source().begin.line));
  }
  check_axis_points(plan, quiet);
  return plan;
}

}  // namespace pb::cli
