// The subcommands of the planarbench command line (SPEC §5).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace pb::cli {

// Each registers its subcommand on `app` and returns the action that runs it
// (returning the process exit code) once CLI11 has parsed the arguments.
using Action = std::function<int()>;
Action add_list_command(CLI::App& app);
Action add_run_command(CLI::App& app, int argc, char** argv);
Action add_check_command(CLI::App& app);
Action add_report_command(CLI::App& app);
Action add_sweep_command(CLI::App& app, int argc, char** argv);
Action add_campaign_command(CLI::App& app, int argc, char** argv);
Action add_impacts_command(CLI::App& app, int argc, char** argv);

}  // namespace pb::cli
