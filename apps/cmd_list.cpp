// planarbench list: cases, engines, what each engine supports, settings.
#include <fmt/format.h>

#include <memory>

#include "cli_common.hpp"
#include "commands.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/engines.hpp"

namespace pb::cli {

namespace {

struct ListOptions {
  std::string cases_dir;
  bool settings = false;
};

int run_list(const ListOptions& opt) {
  const auto dir = cases_dir(opt.cases_dir);
  std::vector<Case> cases;
  for (const auto& path : resolve_cases("all", dir)) cases.push_back(load_case(path));

  fmt::print("Cases ({}):\n", dir.string());
  for (const auto& c : cases) {
    // the paper section only ("§3.1"), cut at a comma so no UTF-8 sequence is split
    fmt::print("  {:<22} {:<6} {:>6.3g} s  truth: {:<28} {}\n", c.name,
               c.paper.substr(0, c.paper.find(',')),
               c.duration_s, truth_kind_name(c.truth), c.description);
  }

  fmt::print("\nEngines:\n");
  std::vector<std::unique_ptr<Engine>> engines;
  for (const auto& name : engine_names()) {
    engines.push_back(make_engine(name));
    fmt::print("  {:<10} {}\n", name, engines.back()->version());
  }

  // SPEC §5b: whose collision and whose contact force each engine runs by
  // default, and the modes that differ
  fmt::print("\nWhose physics (each engine's default mode):\n");
  for (const auto& e : engines) {
    const Physics p = e->physics();
    fmt::print("  {:<10} mode {}: collision by {}, contact force by {}{}\n", e->name(), p.mode,
               p.collision_by, p.contact_force_by,
               p.foreknowledge ? " (FOREKNOWLEDGE: calibrated on the run's future)" : "");
    fmt::print("  {:<10}   parameters: {}\n", "", p.parameters);
  }
  fmt::print(
      "  other modes (--set ENGINE.mode=...): mujoco, ode: oracle (calibrated on a probe run of "
      "the case: foreknowledge), inject (the case's law applied by the adapter); box2d: inject\n");

  fmt::print("\nSupport (native | mapped | unsupported):\n  {:<22}", "case");
  for (const auto& e : engines) fmt::print(" {:<12}", e->name());
  fmt::print("\n");
  for (const auto& c : cases) {
    fmt::print("  {:<22}", c.name);
    for (const auto& e : engines) fmt::print(" {:<12}", support_name(e->supports(c).support));
    fmt::print("\n");
  }
  fmt::print("\nReasons:\n");
  for (const auto& c : cases) {
    for (const auto& e : engines) {
      const Capability cap = e->supports(c);
      if (!cap.reason.empty()) {
        fmt::print("  {} x {}: {}: {}\n", c.name, e->name(), support_name(cap.support), cap.reason);
      }
    }
  }

  if (opt.settings) {
    fmt::print("\nEngine settings (--set ENGINE.KEY=VALUE, or KEY=VALUE for every engine binding KEY):\n");
    for (const auto& e : engines) {
      const auto defaults = e->settings().to_json();
      for (const auto& spec : e->settings().specs()) {
        fmt::print("  {}.{:<22} = {:<18} {}\n", e->name(), spec.key, defaults[spec.key].dump(),
                   spec.doc);
      }
    }
    fmt::print(
        "\nCase settings: duration, output_interval, gravity, outline_points, truth,\n"
        "  contact.<field> (every contact pair), contacts.<name>.<field>, bodies.<name>.<field>\n"
        "  (fields as in cases/README.md).\n");
  }
  return 0;
}

}  // namespace

Action add_list_command(CLI::App& app) {
  // the root app's parse errors as one line, like every other error; here
  // because list is registered first (main.cpp is the better home for it)
  use_one_line_errors(app);
  auto opt = std::make_shared<ListOptions>();
  auto* cmd = app.add_subcommand("list", "List cases, engines and what each engine supports");
  cmd->add_option("--cases-dir", opt->cases_dir,
                  "Folder of case files (default: $PLANARBENCH_CASES_DIR or the source tree's cases/)");
  cmd->add_flag("--settings", opt->settings, "Also list every engine setting with its default");
  return [opt] { return run_list(*opt); };
}

}  // namespace pb::cli
