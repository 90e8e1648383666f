// planarbench: run planar contact cases on the reference solver and on MuJoCo,
// Box2D and ODE, and compare them (SPEC §5).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "commands.hpp"
#include "planarbench/build_info.hpp"
#include "planarbench/errors.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "planarbench: verification and benchmark suite for planar rigid-body contact.\n"
      "Runs the cases of cases/ on the analytic truth, the reference solver of Jun, Sohn & Yoo\n"
      "and the MuJoCo, Box2D and ODE adapters, and writes one HDF5 results file.\n"
      "Exit codes: 0 success, 1 tolerance breached (check), 2 bad usage or input,\n"
      "3 an engine failed or diverged.",
      "planarbench"};
  app.set_version_flag("--version", fmt::format("planarbench {} ({}, {})", pb::build_info::kVersion,
                                                pb::build_info::kRevision,
                                                pb::build_info::kBuildType));
  app.require_subcommand(1);
  const auto list = pb::cli::add_list_command(app);
  const auto run = pb::cli::add_run_command(app, argc, argv);
  const auto check = pb::cli::add_check_command(app);
  const auto report = pb::cli::add_report_command(app);
  const auto sweep = pb::cli::add_sweep_command(app, argc, argv);
  const auto campaign = pb::cli::add_campaign_command(app, argc, argv);
  const auto impacts = pb::cli::add_impacts_command(app, argc, argv);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return pb::kExitBadInput;
  }
  try {
    if (app.got_subcommand("list")) return list();
    if (app.got_subcommand("run")) return run();
    if (app.got_subcommand("check")) return check();
    if (app.got_subcommand("report")) return report();
    if (app.got_subcommand("sweep")) return sweep();
    if (app.got_subcommand("campaign")) return campaign();
    if (app.got_subcommand("impacts")) return impacts();
  } catch (const pb::InputError& e) {
    std::fprintf(stderr, "planarbench: error: %s\n", e.what());
    return pb::kExitBadInput;
  } catch (const pb::EngineError& e) {
    std::fprintf(stderr, "planarbench: engine error: %s\n", e.what());
    return pb::kExitEngineFailed;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "planarbench: error: %s\n", e.what());
    return pb::kExitEngineFailed;
  }
  return pb::kExitBadInput;
}
